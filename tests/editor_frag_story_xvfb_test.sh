#!/bin/sh
# A Fragmentarium frag in the editor as a new artist meets it, under Xvfb with real input
# (xdotool): a frag dropped on the window, one of its sliders dragged, a still exported.
# - the drop (tests/data/frag_import/menger.frag: a DE with its own loop and helper functions,
#   MathUtils' rotation, sliders in two groups, a checkbox, DE-Raytracer's settings and a camera in
#   its Default preset) opens the frag as a document of its own: the status line names
#   Fragmentarium and no error, the frag's DE is the formula's one node (a whole-DE block), every
#   uniform the DE code reads is a parameter widget of the panel, and the values are those of its
#   Default preset, which FragM applies on load;
# - the viewport draws the object (pixels that are not the sky's colour);
# - the Scale slider dragged by hand: the value moves, one undo step, and the object in the
#   viewport changes with it;
# - F12, a file typed, Render: the job ends Done naming two files that exist; the EXR carries the
#   edited preset (its header), whose Scale is the dragged value, and the PNG shows the object;
# - the Formula panel's "Frag preset" combo lists the frag's #presets with Default applied; its
#   row "Twisted" clicked: that preset's values (Twist on, Iterations, Angle) and its camera (Eye)
#   are the document's, one undo step, and Ctrl+Z takes the values back.
# X test tools cannot drag files, so the drop goes through --replay-drops, which hands the path to
# the window's GLFW drop callback, the function a real drop calls.
# Usage: editor_frag_story_xvfb_test.sh FRAKTAL PRESET_DIR FRAG OUT_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$(cd "$2" && pwd)
frag=$(cd "$(dirname "$3")" && pwd)/$(basename "$3")
out=$4
mkdir -p "$out"

ex() { q ".exportDialog.$1"; }
# The viewport's pixels as the screen shows them.
grab_viewport() {
    set -- "$1" $(q '.viewport | map(floor) | "\(.[2])x\(.[3])+\(.[0])+\(.[1])"')
    import -window "$window" -crop "$2" +repage "$1"
}
# Pixels of the middle half of image $1 (the object is in the middle; the letterbox bars of the
# render's aspect are outside it) that are not the sky: unlike the corner's colour by over 5 %.
object_pixels() {
    convert "$1" -gravity center -crop 50%x50%+0+0 +repage "$1.middle.png"
    sky=$(convert "$1.middle.png" -format '%[pixel:p{0,0}]' info:)
    convert "$1.middle.png" -fuzz 5% -fill black -opaque "$sky" -fill white +opaque black -format '%[fx:mean*w*h]' info: |
        awk '{ printf "%d", $1 }'
}

start "$presets/mandelbulb.json" --replay-drops "$drops" --export-size 96x54
drop "$frag"
wait_for '.document.formula.customBlocks | length' 1 100
echo "drop $(basename "$frag"): $(q .status.text)"
[ "$(q .status.error)" = false ] || fail "the dropped frag shows an error: $(q .status.text)"
case "$(q .status.text)" in "Imported $(basename "$frag") (Fragmentarium)"*) ;; *) fail "the status line does not say a Fragmentarium file was imported" ;; esac
[ "$(q '.document.formula.nodes | length')" = 1 ] || fail "the frag's formula has steps besides its DE"
block=$(q '.document.formula.nodes[0].block')
[ "$(q '.document.formula.customBlocks[0].id')" = "$block" ] || fail "the formula's node ($block) is not the frag's own block"
[ "$(q '.document.formula.customBlocks[0].wholeDE')" = true ] || fail "the frag's DE is not a whole-DE block"
# Every uniform the frag's code reads (its name outside its declaration and the presets) is a
# widget of the panel; a vec4 is two, its xyz and its w.
wait_for '.paramWidgets | length > 0' true 60
names=" $(q '[.paramWidgets[].name] | join(" ")') "
echo "parameter widgets:$names"
code=$(sed -e '/^#preset/,/^#endpreset/d' -e '/^uniform /d' "$frag")
for uniform in $(sed -n 's/^uniform [a-z0-9]* \([A-Za-z0-9_]*\);.*\(slider\|color\|checkbox\|menu\)\[.*/\1/p' "$frag"); do
    echo "$code" | grep -q -w "$uniform" || continue
    case "$names" in *" $uniform "*) ;; *) fail "the frag's uniform $uniform, which its DE reads, has no widget" ;; esac
done
# A parameter's value: the node's, or its block's default where the node keeps the default.
param() { q "(.document.formula.nodes[0].params.$1) // (.document.formula.customBlocks[0].params[] | select(.name == \"$1\") | .default)"; }
preset_value() { sed -n "/^#preset Default/,/^#endpreset/s/^$1 = \([-0-9.]*\).*/\1/p" "$frag"; }
for name in Iterations Scale; do
    check "$(param $name) == $(preset_value $name)" ||
        fail "$name is $(param $name), the frag's Default preset says $(preset_value $name)"
done
wait_settled
grab_viewport "$out/frag_dropped.png"
o0=$(object_pixels "$out/frag_dropped.png")
echo "object pixels in the viewport after the drop: $o0"
[ "$o0" -gt 1000 ] || fail "the viewport shows no object ($o0 pixels)"

# The Scale slider dragged to the right, a frame a step, as a hand drags it.
set -- $(widget_centre Scale)
[ $# -eq 2 ] || { fail "the state file records no widget for Scale"; set -- 150 477; }
drag_frames "$1" "$2" 60 0 6
wait_frames 3
dragged=$(param Scale)
echo "Scale after the drag: $dragged, undo: $(q .undoLabel)"
check "$dragged > $(preset_value Scale)" || fail "the drag left Scale at $dragged"
[ "$(q .undoDepth)" = 1 ] || fail "the drag made $(q .undoDepth) undo steps"
wait_settled
grab_viewport "$out/frag_dragged.png"
o_dragged=$(object_pixels "$out/frag_dragged.png")
changed=$(compare -metric AE -fuzz 5% "$out/frag_dropped.png.middle.png" "$out/frag_dragged.png.middle.png" null: 2>&1 || true)
echo "viewport pixels changed by the drag: $changed (the object covered $o0)"
check "$changed > $o0 / 4" || fail "the object in the viewport did not change with the slider ($changed pixels)"

# F12, the file typed, Render.
set -- $(viewport_centre)
to "$1" "$2"
xdotool key F12
wait_for .exportDialog.shown true
[ "$(ex shown)" = true ] || fail "F12 showed no export dialog"
wait_frames 5  # the dialog sizes itself to its contents in its first frames
still="$home/frag_still"
click "export:File"
press_keys ctrl a
xdotool type --delay 10 "$still"
wait_for .exportDialog.output "$still"
[ "$(ex output)" = "$still" ] || { import -window root "$out/export_field.png"; fail "typing the file left '$(ex output)'"; }
click "export:Render"
tries=0
while [ "$(ex status)" = running ] && [ $tries -lt 3000 ]; do sleep 0.2; tries=$((tries + 1)); done
echo "export: $(ex status): $(ex statusText)"
[ "$(ex status)" = done ] || fail "the export ended $(ex status): $(ex statusText)"
case "$(ex statusText)" in "Done: $still.exr and $still.png"*) ;; *) fail "the Done line is '$(ex statusText)'" ;; esac
[ -f "$still.exr" ] && [ -f "$still.png" ] || fail "the files it names are not there"

# The frag's presets: the combo lists them, Default applied; "Twisted" picked from it.
xdotool key Escape
wait_frames 3
[ "$(q '.fragPresets.names | join(",")')" = "$(sed -n 's/^#preset //p' "$frag" | paste -sd,)" ] ||
    fail "the combo lists '$(q '.fragPresets.names | join(",")')', the frag's presets are $(sed -n 's/^#preset //p' "$frag" | paste -sd,)"
[ "$(q .fragPresets.applied)" = Default ] || fail "the preset applied on opening is '$(q .fragPresets.applied)'"
twisted_row=$(sed -n 's/^#preset //p' "$frag" | grep -n -x Twisted | cut -d: -f1)
undo_before=$(q .undoDepth)
pick $((twisted_row - 1)) "$(q '.widgets["combo:Frag preset"] | tojson')"
wait_for .fragPresets.applied Twisted
twisted_value() { sed -n "/^#preset Twisted/,/^#endpreset/s/^$1 = \([-0-9.,a-z]*\).*/\1/p" "$frag"; }
echo "after picking Twisted: $(q .status.text); Twist $(param Twist), Iterations $(param Iterations), Angle $(param Angle); camera $(camera)"
[ "$(q .fragPresets.applied)" = Twisted ] || fail "picking Twisted left '$(q .fragPresets.applied)' applied"
case "$(param Twist)" in 1 | true) ;; *) fail "Twisted sets Twist on; it is $(param Twist)" ;; esac
check "$(param Iterations) == $(twisted_value Iterations)" || fail "Iterations is $(param Iterations), Twisted says $(twisted_value Iterations)"
check "$(param Angle) == $(twisted_value Angle)" || fail "Angle is $(param Angle), Twisted says $(twisted_value Angle)"
[ "$(camera | awk '{ printf "%g,%g,%g", $1, $2, $3 }')" = "$(twisted_value Eye)" ] || fail "the camera is at $(camera), Twisted's Eye is $(twisted_value Eye)"
[ "$(q .undoDepth)" = $((undo_before + 1)) ] || fail "the preset made $(($(q .undoDepth) - undo_before)) undo steps"
press_keys ctrl z
wait_frames 3
case "$(param Twist)" in 0 | false) true ;; *) false ;; esac && check "$(param Iterations) == $(preset_value Iterations)" ||
    fail "Ctrl+Z left Twist $(param Twist), Iterations $(param Iterations)"
stop
cp "$still.png" "$out/frag_export.png"
o1=$(object_pixels "$still.png")
echo "object pixels in the exported still: $o1"
[ "$o1" -gt 200 ] || fail "the exported still shows no object ($o1 pixels)"
# The EXR's header carries the preset it was rendered from: the edited one, as `fraktal edit`
# opens it (a drop of the EXR opens that preset).
exrheader "$still.exr" >"$home/header.txt" 2>/dev/null || true
grep -q "$block" "$home/header.txt" || fail "the EXR's header does not carry the frag's block"
written=$(grep -o '"Scale": *[-0-9.e]*' "$home/header.txt" | head -1 | sed 's/.*: *//')
echo "Scale in the EXR's preset: $written"
check "${written:-0} == $dragged" || fail "the EXR's preset has Scale ${written:-none}, the dragged value is $dragged"

[ $failures = 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
