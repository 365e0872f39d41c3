#!/usr/bin/env bash
# Remakes src/pathtrace/tests/radiance_reference_values.h: the path-traced references of the six
# scenes of RealTimeRadiance (src/pathtrace/tests/radiance_test.cpp), STREAMS independent
# estimates of SPP samples per pixel each, and the real-time render's ratio to them. Run it when
# the real-time lighting model changes on purpose, and say in the commit why the ratios moved.
# Usage: scripts/radiance-reference.sh [STREAMS [SPP]]   (defaults 4 x 1024: about an hour of
# CPU on two cores; run under nice on a shared machine). Needs a built build/ (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
streams=${1:-4}
spp=${2:-1024}
target=src/pathtrace/tests/radiance_reference_values.h
work=$(mktemp "$target.XXXXXX")
trap 'rm -f "$work"' EXIT
CLOUDSCAPE_RADIANCE_REFERENCE_OUT="$work" CLOUDSCAPE_RADIANCE_REFERENCE_STREAMS="$streams" \
    CLOUDSCAPE_RADIANCE_REFERENCE_SPP="$spp" build/test_pathtrace --gtest_also_run_disabled_tests \
    --gtest_filter=RealTimeRadiance.DISABLED_WriteHighSampleReference
mv "$work" "$target"
trap - EXIT
echo "wrote $target"
