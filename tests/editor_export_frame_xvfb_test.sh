#!/bin/sh
# The export frame guide in the real editor under Xvfb (Mesa llvmpipe): for an export at 2:1 and
# one at 1:1 (wider than the default 920x779 viewport, so the viewport widens its view and the
# guide is a band; and narrower, the guide a pillar box), the settled viewport inside the guide is compared with `fraktal render` (what the
# export dialog runs) of the same preset at the export's aspect and the guide's size in window
# pixels. The top of the viewport (the stats overlay) is left out. Each must match (PSNR), and
# match far better than the other aspect's render squeezed to the same size (measured: 26.6 and
# 23.5 dB against 11.8 and 11.3).
# Usage: editor_export_frame_xvfb_test.sh FRAKTAL PRESET OUT_DIR
set -eu
fraktal=$1
preset=$2
out=$3
mkdir -p "$out"
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
# PSNR at half size: the viewport renders at 0.75 of the window and is upsampled, the export at
# full size; halving both compares the picture rather than the fractal's finest texture.
psnr() {
    convert "$1" -resize 50% "$1.half.png"
    convert "$2" -resize 50% "$2.half.png"
    compare -metric PSNR "$1.half.png" "$2.half.png" null: 2>&1 | cut -d' ' -f1
}
check() { awk "BEGIN { exit !($1) }"; }

failures=0
for size in 1600x800 900x900; do
    ew=${size%x*}; eh=${size#*x}
    shot="$out/guide_$size.png"
    HOME="$home" xvfb-run -a -s "-screen 0 1280x800x24" "$fraktal" edit "$preset" --export-size "$size" \
        --frames 3000 --until-settled --screenshot "$shot" --frame-log "$out/guide_$size.jsonl" > /dev/null
    # The guide in window pixels (app/editor/viewport/export_frame.cpp), inset 2 px from its outline, and
    # below the stats overlay.
    set -- $(tail -n 1 "$out/guide_$size.jsonl" | python3 -c "
import json, sys
d = json.loads(sys.stdin.read())
vx, vy, vw, vh = d['viewport']
ea = $ew / $eh
va = vw / vh
if ea <= va: gw, gh = vh * ea, vh
else: gw, gh = vw, vw / ea
x0, y0 = vx + (vw - gw) / 2, vy + (vh - gh) / 2
top = max(y0, vy + 150)
print(int(round(gw)), int(round(gh)), int(round(x0)) + 2, int(round(top)), int(round(gw)) - 4,
      int(round(y0 + gh - top)) - 2, int(round(top - y0)), int(d['settled']))")
    gw=$1 gh=$2 cx=$3 cy=$4 cw=$5 ch=$6 skip=$7 settled=$8
    [ "$settled" = 1 ] || { echo "FAIL $size: the viewport did not settle"; failures=$((failures + 1)); continue; }
    convert "$shot" -crop "${cw}x${ch}+${cx}+${cy}" +repage "$out/guide_${size}_viewport.png"
    "$fraktal" render "$preset" -o "$out/export_$size.exr" --png "$out/export_$size.png" --size "${gw}x${gh}" \
        --spp 2 > /dev/null 2>&1
    convert "$out/export_$size.png" -crop "${cw}x${ch}+2+${skip}" +repage "$out/guide_${size}_export.png"
    match=$(psnr "$out/guide_${size}_viewport.png" "$out/guide_${size}_export.png")
    echo "$size: guide ${gw}x${gh}, viewport inside the guide vs the export: $match dB"
    check "$match > 20" || { echo "FAIL $size: the export does not show what the guide frames"; failures=$((failures + 1)); }
    eval "match_$ew=$match gw_$ew=$gw gh_$ew=$gh"
done
# The control: the other aspect's export, squeezed into this guide, matches worse.
for pair in 1600:900 900:1600; do
    a=${pair%:*}; b=${pair#*:}
    eval "size=\${a}x\$(case $a in 1600) echo 800;; *) echo 900;; esac) other=\${b}x\$(case $b in 1600) echo 800;; *) echo 900;; esac)"
    eval "gw=\$gw_$a gh=\$gh_$a match=\$match_$a"
    [ -n "${match:-}" ] || continue
    w=$(identify -format %w "$out/guide_${size}_viewport.png"); h=$(identify -format %h "$out/guide_${size}_viewport.png")
    convert "$out/export_$other.png" -resize "${gw}x${gh}!" -crop "${w}x${h}+2+$(( gh - h - 2 ))" +repage \
        "$out/control_$size.png"
    control=$(psnr "$out/guide_${size}_viewport.png" "$out/control_$size.png")
    echo "$size: against the $other export squeezed into its guide: $control dB"
    check "$control < $match - 6" || { echo "FAIL $size: the control matches as well ($control dB)"; failures=$((failures + 1)); }
done
[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
