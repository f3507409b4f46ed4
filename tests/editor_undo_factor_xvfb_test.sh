#!/bin/sh
# Undo across the step factor the editor measures in the background, driven as a person does
# under Xvfb. A new document (Ctrl+N), Rotate added from the "Add block..." menu and removed with
# Delete; the editor measures the step factor for the new stack (its further rounds take seconds)
# and the factor joins the removal's undo step: the Edit menu reads "Undo remove Rotate", not
# "Undo change of deFactor". One Ctrl+Z brings Rotate back; the factor measured for it again
# lands in that state without dropping redo, so Ctrl+Y removes Rotate again, with the factor
# measured for the stack without it.
# Usage: editor_undo_factor_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

nodes='[.document.formula.nodes[].block] | join(" ")'
blocks() { q "$nodes"; }
# The Edit menu as drawn, into $menu: opened with a click on its title, its Undo and Redo items
# named by their text (menu_bar.cpp), then closed with Escape.
edit_menu() {
    click "menu:Edit"
    wait_for '[.widgets | keys[] | select(startswith("menu:Undo"))] | length' 1
    menu=$(q '[.widgets | keys[] | select(startswith("menu:Undo") or startswith("menu:Redo"))] | join(" / ")')
    xdotool key Escape
    wait_frames 2
}
# Waits until the step factor is measured to the end (the further rounds included).
measured() {
    wait_for '.stepFactor.measured > 0' true 600
    wait_for '.stepFactor.refining' false 900
    wait_frames 2
}

started=$(date +%s)
start "$presets/mandelbulb.json"
set -- $(viewport_centre)
cx=$1 cy=$2
to "$cx" "$cy"
xdotool key ctrl+n
wait_for .title "untitled - fraktal"
[ "$(q .title)" = "untitled - fraktal" ] || fail "Ctrl+N did not open a new document (title $(q .title))"
[ "$(blocks)" = "mandelbulb add_c escape_potential" ] || fail "the new document holds $(blocks)"
opened=$(q .document.formula.deFactor)

# Add block... sits under the estimator's row; the menu opens at the cursor, rows 19 px apart:
# Transform is the second category, Rotate its third block.
y=$(q '.widgets["row:estimator"][1] + 33 | floor')
to 58 "$y"; wait_frames 1; xdotool click 1; wait_frames 2
to 90 $((y + 16 + 19)); wait_frames 2
to 120 $((y + 16 + 19)); wait_frames 2
to 275 $((y + 16 + 19 + 19 * 2)); wait_frames 2; xdotool click 1
wait_for "$nodes" "mandelbulb rotate add_c escape_potential"
[ "$(blocks)" = "mandelbulb rotate add_c escape_potential" ] || fail "the Add block menu gave $(blocks), not Rotate after the Mandelbulb"
wait_frames 3
[ "$(q .undoLabel)" = "add Rotate" ] || fail "adding Rotate reads 'Undo $(q .undoLabel)'"

# Delete over the viewport removes the selected node (the Rotate just added).
to "$cx" "$cy"
wait_frames 1
xdotool key Delete
wait_for "$nodes" "mandelbulb add_c escape_potential"
[ "$(blocks)" = "mandelbulb add_c escape_potential" ] || fail "Delete left $(blocks)"
removed_at=$(date +%s)
measured
factor=$(q .document.formula.deFactor)
echo "factor: opened $opened, measured $factor on $(q .stepFactor.rays) rays after the delete ($(($(date +%s) - removed_at)) s)"
[ "$factor" = "$(q .stepFactor.measured)" ] || fail "the document's factor $factor is not the measured $(q .stepFactor.measured)"
[ "$(q .undoDepth)" = 2 ] || fail "add and remove left $(q .undoDepth) undo steps, not 2 (Undo $(q .undoLabel))"
[ "$(q .undoLabel)" = "remove Rotate" ] || fail "after the measurement Undo reads 'Undo $(q .undoLabel)', not 'Undo remove Rotate'"
edit_menu
echo "Edit menu: $menu"
[ "$menu" = "menu:Redo  / menu:Undo remove Rotate" ] || fail "the Edit menu reads '$menu'"

# One Ctrl+Z: Rotate comes back, with the factor its state had.
to "$cx" "$cy"
xdotool key ctrl+z
wait_for "$nodes" "mandelbulb rotate add_c escape_potential"
[ "$(blocks)" = "mandelbulb rotate add_c escape_potential" ] || fail "one Ctrl+Z left $(blocks), not Rotate back"
[ "$(q .status.text)" = "Undo remove Rotate" ] || fail "the status line reads '$(q .status.text)'"
# Whatever the editor measures for the restored stack lands in its state, not as a step.
measured
[ "$(q .redoDepth)" = 1 ] || fail "after Ctrl+Z and the measurement the redo steps are $(q .redoDepth), not 1"
[ "$(q .redoLabel)" = "remove Rotate" ] || fail "Redo reads 'Redo $(q .redoLabel)'"
[ "$(q .undoLabel)" = "add Rotate" ] || fail "Undo reads 'Undo $(q .undoLabel)'"
edit_menu
echo "Edit menu after Ctrl+Z: $menu"
[ "$menu" = "menu:Redo remove Rotate / menu:Undo add Rotate" ] || fail "the Edit menu reads '$menu'"

# Ctrl+Y removes Rotate again, with the factor measured for the stack without it, at once.
to "$cx" "$cy"
xdotool key ctrl+y
wait_for "$nodes" "mandelbulb add_c escape_potential"
[ "$(blocks)" = "mandelbulb add_c escape_potential" ] || fail "Ctrl+Y left $(blocks), not Rotate removed again"
wait_frames 3
[ "$(q .document.formula.deFactor)" = "$factor" ] || fail "Ctrl+Y brought factor $(q .document.formula.deFactor), not the measured $factor"
[ "$(q .stepFactor.refining)" = false ] || fail "Ctrl+Y measured the factor again"
[ "$(q .undoLabel)" = "remove Rotate" ] || fail "after Ctrl+Y Undo reads 'Undo $(q .undoLabel)'"
[ "$(q .redoDepth)" = 0 ] || fail "after Ctrl+Y $(q .redoDepth) redo steps are left"
stop
echo "undo across the measurement: $(($(date +%s) - started)) s"
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS editor_undo_factor_xvfb_test"
