#!/bin/sh
# Objects beside the fractal in the real editor under Xvfb, driven with real X input (xdotool): on
# the Menger sponge, a click opens the formula panel's "Objects beside the fractal" header, Add
# object... > Torus adds a torus (joined, at the origin) to the document, which compiles and
# settles; Ctrl+Z takes it back as one undo step.
# Usage: editor_objects_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2


start "$presets/menger.json" --width 1280 --height 1060
wait_settled
objects='.document.formula.objects // [] | length'
[ "$(q "$objects")" = 0 ] || fail "the Menger sponge starts with objects: $(q "$objects")"
# The header sits under the selected node's parameters, below the panel's fold: scroll down to it
# with the wheel, as a person does, until it is drawn inside the panel.
to 150 300
wait_frames 1
wheel_down 10
wait_frames 2
click "header:Objects"
wheel_down 10
wait_frames 2
click "button:Add object"
click "menu:Object Torus"
wait_for "$objects" 1
[ "$(q "$objects")" = 1 ] || fail "Add object > Torus added $(q "$objects") objects"
[ "$(q '.document.formula.objects[0].object')" = torus ] ||
    fail "the object added is $(q '.document.formula.objects[0].object'), not a torus"
wait_settled
[ -z "$(q '.compileError')" ] || fail "the formula with a torus does not compile: $(q '.compileError')"
[ "$(q .viewportSettled)" = true ] || fail "the viewport did not settle with the torus"
to 700 500
wait_frames 1
xdotool keydown ctrl
wait_frames 1
xdotool key z
wait_frames 1
xdotool keyup ctrl
wait_for "$objects" 0
[ "$(q "$objects")" = 0 ] || fail "Ctrl+Z left $(q "$objects") objects"
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor objects: OK"
