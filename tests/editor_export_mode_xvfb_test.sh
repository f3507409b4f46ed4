#!/bin/sh
# The export dialog makes the image the viewport shows, under Xvfb with real input (xdotool), on
# presets/kifs_coloured_lights.json (three coloured sphere lights, path-traced):
# - the Render tab's render mode clicked to "Path traced at rest"; F12: the dialog's render mode is
#   Path traced, with the viewport's samples (the view's path sample cap), its command carries
#   `--mode path`, and it names the preset's 3 sphere lights;
# - samples ctrl+clicked and typed (4), Denoise clicked, the File field typed, Render clicked: the
#   job ends Done naming the two files it wrote, which exist; the EXR holds the path tracer's layers
#   (diffuse_direct, emission: only `--mode path` writes them) and the PNG is in the lights'
#   colours, where the fast renderer's still of the same preset is near grey;
# - the PNG removed: the dialog no longer says Done; typing more into the File field (a file that
#   does not exist): no Done either; the dialog's combo clicked to Fast: the command loses
#   `--mode path` and the dialog says the fast renderer leaves the lights out.
# Usage: editor_export_mode_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)
out=$3
mkdir -p "$out"
preset="$presets/kifs_coloured_lights.json"

rect() { q ".widgets[\"$1\"] | tojson"; }
# ctrl_click WIDGET: a drag field turns into a text field.
ctrl_click() { ctrl_click_at $(centre "$1"); }
ex() { q ".exportDialog.$1"; }

start "$preset" --tab Render --export-size 96x54
set -- $(viewport_centre)
to "$1" "$2"
wait_frames 2
pick 1 "$(q '.viewportRender.modeCombo | tojson')"
[ "$(q .viewportRender.mode)" = path ] || fail "the Render tab's combo left the viewport in the $(q .viewportRender.mode) mode"
cap=$(q .viewportRender.pathSppCap)

set -- $(viewport_centre)
to "$1" "$2"
xdotool key F12
wait_for .exportDialog.shown true
[ "$(ex shown)" = true ] || fail "F12 showed no export dialog"
echo "dialog: mode $(ex mode), $(ex spp) spp; $(ex command)"
echo "dialog: $(ex lights)"
[ "$(ex mode)" = path ] || fail "the export dialog's mode is $(ex mode), the viewport path-traces"
[ "$(ex spp)" = "$cap" ] || fail "the export's samples are $(ex spp), the viewport accumulates $cap"
case "$(ex command)" in *"--mode path"*) ;; *) fail "the command has no --mode path: $(ex command)" ;; esac
case "$(ex lights)" in *"3 sphere lights"*) ;; *) fail "the dialog does not name the 3 sphere lights: $(ex lights)" ;; esac

# Samples: ctrl+click, type 4, Enter. Denoise: a click.
wait_for '.widgets["export:Samples per pixel"] != null' true
ctrl_click "export:Samples per pixel"
xdotool key ctrl+a
wait_frames 1
xdotool type --delay 30 4
xdotool key Return
wait_for .exportDialog.spp 4
[ "$(ex spp)" = 4 ] || fail "typing 4 left the samples at $(ex spp)"
click "export:Denoise"
[ "$(ex denoise)" = true ] || fail "the click left Denoise off"
case "$(ex command)" in *"--spp 4 --mode path --denoise"*) ;; *) fail "the command is not the one chosen: $(ex command)" ;; esac

# The file: a click in the field, everything selected, the new path typed.
still="$home/kifs_path"
click "export:File"
xdotool key ctrl+a
wait_frames 1
xdotool type --delay 10 "$still"
wait_frames 2
[ "$(ex output)" = "$still" ] || fail "typing the file left '$(ex output)'"
click "export:Render"
t0=$(date +%s)
tries=0
while [ "$(ex status)" = running ] && [ $tries -lt 3000 ]; do sleep 0.2; tries=$((tries + 1)); done
echo "export: $(ex status) after $(($(date +%s) - t0)) s: $(ex statusText)"
[ "$(ex status)" = done ] || fail "the export ended $(ex status): $(ex statusText)"
[ "$(ex statusText)" = "Done: $still.exr and $still.png (path traced, 4 spp)." ] ||
    fail "the Done line is '$(ex statusText)'"
[ -f "$still.exr" ] && [ -f "$still.png" ] || fail "the files it names are not there"
import -window root "$out/export_dialog_done.png"
layers=$(exrheader "$still.exr" 2>/dev/null | grep -c -E 'diffuse_direct\.R|emission\.R' || true)
[ "$layers" = 2 ] || fail "the EXR has no path tracer layers (diffuse_direct, emission): not rendered with --mode path"
cp "$still.png" "$out/export_path.png"
"$fraktal" render "$preset" -o "$home/fast.exr" --png "$out/export_fast.png" --size 96x54 --spp 4 -q
# Mean chroma (HCL): the red, green and blue lights colour the path-traced image (measured: 0.20),
# the fast renderer's is near grey (0.015).
chroma() { convert "$1" -colorspace HCL -channel G -separate +channel -format '%[fx:mean]' info:; }
path_chroma=$(chroma "$out/export_path.png")
fast_chroma=$(chroma "$out/export_fast.png")
echo "mean chroma: the dialog's export $path_chroma, the fast renderer's still $fast_chroma"
check "$path_chroma > 4 * $fast_chroma && $path_chroma > 0.1" || fail "the export is not the coloured, path-traced image"

# Done only while the files it wrote are there, and only for them.
rm "$still.png"
wait_frames 3
case "$(ex statusText)" in Done*) fail "Done shown for a removed file: $(ex statusText)" ;; esac
echo "PNG removed: $(ex statusText)"
click "export:File"
xdotool key End
xdotool type --delay 10 "_second"
wait_frames 3
[ "$(ex output)" = "${still}_second" ] || fail "typing at the field's end left '$(ex output)'"
[ ! -e "${still}_second.exr" ] || fail "${still}_second.exr exists"
case "$(ex statusText)" in *Done*) fail "the field edited: the dialog says '$(ex statusText)'" ;; esac
echo "File field edited: $(ex status), '$(ex statusText)'"

# The dialog's own combo back to Fast.
pick 0 "$(rect "export:Render mode")"
[ "$(ex mode)" = fast ] || fail "the clicks on the dialog's combo left the $(ex mode) mode"
case "$(ex command)" in *"--mode"*) fail "the fast mode's command has --mode: $(ex command)" ;; esac
case "$(ex lights)" in "The fast renderer leaves out the preset's 3 sphere lights"*) ;; *) fail "no lights warning in the fast mode: $(ex lights)" ;; esac
echo "fast: $(ex command)"
stop

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
