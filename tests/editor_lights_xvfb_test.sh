#!/bin/sh
# The Lights tab in the real editor under Xvfb, driven with real X input (xdotool), on a unit cube
# (the box estimator with no folds) seen straight on its +z face: Add light > Sphere adds one light
# (one undo step); at the default layout its settings are in view and the wheel scrolls the tab's
# body under a tab bar that stays; a drag of its intensity is one undo step that Ctrl+Z takes back whole; a typed
# aperture turns depth of field on; a bad environment map is refused with a message and the
# document keeps its map, a real EXR is taken (typed, and through Browse...); Pick focus and a
# click on the cube, and a Ctrl+click near the face's corner, set the focus distance to the face's
# depth along the view axis (computed here from the camera in the state file and the cube's face
# z = 1, not from the editor), each one undo step; a Ctrl+click on the sky changes nothing and
# says so; Ctrl+Z takes the last focus back.
# Usage: editor_lights_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

# Waits (at most 100 frames) until the jq expression $1 holds in the state file.
wait_for() {
    tries=0
    while [ "$(q "$1")" != true ] && [ $tries -lt 100 ]; do wait_frames 1; tries=$((tries + 1)); done
    wait_frames 2 # the undo step is committed after the frame that shows the edit
}
# The centre of the Lights tab's widget $1 as last drawn (window coordinates).
widget() { q ".lights.widgets[\"$1\"] | \"\(.[0] + .[2] / 2 | floor) \(.[1] + .[3] / 2 | floor)\""; }
click_widget() {
    wait_for ".lights.widgets[\"$1\"] != null"
    set -- $(widget "$1")
    to "$1" "$2"
    wait_frames 1
    xdotool click 1
    wait_frames 3
}
# ctrl_click X Y: a left click with Ctrl held, each in its own frame.
ctrl_click() {
    to "$1" "$2"
    wait_frames 1
    xdotool keydown ctrl
    wait_frames 1
    xdotool click 1
    wait_frames 2
    xdotool keyup ctrl
    wait_frames 3
}
# type_into WIDGET TEXT: Ctrl+click a drag field (or click a text field), replace its text, Enter.
type_into() {
    set -- "$1" "$2" $(widget "$1")
    ctrl_click "$3" "$4"
    press_keys ctrl a
    xdotool type --delay 30 "$2"
    wait_frames 1
    press_keys Return
    wait_frames 2
}
focus() { q .lights.focusDistance; }
depth() { q .undoDepth; }

cat >"$home/cube.json" <<'EOF'
{"format": "fraktal-preset", "version": 3, "name": "Unit cube",
 "formula": {"iterations": 1, "bailout": 1000, "boundRadius": 2.0,
             "nodes": [{"block": "box", "params": {"size": [1.0, 1.0, 1.0]}}]},
 "camera": {"position": [0.0, 0.0, 4.0], "target": [0.0, 0.0, 0.0], "fovY": 40.0}}
EOF
start "$home/cube.json" --tab Lights
wait_for '.lights.widgets.addLight != null'
[ "$(q .lights.count)" = 0 ] || fail "the cube preset opened with $(q .lights.count) lights"

# Add light > Sphere: one light, one undo step.
click_widget addLight
click_widget addLight.Sphere
wait_for '.lights.count == 1'
[ "$(q .lights.count)" = 1 ] || fail "Add light > Sphere gave $(q .lights.count) lights"
[ "$(q '.lights.items[0].type')" = Sphere ] || fail "the new light is a $(q '.lights.items[0].type')"
[ "$(q .undoLabel)" = "add Sphere light" ] || fail "adding a light reads '$(q .undoLabel)' in the undo list"
added_depth=$(depth)
intensity=$(q '.lights.items[0].intensity')
echo "add: $(q '.lights.items[0].type') light, intensity $intensity, undo depth $added_depth"

# At the default layout of a 1280x800 window (the Formula panel above the Scene panel), the new
# light's settings lie in the tab's view, and the tab's body scrolls under the tab bar, which stays.
# in_body WIDGET: the Lights tab's WIDGET lies whole within the visible part of the tab's body.
in_body() {
    q "(.lights.widgets[\"$1\"]) as \$w | .widgets[\"child:Scene tab body\"] as \$b |
       \$w != null and \$b != null and \$w[1] >= \$b[1] and \$w[1] + \$w[3] <= \$b[1] + \$b[3]"
}
for setting in light.color light.intensity light.position; do
    [ "$(in_body $setting)" = true ] || fail "at 1280x800 the light's $setting is not in the Scene panel's view"
done
tabs=$(q '.widgets["tab:Lights"][1]')
intensity_y=$(q '.lights.widgets["light.intensity"][1]')
wheel_over "child:Scene tab body" 5
[ "$(q '.widgets["tab:Lights"][1]')" = "$tabs" ] ||
    fail "scrolling the Lights tab moved its tab bar from y $tabs to $(q '.widgets["tab:Lights"][1]')"
check "$(q '.lights.widgets["light.intensity"][1]') < $intensity_y" ||
    fail "the wheel over the Lights tab left its settings in place (intensity at y $intensity_y)"
wheel_over "child:Scene tab body" 4
echo "default layout: the light's settings in view; the wheel scrolled them, the tab bar stayed at y $tabs"

# A real drag of the intensity: one undo step; Ctrl+Z restores it, the light stays.
set -- $(widget light.intensity)
drag_frames "$1" "$2" 60 0 6
wait_frames 3
dragged=$(q '.lights.items[0].intensity')
check "$dragged > $intensity" || fail "dragging the intensity right left it at $dragged (was $intensity)"
[ "$(depth)" = $((added_depth + 1)) ] || fail "the intensity drag made $(($(depth) - added_depth)) undo steps"
[ "$(q .undoLabel)" = "change of intensity" ] || fail "the drag reads '$(q .undoLabel)' in the undo list"
set -- $(viewport_centre)
to "$1" "$2"
xdotool key ctrl+z
wait_for ".lights.items[0].intensity == $intensity"
[ "$(q '.lights.items[0].intensity')" = "$intensity" ] || fail "Ctrl+Z left the intensity at $(q '.lights.items[0].intensity')"
[ "$(q .lights.count)" = 1 ] || fail "Ctrl+Z after the drag also removed the light"
[ "$(depth)" = "$added_depth" ] || fail "Ctrl+Z took $((added_depth + 1 - $(depth))) steps back"
echo "drag: intensity $intensity -> $dragged, Ctrl+Z -> $(q '.lights.items[0].intensity')"

# F2 hides the Formula panel: the Scene panel takes the column's height, the rest of the tab in view.
xdotool key F2
wait_frames 3

# A typed aperture turns depth of field on (one step).
before=$(depth)
type_into lens.aperture 0.05
wait_for '.lights.aperture == 0.05'
[ "$(q .lights.aperture)" = 0.05 ] || fail "typing 0.05 set the aperture to $(q .lights.aperture)"
[ "$(depth)" = $((before + 1)) ] || fail "the typed aperture made $(($(depth) - before)) undo steps"

# Environment map: a missing file is refused with a message, a real EXR is taken.
before=$(depth)
type_into environment.map "$home/missing.exr"
wait_for '.lights.messageIsError'
[ "$(q .lights.messageIsError)" = true ] || fail "a missing map gave no error message"
q .lights.message | grep -q "does not exist" || fail "the missing map's message reads '$(q .lights.message)'"
[ "$(q .lights.environmentMap)" = "" ] || fail "a missing map was taken: $(q .lights.environmentMap)"
[ "$(depth)" = "$before" ] || fail "a refused map made an undo step"
echo "bad map: $(q .lights.message)"
cp "$presets/env/sky.exr" "$home/sky.exr"
type_into environment.map "$home/sky.exr"
wait_for '.lights.environmentMap == "sky.exr"'
[ "$(q .lights.environmentMap)" = sky.exr ] || fail "the EXR was not taken as the map ($(q .lights.environmentMap))"
[ "$(q .lights.messageIsError)" = false ] || fail "a good map left the error: $(q .lights.message)"
# Browse...: the file browser lists EXRs; a name typed into its path field and Enter takes it.
cp "$presets/env/sky.exr" "$home/sky2.exr"
click_widget environment.browse
wait_for '.fileBrowser.shown'
[ "$(q .fileBrowser.shown)" = true ] || fail "Browse... did not open the file browser"
xdotool type --delay 30 "$home/sky2.exr"
wait_frames 1
press_keys Return
wait_for '.lights.environmentMap == "sky2.exr"'
[ "$(q .lights.environmentMap)" = sky2.exr ] || fail "the browser's choice was not taken as the map ($(q .lights.environmentMap))"
[ "$(q .fileBrowser.shown)" = false ] || fail "the file browser stays open after choosing"
echo "map: typed sky.exr, then browsed to $(q .lights.environmentMap)"

# Focus on the cube. The centre ray is the view axis: it meets the face z = 1 at depth t with
# position.z + t * forward.z = 1 (forward from the camera in the state file).
expected=$(q '.camera as $c | ($c.target[0] - $c.position[0]) as $x | ($c.target[1] - $c.position[1]) as $y |
    ($c.target[2] - $c.position[2]) as $z | ($x * $x + $y * $y + $z * $z | sqrt) as $n |
    (1 - $c.position[2]) / ($z / $n)')
echo "camera $(camera); the face z = 1 lies at depth $expected along the view axis"
before=$(depth)
start_camera=$(camera)
click_widget lens.pickFocus
[ "$(q .lights.pickFocus)" = true ] || fail "Pick focus did not arm the pick"
set -- $(viewport_centre)
to "$1" "$2"
wait_frames 1
xdotool click 1
wait_for '.lights.focusDistance > 0'
f=$(focus)
check "($f - $expected)^2 < (0.1 * $expected)^2" || fail "Pick focus on the cube's centre set $f, expected $expected"
[ "$(depth)" = $((before + 1)) ] || fail "Pick focus made $(($(depth) - before)) undo steps"
[ "$(q .lights.pickFocus)" = false ] || fail "Pick focus stays armed after the click"
[ "$(camera)" = "$start_camera" ] || fail "the click moved the camera to $(camera)"
echo "pick focus: $f (expected $expected)"

# Ctrl+click near the face's corner (x = y = 0.85): the depth is the same plane's, the ray longer.
set -- $(q '.viewport | map(floor) | join(" ")')
vx=$1 vy=$2 vw=$3 vh=$4
set -- $(awk -v vx="$vx" -v vy="$vy" -v vw="$vw" -v vh="$vh" -v e="$expected" 'BEGIN {
    t = sin(20 * 3.14159265 / 180) / cos(20 * 3.14159265 / 180); ndcY = 0.85 / (e * t); ndcX = ndcY * vh / vw
    printf "%d %d\n", vx + (ndcX + 1) * vw / 2, vy + (1 - ndcY) * vh / 2 }')
ray=$(awk -v e="$expected" 'BEGIN { print sqrt(e * e + 2 * 0.85 * 0.85) }')
before=$(depth)
previous=$f
ctrl_click "$1" "$2"
wait_for ".lights.focusDistance != $previous"
f=$(focus)
check "($f - $expected)^2 < (0.1 * $expected)^2" || fail "Ctrl+click near the corner set $f, expected $expected"
check "($f - $expected)^2 < ($f - $ray)^2" || fail "Ctrl+click set $f: the ray length ($ray), not the depth ($expected)"
[ "$(depth)" = $((before + 1)) ] || fail "Ctrl+click made $(($(depth) - before)) undo steps"
echo "ctrl+click near the corner: $f (depth $expected, ray length $ray)"

# Ctrl+click on the sky: nothing changes, and it says so.
before=$(depth)
ctrl_click $((vx + vw - 12)) $((vy + 12))
wait_frames 3
[ "$(focus)" = "$f" ] || fail "a click on the sky changed the focus to $(focus)"
[ "$(depth)" = "$before" ] || fail "a click on the sky made an undo step"
q .status.text | grep -qi "sky" || fail "a click on the sky says '$(q .status.text)'"
echo "sky: focus stays $(focus): $(q .status.text)"

# Ctrl+Z takes the last focus back in one step.
to $((vx + vw / 2)) $((vy + vh / 2))
xdotool key ctrl+z
wait_for ".lights.focusDistance == $previous"
[ "$(focus)" = "$previous" ] || fail "Ctrl+Z after the Ctrl+click left the focus at $(focus), not $previous"

stop
[ "$failures" = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "editor lights: all checks passed"
