#!/bin/sh
# Add object > Plane makes a floor, in the real editor under Xvfb driven with real X input
# (xdotool). On the Menger sponge seen from its preset's camera, the Formula panel's Add object...
# > Plane adds a plane that faces the camera's up and lies under the sponge's bottom face. The
# settled viewport's screenshot, against the one taken before, shows it across the whole width
# of the image's lower part, corners included: a plane cut off at the preset's bound (radius 1.8)
# would be a disc no wider than the sponge's surroundings, and a plane facing the camera would
# not leave the top of the image as it was. The top stays sky.
# Usage: editor_floor_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"

# changed_share A B WxH+X+Y: the share of the rectangle's pixels that differ by more than 6 %
# between screenshots A and B.
changed_share() {
    convert \( "$1" -crop "$3" +repage \) \( "$2" -crop "$3" +repage \) -compose difference -composite \
        -colorspace Gray -threshold 6% -format "%[fx:mean]" info:
}

start "$presets/menger.json" --width 1280 --height 1060
wait_settled
[ "$(q '.document.formula.objects // [] | length')" = 0 ] || fail "the Menger sponge starts with objects"
set -- $(q '.viewport | map(floor) | join(" ")')
vx=$1 vy=$2 vw=$3 vh=$4
import -window "$window" "$out/before.png"

# The Objects header sits below the panel's fold: scroll to it with the wheel, as a person does.
to 150 300
wait_frames 1
wheel_down 10
wait_frames 2
click "header:Objects"
wheel_down 10
wait_frames 2
click "button:Add object"
click "menu:Object Plane"
wait_for '.document.formula.objects // [] | length' 1
[ "$(q '.document.formula.objects[0].object')" = plane ] ||
    fail "Add object > Plane added $(q '.document.formula.objects[0].object // "nothing"')"
echo "floor: $(q '.document.formula.objects[0] | tojson'), bound radius $(q .document.formula.boundRadius)"
# Park the pointer over the panel, away from the viewport; the new structure compiles in the
# background (the old image stays settled meanwhile), then its image settles.
to 150 300
tries=0
while [ "$(q '.viewportCompiling or (.viewportSettled | not)')" != true ] && [ $tries -lt 100 ]; do
    wait_frames 1
    tries=$((tries + 1))
done
tries=0
while [ "$(q '.viewportCompiling // false')" = true ] && [ $tries -lt 600 ]; do
    wait_frames 1
    tries=$((tries + 1))
done
wait_settled
[ -z "$(q '.compileError')" ] || fail "the formula with a plane does not compile: $(q '.compileError')"
[ "$(q .viewportSettled)" = true ] || fail "the viewport did not settle with the plane"
import -window "$window" "$out/after.png"

# The lower band of the viewport, in eight slices across its width: the floor changes each.
band_y=$((vy + vh * 82 / 100))
band_h=$((vh * 14 / 100))
slice_w=$((vw / 8))
i=0
while [ $i -lt 8 ]; do
    share=$(changed_share "$out/before.png" "$out/after.png" "${slice_w}x${band_h}+$((vx + i * slice_w))+$band_y")
    echo "lower band, slice $((i + 1)) of 8: $share of its pixels changed"
    check "$share > 0.6" || fail "slice $((i + 1)) of the lower band shows no floor ($share changed)"
    i=$((i + 1))
done
# The top of the viewport, right of the statistics overlay: sky before and after.
top=$(changed_share "$out/before.png" "$out/after.png" "$((vw * 45 / 100))x$((vh * 5 / 100))+$((vx + vw / 2))+$((vy + vh * 2 / 100))")
echo "top band: $top of its pixels changed"
check "$top < 0.05" || fail "the top of the image changed ($top): the plane is not a floor below the view"
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor floor: OK"
