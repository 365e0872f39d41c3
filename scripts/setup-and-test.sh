#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a full test run: installs what is missing,
# builds, and runs every test: the cpu category and the gpu category (on lavapipe where there
# is no GPU; the validation layers are on in the gpu tests).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"   # labels: cpu, gpu (lavapipe here)
