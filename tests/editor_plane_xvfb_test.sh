#!/bin/sh
# The 2D editor under Xvfb with real input (xdotool), as a person explores a Julia set
# (presets/2d/julia.json, opened with --state-file; every 2D preset opening clean is
# editor_presets_clean_xvfb_test.sh): a left drag across the viewport pans the view by the drag
# (the centre moves against the drag by its length in plane units, the width stays; moving the view
# is no undo step); three wheel notches up over the viewport zoom in (the width shrinks by 1.25^3)
# keeping the plane point under the pointer in place; the title then says the document changed,
# and a screenshot of the viewport differs from the one taken before.
# Usage: editor_plane_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)
out=$3
mkdir -p "$out"

start "$presets/2d/julia.json"
# The view refines over many frames on llvmpipe: the screenshots are taken after as many frames.
wait_frames 30
[ "$(q .title)" = "julia.json - fraktal" ] || fail "julia.json opens as '$(q .title)'"
set -- $(q '.viewport | map(floor) | join(" ")')
vx=$1 vy=$2 vw=$3 vh=$4
crop="${vw}x$((vh - 160))+$vx+$((vy + 160))" # below the stats overlay
shot() { import -window root "$out/$1.png"; convert "$out/$1.png" -crop "$crop" +repage "$out/$1_viewport.png"; }
shot plane_opened
cx0=$(q '.document.view.center[0]') cy0=$(q '.document.view.center[1]') w0=$(q '.document.view.width')

# A drag right and down by (160, 80) window pixels: the plane follows the pointer.
set -- $(viewport_centre)
mx=$1 my=$2
drag_frames $((mx - 80)) $((my - 40)) 160 80 8
wait_frames 3
cx1=$(q '.document.view.center[0]') cy1=$(q '.document.view.center[1]') w1=$(q '.document.view.width')
echo "drag (160, 80) px: centre ($cx0, $cy0) -> ($cx1, $cy1), width $w0 -> $w1, viewport ${vw}x$vh"
# One window pixel is width / viewport width plane units.
check "($cx0 - $cx1) / (160 * $w0 / $vw) > 0.95 && ($cx0 - $cx1) / (160 * $w0 / $vw) < 1.05" ||
    fail "the drag moved the centre's x by $cx0 -> $cx1, not by 160 px of plane"
check "($cy1 - $cy0) / (80 * $w0 / $vw) > 0.95 && ($cy1 - $cy0) / (80 * $w0 / $vw) < 1.05" ||
    fail "the drag moved the centre's y by $cy0 -> $cy1, not by 80 px of plane (up the image is +y)"
[ "$w1" = "$w0" ] || fail "the drag changed the width: $w0 -> $w1"
[ "$(q .undoDepth)" = 0 ] || fail "the drag made $(q .undoDepth) undo steps (moving the view is no edit)"

# Three notches up with the pointer over the viewport, off its centre: zoom in about it.
px=$((mx + 150)) py=$((my - 100))
to "$px" "$py"
wait_frames 2
for i in 1 2 3; do xdotool click 4; wait_frames 1; done
wait_frames 3
cx2=$(q '.document.view.center[0]') cy2=$(q '.document.view.center[1]') w2=$(q '.document.view.width')
echo "3 notches up at ($px, $py): width $w1 -> $w2, centre ($cx1, $cy1) -> ($cx2, $cy2)"
check "$w1 / $w2 > 1.95 - 0.01 && $w1 / $w2 < 1.96 + 0.01" || fail "the wheel zoomed by $w1 / $w2, not 1.25^3"
# The plane point under the pointer stays: (pointer - centre) * width / vw + centre is the same.
ux1=$(awk -v c="$cx1" -v w="$w1" 'BEGIN { print c + ('"$px - $vx"' - '"$vw"' / 2) * w / '"$vw"' }')
ux2=$(awk -v c="$cx2" -v w="$w2" 'BEGIN { print c + ('"$px - $vx"' - '"$vw"' / 2) * w / '"$vw"' }')
check "($ux1 - $ux2) < 0.01 * $w1 && ($ux2 - $ux1) < 0.01 * $w1" ||
    fail "the plane point under the pointer moved: x $ux1 -> $ux2"
case "$(q .title)" in "* julia.json - fraktal") ;; *) fail "after the drag and zoom the title is '$(q .title)'" ;; esac

wait_frames 30
shot plane_panned_zoomed
pixels=$(identify -format '%[fx:w*h]' "$out/plane_opened_viewport.png")
differing=$(compare -metric AE -fuzz 6% "$out/plane_opened_viewport.png" "$out/plane_panned_zoomed_viewport.png" null: 2>&1 |
    cut -d' ' -f1)
echo "screenshots: $differing of $pixels viewport pixels differ after the pan and zoom"
check "$differing > $pixels / 5" || fail "the viewport looks as it did before the pan and zoom ($differing pixels differ)"
stop

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
