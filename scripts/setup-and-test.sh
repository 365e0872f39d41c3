#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a full test run: installs what is missing,
# builds, and runs every test: the cpu category and the gpu category (on lavapipe where there
# is no GPU; the validation layers are on in the gpu tests), then the sanitizer stage
# (scripts/sanitizer-test.sh: the library, the cpu tests and the fuzz harnesses built with clang
# under ASan + UBSan in build-asan/, each harness replaying its corpus). Arguments go to the
# first ctest only. docs/RELIABILITY.md has the stage's times.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"   # labels: cpu, gpu (lavapipe here)
./scripts/sanitizer-test.sh
