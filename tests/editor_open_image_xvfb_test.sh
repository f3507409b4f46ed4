#!/bin/sh
# Opening an image where a preset is expected, in the real editor under Xvfb with real keys:
# - `fraktal edit picture.png`: the editor opens with a new document and one clear message in the
#   status line ("picture.png is an image, not a fraktal preset..."), not the JSON parser's text;
#   stderr holds that one line, not an error per frame;
# - Ctrl+O, the PNG's path typed into the browser's field, Enter: the same message, the document,
#   undo list and title unchanged, and still no flood on stderr.
# Usage: editor_open_image_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)

convert -size 64x48 gradient:red-blue "$home/picture.png"
errors="$home/stderr.txt"
clear_message() {
    text=$(q .status.text)
    echo "$1: status '$text' (error: $(q .status.error))"
    [ "$(q .status.error)" = true ] || fail "$1: no error shown"
    case "$text" in
        "picture.png is an image, not a fraktal preset"*) ;;
        *) fail "$1: the message is not the clear one: $text" ;;
    esac
    case "$text" in *JSON* | *json.exception* | *"parse error"* | *"last read"*) fail "$1: parser text shown: $text" ;; esac
}
no_flood() {
    lines=$(wc -l <"$errors")
    echo "$1: $lines line(s) on stderr"
    [ "$lines" -le 1 ] || fail "$1: $lines lines on stderr: $(head -c 400 "$errors")"
    if grep -q "UTF-8" "$errors"; then fail "$1: UTF-8 errors on stderr"; fi
}

start "$home/picture.png" 2>"$errors"
wait_frames 20
kill -0 "$pid" 2>/dev/null || fail "the editor is gone after opening a PNG"
clear_message "fraktal edit picture.png"
no_flood "fraktal edit picture.png"
grep -q "picture.png is an image, not a fraktal preset" "$errors" || fail "stderr does not say it: $(cat "$errors")"
stop

start "$presets/mandelbulb.json" 2>"$errors"
before=$(jq -c '[.document, .undoDepth, .title]' "$state")
set -- $(viewport_centre)
to "$1" "$2"
xdotool key ctrl+o
wait_for .fileBrowser.shown true
wait_for .fileBrowser.fieldActive true
xdotool type --delay 20 "$home/picture.png"
wait_frames 1
xdotool key Return
wait_frames 20
[ "$(q .fileBrowser.shown)" = false ] || fail "the browser stayed open: $(q .fileBrowser.error)"
clear_message "Ctrl+O picture.png"
[ "$(jq -c '[.document, .undoDepth, .title]' "$state")" = "$before" ] || fail "opening the PNG changed the document"
no_flood "Ctrl+O picture.png"
stop

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
