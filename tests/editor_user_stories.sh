#!/bin/sh
# User stories: starts the real editor under Xvfb and drives it with real X input events
# (xdotool), the way a person does, then asserts on the state the editor writes after every
# frame (--state-file, JSON) and on screenshots.
# Usage: editor_user_stories.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"

# 1. Frames of 400 ms: a click in the viewport after using a panel leaves the camera where it
#    is, and so does a press that wobbles by 2 pixels; a drag ends where the same drag ends at
#    full speed.
start "$presets/mandelbulb.json" --slow-frames 400
set -- $(viewport_centre)
cx=$1 cy=$2
before=$(camera)
to 100 600
wait_frames 2
xdotool mousemove --window "$window" "$cx" "$cy" click 1
wait_frames 3
[ "$(camera)" = "$before" ] || fail "click without drag moved the camera: $before -> $(camera)"
to "$cx" "$cy"
xdotool mousedown 1
to $((cx + 2)) $((cy + 1))
xdotool mouseup 1
wait_frames 3
[ "$(camera)" = "$before" ] || fail "a 2-pixel wobble moved the camera: $before -> $(camera)"
drag "$cx" "$cy" 160 60 8
wait_frames 3
slow_drag=$(camera)
stop

start "$presets/mandelbulb.json"
set -- $(viewport_centre)
drag "$cx" "$cy" 160 60 8
wait_frames 3
fast_drag=$(camera)
d=$(moved "$fast_drag" "$before")
check "$d > 0.1" || fail "a 160 px drag did not orbit the camera (moved $d)"
d=$(moved "$slow_drag" "$fast_drag")
check "$d < 1e-6" || fail "the same drag at 400 ms frames ends elsewhere ($slow_drag vs $fast_drag, $d)"
echo "drag: full speed $fast_drag; slow frames $slow_drag"
[ "$(q .undoDepth)" = 0 ] || fail "orbiting the camera added an undo step ($(q .undoLabel))"

# 4. Undo after a slider drag: the whole drag is one step, the Edit menu's label names it, and
#    one Ctrl+Z returns the value.
power() { q '.document.formula.nodes[0].params.power // 8'; }
set -- $(widget_centre power)
[ $# -eq 2 ] || { fail "the state file records no widget for the power parameter"; set -- 150 477; }
drag_frames "$1" "$2" 60 0 6
# The release is seen at the start of a frame, the step committed at its end, written after the next.
wait_frames 3
dragged=$(power)
[ "$dragged" != 8 ] || fail "dragging the power slider did not change the power"
[ "$(q .undoDepth)" = 1 ] || fail "a slider drag made $(q .undoDepth) undo steps, not 1"
[ "$(q .undoLabel)" = "change of power" ] || fail "Undo would do '$(q .undoLabel)', not 'change of power'"
xdotool key ctrl+z
wait_frames 3
[ "$(power)" = 8 ] || fail "one Ctrl+Z after the slider drag left the power at $(power) (dragged to $dragged)"
[ "$(q .undoDepth)" = 0 ] || fail "undo left $(q .undoDepth) steps"
echo "undo: power 8 -> $dragged -> $(power) in one step"

# 2. Keys: V over the viewport switches to fly mode; "wasd" typed into the preset name field
#    goes into the name and moves no camera; a W tap over the viewport moves it.
to "$cx" "$cy"
wait_frames 1
xdotool key v
wait_frames 2
[ "$(q .flyMode)" = true ] || fail "V over the viewport did not switch to fly mode"
before=$(camera)
to 180 62
xdotool click 1
wait_frames 1
xdotool type --delay 30 wasd
wait_frames 3
[ "$(camera)" = "$before" ] || fail "typing wasd into a text field moved the camera"
q .document.name | grep -q wasd || fail "the name field did not get the typed text: $(q .document.name)"
xdotool key Escape
to "$cx" "$cy"
xdotool click 1
wait_frames 2
before=$(camera)
xdotool key w
wait_frames 2
d=$(moved "$(camera)" "$before")
check "$d > 0" || fail "a W tap over the viewport in fly mode did not move the camera"
xdotool key v
wait_frames 1
xdotool key F1
wait_frames 2
[ "$(q .shortcutHelp)" = true ] || fail "F1 did not open the shortcut list"
wait_frames 1
import -window root "$out/story_shortcuts.png"
xdotool key F1
echo "keys: W tap moved the camera by $d (relative)"
stop

# 3. A new formula from three blocks: from the Mandelbulb template, delete its power node and add
#    Box fold, Sphere fold and Scale after its Add c from the "Add block..." menu (a Mandelbox,
#    iterated from another point). The estimator, bailout and bound follow the blocks and
#    the viewport shows an object; F frames it (the camera moves outside the surface, the object
#    fills more of the view).
start "$presets/mandelbulb.json"
to 330 235; xdotool click 1; wait_frames 2
# add_block ROW_Y CATEGORY_ROW ITEM_ROW: the menu opens at the cursor; rows are 19 px apart.
add_block() {
    to 58 "$1"; xdotool click 1; wait_frames 2
    to 90 $(($1 + 16 + 19 * $2)); wait_frames 2
    to 120 $(($1 + 16 + 19 * $2)); wait_frames 2
    to 275 $(($1 + 16 + 19 * $2 + 19 * $3)); xdotool click 1; wait_frames 2
}
add_block 281 0 2 # fold / Box fold
add_block 308 0 3 # fold / Sphere fold
add_block 335 1 0 # transform / Scale
to 1100 700
wait_frames 6
wait_settled
nodes=$(q '[.document.formula.nodes[].block] | join(" ")')
[ "$nodes" = "add_c box_fold sphere_fold scale escape_linear" ] || fail "the node list is '$nodes', not the three blocks added"
echo "new formula: $nodes, estimator $(q .document.formula.estimator.block), bailout $(q .document.formula.bailout), bound $(q .document.formula.boundRadius)"
set -- $(q '.viewport | map(floor) | join(" ")')
crop="$3x$4+$1+$2"
# An object in view: surface detail (edge pixels) on at least 3 % of the viewport (the sky alone
# gives none; a new formula's object small in view is framed after the edit: about 5 %),
# and lit (a camera inside the surface sees a dark cave, mean < 0.1; the sky alone has no edges).
coverage() { convert "$1" -crop "$crop" +repage -colorspace Gray -edge 1 -threshold 8% -format "%[fx:mean]" info:; }
brightness() { convert "$1" -crop "$crop" +repage -colorspace Gray -format "%[fx:mean]" info:; }
shows_object() {
    import -window root "$out/$1.png"
    cov=$(coverage "$out/$1.png")
    mean=$(brightness "$out/$1.png")
    echo "$1: edge coverage $cov, mean $mean; camera $(camera)"
    check "$cov > 0.03 && $mean > 0.15"
}
shows_object story_new_formula || fail "the new formula's viewport shows no object"
eye=$(q .eyeDistance)
bound=$(q .document.formula.boundRadius)
check "$eye > 0.01 * $bound" || fail "after the formula edit the camera is not outside the surface (DE at the eye $eye)"
to "$cx" "$cy"
xdotool key f
wait_frames 8
wait_settled
shows_object story_framed || fail "after F the viewport shows no object"
framed=$(camera)
# Zoom into the object with the wheel, then F frames it again: the same view (F keeps the
# viewing direction), outside the surface.
xdotool click --repeat 30 --delay 20 4
wait_frames 4
zoomed_eye=$(q .eyeDistance)
xdotool key f
wait_frames 4
eye=$(q .eyeDistance)
echo "F: DE at the eye zoomed in $zoomed_eye, framed $eye"
check "$eye > 0.01 * $bound && $eye > 10 * $zoomed_eye" || fail "F did not move the camera out from the surface ($zoomed_eye -> $eye)"
d=$(moved "$(camera)" "$framed")
check "$d < 1e-6" || fail "F from the same direction frames differently ($(camera) vs $framed)"
stop
# 5. A custom GLSL block that does not compile, at position 2 of the node list: the error the
#    editor reports names it as the list shows it (number from 1 and label).
broken="$home/broken_fold.json"
jq '.formula.customBlocks = [{"id": "broken_fold", "label": "Broken fold", "category": "fold",
      "params": [{"name": "amount", "default": 1, "min": 0, "max": 2, "help": "x"}],
      "glsl": "p.xyz *= amount;\np.xyz += not_declared_anywhere;\n"}]
    | .formula.nodes |= .[:1] + [{"block": "broken_fold"}] + .[1:]' "$presets/mandelbox.json" >"$broken"
start "$broken"
tries=0
while [ -z "$(q .compileError)" ] && [ $tries -lt 30 ]; do wait_frames 1; tries=$((tries + 1)); done
error=$(q .compileError)
echo "$error" | grep -q 'node 2 "Broken fold" (broken_fold), GLSL line 2' ||
    fail "the compile error does not name node 2 \"Broken fold\" as the list shows it: $error"
import -window root "$out/story_compile_error.png"
echo "compile error: $(echo "$error" | grep -m1 'node 2')"
# The banner hides no control: the block's GLSL editor (select node 2, scroll the Formula panel
# down, "Edit GLSL...") dragged so that its close button lies under the banner (bottom middle of the
# viewport) still closes on a click there.
to 100 262; wait_frames 1; xdotool mousedown 1; wait_frames 1; xdotool mouseup 1; wait_frames 2
to 150 400; xdotool click --repeat 10 --delay 30 5; wait_frames 3
edit=$(q '.widgets["button:Edit GLSL"] | "\(.[0] + .[2] / 2 | floor) \(.[1] + .[3] / 2 | floor)"')
to ${edit% *} ${edit#* }; wait_frames 1; xdotool mousedown 1; wait_frames 1; xdotool mouseup 1; wait_frames 4
[ "$(q .blockEditorOpen)" = true ] || fail "Edit GLSL... did not open the block editor"
drag_frames 300 70 300 640 6
wait_frames 3
import -window root "$out/story_banner_over_close.png"
to 966 710; wait_frames 1; xdotool mousedown 1; wait_frames 1; xdotool mouseup 1; wait_frames 3
[ -n "$(q .compileError)" ] || fail "the compile error went away during the test"
[ "$(q .blockEditorOpen)" = false ] || fail "the block editor's close button under the compile-error banner did not close it"
stop

# 6. The step factor follows the structure. Deleting a Rotate in front of the Mandelbulb changes the
#    structure: the check measures the new stack and the document's factor becomes the measured
#    one. A Kleinian step whose wrap widths are not its group's, between a rotation and two folds,
#    has no safe factor: after the same delete the editor applies the smallest factor and says so
#    in the DE step factor section, naming the Kleinian step as one that jumps.
bulb="$home/rotate_bulb.json"
jq '.formula.nodes = [{"block": "rotate"}] + .formula.nodes' "$presets/mandelbulb.json" >"$bulb"
# A file whose factor was settled for its structure (its formula.deFactorMeasuredFor) opens as it
# is: nothing is measured.
start "$presets/mandelbulb.json"
wait_frames 5
[ "$(q .stepFactor.measured)" = 0 ] || fail "opening a measured file measured its factor ($(q .stepFactor.measured))"
stop
# The Rotate was added by hand, so the file's tag names another structure: its factor was never
# measured for this stack, and the editor measures it as the file opens.
start "$bulb"
wait_for '.stepFactor.measured > 0' true
wait_for '.stepFactor.refining' false 600
opened=$(q .stepFactor.measured)
[ "$(q .document.formula.deFactor)" = "$opened" ] ||
    fail "the file opened at factor $(q .document.formula.deFactor), not the $opened measured for it"
set -- $(viewport_centre)
to "$1" "$2"
xdotool key Delete
# The delete is handled, and the new stack's settled rounds measured, in the frames after it.
wait_frames 3
wait_for '.stepFactor.refining' false 600
measured=$(q .stepFactor.measured)
[ "$(q .document.formula.deFactor)" = "$measured" ] ||
    fail "after the delete the factor is $(q .document.formula.deFactor), not the measured $measured"
[ "$(q .stepFactor.noSafeFactor)" = false ] || fail "the Mandelbulb has no safe factor (worst $(q .stepFactor.worst))"
[ "$(q .stepFactor.jumpingStep)" = -1 ] || fail "the power-8 Mandelbulb is said to jump at step $(q .stepFactor.jumpingStep)"
echo "step factor: measured $opened as the hand-edited file opened, $measured on $(q .stepFactor.rays) rays after deleting the Rotate"
stop
# The Amazing Surf's worst rays at bailout 100 are rare: the factor applied at once rests on the settled rounds
# (a few hundred rays), then the check's further rounds run beside the frames and their factor
# replaces it when they end: the one `fraktal check` reports for the document as the editor holds
# it (the edit also fits the bound radius to the object).
surf="$home/rotate_surf.json"
jq '.formula.nodes = [{"block": "rotate"}] + .formula.nodes | .formula.bailout = 100' "$presets/amazing_surf.json" >"$surf"
start "$surf"
# Measured as it opens (the Rotate added by hand); that measurement ends before the edit.
wait_for '.stepFactor.measured > 0' true
wait_for '.stepFactor.refining' false 600
set -- $(viewport_centre)
to "$1" "$2"
xdotool key Delete
wait_frames 3
wait_for .stepFactor.measuring false 300
first=$(q .stepFactor.measured)
first_rays=$(q .stepFactor.rays)
wait_for '.stepFactor.refining' false 600
[ "$(q .stepFactor.refining)" = false ] || fail "the further rounds did not end in 600 frames"
measured=$(q .stepFactor.measured)
[ "$(q .document.formula.deFactor)" = "$measured" ] ||
    fail "after the further rounds the factor is $(q .document.formula.deFactor), not the measured $measured"
q .document >"$home/surf_as_edited.json"
line=$("$fraktal" check "$home/surf_as_edited.json" | grep '^safe step factor: formula.deFactor') || true
checked=$(echo "$line" | sed -n 's/^safe step factor: formula.deFactor \([0-9.]*\) .*/\1/p')
checked_rays=$(echo "$line" | sed -n 's/.*; over \([0-9]*\) rays, worst.*/\1/p')
[ -n "$checked" ] && [ -n "$checked_rays" ] || fail "fraktal check printed no safe step factor for the edited document: $line"
check "$measured - ${checked:-0} < 0.0015 && ${checked:-0} - $measured < 0.0015" ||
    fail "after the further rounds the editor's factor is $measured, fraktal check's $checked"
[ "$(q .stepFactor.rays)" = "$checked_rays" ] ||
    fail "the factor rests on $(q .stepFactor.rays) rays, fraktal check's on $checked_rays"
import -window root "$out/story_step_factor_refined.png"
echo "step factor: $first on $first_rays rays at once, $measured on $(q .stepFactor.rays) rays after the further rounds (fraktal check: $checked)"
stop
wrap="$home/kleinian_wrap.json"
jq '.formula.nodes = [{"block": "rotate"}, {"block": "rotate", "params": {"axis": [-0.765, -0.0866, -0.585], "angle": 55.6}},
      {"block": "kleinian", "params": {"klein_r": 1.51, "klein_i": 0.382, "box_size": [3.77, 3.05, 1.92], "separation": 0.631}},
      {"block": "sierpinski_fold"}, {"block": "abs_fold"}, {"block": "box"}]
    | .formula.iterations = 6 | .formula.bailout = 1000
    | .formula.boundRadius = 3 | .formula.deFactor = 1 | .camera.position = [0, 0, 6] | .camera.target = [0, 0, 0]
    | del(.animation)' "$presets/kleinian.json" >"$wrap"
start "$wrap"
set -- $(viewport_centre)
to "$1" "$2"
xdotool key Delete
wait_for '.document.formula.nodes | length' 5
wait_for '.stepFactor.measured > 0 or .stepFactor.noHits' true
[ "$(q .stepFactor.noSafeFactor)" = true ] ||
    fail "the Kleinian wrap outside its group got a safe factor $(q .stepFactor.measured) (worst $(q .stepFactor.worst))"
[ "$(q .document.formula.deFactor)" = 0.001 ] || fail "without a safe factor the editor applied $(q .document.formula.deFactor)"
# The section also says which step jumps: the Kleinian step, second after the delete.
[ "$(q .stepFactor.jumpingStep)" = 1 ] || fail "the Kleinian step is not named as jumping ($(q .stepFactor.jumpingStep))"
import -window root "$out/story_no_safe_factor.png"
echo "no safe factor: worst DE / true distance $(q .stepFactor.worst), factor $(q .document.formula.deFactor)"
stop

# A held camera drag draws the side column from the copy kept at its start (viewport/ui_redraw.hpp):
# mid-drag, on a frame drawn from the copy, the column and the menu bar are the same picture as
# before the drag, the viewport shows the turned fractal, and letting go draws everything again.
start "$presets/mandelbulb.json" --tab Shading --slow-frames 60
wait_settled
set -- $(viewport_centre)
cx=$1 cy=$2
to "$cx" "$cy"
wait_frames 2
import -window root "$out/story_ui_before.png"
xdotool mousedown 1
for step in 1 2 3 4 5 6; do to $((cx + 20 * step)) "$cy"; wait_frames 1; done
wait_for .uiDraw cached
import -window root "$out/story_ui_cached.png"
# The column without its right edge, the border ImGui lights while the mouse is held elsewhere.
column_w=$(q '.viewport[0] - 2 | floor')
viewport_box="$(q '"\(.viewport[2] | floor)x\(.viewport[3] | floor)+\(.viewport[0] | floor)+\(.viewport[1] | floor)"')"
for shot in before cached; do
    convert "$out/story_ui_$shot.png" -crop "${column_w}x10000+0+0" +repage "$out/story_ui_${shot}_column.png"
    convert "$out/story_ui_$shot.png" -crop "$viewport_box" +repage "$out/story_ui_${shot}_viewport.png"
done
column_diff=$(compare -metric AE "$out/story_ui_before_column.png" "$out/story_ui_cached_column.png" null: 2>&1 || true)
[ "$column_diff" = 0 ] || fail "mid-drag the side column drawn from the kept copy differs in $column_diff pixels"
viewport_diff=$(compare -metric AE -fuzz 5% "$out/story_ui_before_viewport.png" "$out/story_ui_cached_viewport.png" null: 2>&1 || true)
check "${viewport_diff%% *} > 1000" || fail "mid-drag the viewport did not change ($viewport_diff pixels)"
mean=$(convert "$out/story_ui_cached_viewport.png" -colorspace Gray -format '%[fx:mean]' info:)
check "$mean > 0.05" || fail "mid-drag the viewport is dark (mean $mean): the live layers were not drawn"
xdotool mouseup 1
wait_for .uiDraw full
echo "ui cache: column unchanged mid-drag, viewport changed in $viewport_diff pixels"
stop

[ $failures -eq 0 ] && echo "editor_user_stories: all OK" || { echo "editor_user_stories: $failures failure(s)"; exit 1; }
