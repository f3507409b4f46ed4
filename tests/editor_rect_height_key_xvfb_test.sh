#!/bin/sh
# A rect light's height is keyed like its width, in the real editor under Xvfb driven with real X
# input (xdotool), on a copy of presets/studio_mandelbulb.json (light 1 a rect softbox, height
# 1.6): in the Lights tab, a click on the key marker beside Height keys it at frame 0; at frame 40
# a height typed into the slider and a second click key 3.6 there; scrubbing to frame 20 shows the
# height between the keys (two keys: the smooth track is a straight line), and Ctrl+S writes the
# track into the file.
# Usage: editor_rect_height_key_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1280x1060x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

# (not "target": the helpers' wait_frames uses that name)
track='lights[0].height'
height() { q '.lights.items[0].height'; }
key_at() { q ".document.animation.tracks[]? | select(.target == \"$track\") | .keys[] | select(.frame == $1) | .value"; }
# The x of frame $1 on the scrub bar, and the y of its ruler.
frame_x() { q "(.timeline.bar[0] + ($1 - .timeline.shownFrames[0]) / (.timeline.shownFrames[1] - .timeline.shownFrames[0]) * .timeline.bar[2]) | round"; }
ruler_y() { q '.timeline.bar[1] + 8 | round'; }
scrub_to() { to "$(frame_x "$1")" "$(ruler_y)"; xdotool click 1; wait_frames 3; }
# click_marker: a click on the key marker beside the height, as a person does.
click_marker() {
    wait_for ".timeline.keyMarkers[\"$track\"] != null" true
    if [ "$(q ".timeline.keyMarkers[\"$track\"] != null")" != true ]; then
        fail "no key marker beside the rect light's height"
        return
    fi
    set -- $(q ".timeline.keyMarkers[\"$track\"] | map(round) | join(\" \")")
    to "$1" "$2"
    wait_frames 1
    xdotool click 1
    wait_frames 3
}

preset="$home/studio.json"
cp "$presets/studio_mandelbulb.json" "$preset"
start "$preset" --width 1280 --height 1060 --tab Lights
# F2 hides the Formula panel: the Scene panel takes the column's height, the whole tab in view.
xdotool key F2
wait_frames 3
wait_for '.lights.widgets["light.height"] != null' true
[ "$(q '.lights.items[0].type')" = Rect ] || fail "light 1 of the studio preset is a $(q '.lights.items[0].type')"
[ "$(height)" = 1.6 ] || fail "the softbox opened with height $(height)"

# Frame 0: key the height as it is.
[ "$(q .timeline.frame)" = 0 ] || scrub_to 0
click_marker
wait_for "[.document.animation.tracks[]? | select(.target == \"$track\")] | length" 1
[ "$(key_at 0)" = 1.6 ] || fail "the key marker did not key height 1.6 at frame 0 ($(key_at 0))"

# Frame 40: a new height typed into the slider, then keyed.
scrub_to 40
last_frame=$(q .timeline.frame)
set -- $(q '.lights.widgets["light.height"] | "\(.[0] + .[2] / 2 | floor) \(.[1] + .[3] / 2 | floor)"')
to "$1" "$2"
wait_frames 1
xdotool keydown ctrl
wait_frames 1
xdotool click 1
wait_frames 2
xdotool keyup ctrl
wait_frames 2
press_keys ctrl a
xdotool type --delay 30 3.6
wait_frames 1
press_keys Return
wait_frames 3
[ "$(height)" = 3.6 ] || fail "typing 3.6 set the height to $(height)"
click_marker
wait_for "[.document.animation.tracks[]? | select(.target == \"$track\") | .keys[]] | length" 2
[ "$(key_at "$last_frame")" = 3.6 ] || fail "no key 3.6 at frame $last_frame ($(key_at "$last_frame"))"
echo "keys: $(q ".document.animation.tracks[]? | select(.target == \"$track\") | .keys | tojson")"

# Between the keys the height is between them, where the straight line puts it.
scrub_to 20
frame=$(q .timeline.frame)
expected=$(awk -v f="$frame" -v F="$last_frame" 'BEGIN { printf "%.12g", 1.6 + 2.0 * f / F }')
echo "frame $frame: height $(height), the track gives $expected"
check "($(height) - $expected)^2 < 1e-12" || fail "at frame $frame the height is $(height), the track gives $expected"
scrub_to 0
[ "$(height)" = 1.6 ] || fail "back at frame 0 the height is $(height)"

# Saved with the preset.
xdotool key ctrl+s
wait_frames 5
saved=$(jq -r ".animation.tracks[]? | select(.target == \"$track\") | .keys | length" "$preset")
[ "$saved" = 2 ] || fail "the saved preset holds $saved keys of the height, not 2"
stop
[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "editor rect height key: OK"
