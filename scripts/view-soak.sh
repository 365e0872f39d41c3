#!/usr/bin/env bash
# The viewer's soak (issue 13): a long scripted session in a real window under Xvfb on the
# Vulkan device - a camera path and slider changes in a loop - printing the resident memory every
# 500 frames (`memory`; lavapipe's device memory is host memory, so it is counted there) and the
# session's figures at the end (--stats: frames per second, and a scene change's latency to its
# first presented frame). A benchmark, not a test: it runs at nice 19 (SOAK_NICE=0 gives it a
# fair share beside other work, e.g. a fuzzer).
#   scripts/view-soak.sh [FRAMES] [WIDTHxHEIGHT] [TIER] [build dir]
# defaults: 10000 frames at 64x36, tier low, build/.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-10000}
size=${2:-64x36}
tier=${3:-low}
build=${4:-build}
script=$(mktemp /tmp/cloudscape-soak-XXXXXX.txt)
trap 'rm -f "$script"' EXIT
{
    echo "tier $tier"
    echo "wait 100"
    echo "memory"
    # One loop: 250 frames; a slow pan, a fly forward and back, four slider changes.
    loops=$(((frames - 100) / 250))
    for ((i = 0; i < loops; i++)); do
        cov=$(printf '0.%d' $((3 + i % 5)))
        echo "set weather.coverage $cov"
        echo "path slow-pan 60"
        echo "set sun.elevation_deg $((20 + i % 40))"
        echo "path fly-forward 60"
        echo "move 0 0 -2400"
        echo "set wind.speed_mps $((i % 20))"
        echo "orbit 2000 10 0"
        echo "wait 65"
        echo "set lighting.light_samples $((4 + i % 4))"
        # The debug views, each for a few frames (read back and made on the host).
        views=(temporal-source samples density-slice shadow-map depth)
        echo "view ${views[i % 5]}"
        echo "wait 5"
        echo "view picture"
        echo "wait 60"
        if (((i + 1) % 2 == 0)); then echo "memory"; fi
    done
    echo "wait $((frames - 100 - loops * 250))" # the rest of FRAMES
    echo "memory"
} >"$script"
nice -n "${SOAK_NICE:-19}" xvfb-run -a -s '-screen 0 1400x900x24' "$build/cloudscape" view --stats \
    --width "${size%x*}" --height "${size#*x}" --script "$script"
