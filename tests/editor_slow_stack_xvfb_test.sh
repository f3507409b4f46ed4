#!/bin/sh
# A crawling stack explains itself (app/editor/document/slow_stack.hpp), driven as a person does
# under Xvfb. The artist has a twist before an octahedral KIFS, closed by the linear escape-time
# estimate at bailout 1000, and duplicates the twist (Ctrl+D): a structure change, so the editor
# measures the step factor, finds the estimate useless, and the Formula panel says why and offers
# the fit's estimator. One click on that offer applies it; one Ctrl+Z takes it back, and only it.
# The screenshots show the explanation in its warning colour, and show it gone after the fix.
# Usage: editor_slow_stack_xvfb_test.sh FRAKTAL OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
out=$2
mkdir -p "$out"
# The share of a window rectangle (WxH+X+Y) in the explanation's colour (1, 0.8, 0.35): its text.
warning_share() {
    convert "$1" -crop "$2" +repage -fuzz 15% -fill black +opaque "rgb(255,204,89)" -fill white \
        -opaque "rgb(255,204,89)" -colorspace Gray -format "%[fx:mean]" info:
}

preset="$home/twisted.json"
cp "$(dirname "$0")/slow_presets/twisted_kifs.json" "$preset"

estimator() { q '.document.formula.nodes[-1].block'; }
start "$preset"
wait_frames 2
[ "$(estimator)" = escape_linear ] || fail "the preset opened with $(estimator), not escape_linear"

# Ctrl+D duplicates the selected node (the twist, node 1): the structure changes.
xdotool key --window "$window" ctrl+d
wait_for '.document.formula.nodes | length' 4
[ "$(q '.document.formula.nodes | length')" = 4 ] || fail "Ctrl+D did not duplicate the twist"

# The measurement and the explanation run on worker threads: seconds on this machine.
wait_for '.slowStack.text | length > 0' true 900
text=$(q .slowStack.text)
echo "explanation: $text"
case "$text" in *useless*) ;; *) fail "the explanation does not say the estimate is useless: $text" ;; esac
case "$text" in *"Estimator box at bailout"*) ;; *) fail "the explanation names no faster estimator: $text" ;; esac
wait_for '.widgets["text:Slow stack"] != null' true
rect=$(q '.widgets["text:Slow stack"] | map(floor) | "\(.[2])x\(.[3])+\(.[0])+\(.[1])"')
import -window "$window" "$out/slow_stack_explained.png"
shown=$(warning_share "$out/slow_stack_explained.png" "$rect")
echo "explanation at $rect: $shown of its pixels in the warning colour"
check "$shown > 0.02" || fail "the screenshot shows no explanation at $rect ($shown)"
[ "$(q .slowStack.faster.estimator)" = box ] || fail "the offer is $(q .slowStack.faster.estimator), not box"
offered_bailout=$(q .slowStack.faster.bailout)
offered_factor=$(q .slowStack.faster.deFactor)
check "$offered_bailout < 1000" || fail "the offered bailout is $offered_bailout"

# One click on the offer, with a person's timing (the panel draws it from the frame after the
# explanation arrives).
wait_for '.widgets["button:Use faster estimator"] != null' true
set -- $(q '.widgets["button:Use faster estimator"] | "\(.[0] + .[2] / 2 | floor) \(.[1] + .[3] / 2 | floor)"')
to "$1" "$2"
sleep 0.15
xdotool mousedown 1
sleep 0.08
xdotool mouseup 1
wait_for '.document.formula.nodes[-1].block' box
[ "$(estimator)" = box ] || fail "the click did not apply the box estimator (estimator $(estimator))"
[ "$(q .document.formula.bailout)" = "$offered_bailout" ] || fail "bailout $(q .document.formula.bailout), offered $offered_bailout"
# Measured again for the new estimator, on a worker: the offer's factor, or less once the check's
# further rounds end.
wait_for .stepFactor.measuring false 300
factor=$(q .document.formula.deFactor)
check "$factor <= $offered_factor && $factor > 0.05" || fail "factor $factor, offered $offered_factor"
check "$(q .stepFactor.speed) > 0.05" || fail "the applied estimator's speed is $(q .stepFactor.speed)"
wait_for '.slowStack.text' ''
[ "$(q .slowStack.text)" = "" ] || fail "the explanation stayed after the fix: $(q .slowStack.text)"
wait_frames 2
import -window "$window" "$out/slow_stack_fixed.png"
gone=$(warning_share "$out/slow_stack_fixed.png" "$rect")
echo "after the fix: $gone of those pixels in the warning colour"
check "$gone < 0.002" || fail "the screenshot still shows the explanation after the fix ($gone)"

# One Ctrl+Z undoes the fix, and only the fix: the duplicated twist stays.
wait_frames 2
xdotool key --window "$window" ctrl+z
wait_for '.document.formula.nodes[-1].block' escape_linear
[ "$(estimator)" = escape_linear ] || fail "Ctrl+Z left estimator $(estimator)"
[ "$(q .document.formula.bailout)" = 1000 ] || fail "Ctrl+Z left bailout $(q .document.formula.bailout)"
[ "$(q '.document.formula.nodes | length')" = 4 ] || fail "Ctrl+Z undid more than the fix"
stop
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS editor_slow_stack_xvfb_test"
