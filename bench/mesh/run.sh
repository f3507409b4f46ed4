#!/bin/bash
# Memory and time of `fraktal mesh` against the resolution, on the Mandelbulb and the Menger
# sponge, and mandelbulber2's own mesh export (`mandelbulber2 -n -V ply`) on the same lattice,
# side by side in one run. Prints the Markdown table of bench/mesh/README.md.
#
# Usage: bench/mesh/run.sh BUILD_DIR [OUT_DIR]
#   SIZES="256 512 1024 2048"   fraktal's lattices (voxels across the bound)
#   MB2_SIZES="128 256"         mandelbulber2's (its export samples a dense lattice: 512^3 takes
#                               it about 8x its 256^3 time)
#   SCENES="mandelbulb menger"
# Each row is one process: its wall time and its peak resident memory (/usr/bin/time's maximum
# RSS), the bricks of 8^3 voxels sampled (of those in the bound) and the triangles written. The
# "x per doubling" column is the peak's ratio to the row above: a surface grows 4x per doubling
# of the resolution, a volume 8x (a fractal surface somewhat over 4x).
set -euo pipefail
build=${1:?usage: bench/mesh/run.sh BUILD_DIR [OUT_DIR]}
out=${2:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/../.." && pwd)
fraktal="$build/app/fraktal"
sizes=${SIZES:-256 512 1024 2048}
mb2_sizes=${MB2_SIZES:-128 256}
scenes=${SCENES:-mandelbulb menger}
mkdir -p "$out"

# mandelbulber2 settings of the same fractal on the same cube: the bulb (formula 2, power 8) of
# presets/mandelbulb.json (12 iterations, bailout 2) in its 1.5 bound, the sponge (formula 7) of
# presets/menger.json (8 iterations) in its 1.8 bound; the export's membership test runs the
# preset's iterations (voxel_max_iter).
mb2_settings() { # scene size
    local formula bound iterations bailout
    case $1 in
        mandelbulb) formula=2 bound=1.5 iterations=12 bailout=2 ;;
        menger) formula=7 bound=1.8 iterations=8 bailout=10 ;;
    esac
    cat <<SETTINGS
# Mandelbulber settings file
# version 2.20
# only modified parameters
[main_parameters]
formula_1 $formula;
N $iterations;
bailout $bailout;
voxel_custom_limit_enabled true;
voxel_limit_min -$bound -$bound -$bound;
voxel_limit_max $bound $bound $bound;
voxel_max_iter $iterations;
voxel_samples_x $2;
voxel_samples_y $2;
voxel_samples_z $2;
voxel_image_path $out/mb2-$1-$2/;
[fractal_1]
power 8;
SETTINGS
}

# Runs a command under /usr/bin/time; sets $seconds and $peak_mb, and $failed to its error line
# when it fails (a lattice refused up front is a row of the table, not the end of the run).
timed() {
    local log=$1
    shift
    failed=
    /usr/bin/time -f "%e %M" -o "$log.time" "$@" > "$log" 2>&1 || failed=$(grep -m1 'error' "$log" || tail -1 "$log")
    read -r seconds peak_kb < <(tail -1 "$log.time")
    peak_mb=$((peak_kb / 1024))
}

echo "| program | scene | lattice | bricks sampled | triangles | peak MB | x per doubling | wall s |"
echo "|---|---|---|---|---|---|---|---|"
for scene in $scenes; do
    previous=
    for n in $sizes; do
        log="$out/fraktal-$scene-$n.log"
        timed "$log" "$fraktal" mesh "$root/presets/$scene.json" --resolution "$n" -o "$out/$scene-$n.ply"
        if [ -n "$failed" ]; then
            echo "| fraktal | $scene | ${n}^3 | ${failed#fraktal: error: } | | $peak_mb | | $seconds |"
            continue
        fi
        bricks=$(sed -n 's/.* \([0-9]*\) of \([0-9]*\) bricks near the surface.*/\1 of \2/p' "$log")
        triangles=$(sed -n 's/^wrote .*: \([0-9]*\) triangles.*/\1/p' "$log")
        ratio=${previous:+$(awk -v a="$peak_mb" -v b="$previous" 'BEGIN { printf "%.1f", a / b }')}
        echo "| fraktal | $scene | ${n}^3 | $bricks | $triangles | $peak_mb | ${ratio:--} | $seconds |"
        previous=$peak_mb
        rm -f "$out/$scene-$n.ply"
    done
    previous=
    for n in $mb2_sizes; do
        command -v mandelbulber2 > /dev/null || break
        settings="$out/mb2-$scene-$n.fract"
        mb2_settings "$scene" "$n" > "$settings"
        mkdir -p "$out/mb2-$scene-$n" "$out/mb2-home"
        timed "$out/mb2-$scene-$n.log" env HOME="$out/mb2-home" QT_QPA_PLATFORM=offscreen mandelbulber2 -n -V ply "$settings"
        if [ -n "$failed" ]; then
            echo "| mandelbulber2 | $scene | ${n}^3 | failed: $failed | | $peak_mb | | $seconds |"
            continue
        fi
        ply=$(find "$out/mb2-$scene-$n" "$out/mb2-home/.mandelbulber/slices" -name '*.ply' -newer "$settings" 2> /dev/null | head -1)
        triangles=$([ -n "$ply" ] && sed -n 's/^element face \([0-9]*\)/\1/p' "$ply" | head -1 || echo "?")
        ratio=${previous:+$(awk -v a="$peak_mb" -v b="$previous" 'BEGIN { printf "%.1f", a / b }')}
        echo "| mandelbulber2 | $scene | ${n}^3 | dense | $triangles | $peak_mb | ${ratio:--} | $seconds |"
        previous=$peak_mb
        rm -f "$ply"
    done
done
