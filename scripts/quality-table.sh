#!/usr/bin/env bash
# Measures the real-time lighting models against the path-traced ground truth on every preset and
# prints the Markdown table of docs/QUALITY.md. Usage:
#   scripts/quality-table.sh [WIDTH HEIGHT SPP] [PRESET...]
# Renders go to out/quality/ (path-traced images are resumed, so a rerun with a larger SPP adds
# samples). The real-time renders use the reference tier (many steps, no march shortcuts) and
# no distance LOD, so that what differs from the path tracer is the lighting model alone. The
# ground truth uses the HG+Draine Mie fit for 20 um droplets: the physical phase function.
set -euo pipefail
cd "$(dirname "$0")/.."
W=${1:-160}
H=${2:-90}
SPP=${3:-64}
shift $(($# < 3 ? $# : 3))
PRESETS=("$@")
if [ ${#PRESETS[@]} -eq 0 ]; then
    PRESETS=(fair-weather-cumulus broken-stratocumulus overcast-stratus rain-storm sunset
             above-the-deck inside-cloud)
fi
CS=${CLOUDSCAPE:-build/cloudscape} # CLOUDSCAPE=path runs another build
OUT=out/quality
mkdir -p "$OUT"
TRUTH=(--set lighting.phase=hg-draine lighting.droplet_diameter_um=20)
# The path tracer has no terrain: a preset with a landscape is compared as the sky it had before
# the landscape was added, named here key by key (fair weather: flat ground, camera 2 m up).
declare -A SKY_ONLY=(
    [fair-weather-cumulus]="terrain.enabled=false cloud_shadow.enabled=false camera.position=[0,2,0]
        camera.pitch_deg=12 atmosphere.ground_albedo=[0.15,0.15,0.15]"
)

# name|overrides: the seeds' model first, then one improvement at a time. Every lighting key is
# set explicitly, so the table does not move when the defaults do.
SEEDS="lighting.phase=two-lobe lighting.silver_weight=0 lighting.scattering_octaves=1"
WRENNINGE="lighting.scattering_octaves=3 lighting.octave_factors=[0.5,0.5,0.5]"
TUNED="lighting.scattering_octaves=4 lighting.octave_factors=[0.6,0.3,0.5]"
VARIANTS=(
    "seeds|$SEEDS lighting.energy_conserving_steps=false"
    "+exact steps|$SEEDS"
    "+octaves|$SEEDS $WRENNINGE"
    "+two-lobe (old default)|lighting.phase=two-lobe lighting.silver_weight=0.3 $WRENNINGE"
    "+hg-draine|lighting.phase=hg-draine $WRENNINGE"
    "+tuned octaves (default)|lighting.phase=hg-draine $TUNED"
    "default without powder|lighting.phase=hg-draine $TUNED lighting.powder=0"
)

metric() { # file key -> value
    awk -v k="$2" 'index($0, k) == 1 { print $(NF - ($0 ~ /dB$/ ? 1 : 0)) }' "$1"
}

echo "| preset | model | SSIM | MS-SSIM | rel. HDR error | mean ratio | real-time ms |"
echo "|---|---|---|---|---|---|---|"
for p in "${PRESETS[@]}"; do
    sky=${SKY_ONLY[$p]:-}
    for stream in 0 1; do
        # shellcheck disable=SC2086
        $CS pathtrace "$p" --width "$W" --height "$H" --spp "$SPP" --stream $stream --resume \
            "${TRUTH[@]}" $sky -o "$OUT/$p.pt$stream.exr" >/dev/null
    done
    # The noise floor: two independent path-traced estimates against each other.
    $CS compare --clamp 64 "$OUT/$p.pt0.exr" "$OUT/$p.pt1.exr" >"$OUT/$p.noise.txt"
    echo "| $p | *path tracer noise floor ($SPP spp)* | $(metric "$OUT/$p.noise.txt" SSIM) |" \
         "$(metric "$OUT/$p.noise.txt" MS-SSIM) | $(metric "$OUT/$p.noise.txt" relative) |" \
         "$(metric "$OUT/$p.noise.txt" "mean radiance") | |"
    for v in "${VARIANTS[@]}"; do
        name=${v%%|*}
        sets=${v#*|}
        file="$OUT/$p.$(echo "$name" | tr -cd 'a-z0-9+-').exr"
        rm -f "$file"
        # shellcheck disable=SC2086
        $CS render "$p" --backend cpu --tier reference --width "$W" --height "$H" --stats \
            --set march.distance_lod=false ${sets:+$sets} $sky -o "$file" >"$file.stats.txt"
        ms=$(awk '/render time/ { printf "%.0f", $3 * 1000 }' "$file.stats.txt")
        $CS compare --clamp 64 "$OUT/$p.pt0.exr" "$file" >"$file.cmp.txt"
        echo "| $p | $name | $(metric "$file.cmp.txt" SSIM) | $(metric "$file.cmp.txt" MS-SSIM) |" \
             "$(metric "$file.cmp.txt" relative) | $(metric "$file.cmp.txt" "mean radiance") |" \
             "$ms |"
    done
done
