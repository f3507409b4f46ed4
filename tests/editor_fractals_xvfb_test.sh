#!/bin/sh
# Whole fractals combined in the real editor under Xvfb, driven with real X input (xdotool): on
# the Menger sponge, a click opens the formula panel's "Fractals combined with this one" header,
# Add fractal... > mandelbulb joins the shipped Mandelbulb preset's fractal to the document, which
# compiles and settles; Ctrl+Z takes it back as one undo step.
# Usage: editor_fractals_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

# Ten wheel clicks down over the formula panel.
scroll_down() {
    to 150 300
    wait_frames 1
    wheel_down 10
    wait_frames 2
}

start "$presets/menger.json" --width 1280 --height 1060
wait_settled
fractals='.document.formula.fractals // [] | length'
[ "$(q "$fractals")" = 0 ] || fail "the Menger sponge starts with combined fractals: $(q "$fractals")"
# The header sits under the objects' header, below the panel's fold: scroll down to it with the
# wheel, as a person does, until it is drawn inside the panel.
scroll_down
click "header:Fractals"
scroll_down
click "button:Add fractal"
click "menu:Fractal mandelbulb"
wait_for "$fractals" 1
[ "$(q "$fractals")" = 1 ] || fail "Add fractal... > mandelbulb added $(q "$fractals") fractals"
[ "$(q '.document.formula.fractals[0].nodes[0].block')" = mandelbulb ] ||
    fail "the fractal added starts with $(q '.document.formula.fractals[0].nodes[0].block'), not a mandelbulb"
[ "$(q '.document.formula.fractals[0].operation // "join"')" = join ] ||
    fail "the fractal added is combined by $(q '.document.formula.fractals[0].operation'), not joined"
[ "$(q '.document.formula.nodes | length')" = 5 ] ||
    fail "adding a fractal changed the sponge's own nodes: $(q '.document.formula.nodes | map(.block) | join(" ")')"
wait_settled
[ -z "$(q '.compileError')" ] || fail "the sponge with a Mandelbulb does not compile: $(q '.compileError')"
[ "$(q .viewportSettled)" = true ] || fail "the viewport did not settle with the Mandelbulb"
to 700 500
wait_frames 1
xdotool keydown ctrl
wait_frames 1
xdotool key z
wait_frames 1
xdotool keyup ctrl
wait_for "$fractals" 0
[ "$(q "$fractals")" = 0 ] || fail "Ctrl+Z left $(q "$fractals") fractals"
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor fractals: OK"
