# Helpers for the tests that drive the real editor under Xvfb with xdotool (sourced, not run):
# a private HOME, the editor in the background writing its state file, waits on its frames,
# pointer moves and drags in window coordinates. Sourced first thing, it re-runs the calling script
# under its own Xvfb server (a sourced file sees the caller's "$0" and "$@"); the screen is
# $xvfb_screen, 1280x800x24 unless the caller sets it. The functions expect $fraktal set; sets
# $home, $state, $pid, $window.
if [ -z "${FRAKTAL_UNDER_XVFB:-}" ]; then
    FRAKTAL_UNDER_XVFB=1 exec xvfb-run -a -s "-screen 0 ${xvfb_screen:-1280x800x24}" "$0" "$@"
fi
# A private HOME and config folder: the editor's ini and recent list must not leak in or out.
# Mesa's compiled-shader cache stays the user's (it takes the home folder from the passwd entry,
# not from HOME), shared with every other GL test of the suite.
home=$(mktemp -d)
export XDG_CONFIG_HOME="$home/config"
state="$home/state.json"
pid=
cleanup() {
    [ -z "$pid" ] || kill "$pid" 2>/dev/null || true
    rm -rf "$home"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

q() { jq -r "$1" "$state"; }
# Drops: X test tools cannot drag files, so a story starts the editor with --replay-drops "$drops",
# which hands the paths listed there to the window's GLFW drop callback, the function a real drop
# calls. drop FILE...: the editor takes the list on its next frame (written whole, then renamed).
drops="$home/drops"
drop() {
    printf '%s\n' "$@" >"$drops.tmp"
    mv "$drops.tmp" "$drops"
    tries=0
    while [ -f "$drops" ] && [ $tries -lt 100 ]; do sleep 0.1; tries=$((tries + 1)); done
    wait_frames 2
}
# The editor's tick: the frame count, the window events it holds for later frames and whether the
# view settled, from the line it writes beside the state file every frame (frameTickLine in
# app/editor/state_dump.hpp), read by the shell itself: the polls below run ten times a second, and
# two jq processes each (33 ms of CPU apiece) cost a waiting story about 40 % of a core that the
# editor's frames wanted.
editor_tick() {
    tick_frame=0 tick_pending=0 tick_settled=false
    [ ! -f "$state.frame" ] || read -r tick_frame tick_pending tick_settled < "$state.frame" || true
}
frame() { editor_tick; echo "$tick_frame"; }
pending_input() { editor_tick; echo "$tick_pending"; }
# Waits until the editor has drawn N more frames (events are handled at the start of a frame) and
# has handed every window event it received to a frame (app/editor/input/imgui_input.hpp: a move, a
# press and a release that arrive between two frames take a frame each).
# (sh has no local variables: its counter is its own, not the callers' `tries`.)
wait_frames() {
    editor_tick
    target=$((tick_frame + $1))
    polls=0
    while [ "$tick_frame" -lt "$target" ] || [ "$tick_pending" != 0 ]; do
        polls=$((polls + 1))
        [ $polls -lt 600 ] || { echo "the editor stopped drawing frames"; exit 1; }
        sleep 0.1
        editor_tick
    done
}
# wait_for QUERY VALUE [N]: waits until the state file's QUERY reads VALUE, at most N frames
# (default 30): an ImGui popup closes a frame after the key that closes it.
wait_for() {
    tries=0
    while [ "$(q "$1")" != "$2" ] && [ $tries -lt "${3:-30}" ]; do
        wait_frames 1
        tries=$((tries + 1))
    done
}
# Waits until the viewport's image has converged at full resolution (at most 300 s): a structure
# edit compiles in the background and the image then refines over many frames, at rest as many
# as its march steps need within the frame-time target (a heavy formula takes short frames).
wait_settled() {
    settle_end=$(($(date +%s) + 300))
    editor_tick
    while [ "$tick_settled" != true ] && [ "$(date +%s)" -lt $settle_end ]; do
        wait_frames 1
    done
}
# start PRESET [OPTIONS...]: the editor in the background, after its first frames.
# Its viewport anti-aliases to $story_aa_cap samples per pixel at rest (`fraktal edit --aa-cap`;
# default 2): the editor refines after every edit a story makes until the view settles, and on
# llvmpipe each sample past the first cost a Mandelbulb settle about 1.3 s of CPU (10.5 s at the
# shipped cap of 8, 4.0 s at 2, 2.4 s at 1, start-up included), which the story beside it on CI's
# two cores waited for. A story that measures the refinement at rest sets story_aa_cap= (empty:
# the document's cap).
start() {
    rm -f "$state" "$state.frame"
    preset=$1
    shift
    aa_cap=${story_aa_cap-2}
    HOME="$home" "$fraktal" edit "$preset" --state-file "$state" ${aa_cap:+--aa-cap "$aa_cap"} "$@" &
    pid=$!
    wait_frames 3
    window=$(xdotool search --sync --onlyvisible --name "fraktal" | head -1)
}
stop() {
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    pid=
}
camera() { q '.camera.position | map(tostring) | join(" ")'; }
# Move the pointer to window coordinates.
to() { xdotool mousemove --window "$window" "$1" "$2"; }
# drag X Y DX DY STEPS: left-drag from (X, Y) by (DX, DY) in STEPS moves.
drag() {
    to "$1" "$2"
    xdotool mousedown 1
    i=1
    while [ $i -le "$5" ]; do
        to $(($1 + $3 * i / $5)) $(($2 + $4 * i / $5))
        i=$((i + 1))
    done
    xdotool mouseup 1
}
# The same, a frame per step: ImGui 1.86 polls the cursor once a frame, so its widgets need to
# see the button down and the cursor move in separate frames, as with a person's hand.
drag_frames() {
    to "$1" "$2"
    wait_frames 1
    xdotool mousedown 1
    wait_frames 1
    i=1
    while [ $i -le "$5" ]; do
        to $(($1 + $3 * i / $5)) $(($2 + $4 * i / $5))
        wait_frames 1
        i=$((i + 1))
    done
    xdotool mouseup 1
}
# The centre of a widget the editor recorded (e.g. header:Objects) in window coordinates.
centre() { q ".widgets[\"$1\"] | \"\\(.[0] + .[2] / 2 | floor) \\(.[1] + .[3] / 2 | floor)\""; }
# click WIDGET: waits (at most 30 frames) for the editor to draw WIDGET, then clicks its centre as
# a person does (move, a moment, press, release).
click() {
    wait_for ".widgets[\"$1\"] != null" true
    [ "$(q ".widgets[\"$1\"] != null")" = true ] || { fail "no $1 drawn"; return; }
    set -- $(centre "$1")
    to "$1" "$2"
    wait_frames 1
    xdotool mousedown 1
    wait_frames 1
    xdotool mouseup 1
    wait_frames 3
}
# press X Y: a click held over two frames at window point (X, Y) (a combo reacts to the press, its
# list to the release).
press() { to "$1" "$2"; wait_frames 2; xdotool mousedown 1; wait_frames 2; xdotool mouseup 1; wait_frames 3; }
# pick ROW RECT: opens the combo drawn at RECT (the state file's [x, y, w, h]) and picks its list's
# row ROW (from 0). The list opens below the combo (after the popup's 8 px padding), a row 2 px
# shorter than the combo (measured: 19 px rows under the 21 px combo of the editor's style).
pick() {
    row=$1
    shift
    set -- $(echo "$1" | tr '[],' '   ' | xargs printf '%.0f ')
    press $(($1 + $3 / 2)) $(($2 + $4 / 2))
    press $(($1 + $3 / 2)) $(($2 + $4 + 8 + ($4 - 2) * row + ($4 - 2) / 2))
}
# Relative difference of two camera positions (0: the same place).
moved() { awk -v a="$1" -v b="$2" 'BEGIN { split(a, p, " "); split(b, r, " "); d = 0; n = 0;
    for (i = 1; i <= 3; i++) { d += (p[i] - r[i]) ^ 2; n += r[i] ^ 2 } print sqrt(d / n) }'; }
check() { awk "BEGIN { exit !($1) }"; }
# wheel_over WIDGET BUTTON: eight clicks of the wheel (button 5: down, 4: up) over WIDGET's centre.
wheel_over() {
    set -- $(centre "$1") "$2"
    to "$1" "$2"
    wait_frames 2
    xdotool click --repeat 8 --delay 30 "$3"
    wait_frames 5
}

# wheel_down N: N clicks of the wheel down (button 5) where the pointer is, a frame after each.
wheel_down() {
    wheel_i=0
    while [ $wheel_i -lt "$1" ]; do
        xdotool click 5
        wait_frames 1
        wheel_i=$((wheel_i + 1))
    done
}
# ctrl_click_at X Y: Ctrl+click at window point (X, Y), each press and release a frame of its own
# (ImGui turns a drag field into a text field with its text selected).
ctrl_click_at() {
    to "$1" "$2"
    wait_frames 1
    xdotool keydown ctrl
    wait_frames 1
    xdotool mousedown 1
    wait_frames 1
    xdotool mouseup 1
    wait_frames 1
    xdotool keyup ctrl
    wait_frames 1
}

# Viewport centre and panel points at the default 1280x800 layout (from the state file).
viewport_centre() { q '"\(.viewport[0] + .viewport[2] / 2 | floor) \(.viewport[1] + .viewport[3] / 2 | floor)"'; }
# widget_centre NAME: the centre of the block parameter NAME's widget, as the state file records it
# (where the panel draws it this frame, so that a row added above it moves nothing in a test).
widget_centre() { q ".paramWidgets[] | select(.name == \"$1\") | .rect | \"\\(.[0] + .[2] / 2 | floor) \\(.[1] + .[3] / 2 | floor)\""; }

# press_keys KEY...: a key or chord tapped as a hand taps it: down in order, held 60 ms, up in
# reverse; then the frames that take it. The editor's input queue hands the press and the release
# to ImGui in frames of their own however slow a frame is. Held until a frame is drawn instead,
# a key stays down past ImGui's key-repeat delay (275 ms) whenever a loaded machine's frame takes
# longer, and a repeat is what a person holding the key gets: one Down would move two lines.
press_keys() {
    for k in "$@"; do last="$k $(echo ${last:-})"; done
    xdotool keydown "$@" sleep 0.06 keyup $last
    last=
    wait_frames 1
}
# The editor's frame log ($log, from `--frame-log`): the frames that refined the viewport at full
# size at rest (a reset or a continued view). wait_rest_frames N waits until N such frames were
# logged (at most 300 s); rest_frame_ms P gives the P-th percentile of their frame times (ms).
rest_filter='.[] | select(.scale == 1 and .render_ms > 0 and (.action == "continue" or .action == "reset"))'
rest_frames() { jq -s "[$rest_filter] | length" "$log"; }
wait_rest_frames() {
    rest_tries=0
    while [ "$(rest_frames)" -lt "$1" ] && [ $rest_tries -lt 600 ]; do
        sleep 0.5
        rest_tries=$((rest_tries + 1))
        kill -0 "$pid" 2>/dev/null || { fail "the editor is gone"; break; }
    done
    [ "$(rest_frames)" -ge "$1" ] || fail "only $(rest_frames) frames at rest at full size in 300 s"
}
rest_frame_ms() { jq -s "[$rest_filter | .frame_ms] | sort | .[length * $1 / 100 | floor] // 0" "$log"; }
