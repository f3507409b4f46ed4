#!/bin/sh
# The window never freezes on a heavy stack, in the real editor under Xvfb (Mesa llvmpipe): three
# Kleinian nodes (kleinian.json with its group block three times; with the whole view a frame,
# 0.9-1 s a frame at rest on two cores, and seconds on the frames after opening). Opened and left
# alone, the pointer over the viewport, its frames at full size (a reset and the frames at rest,
# each refining one slice of the view) stay short: their 95th percentile under 300 ms (the target
# is 50 ms; with two stories side by side on two cores, as CI runs them, the 95th percentile was
# 157 ms; with the whole view a frame it was 12 s) in the editor's frame log. Input
# during the refinement goes where it was meant, within a few frames: a click on the View menu
# opens it, Escape closes it, Ctrl+O shows the Open dialog and Escape cancels it. A change of
# structure (Ctrl+D) holds no frame either, nor does the first picture after opening (under 300 ms).
# Usage: editor_never_freezes_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
# The refinement at rest is what this story measures: the document's own AA cap.
story_aa_cap=
fraktal=$1
presets=$2
log="$home/frames.jsonl"
stack="$home/three_kleinian.json"
jq '.name = "Three Kleinian nodes" | .formula.nodes = [.formula.nodes[0], .formula.nodes[0], .formula.nodes[0], .formula.nodes[1]]' \
    "$presets/kleinian.json" > "$stack"

start "$stack" --frame-log "$log"
set -- $(viewport_centre)
to "$1" "$2"
wait_rest_frames 40
# The first picture after opening is a small whole view that the frames at rest then refine, not
# the whole view at full size in one frame (0.4-0.9 s on the heavy presets in the viewport bench,
# where frames that rendered nothing while the programs compiled had taught the dynamic resolution
# that a whole view was cheap). This stack opened small even before that was mended (124 ms at an
# eighth: its step factor is measured first, and no frame renders meanwhile), so this check guards
# the frame's length; editor_rest_frames_xvfb_test is the one that failed on the old code.
first_ms=$(jq -s '[.[] | select(.render_ms > 0)][0].render_ms' "$log")
first_scale=$(jq -s '[.[] | select(.render_ms > 0)][0].scale' "$log")
echo "the first picture: $first_ms ms at scale $first_scale"
check "$first_ms < 300" || fail "the first picture after opening held the window $first_ms ms (scale $first_scale)"
p95=$(rest_frame_ms 95)
p50=$(rest_frame_ms 50)
echo "three Kleinian nodes at rest: frames $p50 ms (median), $p95 ms (95th percentile)"
check "$p95 > 0 && $p95 < 300" || fail "the frames at rest took $p95 ms (95th percentile), over 300 ms"
[ "$(q .viewportSettled)" = false ] || fail "the view settled before the input below: it tests nothing"

# A click on the View menu during the refinement opens it within a few frames.
click menu:View
wait_for '.widgets["menu:View/Stats overlay"] != null' true 5
[ "$(q '.widgets["menu:View/Stats overlay"] != null')" = true ] || fail "the click on the View menu did not open it"
press_keys Escape
wait_for .popupOpen false 5
[ "$(q .popupOpen)" = false ] || fail "Escape did not close the View menu"
# Ctrl+O shows the Open dialog, and Escape cancels it.
press_keys ctrl+o
wait_for .fileBrowser.shown true 5
[ "$(q .fileBrowser.shown)" = true ] || fail "Ctrl+O did not show the Open dialog"
press_keys Escape
wait_for .fileBrowser.shown false 5
[ "$(q .fileBrowser.shown)" = false ] || fail "Escape did not cancel the Open dialog"
# Frames stayed short while the input came.
p95=$(rest_frame_ms 95)
check "$p95 < 300" || fail "with the input, the frames at rest took $p95 ms (95th percentile)"

# A change of structure: Ctrl+D duplicates the selected node. The step factor is measured for the
# new stack on a worker (its settled rounds: 0.8-1 s of CPU for three or four Kleinian nodes alone,
# which the frame of the edit took when they ran on the main thread), the programs compile on
# another, and the last image stays meanwhile. No frame from the edit to the new stack's tenth
# rendered frame holds the window (frames of a settled view wait for input: not counted).
edit_from=$(wc -l < "$log")
press_keys ctrl+d
wait_for '.document.formula.nodes | length' 5
[ "$(q '.document.formula.nodes | length')" = 5 ] || fail "Ctrl+D did not duplicate a node"
edit_frames() { tail -n +"$((edit_from + 1))" "$log" | jq -s "$1"; }
tries=0
while [ "$(edit_frames '[.[] | select(.render_ms > 0)] | length')" -lt 10 ] && [ $tries -lt 600 ]; do
    sleep 0.5
    tries=$((tries + 1))
done
[ "$(edit_frames '[.[] | select(.render_ms > 0)] | length')" -ge 10 ] || fail "the new stack rendered no 10 frames"
edit_max=$(edit_frames '[.[] | select(.settled | not) | .frame_ms] | max // 0')
echo "the structure edit: $(edit_frames length) frames, the longest $edit_max ms"
check "$edit_max < 600" || fail "a frame of the structure edit held the window $edit_max ms"
stop
[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok: three Kleinian nodes never hold the window"
