#!/bin/sh
# A heavy formula does not hold the window at rest, in the real editor under Xvfb (Mesa llvmpipe):
# kleinian.json opened and left alone, the pointer over the viewport. Its first frames at rest
# march the settings' 30 steps a ray (3.5-8 s a frame on two cores); after them each frame at rest
# marches the steps that fit the frame-time target (viewport::RestSteps), fewer than 30, and
# the frames come at least twice as often as the 30-step frame did, measured in the same
# run from the editor's frame log. A click on the Scene panel's Render tab during these frames
# then acts within a few frames.
# Usage: editor_rest_frames_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2
log="$home/frames.jsonl"

start "$presets/kleinian.json" --frame-log "$log"
set -- $(viewport_centre)
to "$1" "$2"
# Frames that rendered the viewport at rest (a continued view with steps), from the log.
rest_frames() { jq -s '[.[] | select(.action == "continue" and .render_ms > 0)] | length' "$log"; }
tries=0
while [ "$(rest_frames)" -lt 10 ] && [ $tries -lt 600 ]; do
    sleep 0.5
    tries=$((tries + 1))
    kill -0 "$pid" 2>/dev/null || { fail "the editor is gone"; break; }
done
[ "$(rest_frames)" -ge 10 ] || fail "only $(rest_frames) frames at rest in 300 s"

# The 30-step frames at rest, and the ones after them.
full=$(jq -s '[.[] | select(.action == "continue" and .render_ms > 0 and .steps_per_frame == 30) | .frame_ms] | max // 0' "$log")
fitted=$(jq -s '[.[] | select(.action == "continue" and .render_ms > 0 and .steps_per_frame < 30) | .frame_ms] | sort | .[length / 2 | floor] // 0' "$log")
steps=$(jq -s '[.[] | select(.action == "continue" and .render_ms > 0)] | last | .steps_per_frame' "$log")
echo "at rest: the 30-step frame took $full ms, the fitted frames $fitted ms (median), last $steps steps a frame"
check "$full > 0" || fail "no frame at rest marched the settings' 30 steps"
check "$steps >= 1 && $steps < 30" || fail "the steps at rest stayed at $steps"
check "$fitted > 0 && $fitted * 2 <= $full" ||
    fail "the fitted frames ($fitted ms) are not twice as short as the 30-step one ($full ms)"

# A click during the fitted frames acts within a few frames.
click tab:Render
[ "$(q .sceneTab)" = Render ] || fail "the click on the Render tab did not act (tab: $(q .sceneTab))"
stop
[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok: frames at rest on kleinian.json"
