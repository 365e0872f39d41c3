#!/usr/bin/env bash
# shellcheck disable=SC2086  # the key lists ($VIEW, $NOAIR, ...) are meant to split into words
# Measures the real-time terrain with its cloud shadows (issue 12) and the storm's emission
# (issue 14) against the path tracer, and prints the rows of docs/QUALITY.md sections 7 and 8.
# Usage: scripts/quality-world.sh [WIDTH HEIGHT SPP [PART]]   (the tables: 96 54 256; the storm
# gets SPP / 4; PART: all (default), terrain (section 7) or storm (section 8))
# Renders go to out/quality-world/; path-traced images are resumed, so a rerun with a larger SPP
# adds samples. Everything runs at nice 10 (a shared machine). The real-time renders use the
# reference tier and no distance LOD, as scripts/quality-table.sh does; the ground truth uses the
# HG+Draine Mie fit for 20 um droplets.
set -euo pipefail
cd "$(dirname "$0")/.."
W=${1:-96}
H=${2:-54}
SPP=${3:-256}
PART=${4:-all}
case "$PART" in all | terrain | storm) ;; *)
    echo "quality-world.sh: PART '$PART': expected all, terrain or storm" >&2
    exit 2
    ;;
esac
CS=${CLOUDSCAPE:-build/cloudscape}
OUT=out/quality-world
mkdir -p "$OUT"
TRUTH="lighting.phase=hg-draine lighting.droplet_diameter_um=20"
RT="--backend cpu --tier reference --width $W --height $H --set march.distance_lod=false"
PT="--width $W --height $H --resume"

pathtrace() { # preset spp out [keys...]
    local preset=$1 spp=$2 out=$3
    shift 3
    # shellcheck disable=SC2086
    nice -n 10 "$CS" pathtrace "$preset" $PT --spp "$spp" --set $TRUTH "$@" -o "$out" >/dev/null
}
render() { # preset out [keys...]
    local preset=$1 out=$2
    shift 2
    rm -f "$out"
    # shellcheck disable=SC2086
    nice -n 10 "$CS" render "$preset" $RT "$@" -o "$out" >/dev/null
}
row() { # label reference test
    "$CS" compare --clamp 64 "$2" "$3" | awk -v l="$1" '
        /^SSIM/ { s = $NF } /^MS-SSIM/ { m = $NF } /relative/ { r = $NF }
        /mean radiance/ { q = $NF }
        END { printf "| %s | %s | %s | %s | %s |\n", l, s, m, r, q }'
}
mean_ratio() { # reference test: mean(test) / mean(reference), unclamped
    "$CS" compare --clamp 1e30 "$1" "$2" | awk '/mean radiance/ { print $NF }'
}

terrain_section() {
# ---- Section 7: the terrain. Looking down on the mountains (pitch -25): mostly terrain.
VIEW="camera.pitch_deg=-25"
NOAIR="atmosphere.aerial_perspective=false shafts.enabled=false"
for s in 0 1; do
    pathtrace mountains "$SPP" "$OUT/m.pt$s.exr" $VIEW --stream $s
done
pathtrace mountains "$SPP" "$OUT/m.clear.pt.exr" $VIEW weather.coverage=0
AIR_SPP=$((SPP * 3 / 8 > 0 ? SPP * 3 / 8 : 1)) # the traced air costs about 3x
pathtrace mountains "$AIR_SPP" "$OUT/m.air.pt.exr" $VIEW pathtrace.atmosphere=true
render mountains "$OUT/m.clear.exr" --set $VIEW $NOAIR weather.coverage=0
render mountains "$OUT/m.map.exr" --set $VIEW $NOAIR
render mountains "$OUT/m.nomap.exr" --set $VIEW $NOAIR cloud_shadow.enabled=false
render mountains "$OUT/m.steps128.exr" --set $VIEW $NOAIR cloud_shadow.steps=128
render mountains "$OUT/m.res2048.exr" --set $VIEW $NOAIR cloud_shadow.resolution=2048
render mountains "$OUT/m.shafts.exr" --set $VIEW
render mountains "$OUT/m.ap.exr" --set $VIEW shafts.enabled=false
echo "| comparison | SSIM | MS-SSIM | rel. HDR error | mean ratio |"
echo "|---|---|---|---|---|"
row "path tracer noise floor ($SPP spp, stream 1 vs 0)" "$OUT/m.pt0.exr" "$OUT/m.pt1.exr"
row "no clouds (coverage 0): terrain shading and sky term" "$OUT/m.clear.pt.exr" "$OUT/m.clear.exr"
row "shadow map (the preset's: 256 texels, 60 km, 96 steps)" "$OUT/m.pt0.exr" "$OUT/m.map.exr"
row "shadow map, 128 steps" "$OUT/m.pt0.exr" "$OUT/m.steps128.exr"
row "shadow map, 2048 texels" "$OUT/m.pt0.exr" "$OUT/m.res2048.exr"
row "no map: groundCloudShadow's two cheap samples" "$OUT/m.pt0.exr" "$OUT/m.nomap.exr"
row "with the air: shadow map, aerial perspective, shafts (the preset)" "$OUT/m.air.pt.exr" \
    "$OUT/m.shafts.exr"
row "with the air: shadow map, aerial perspective, no shafts" "$OUT/m.air.pt.exr" "$OUT/m.ap.exr"
}

storm_section() {

# ---- Section 8: the storm's emission. The superstorm preset (glow), and a ground discharge.
# A quarter of the samples: the storm converges faster than the terrain's fireflies.
S_SPP=$((SPP / 4 > 0 ? SPP / 4 : 1))
# The flash at strength 300 (the default until 2026-12-04; the table in QUALITY.md was made at it).
FLASH="storm.lightning=true time_s=300.433 storm.lightning_strength=300"
NOAP="atmosphere.aerial_perspective=false" # no air in view, as the tabled path tracer
# The path tracer has no high layer, so the real-time renders leave out the storm's cirrus.
NOCI="storm.cirrus=0"
for s in 0 1; do
    pathtrace superstorm "$S_SPP" "$OUT/s.pt$s.exr" --stream $s
done
pathtrace superstorm "$S_SPP" "$OUT/s.noglow.pt.exr" storm.glow_strength=0
pathtrace superstorm "$S_SPP" "$OUT/s.flash.pt.exr" $FLASH
pathtrace superstorm "$S_SPP" "$OUT/s.noflash.pt.exr" time_s=300.433
pathtrace superstorm "$S_SPP" "$OUT/s.flash0.pt.exr" $FLASH clouds.albedo=0
render superstorm "$OUT/s.exr" --set $NOCI $NOAP
render superstorm "$OUT/s.ap.exr" --set $NOCI
render superstorm "$OUT/s.noglow.exr" --set $NOCI $NOAP storm.glow_strength=0
render superstorm "$OUT/s.flash.exr" --set $NOCI $NOAP $FLASH
render superstorm "$OUT/s.noflash.exr" --set $NOCI $NOAP time_s=300.433
render superstorm "$OUT/s.flash0.exr" --set $NOCI $NOAP $FLASH clouds.albedo=0
echo
echo "| comparison | SSIM | MS-SSIM | rel. HDR error | mean ratio |"
echo "|---|---|---|---|---|"
row "superstorm: path tracer noise floor ($S_SPP spp)" "$OUT/s.pt0.exr" "$OUT/s.pt1.exr"
row "superstorm (glow), no aerial perspective" "$OUT/s.pt0.exr" "$OUT/s.exr"
row "superstorm (glow), the preset (aerial perspective)" "$OUT/s.pt0.exr" "$OUT/s.ap.exr"
row "ground discharge (flash, bolt), no aerial perspective" "$OUT/s.flash.pt.exr" \
    "$OUT/s.flash.exr"
row "ground discharge, clouds.albedo 0 (emission and absorption only)" \
    "$OUT/s.flash0.pt.exr" "$OUT/s.flash0.exr"
# The emission's own share of the mean radiance, (with / without) - 1, each side: the path
# tracer's pairs share their random numbers (emission draws none), so the difference is clean.
echo
glow_pt=$(mean_ratio "$OUT/s.noglow.pt.exr" "$OUT/s.pt0.exr")
glow_rt=$(mean_ratio "$OUT/s.noglow.exr" "$OUT/s.exr")
flash_pt=$(mean_ratio "$OUT/s.noflash.pt.exr" "$OUT/s.flash.pt.exr")
flash_rt=$(mean_ratio "$OUT/s.noflash.exr" "$OUT/s.flash.exr")
echo "glow: mean radiance with / without: path tracer $glow_pt, real-time $glow_rt"
echo "flash: mean radiance with / without: path tracer $flash_pt, real-time $flash_rt"

# The storm's lighting: today's (the clouds' light reads the shadow map beyond its cone, the
# ambient as it is under the storm) against the earlier one (the long sample, the light march's
# density scale 8, the ambient doubled low under the storm), glow off, no air, no cirrus.
OLDLIGHT="cloud_shadow.on_clouds=false storm.light_density_scale=8 storm.ambient_scale=2"
LIT="$NOCI $NOAP storm.glow_strength=0"
pathtrace under-the-storm "$S_SPP" "$OUT/u.noglow.pt.exr" $LIT
render under-the-storm "$OUT/u.noglow.exr" --set $LIT
render under-the-storm "$OUT/u.noglow.old.exr" --set $LIT $OLDLIGHT
render superstorm "$OUT/s.noglow.old.exr" --set $LIT $OLDLIGHT
render superstorm "$OUT/s.noglow.rt.exr" --set $LIT
echo
echo "| the storm's lighting, glow off (real-time vs path tracer) | SSIM | MS-SSIM | rel. HDR error | mean ratio |"
echo "|---|---|---|---|---|"
row "superstorm, earlier lighting (long sample, density scale 8, ambient x2)" \
    "$OUT/s.noglow.pt.exr" "$OUT/s.noglow.old.exr"
row "superstorm, the map beyond the cone, ambient x1" "$OUT/s.noglow.pt.exr" "$OUT/s.noglow.rt.exr"
row "under-the-storm, earlier lighting" "$OUT/u.noglow.pt.exr" "$OUT/u.noglow.old.exr"
row "under-the-storm, ambient x1 (the preset has no map)" "$OUT/u.noglow.pt.exr" \
    "$OUT/u.noglow.exr"
}

[ "$PART" = storm ] || terrain_section
[ "$PART" = terrain ] || storm_section
