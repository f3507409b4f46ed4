#!/bin/sh
# File > Export mesh... meshes the document for printing, under Xvfb with real input (xdotool), on
# presets/menger.json:
# - the File menu clicked, then its Export mesh... item: the dialog shows, idle, its status line
#   grey (no pixel of it in the Done colour);
# - the File field typed (a .ply), the resolution ctrl+clicked and typed (32), the print size typed
#   (120): the command carries `--resolution 32 --print-size 120mm` and the dialog gives the voxel
#   size; the Format list picked to OpenVDB: the file becomes .vdb and the command loses the print
#   size; picked back to PLY; Remove cavities clicked: the command carries `--remove-cavities`;
# - Export clicked: the job ends Done (the state file), the file exists and is a PLY (its header),
#   in millimetres, and the status line on screen turns to the Done colour;
# - the PLY removed: the dialog no longer says Done;
# - File > New 2D (Ctrl+Shift+N): the dialog shows, in red, that a 2D document has nothing to
#   mesh, and its Export button does nothing.
# Usage: editor_export_mesh_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)
out=$3
mkdir -p "$out"
me() { q ".meshExportDialog.$1"; }
# colour_share SCREENSHOT WIDGET RGB: the share of WIDGET's rect (the state file's) in the colour
# RGB. The dialog's colours (export_widgets.cpp): Done (0.5, 0.9, 0.5), an error (1, 0.45, 0.4).
colour_share() {
    set -- "$1" "$3" $(q ".widgets[\"$2\"] | map(floor) | join(\" \")")
    convert "$1" -crop "$5x$6+$3+$4" +repage -fuzz 12% -fill black +opaque "$2" -fill white -opaque "$2" \
        -colorspace Gray -format "%[fx:mean]" info:
}
done_colour="rgb(128,230,128)"
error_colour="rgb(255,115,102)"

start "$presets/menger.json"
click menu:File
click "menu:File/Export mesh..."
wait_for .meshExportDialog.shown true
[ "$(me shown)" = true ] || fail "File > Export mesh... showed no dialog"
[ "$(me status)" = idle ] || fail "the new dialog's job is $(me status)"
wait_for '.widgets["meshExport:Status"] != null' true
import -window "$window" "$out/mesh_dialog_idle.png"
before=$(colour_share "$out/mesh_dialog_idle.png" meshExport:Status "$done_colour")
echo "idle: '$(me statusText)', $before of its status line in the Done colour"
check "$before < 0.002" || fail "the idle dialog's status line shows the Done colour ($before)"

# The file: a click in the field, everything selected, the path typed.
mesh="$home/sponge.ply"
click meshExport:File
press_keys ctrl a
wait_frames 1
xdotool type --delay 10 "$mesh"
wait_frames 2
[ "$(me output)" = "$mesh" ] || fail "typing the file left '$(me output)'"
[ "$(me format)" = .ply ] || fail "the format of $mesh is '$(me format)'"
# The resolution: ctrl+click, type 32, Enter.
ctrl_click_at $(centre meshExport:Resolution)
press_keys ctrl a
wait_frames 1
xdotool type --delay 30 32
xdotool key Return
wait_for .meshExportDialog.resolution 32
[ "$(me resolution)" = 32 ] || fail "typing 32 left the resolution at $(me resolution)"
case "$(me command)" in *"-o $mesh --resolution 32"*) ;; *) fail "the command is not the one chosen: $(me command)" ;; esac
check "$(me voxel) > 0" || fail "no voxel size for the resolution: $(me voxel)"
# The print size, typed in millimetres.
click "meshExport:Print size"
xdotool type --delay 30 120
wait_for .meshExportDialog.printSizeMm 120
[ "$(me printSizeMm)" = 120 ] || fail "typing 120 left the print size '$(me printSizeMm)'"
case "$(me command)" in *"--resolution 32 --print-size 120mm") ;; *) fail "no --print-size 120mm: $(me command)" ;; esac
# The Format list: the level set changes the file's extension and takes no print size; PLY again.
pick 4 "$(q '.widgets["meshExport:Format"] | tojson')"
[ "$(me output)" = "$home/sponge.vdb" ] || fail "the OpenVDB format left the file '$(me output)'"
case "$(me command)" in *--print-size*) fail "a level set with a print size: $(me command)" ;; esac
pick 0 "$(q '.widgets["meshExport:Format"] | tojson')"
[ "$(me output)" = "$mesh" ] || fail "the PLY format left the file '$(me output)'"
# Remove cavities: a click.
click "meshExport:Remove cavities"
[ "$(me removeCavities)" = true ] || fail "the click left Remove cavities off"
case "$(me command)" in *"--print-size 120mm --remove-cavities") ;; *) fail "no --remove-cavities: $(me command)" ;; esac
echo "dialog: voxel $(me voxel); $(me command)"

click meshExport:Export
t0=$(date +%s)
tries=0
while [ "$(me status)" = running ] && [ $tries -lt 300 ]; do sleep 0.2; tries=$((tries + 1)); done
echo "export: $(me status) after $(($(date +%s) - t0)) s: $(me statusText)"
[ "$(me status)" = done ] || fail "the export ended $(me status): $(me statusText)"
[ "$(me outputsExist)" = true ] || fail "the state file says the file is not there"
[ -f "$mesh" ] || fail "$mesh is not there"
[ "$(head -c 3 "$mesh" 2>/dev/null)" = ply ] || fail "$mesh is not a PLY: $(head -c 16 "$mesh" | od -c | head -1)"
case "$(me statusText)" in "Done: $mesh"*" mm "*) ;; *) fail "the Done line is '$(me statusText)'" ;; esac
wait_frames 3
import -window "$window" "$out/mesh_dialog_done.png"
after=$(colour_share "$out/mesh_dialog_done.png" meshExport:Status "$done_colour")
echo "done: $after of its status line in the Done colour"
check "$after > 0.01" || fail "the screen shows no Done line in the dialog ($after)"

# Done only while the file it wrote is there.
rm "$mesh"
wait_frames 3
case "$(me statusText)" in Done*) fail "Done shown for a removed file: $(me statusText)" ;; esac
echo "PLY removed: $(me statusText)"

# A 2D document (File > New 2D): nothing to mesh; the dialog says so on screen, in the error colour.
press_keys ctrl shift n
wait_for .meshExportDialog.available false
[ "$(me available)" = false ] || fail "Ctrl+Shift+N left a document the mesh export takes"
case "$(me optionsError)" in *"2D document"*) ;; *) fail "the dialog gives no reason for a 2D document: '$(me optionsError)'" ;; esac
wait_frames 3
import -window "$window" "$out/mesh_dialog_2d.png"
red=$(colour_share "$out/mesh_dialog_2d.png" meshExport:Error "$error_colour")
echo "2D: '$(me optionsError)', $red of its line in the error colour"
check "$red > 0.02" || fail "the dialog shows no reason for the 2D document ($red)"
click meshExport:Export
[ "$(me status)" != running ] || fail "Export ran for a 2D document"
stop

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
