#!/bin/sh
# Every edit shows at once, in the real editor under Xvfb with real X input (xdotool): on the
# Menger sponge with objects, with the viewport settled, the "Objects beside the fractal" header is
# opened, the sphere's radius ctrl+clicked, 0.2 typed and Enter pressed. The viewport must start
# again and settle to the picture a fresh editor shows of the same preset with that radius
# (compared on screenshots of the viewport, PSNR), and that picture must differ from the one
# before the edit (the sphere shrank on screen).
# Usage: editor_edit_at_rest_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"
radius='.document.formula.objects[0].params.radius'

# Opens PRESET with the stats overlay off (its changing figures are no part of the picture) and
# waits for the viewport to settle.
open_settled() {
    start "$1" --width 1280 --height 1060
    set -- $(viewport_centre)
    to "$1" "$2"
    wait_frames 1
    xdotool key F4
    wait_settled
    [ "$(q .viewportSettled)" = true ] || fail "the viewport did not settle on $(basename "$1")"
    set -- $(q '.viewport | map(floor) | join(" ")')
    crop="$3x$4+$1+$2"
}
# shot NAME: the viewport as the screen shows it, once the status line over its foot ("Opened
# ...", for a few seconds) has gone: a view that settles sooner than that would show it.
shot() {
    wait_frames 2
    wait_for .status.shown false 300
    [ "$(q .status.shown)" = false ] || fail "the status line is still shown: $(q .status.text)"
    import -window root "$out/$1_screen.png"
    convert "$out/$1_screen.png" -crop "$crop" +repage "$out/$1.png"
}
psnr() { compare -metric PSNR "$out/$1.png" "$out/$2.png" null: 2>&1 | cut -d' ' -f1 | sed 's/inf/99/'; }

open_settled "$presets/menger_objects.json"
[ "$(q "$radius")" = 0.6 ] || fail "the sphere's radius starts at $(q "$radius"), not 0.6"
shot before
# The header sits below the selected node's parameters: scroll to it with the wheel, open it,
# scroll on to the sphere's parameters.
to 150 300
wait_frames 1
wheel_down 10
wait_frames 2
click "header:Objects"
wheel_down 6
wait_frames 2
widget='[.paramWidgets[] | select(.name == "radius")][0].rect'
wait_for "$widget != null" true
[ "$(q "$widget != null")" = true ] || fail "no radius widget drawn for the sphere"
set -- $(q "$widget | \"\\(.[0] + .[2] / 2 | floor) \\(.[1] + .[3] / 2 | floor)\"")
# Ctrl+click turns the slider into a text field; type the value as a person does.
ctrl_click_at "$1" "$2"
xdotool key ctrl+a
wait_frames 1
xdotool type --delay 30 "0.2"
xdotool key Return
wait_for "$radius" 0.2
[ "$(q "$radius")" = 0.2 ] || fail "typing 0.2 left the radius at $(q "$radius")"
# Away from the panel, so no hover changes the picture; then the view must refine again.
set -- $(viewport_centre)
to "$1" "$2"
wait_frames 3
wait_settled
shot edited
stop

# The same preset with the radius written in the file, opened afresh.
jq '.formula.objects[0].params.radius = 0.2' "$presets/menger_objects.json" > "$out/menger_objects_radius.json"
open_settled "$out/menger_objects_radius.json"
shot fresh
stop

same=$(psnr edited fresh)
before=$(psnr before fresh)
echo "edited at rest against a fresh open: PSNR $same dB; before the edit against it: $before dB"
check "$same >= 35" || fail "the settled viewport after the edit is not the fresh open's picture ($same dB)"
check "$before < $same - 3" || fail "the edit did not change the picture ($before dB against $same dB)"
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor edit at rest: OK"
