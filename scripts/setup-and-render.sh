#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a picture: installs what is missing, builds,
# and renders the default scene (fair-weather cumulus) to out/default.png.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
mkdir -p out
./build/cloudscape render -o out/default.png --stats "$@"
echo "wrote out/default.png"
