#!/bin/sh
# Files into the editor, under Xvfb with real keys (xdotool):
# - drops of a text file, a PNG, a folder and a broken preset each show a message naming the file
#   and the reason and change nothing (document, undo list, title); a drop of an EXR that fraktal
#   rendered opens the preset in its header, and a drop of a Mandelbulber2 settings file imports it
#   (naming what it drops). X test tools cannot drag files, so the drops go
#   through --replay-drops, which hands the listed paths to the window's GLFW drop callback, the
#   function a real drop calls;
# - the file browser: Ctrl+O, a folder typed into its path field, then a preset's name, Enter: it
#   opens; after a restart the browser lists it under recent files and its folder under recent
#   folders; Save As onto an existing file asks first and Escape leaves the file as it was.
# Usage: editor_files_xvfb_test.sh FRAKTAL PRESET_DIR BAD_PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)
bad=$3

snapshot() { jq -c '[.document, .undoDepth, .redoDepth, .undoLabel, .title]' "$state"; }

echo "plain text, not a preset" >"$home/notes.txt"
convert -size 8x8 xc:red "$home/picture.png"
"$fraktal" render "$presets/menger.json" -o "$home/menger.exr" --size 64x40 --spp 1 -q

start "$presets/mandelbulb.json" --replay-drops "$drops"
# An edit first (the power slider, as a person drags it), so there is something to lose.
set -- $(widget_centre power)
[ $# -eq 2 ] || { fail "the state file records no widget for the power parameter"; set -- 150 477; }
drag_frames "$1" "$2" 60 0 6
wait_frames 3
[ "$(q .undoDepth)" = 1 ] || fail "the slider drag made no undo step"
before=$(snapshot)
for f in "$home/notes.txt" "$home/picture.png" "$bad/a_directory.json" "$bad/camera_degenerate.json"; do
    drop "$f"
    name=$(basename "$f")
    text=$(q .status.text)
    echo "drop $name: $text"
    [ "$(q .status.error)" = true ] || fail "dropping $name shows no error"
    echo "$text" | grep -q "dropped file $name: ." || fail "the message for $name does not name it and a reason: $text"
    [ "$(snapshot)" = "$before" ] || fail "dropping $name changed the document, undo list or title"
done
# Back to the file as opened (nothing unsaved), then an EXR from `fraktal render`: it opens.
xdotool key ctrl+z
wait_frames 3
drop "$home/menger.exr"
echo "drop menger.exr: $(q .status.text)"
[ "$(q .status.error)" = false ] || fail "the rendered EXR did not open: $(q .status.text)"
[ "$(q '.document.formula.nodes | map(.block) | join(" ")')" = "$(jq -r '.formula.nodes | map(.block) | join(" ")' "$presets/menger.json")" ] ||
    fail "the dropped EXR's formula is not the Menger sponge's: $(q '.document.formula.nodes | map(.block) | join(" ")')"
[ "$(q .undoDepth)" = 0 ] || fail "opening the EXR left $(q .undoDepth) undo steps"


# type_into_browser TEXT: typed into the browser's path field once it has the keys (a new folder's
# field takes them a frame or two after the Enter that went there), then Enter.
type_into_browser() {
    wait_for .fileBrowser.fieldActive true
    xdotool type --delay 20 "$1"
    wait_frames 1
    xdotool key Return
    wait_frames 3
}
to 800 400
xdotool key ctrl+o
wait_frames 3
[ "$(q .fileBrowser.shown)" = true ] || fail "Ctrl+O did not show the file browser"
type_into_browser "$presets/"
[ "$(q .fileBrowser.folder)" = "$presets" ] ||
    fail "typing a folder and Enter did not go into it: $(q .fileBrowser.folder)"
type_into_browser kifs_icosahedral.json
[ "$(q .fileBrowser.shown)" = false ] || fail "Enter on a preset's name left the browser open (field: $(q .fileBrowser.name), error: $(q .fileBrowser.error))"
[ "$(q '.document.formula.nodes | map(.block) | join(" ")')" = "$(jq -r '.formula.nodes | map(.block) | join(" ")' "$presets/kifs_icosahedral.json")" ] ||
    fail "the browser did not open kifs_icosahedral.json: $(q .status.text)"
echo "browser: $(q .status.text)"
# Save As onto an existing file: the question comes, Escape keeps the file.
cp "$presets/menger.json" "$home/existing.json"
xdotool key ctrl+shift+s
wait_frames 3
type_into_browser "$home/existing.json"
[ "$(q .fileBrowser.replaceAsked)" = true ] || fail "Save As onto an existing file did not ask before replacing it"
xdotool key Escape
wait_for .fileBrowser.replaceAsked false
cmp -s "$presets/menger.json" "$home/existing.json" || fail "Escape at the replace question still changed the file"
wait_frames 2
xdotool key Escape
wait_for .fileBrowser.shown false
[ "$(q .fileBrowser.shown)" = false ] || fail "Escape did not close the browser"
xdotool key ctrl+q
wait "$pid" || fail "the editor did not quit cleanly"
pid=

start "$presets/mandelbulb.json"
to 800 400
xdotool key ctrl+o
wait_frames 3
q '.fileBrowser.recentFiles[]' | grep -q "/kifs_icosahedral.json$" ||
    fail "after a restart the browser's recent files do not list kifs_icosahedral.json: $(jq -c .fileBrowser.recentFiles "$state")"
q '.fileBrowser.recentFolders[]' | grep -q "presets$" ||
    fail "after a restart the browser's recent folders do not list the presets folder: $(jq -c .fileBrowser.recentFolders "$state")"
echo "recent after restart: $(jq -c .fileBrowser.recentFiles "$state")"
xdotool key Escape
stop

# A Mandelbulber2 settings file opens by import: the Menger sponge's one block. One that uses what
# fraktal cannot express opens too, and the status line (an error) names each dropped thing. An
# import is a new document that is not saved yet (its step factor is measured once it is open), so
# each drop goes to an editor of its own.
printf '# Mandelbulber settings file\n# version 2.20\n[main_parameters]\nformula_1 7;\nN 10;\n' >"$home/sponge.fract"
printf '# Mandelbulber settings file\n# version 2.20\n[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 4;\n' \
    >"$home/hyper.fract"
nodes() { q '.document.formula.nodes | map(.block) | join(" ")'; }
start "$presets/mandelbulb.json" --replay-drops "$drops"
drop "$home/sponge.fract"
echo "drop sponge.fract: $(q .status.text)"
[ "$(q .status.error)" = false ] || fail "the Mandelbulber2 file did not open: $(q .status.text)"
q .status.text | grep -q "Imported sponge.fract" || fail "the status does not say the file was imported: $(q .status.text)"
[ "$(nodes)" = "menger_rotate escape_linear" ] || fail "the imported Menger sponge is not one menger_rotate: $(nodes)"
stop
start "$presets/mandelbulb.json" --replay-drops "$drops"
drop "$home/hyper.fract"
echo "drop hyper.fract: $(q .status.text)"
[ "$(q .status.error)" = true ] || fail "a lenient import shows no warning"
q .status.text | grep -q "slot 2 (hypercomplex)" || fail "the status does not name the dropped slot: $(q .status.text)"
[ "$(nodes)" = "box_fold sphere_fold scale add_c escape_linear" ] || fail "the hybrid's Mandelbox part did not open: $(nodes)"
stop

[ $failures -eq 0 ] && echo "editor_files_xvfb_test: all OK" || { echo "editor_files_xvfb_test: $failures failure(s)"; exit 1; }
