#!/bin/sh
# An object's own colour, in the real editor under Xvfb driven with real X input (xdotool): on the
# Menger sponge, Add object... > Plane lays a floor under it, grey (the default colour). A 0 typed
# into the red field of the floor's Colour widget (Ctrl+click, as ImGui edits a drag field) takes
# the red out of it (one undo step, no recompile); once the view settles, the floor's band of the screenshot is the new colour, a
# blue-green, in every slice across the width, with no stripes (the fractal's orbit-trap palette
# coloured objects before they had a colour of their own).
# Usage: editor_object_color_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"

# band_stats IMAGE WxH+X+Y: the rectangle's mean red, green and blue (0..1), and the standard
# deviation over its pixels of the red share r / (r + g + b) (ImageMagick's fx, one pass each).
band_stats() {
    convert "$1" -crop "$2" +repage -format "%[fx:mean.r] %[fx:mean.g] %[fx:mean.b]\n" info:
}
red_share_spread() {
    convert "$1" -crop "$2" +repage -fx "r / (r + g + b + 0.0001)" -format "%[fx:standard_deviation.r]" info:
}
# settle_after_edit: waits for the edit's image to settle; `compiled` says whether the viewport
# compiled a new structure meanwhile.
settle_after_edit() {
    compiled=false
    tries=0
    while [ "$(q '.viewportSettled')" = true ] && [ $tries -lt 30 ]; do
        [ "$(q '.viewportCompiling // false')" = false ] || compiled=true
        wait_frames 1
        tries=$((tries + 1))
    done
    tries=0
    while [ "$(q '.viewportCompiling // false')" = true ] && [ $tries -lt 600 ]; do
        compiled=true
        wait_frames 1
        tries=$((tries + 1))
    done
    wait_settled
}

start "$presets/menger.json" --width 1280 --height 1060
wait_settled
set -- $(q '.viewport | map(floor) | join(" ")')
vx=$1 vy=$2 vw=$3 vh=$4

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
to 150 300
settle_after_edit
[ -z "$(q '.compileError')" ] || fail "the formula with a plane does not compile: $(q '.compileError')"
import -window "$window" "$out/grey.png"

# The floor's Colour widget, scrolled into the panel; its red field is the leftmost of the three.
wheel_down 10
wait_frames 2
wait_for '.widgets["color:Object 1"] != null' true
if [ "$(q '.widgets["color:Object 1"] != null')" != true ]; then
    fail "no Colour widget for the floor"
else
    set -- $(q '.widgets["color:Object 1"] | "\(.[0] + 12 | floor) \(.[1] + .[3] / 2 | floor)"')
    # Ctrl+click turns ImGui's drag field into a text field with its text selected; 0 and Enter
    # set the channel, as a person types a value.
    ctrl_click_at "$1" "$2"
    wait_frames 1
    press_keys ctrl a
    press_keys 0
    press_keys Return
    wait_frames 3
fi
wait_for '.document.formula.objects[0].color[0] // 1 | . < 0.01' true
red=$(q '.document.formula.objects[0].color[0] // "none"')
green=$(q '.document.formula.objects[0].color[1] // "none"')
echo "floor colour after typing: $(q '.document.formula.objects[0].color // [] | tojson')"
check "\"$red\" != \"none\" && $red < 0.01" 2>/dev/null || fail "typing 0 left the floor's red at $red"
check "\"$green\" != \"none\" && $green > 0.6" 2>/dev/null || fail "typing into the red field changed the floor's green to $green"
[ "$(q '.undoLabel')" = "change of colour" ] || fail "the undo step reads \"$(q '.undoLabel')\""
to 150 300
settle_after_edit
[ "$compiled" = false ] || fail "a change of colour compiled the formula again"
[ -z "$(q '.compileError')" ] || fail "the coloured floor does not compile: $(q '.compileError')"
[ "$(q .viewportSettled)" = true ] || fail "the viewport did not settle with the coloured floor"
import -window "$window" "$out/teal.png"

# The floor's band (as in editor_floor_xvfb_test.sh), in eight slices across the width: grey
# before (its red share a third), blue-green after (no red), one colour across each slice.
band_y=$((vy + vh * 82 / 100))
band_h=$((vh * 14 / 100))
slice_w=$((vw / 8))
i=0
while [ $i -lt 8 ]; do
    rect="${slice_w}x${band_h}+$((vx + i * slice_w))+$band_y"
    set -- $(band_stats "$out/grey.png" "$rect")
    grey_r=$1 grey_g=$2 grey_b=$3
    set -- $(band_stats "$out/teal.png" "$rect")
    teal_r=$1 teal_g=$2 teal_b=$3
    spread=$(red_share_spread "$out/teal.png" "$rect")
    grey_spread=$(red_share_spread "$out/grey.png" "$rect")
    echo "slice $((i + 1)): grey $grey_r $grey_g $grey_b (red share spread $grey_spread)," \
        "after $teal_r $teal_g $teal_b (red share spread $spread)"
    check "$grey_r > 0.6 * $grey_g && $grey_r > 0.6 * $grey_b" ||
        fail "slice $((i + 1)): the grey floor is not grey ($grey_r $grey_g $grey_b)"
    check "$teal_r < 0.35 * $teal_g && $teal_r < 0.35 * $teal_b" ||
        fail "slice $((i + 1)): the floor is not blue-green after typing ($teal_r $teal_g $teal_b)"
    check "$spread < 0.03 && $grey_spread < 0.03" ||
        fail "slice $((i + 1)): the floor's colour varies across it (spread $grey_spread, then $spread): stripes"
    i=$((i + 1))
done
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor object colour: OK"
