#!/bin/sh
# No click is lost, whatever the frame time (app/editor/input/imgui_input.hpp). The real editor under
# Xvfb with frames made at least 250 ms long (--slow-frames, as a heavy preset on llvmpipe gives
# 190-340 ms), driven with real X input: every Scene tab is clicked in turn, first as a quick tap
# (the pointer moved onto the tab and clicked at once, all between two frames: Dear ImGui 1.86
# dropped 7-8 of 10 of these), then with a person's timing (move, 150 ms, press for 80 ms), over
# two rounds each; then the Camera tab's view-slot buttons (Store and Clear, quick taps). Each
# click must take effect, read from the state file: the tab in front, the document's view slots.
# Usage: editor_clicks_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1920x1080x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

tap() { xdotool mousemove --window "$window" "$1" "$2" click 1; }
person() {
    xdotool mousemove --window "$window" "$1" "$2"
    sleep 0.15
    xdotool mousedown 1
    sleep 0.08
    xdotool mouseup 1
}
clicks=0
lost=0
# click HOW WIDGET QUERY VALUE: clicks WIDGET the way HOW does, then waits (up to 12 frames: the
# queue hands ImGui a move, a press and a release in separate frames) for QUERY to read VALUE.
click() {
    set -- "$1" "$2" "$3" "$4" $(centre "$2")
    "$1" "$5" "$6"
    clicks=$((clicks + 1))
    wait_for "$3" "$4" 12
    if [ "$(q "$3")" != "$4" ]; then
        lost=$((lost + 1))
        fail "$1 click on $2 was lost: $3 is $(q "$3"), not $4"
    fi
}

# Tall enough that the Camera tab shows its view-slot buttons without scrolling.
start "$presets/mandelbulb.json" --slow-frames 250 --width 1280 --height 1060
wait_frames 2
slow=$(q .frame)
tabs="Render Shading Lights Presets Camera"
for how in tap person; do
    for round in 1 2; do
        for tab in $tabs; do click "$how" "tab:$tab" .sceneTab "$tab"; done
    done
done
# The Camera tab is in front: its view-slot buttons.
for slot in 1 2 3; do click tap "button:Store $slot" ".document.editor.viewSlots[$((slot - 1))] | type" object; done
for slot in 1 2 3; do click tap "button:Clear $slot" ".document.editor.viewSlots[$((slot - 1))] | type" null; done
echo "clicks: $clicks, lost: $lost, over $(( $(q .frame) - slow )) frames of at least 250 ms"
stop
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS editor_clicks_xvfb_test"
