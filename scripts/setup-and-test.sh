#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a full test run: installs what is missing,
# builds, and runs every test: the cpu category and the gpu category (on lavapipe where there
# is no GPU; the validation layers are on in the gpu tests). Arguments go to ctest.
# The sanitizer stage (the cpu category built with clang under ASan + UBSan, each fuzz harness
# replaying its corpus) is scripts/sanitizer-test.sh; it is not yet part of this command because
# it has not yet been timed and passed on the merged suite (fuzz/, scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"   # labels: cpu, gpu (lavapipe here)
