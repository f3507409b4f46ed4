#!/bin/sh
# An imported frag's distance estimate edited in the editor, driven as a person does under Xvfb.
# The artist opens a preset imported from a FragM frag (tests/data/frag_import/menger.frag): its
# parameters show under their #group headings. "Edit GLSL..." opens the code in the GLSL block
# window, fixed to the estimator category. The artist clicks into the code, types a helper that
# reads an undeclared name above boxDistance and applies: the compile error is listed under the
# code naming the line typed, the gutter marks that line red, and the viewport keeps the last good
# image. A click on the listed error puts the cursor on that line; the artist deletes it and
# applies again: the errors are gone, the sponge renders again, and the edit is one undo step.
# Usage: editor_glsl_errors_xvfb_test.sh FRAKTAL SOURCE_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
source_dir=$2
out=$3
mkdir -p "$out"
# The share of a window rectangle (WxH+X+Y) of IMAGE in COLOUR (within 12 %).
colour_share() {
    convert "$1" -crop "$2" +repage -fuzz 12% -fill black +opaque "$3" -fill white -opaque "$3" \
        -colorspace Gray -format "%[fx:mean]" info:
}
# The root-mean-square difference (0 to 1) of two images' same rectangle.
difference() {
    convert "$1" -crop "$3" +repage "$home/a.png"
    convert "$2" -crop "$3" +repage "$home/b.png"
    compare -metric RMSE "$home/a.png" "$home/b.png" null: 2>&1 | sed 's/.*(\(.*\))/\1/'
}
# The spread of a rectangle's brightness (0 to 0.5): above a few hundredths it is no blank background.
spread() { convert "$1" -crop "$2" +repage -colorspace Gray -format "%[fx:standard_deviation]" info:; }
rect_of() { q ".widgets[\"$1\"] | map(floor) | \"\\(.[2])x\\(.[3])+\\(.[0])+\\(.[1])\""; }
# Click at window point (X, Y) with a person's timing.
click_at() {
    to "$1" "$2"
    wait_frames 1
    xdotool mousedown 1
    wait_frames 1
    xdotool mouseup 1
    wait_frames 2
}

preset="$home/menger_frag.json"
"$fraktal" import "$source_dir/tests/data/frag_import/menger.frag" -o "$preset" >/dev/null
id=$(jq -r '.formula.customBlocks[0].id' "$preset")
# The line the artist types on: the one boxDistance starts on, which moves down by one.
line=$(jq -r '.formula.customBlocks[0].glsl' "$preset" | grep -n '^float boxDistance' | cut -d: -f1)
[ -n "$line" ] || { echo "FAIL menger.frag's DE has no boxDistance line"; exit 1; }
echo "whole DE $id; the broken line goes in at line $line"

start "$preset"
wait_settled
# The parameters under the frag's #group headings, in its order.
groups=$(q '[.paramGroups[]?.name] | join(",")')
[ "$groups" = "Menger,Twist" ] || fail "the parameters show under groups '$groups', not Menger,Twist"
[ "$(q '(.paramGroups[1].firstWidget // -1) as $k | .paramWidgets[$k].name')" = Twist ] ||
    fail "the Twist group does not head its Twist checkbox"
wait_frames 2
import -window "$window" "$out/glsl_before.png"

# Edit GLSL... (the estimator, the formula's only step, is selected); scroll the panel down first.
set -- $(widget_centre Scale)
to "$1" "$2"
wheel_down 6
click "button:Edit GLSL"
[ "$(q .blockEditorOpen)" = true ] || fail "Edit GLSL... did not open the block editor"
[ "$(q .blockEditor.wholeDE)" = true ] || fail "the block editor does not hold the whole DE"
[ "$(q .blockEditor.category)" = estimator ] || fail "the whole DE's category reads $(q .blockEditor.category)"
[ "$(q '.blockEditor.errors | length')" = 0 ] || fail "errors before any edit: $(q .blockEditor.errors)"

# The wheel over the code scrolls it, line numbers and all; back to the top.
wheel_over "glsl:text" 5
top=$(q .blockEditor.firstLineInView)
echo "the wheel down over the code: line $top at the top"
check "$top > 4" || fail "the wheel over the code left line $top at the top"
wheel_over "glsl:text" 4
[ "$(q .blockEditor.firstLineInView)" = 1 ] || fail "the wheel up left line $(q .blockEditor.firstLineInView) at the top"

# Into the code: Ctrl+Home, down to the line, and type the broken helper there.
click "glsl:text"
press_keys ctrl+Home
i=1
while [ $i -lt "$line" ]; do
    press_keys Down
    i=$((i + 1))
done
press_keys Home
[ "$(q .blockEditor.cursorLine)" = "$line" ] || fail "the cursor is on line $(q .blockEditor.cursorLine), not $line"
xdotool type --delay 40 "float brokenHelper() { return not_declared_here; }"
press_keys Return
wait_frames 2
case "$(q '.document.formula.customBlocks[0].glsl')" in
*"not_declared_here"*) fail "the typed line reached the document before Apply" ;;
esac

click "button:Apply GLSL"
# The structure compiles in the background; the errors come back from the driver.
wait_for '.blockEditor.errors | length > 0' true 600
errors=$(q '.blockEditor.errors')
echo "errors listed: $errors"
[ "$(q '.blockEditor.errors[0].line')" = "$line" ] ||
    fail "the error is listed on line $(q '.blockEditor.errors[0].line'), not the typed line $line"
case "$(q '.blockEditor.errors[0].message')" in
*not_declared_here*) ;;
*) fail "the listed error does not name not_declared_here: $(q '.blockEditor.errors[0].message')" ;;
esac
case "$(q .compileError)" in
*"($id), GLSL line $line:"*) ;;
*) fail "the viewport's compile error does not name line $line: $(q .compileError)" ;;
esac
case "$(q '.document.formula.customBlocks[0].glsl')" in
*"not_declared_here"*) ;;
*) fail "Apply did not put the edited code in the document" ;;
esac
wait_frames 3
import -window "$window" "$out/glsl_error.png"
# The gutter's red mark on the line, and the listed error in its red.
mark=$(rect_of "glsl:first error mark")
share=$(colour_share "$out/glsl_error.png" "$mark" "rgb(215,48,39)")
echo "gutter mark at $mark: $share of its pixels red"
check "$share > 0.5" || fail "the screenshot shows no red mark in the gutter at $mark ($share)"
row=$(rect_of "glsl:first error")
text=$(colour_share "$out/glsl_error.png" "$row" "rgb(255,115,102)")
echo "error row at $row: $text of its pixels in the error colour"
check "$text > 0.02" || fail "the screenshot shows no error row at $row ($text)"
# The last good image stays in the viewport beside the window (between the stats at its top and
# the compile error's banner at its bottom).
set -- $(q '.viewport | map(floor) | join(" ")') $(q '.widgets["window:GLSL block"] | map(floor) | join(" ")')
left=$(($5 + $7 + 4))
beside="$(($1 + $3 - left))x$(($4 * 9 / 20))+$left+$(($2 + $4 / 5))"
kept=$(difference "$out/glsl_before.png" "$out/glsl_error.png" "$beside")
echo "viewport beside the window ($beside) after the failed compile: RMSE $kept against before"
check "$(spread "$out/glsl_error.png" "$beside") > 0.03" || fail "the viewport is blank after the failed compile"
check "$kept < 0.05" || fail "the viewport did not keep its last good image (RMSE $kept)"

# A click on the listed error puts the cursor on its line; Shift+End and two Deletes take it away.
press_keys ctrl+End
click "glsl:first error"
wait_frames 3
[ "$(q .blockEditor.cursorLine)" = "$line" ] ||
    fail "the error's row put the cursor on line $(q .blockEditor.cursorLine), not $line"
check "$(q .blockEditor.firstLineInView) <= $line" || fail "line $line is scrolled out of view above"
press_keys shift+End
press_keys Delete
press_keys Delete
click "button:Apply GLSL"
wait_for '.compileError' '' 600
wait_for '.blockEditor.errors | length' 0
[ "$(q '.blockEditor.errors | length')" = 0 ] || fail "errors stay after the fix: $(q .blockEditor.errors)"
[ -z "$(q .compileError)" ] || fail "the compile error stays after the fix: $(q .compileError)"
case "$(q '.document.formula.customBlocks[0].glsl')" in
*"not_declared_here"*) fail "the fixed code still holds the broken line" ;;
esac
[ "$(q .undoLabel)" = "edit of $(q '.document.formula.customBlocks[0].label // .document.formula.customBlocks[0].id')" ] ||
    fail "the undo step reads '$(q .undoLabel)'"
wait_settled
wait_frames 2
import -window "$window" "$out/glsl_fixed.png"
share=$(colour_share "$out/glsl_fixed.png" "$mark" "rgb(215,48,39)")
check "$share < 0.05" || fail "the gutter still shows a red mark after the fix ($share)"
again=$(difference "$out/glsl_before.png" "$out/glsl_fixed.png" "$beside")
echo "viewport after the fix: RMSE $again against before"
check "$(spread "$out/glsl_fixed.png" "$beside") > 0.03" || fail "the viewport is blank after the fix"
check "$again < 0.05" || fail "the viewport does not show the sponge again after the fix (RMSE $again)"
stop
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS editor_glsl_errors_xvfb_test"
