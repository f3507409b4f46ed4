#!/bin/sh
# A value typed outside a slider's range is clamped and said so, in the real editor under Xvfb
# driven with real X input (xdotool): on the Mandelbulb with the Lights tab open, 0 typed into the
# Formula panel's Bound radius (Ctrl+click, type, Enter), 1000 into the Mandelbulb's power (a
# block parameter's widget), 50 into the lens's Aperture radius (a Scene tab's setting) and 5000
# into the power node's From (an input box of its schedule) and 5000 into the timeline's frames per
# second are each clamped to the nearer end of the range, and the status line names the slider, what was
# typed and what it became: in the state file, and on screen in the error colour where the
# screenshot before showed none. A value typed inside the range says nothing.
# Usage: editor_clamp_notice_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"

# replace_text TEXT: in the field being edited, select all, type TEXT, Enter.
replace_text() {
    press_keys ctrl a
    xdotool type --delay 30 "$1"
    wait_frames 1
    press_keys Return
    wait_frames 3
}
# type_at X Y TEXT: Ctrl+click the drag at (X, Y) to type into it, replace its text, Enter.
type_at() {
    to "$1" "$2"
    wait_frames 1
    xdotool keydown ctrl
    wait_frames 1
    xdotool click 1
    wait_frames 2
    xdotool keyup ctrl
    wait_frames 2
    replace_text "$3"
}
# box_type X Y TEXT: click into the number box at (X, Y), replace its text, Enter.
box_type() {
    to "$1" "$2"
    wait_frames 1
    xdotool click 1
    wait_frames 2
    replace_text "$3"
}
rect_centre() { echo "$1" | jq -r '"\(.[0] + .[2] / 2 | floor) \(.[1] + .[3] / 2 | floor)"'; }
# The share of the status line's corner of the viewport in the error colour (1, 0.45, 0.4).
error_share() {
    convert "$1" -crop "$2" +repage -fuzz 15% -fill black +opaque "rgb(255,115,102)" -fill white \
        -opaque "rgb(255,115,102)" -colorspace Gray -format "%[fx:mean]" info:
}
# expect_notice SCREENSHOT MESSAGE: the status line reads MESSAGE in the state file and shows it.
expect_notice() {
    [ "$(q .status.text)" = "$2" ] || fail "the status line reads '$(q .status.text)', not '$2'"
    [ "$(q .status.error)" = true ] || fail "the notice '$2' is not shown as a warning"
    import -window "$window" "$1"
    shown=$(error_share "$1" "$status_rect")
    echo "'$(q .status.text)': $shown of the status corner in the warning colour"
    check "$shown > 0.01" || fail "the screenshot shows no notice in the status corner ($shown)"
}

start "$presets/mandelbulb.json" --width 1280 --height 1060 --tab Lights
wait_frames 5
set -- $(q '.viewport | map(floor) | join(" ")')
status_rect="$(($3 / 2))x60+$1+$(($2 + $4 - 70))"
import -window "$window" "$out/before.png"
before=$(error_share "$out/before.png" "$status_rect")
echo "before: $before of the status corner in the warning colour"
check "$before < 0.001" || fail "the status corner shows the warning colour before any typing ($before)"

# The Formula panel's own slider.
wait_for '.widgets["Bound radius"] != null' true
if [ "$(q '.widgets["Bound radius"] != null')" = true ]; then
    type_at $(rect_centre "$(q '.widgets["Bound radius"]')") 0
    [ "$(q .document.formula.boundRadius)" = 0.01 ] || fail "typing 0 left the bound radius at $(q .document.formula.boundRadius)"
    expect_notice "$out/bound_radius.png" "Bound radius: 0 is outside 0.01 .. 100, set to 0.01"
else
    fail "the editor recorded no Bound radius slider"
fi

# A block parameter's widget.
wait_for '[.paramWidgets[] | select(.name == "power")] | length' 1
type_at $(rect_centre "$(q '.paramWidgets[] | select(.name == "power") | .rect')") 1000
[ "$(q '.document.formula.nodes[0].params.power')" = 32 ] ||
    fail "typing 1000 left the power at $(q '.document.formula.nodes[0].params.power')"
expect_notice "$out/power.png" "Power: 1000 is outside 1 .. 32, set to 32"

# A Scene tab's setting.
wait_for '.lights.widgets["lens.aperture"] != null' true
type_at $(rect_centre "$(q '.lights.widgets["lens.aperture"]')") 50
[ "$(q .lights.aperture)" = 10 ] || fail "typing 50 left the aperture at $(q .lights.aperture)"
expect_notice "$out/aperture.png" "Aperture radius: 50 is outside 0 .. 10, set to 10"

# A number field of the node's schedule (an input box with +/- buttons, not a slider): click into
# it, type, Enter.
wait_for '[.paramWidgets[] | select(.name == "schedule:From")] | length' 1
box_type $(q '.paramWidgets[] | select(.name == "schedule:From") | .rect | "\(.[0] + 12 | floor) \(.[1] + .[3] / 2 | floor)"') 5000
kill -0 "$pid" 2>/dev/null || fail "the editor is gone after typing into From"
[ "$(q '.document.formula.nodes[0].start')" = 999 ] ||
    fail "typing 5000 into From left the node's start at $(q '.document.formula.nodes[0].start')"
expect_notice "$out/schedule_from.png" "From: 5000 is outside 0 .. 999, set to 999"

# A number box of the timeline (its frames per second): click into it, type, Enter.
wait_for '.widgets["timeline:fps"] != null' true
box_type $(rect_centre "$(q '.widgets["timeline:fps"]')") 5000
[ "$(q '.document.animation.fps')" = 1000 ] || fail "typing 5000 into fps left it at $(q '.document.animation.fps')"
expect_notice "$out/timeline_fps.png" "fps: 5000 is outside 0.001 .. 1000, set to 1000"

# Inside the range: taken as typed, and nothing said about it.
[ "$(q '.widgets["Bound radius"] != null')" = true ] && type_at $(rect_centre "$(q '.widgets["Bound radius"]')") 2.5
[ "$(q .document.formula.boundRadius)" = 2.5 ] || fail "typing 2.5 set the bound radius to $(q .document.formula.boundRadius)"
case "$(q .status.text)" in "Bound radius"*) fail "a value inside the range was reported: $(q .status.text)" ;; esac
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor clamp notice: OK"
