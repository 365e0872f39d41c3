#!/usr/bin/env bash
# The viewer's frame rate (issue 13): `cloudscape view --stats` in a real window under Xvfb on the
# Vulkan device (lavapipe on a machine without a GPU), default scene, for each window size and
# tier: a still camera (what a person authoring the sky sees between drags: the renderer keeps
# the shadow map and the background), a camera flying forward (everything is made every frame),
# and a slider change's time to its first presented frame. Prints one --stats line per run: the
# fps in the window includes the first frame's set-up (its pipelines and uploads), the fps after
# the first frame does not.
# A benchmark, not a test: interleave runs when comparing two builds.
#   bench/view_fps.sh [build dir] [sizes...]   (default: build 640x360 1280x720)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(640x360 1280x720)
dir=$(mktemp -d /tmp/cloudscape-view-fps-XXXXXX)
trap 'rm -rf "$dir"' EXIT
printf 'wait 90\n' >"$dir/still.txt"
printf 'wait 2\npath fly-forward 30\n' >"$dir/moving.txt"
printf 'wait 20\nset weather.coverage 0.35\nwait 10\nset weather.coverage 0.5\nwait 10\n' \
    >"$dir/change.txt"
for size in "${sizes[@]}"; do
    for tier in low default; do
        for run in still moving change; do
            printf '%s %s %s: ' "$size" "$tier" "$run"
            tierFlag=()
            [ "$tier" != default ] && tierFlag=(--tier "$tier")
            xvfb-run -a -s '-screen 0 1400x900x24' "$build/cloudscape" view --stats \
                --width "${size%x*}" --height "${size#*x}" "${tierFlag[@]}" \
                --script "$dir/$run.txt" 2>&1 | grep '^view:' || echo "failed"
        done
    done
done
