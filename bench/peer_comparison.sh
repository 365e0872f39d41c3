#!/usr/bin/env bash
# Our side of the comparison with TerrainEngine-OpenGL (issue 15): the default scene at 1280x720
# through the temporal path on Vulkan (lavapipe on a machine without a GPU), at the default and
# the low tier, in milliseconds per frame as `render --frames --stats` reports them (the renderer's
# own time per frame, not the PNG writes): the mean over all frames, and the steady state (the
# median of the frames after the first, which builds the pipelines), the figure to set beside the
# peer's median of its frames 6-8. The peer is built and run outside the project (its
# build and the numbers are in docs/PERFORMANCE.md); run both in one session, interleaved, on a
# quiet machine.
#
#   bench/peer_comparison.sh [build dir] [frames]
set -euo pipefail
build=${1:-build}
frames=${2:-24}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for tier in default low; do
    tierArgs=()
    if [ "$tier" != default ]; then
        tierArgs=(--tier "$tier")
    fi
    line=$("$build/cloudscape" render --backend vulkan --width 1280 --height 720 "${tierArgs[@]}" \
        --frames "0:$((frames - 1))" --checkpoint-every 0 --force --stats -o "$out/f%04d.png" |
        grep -E "ms per frame|steady state" | tr '\n' ' ')
    echo "$tier tier: $line"
done
