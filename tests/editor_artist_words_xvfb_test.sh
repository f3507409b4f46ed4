#!/bin/sh
# The editor speaks to an artist, under Xvfb with real input (xdotool):
# - the Kleinian's parameters show labels from their declarations, in words: none shows a preset
#   name with underscores (klein_r, box_size), and klein_r is not shown as klein_r;
# - the node list says when an alternating node runs in words, not in code ("iter % 2 = 0");
# - the Render tab keeps the renderer's own knobs (cone pre-pass tile and the like) under an
#   Advanced header that starts closed: the tile's slider is drawn only after a click on it;
# - Help > Tour opens a window with the tour's text, drawn without cut text; the View menu offers
#   the panels and no ImGui metrics.
# Usage: editor_artist_words_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

start "$presets/kleinian.json"
wait_for '.paramWidgets | length > 0' true
echo "Kleinian parameters: $(q '.paramWidgets | map(.label) | join(", ")')"
[ "$(q '[.paramWidgets[] | select(.name == "klein_r")] | length')" = 1 ] || fail "no widget for klein_r drawn"
[ "$(q '.paramWidgets[] | select(.name == "klein_r") | .label')" != klein_r ] || fail "klein_r is labelled klein_r"
[ "$(q '[.paramWidgets[] | select(.label == null or (.label | test("_")))] | length')" = 0 ] ||
    fail "parameters labelled in code: $(q '[.paramWidgets[] | select(.label == null or (.label | test("_"))) | .name] | join(", ")')"

click tab:Render
[ "$(q .sceneTab)" = Render ] || fail "clicking the Render tab shows $(q .sceneTab)"
[ "$(q '.widgets["Cone pre-pass tile"] != null')" = false ] || fail "the cone pre-pass tile shows outside Advanced"
# The header is the tab's last row: the Scene panel scrolled to its end first.
set -- $(centre tab:Render)
to "$1" $(($2 + 100))
wait_frames 1
xdotool click --repeat 20 --delay 30 5
wait_frames 3
click header:Advanced
wait_for '.widgets["Cone pre-pass tile"] != null' true
[ "$(q '.widgets["Cone pre-pass tile"] != null')" = true ] || fail "opening Advanced shows no cone pre-pass tile"

click menu:View
wait_for '.widgets["menu:View/Stats overlay"] != null' true
[ "$(q '.widgets["menu:View/Stats overlay"] != null')" = true ] || fail "the View menu shows no Stats overlay item"
[ "$(q '[.widgets | keys[] | select(test("metrics"; "i"))] | length')" = 0 ] || fail "the View menu offers ImGui metrics"
xdotool key Escape
wait_frames 3
click menu:Help
click menu:Help/Tour
wait_for .tour.shown true
[ "$(q .tour.shown)" = true ] || fail "Help > Tour opened no tour"
check "$(q .tour.text) > 1000" || fail "the tour shows $(q .tour.text) characters of text"
[ "$(q '.clippedText | length')" = 0 ] || fail "text cut with the tour open: $(q '.clippedText | map(.text) | join("; ")')"
stop

start "$presets/hybrid_box_bulb.json"
echo "hybrid_box_bulb nodes: $(q '.nodeLabels | join(" | ")')"
[ "$(q '.nodeLabels | length')" -gt 0 ] || fail "the state file names no node list rows"
[ "$(q '[.nodeLabels[] | select(test("%|iter "))] | length')" = 0 ] ||
    fail "node rows in code: $(q '[.nodeLabels[] | select(test("%|iter "))] | join(" | ")')"
[ "$(q '.nodeLabels[0]')" = "1. Box fold  (every 2nd iteration from the 1st)" ] ||
    fail "the first row reads '$(q '.nodeLabels[0]')'"
stop

[ $failures -eq 0 ] && echo "editor_artist_words_xvfb_test: all OK" || { echo "editor_artist_words_xvfb_test: $failures failure(s)"; exit 1; }
