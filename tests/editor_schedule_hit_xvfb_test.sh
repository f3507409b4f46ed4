#!/bin/sh
# A node's iteration window and the estimator's hit rule under a person's hands: the real editor
# under Xvfb, driven with real X input (xdotool), asserted on the state file and on screenshots.
#  1. The Mandelbulb's power node runs only on iterations 2 to 4: tick Before, type 2 into From and
#     5 into Before's field. The document holds the window, the node row names it, each edit is an
#     undo step, and the picture changes (a bulb powered on three iterations is another object).
#     Ctrl+Z back to the whole loop gives the first picture again.
#  2. Hits only inside: select the estimator, tick "Hit only inside". The document holds it, the
#     viewport recompiles and still shows the object; Ctrl+Z takes it back.
#  3. Interior walls: tick "Hit interior walls". The document holds that rule, and the viewport
#     recompiles and still shows the bulb (from outside its walls are its surface).
# Usage: editor_schedule_hit_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"

# A parameter-panel widget (.paramWidgets) in window coordinates (a panel widget's centre:
# `centre`, editor_xvfb_helpers.sh); the field of an InputInt is its left part (its step buttons
# sit on the right).
field() { q ".paramWidgets[] | select(.name == \"$1\") | .rect | \"\\(.[0] + 12 | floor) \\(.[1] + .[3] / 2 | floor)\""; }
tick() { q ".paramWidgets[] | select(.name == \"$1\") | .rect | \"\\(.[0] + .[3] / 2 | floor) \\(.[1] + .[3] / 2 | floor)\""; }
click_at() {
    to "$1" "$2"
    wait_frames 1
    xdotool click 1
    wait_frames 2
}
# type_into X Y TEXT: click into a number field, replace its text, Enter.
type_into() {
    click_at "$1" "$2"
    xdotool key ctrl+a
    xdotool type --delay 40 "$3"
    xdotool key Return
    wait_frames 3
}
node() { q ".document.formula.nodes[0] | \"\\(.block) \\(.start // 0) \\(.stop // \"end\")\""; }
# The viewport's pixels as a grey-level signature; differ A B: the mean absolute difference (0-1).
set_crop() { set -- $(q '.viewport | map(floor) | join(" ")'); crop="$3x$4+$1+$2"; }
shot() { wait_settled; wait_frames 2; import -window root "$out/$1.png"; }
differ() {
    compare -metric MAE "$out/$1.png" "$out/$2.png" -crop "$crop" null: 2>&1 | sed 's/.*(\(.*\)).*/\1/'
}

start "$presets/mandelbulb.json"
set_crop
shot whole_loop
first=$(jq -c .document.formula "$state")
# The stories' editor stops anti-aliasing at 2 samples (editor_xvfb_helpers.sh: --aa-cap 2); the
# document keeps its own cap of 8.
[ "$(q '"\(.viewportRender.aaSamples) \(.viewportRender.aaCap) \(.document.editor.view.aaCap)"')" = "2 2 8" ] ||
    fail "settled at --aa-cap 2: samples, cap and the document's cap read '$(q '"\(.viewportRender.aaSamples) \(.viewportRender.aaCap) \(.document.editor.view.aaCap)"')', not '2 2 8'"
[ "$(node)" = "mandelbulb 0 end" ] || fail "the Mandelbulb preset's power node is '$(node)', not the whole loop"

# 1. The window [2, 5) on the power node (selected when the preset opens).
set -- $(tick "schedule:Before")
click_at "$1" "$2"
wait_for '.document.formula.nodes[0].stop // "end"' 1 12
[ "$(node)" = "mandelbulb 0 1" ] || fail "ticking Before gave '$(node)', not the first iteration alone"
set -- $(field "schedule:From")
type_into "$1" "$2" 2
set -- $(field "schedule:Before iteration")
type_into "$1" "$2" 5
wait_for '.document.formula.nodes[0].stop // "end"' 5 12
[ "$(node)" = "mandelbulb 2 5" ] || fail "typing From 2, Before 5 gave '$(node)'"
label=$(q .undoLabel)
[ "$label" = "change of iteration window" ] || fail "Undo would do '$label', not 'change of iteration window'"
shot window
d=$(differ whole_loop window)
check "$d > 0.01" || fail "the power node on iterations 2-4 left the picture as it was (difference $d)"
echo "window: $(node), undo '$label', picture difference $d"
# Back to the first formula: one Ctrl+Z an edit (the step factor measured after a change of
# structure may land as a step of its own, depending on when the measurement ends).
for _ in 1 2 3 4 5 6 7 8; do
    [ "$(jq -c .document.formula "$state")" = "$first" ] && break
    xdotool key ctrl+z
    wait_frames 3
done
[ "$(node)" = "mandelbulb 0 end" ] || fail "Ctrl+Z did not bring the whole loop back: '$(node)'"
[ "$(jq -c .document.formula "$state")" = "$first" ] || fail "Ctrl+Z did not bring the first formula back"
shot undone
d=$(differ whole_loop undone)
check "$d < 0.01" || fail "after undoing the window the picture differs from the first (difference $d)"

# 2. Hits only inside, on the estimator.
set -- $(centre "row:estimator")
click_at "$1" "$2"
wait_for '.widgets["checkbox:Hit only inside"] != null' true 12
set -- $(q '.widgets["checkbox:Hit only inside"] | "\(.[0] + .[3] / 2 | floor) \(.[1] + .[3] / 2 | floor)"')
click_at "$1" "$2"
wait_for '.document.formula.hitRule // "surface"' insideOnly 12
[ "$(q '.document.formula.hitRule // "surface"')" = insideOnly ] || fail "ticking 'Hit only inside' left the hit rule off"
# A change of structure: the step factor is measured again, in the same undo step.
q .undoLabel | grep -q "hit rule" || fail "Undo would do '$(q .undoLabel)', not the hit rule's change"
shot inside_only
coverage=$(convert "$out/inside_only.png" -crop "$crop" +repage -colorspace Gray -edge 1 -threshold 8% -format "%[fx:mean]" info:)
check "$coverage > 0.03" || fail "with hits only inside the viewport shows no object (edge share $coverage)"
echo "hits only inside: edge share $coverage, difference from the plain rule $(differ undone inside_only)"
# The step factor measured after the change may land as a step of its own: at most two Ctrl+Z.
for _ in 1 2; do
    xdotool key ctrl+z
    wait_for '.document.formula.hitRule // "surface"' surface 12
    [ "$(q '.document.formula.hitRule // "surface"')" = surface ] && break
done
[ "$(q '.document.formula.hitRule // "surface"')" = surface ] || fail "Ctrl+Z twice left hits only inside on"

# 3. Interior walls (Mandelbulber2's interior mode), the next checkbox: from outside the bulb the
# walls are its surface, so the picture keeps an object; ticking it clears hits only inside.
set -- $(q '.widgets["checkbox:Hit interior walls"] | "\(.[0] + .[3] / 2 | floor) \(.[1] + .[3] / 2 | floor)"')
click_at "$1" "$2"
wait_for '.document.formula.hitRule // "surface"' interiorWalls 12
[ "$(q '.document.formula.hitRule // "surface"')" = interiorWalls ] || fail "ticking 'Hit interior walls' left the rule at '$(q '.document.formula.hitRule // "surface"')'"
shot interior_walls
coverage=$(convert "$out/interior_walls.png" -crop "$crop" +repage -colorspace Gray -edge 1 -threshold 8% -format "%[fx:mean]" info:)
check "$coverage > 0.03" || fail "with interior walls the viewport shows no object (edge share $coverage)"
echo "interior walls: edge share $coverage, difference from the plain rule $(differ undone interior_walls)"
stop
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS editor_schedule_hit_xvfb_test"
