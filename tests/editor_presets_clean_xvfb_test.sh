#!/bin/sh
# Every shipped preset (presets/*.json and presets/2d/*.json) opened in the real editor under Xvfb
# with --state-file, left alone for 10 frames with the pointer over the viewport: the editor keeps
# drawing and writing its state, the title has no unsaved mark (nothing asks to be saved), and a
# 3D preset's camera position and target are the file's numbers exactly (a keyed camera: its first
# position key; a keyed orientation sets the target), a 2D preset's view centre and width likewise.
# Usage: editor_presets_clean_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)

opened=0
for preset in "$presets"/*.json "$presets"/2d/*.json; do
    name=$(basename "$preset")
    # A smaller window than the stories' 1280x800: what is checked does not depend on its size, and
    # the viewport has 2.3 times fewer pixels to refine (this test: 191 s -> 133 s in CI's suite).
    start "$preset" --width 960 --height 600
    set -- $(viewport_centre)
    to "$1" "$2"
    wait_frames 10
    kill -0 "$pid" 2>/dev/null || fail "$name: the editor is gone"
    title=$(q .title)
    [ "$title" = "$name - fraktal" ] || fail "$name: opens as '$title'"
    if [ "$(jq -r '.dimension // 3' "$preset")" = 2 ]; then
        want=$(jq -c '[.view.center, .view.width]' "$preset")
        have=$(q '[.document.view.center, .document.view.width] | tojson')
    elif jq -e '[.animation.tracks[]?.target] | index("camera.orientation")' "$preset" >/dev/null; then
        # The keyed orientation (a quaternion) sets the target: the position is the file's.
        want=$(jq -c '[.animation.tracks[] | select(.target == "camera.position") | .keys[0].value][0] // .camera.position' "$preset")
        have=$(q '.document.camera.position | tojson')
    else
        want=$(jq -c '[[.animation.tracks[]? | select(.target == "camera.position") | .keys[0].value][0] // .camera.position, .camera.target]' "$preset")
        have=$(q '[.document.camera.position, .document.camera.target] | tojson')
    fi
    [ "$have" = "$want" ] || fail "$name: the file says $want, the editor holds $have"
    echo "$name: '$title', $have"
    opened=$((opened + 1))
    stop
done
[ $opened -ge 39 ] || fail "only $opened presets were opened"

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok: $opened presets"
