#!/bin/sh
# The window never freezes on a heavy stack, in the real editor under Xvfb (Mesa llvmpipe): three
# Kleinian nodes (kleinian.json with its group block three times; with the whole view a frame,
# 0.9-1 s a frame at rest on two cores, and seconds on the frames after opening). Opened and left
# alone, the pointer over the viewport, its frames at full size (a reset and the frames at rest,
# each refining one slice of the view) stay short: their 95th percentile under 300 ms (the target
# is 50 ms; with two stories side by side on two cores, as CI runs them, the 95th percentile was
# 157 ms; with the whole view a frame it was 12 s) in the editor's frame log. Input
# during the refinement goes where it was meant, within a few frames: a click on the View menu
# opens it, Escape closes it, Ctrl+O shows the Open dialog and Escape cancels it.
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
stop
[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok: three Kleinian nodes never hold the window"
