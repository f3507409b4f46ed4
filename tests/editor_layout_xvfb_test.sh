#!/bin/sh
# The editor's layout at 1280x800, driven with real X input (xdotool) under Xvfb: the viewport is
# a landscape rectangle of at least 60 % of the window; the side column's edge resizes it;
# Ctrl+Backslash and the menu bar's arrow fold the column away (the viewport takes the width) and
# back; the column's width, its folded state and the window's size come back after a restart
# (the ini in $XDG_CONFIG_HOME/fraktal). A parameter's slider, hovered, shows its block's help
# text as a tooltip: the pixels under it change and the state file's "tooltip" is the help text
# of the parameter's declaration. An on/off parameter is a checkbox: one click on Add c's julia
# flips it, and one Ctrl+Z flips it back.
# Usage: editor_layout_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1920x1080x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

viewport() { q '.viewport | map(floor) | join(" ")'; }
# The help text a block's declaration gives parameter NAME (a ParamDecl or toggleParam line):
# declared_help FILE NAME (formulas/*.hpp).
declared_help() { sed -n "s/.*\\(ParamDecl{\\|toggleParam(\\)\"$2\", .*, \"\\([^\"]*\\)\"[})],\$/\\2/p" "$1"; }

start "$presets/mandelbulb.json"
[ "$(q '.window.size | join("x")')" = 1280x800 ] || fail "the first window is $(q '.window.size | join("x")'), not 1280x800"
set -- $(viewport)
echo "default viewport: $3 x $4 at $1,$2 in 1280x800"
check "$3 > $4" || fail "the default viewport is not landscape ($3 x $4)"
check "$3 * $4 >= 0.6 * 1280 * 800" || fail "the default viewport covers less than 60 % of the window ($3 x $4)"
default_x=$1
# The tooltip: the region right of and below the power slider changes when the pointer rests on it
# (where the slider is: the state file's record of it, so that a row added above moves nothing here).
set -- $(widget_centre power)
[ $# -eq 2 ] || { fail "the state file records no widget for the power parameter"; set -- 150 477; }
region=420x140+$1+$(($2 + 8))
to 700 400
wait_frames 2
import -window root "$home/no_tooltip.png"
to "$1" "$2"
wait_frames 5
import -window root "$home/tooltip.png"
for f in no_tooltip tooltip; do convert "$home/$f.png" -crop "$region" +repage "$home/$f.crop.png"; done
changed=$(compare -metric AE "$home/no_tooltip.crop.png" "$home/tooltip.crop.png" null: 2>&1 || true)
echo "tooltip: $changed pixels changed under the hovered power slider"
check "${changed:-0} > 2000" || fail "hovering the power slider showed no tooltip ($changed pixels changed)"
# Its text: the widget records the help it showed; it must be the declaration's, word for word.
help=$(declared_help "$presets/../formulas/mandelbulb.hpp" power)
[ -n "$help" ] || fail "no help text found for power in formulas/mandelbulb.hpp"
set -- $(widget_centre power)
[ $# -eq 2 ] || { fail "the state file records no widget for the power parameter"; set -- 0 0; }
to "$1" "$2"
wait_frames 3
[ "$(q .tooltipParam)" = power ] || fail "hovering the power slider at $1,$2 showed the tooltip of '$(q .tooltipParam)'"
[ "$(q .tooltip)" = "$help" ] || fail "the power slider's tooltip reads '$(q .tooltip)', not the declaration's '$help'"
echo "tooltip text: $(q .tooltip)"
to 700 400
wait_frames 2
[ -z "$(q .tooltip)" ] || fail "the tooltip '$(q .tooltip)' stays with the pointer off the slider"
# The column's right edge (ImGui's resize border) dragged 80 px to the right.
drag_frames $((default_x - 1)) 300 80 0 4
wait_frames 2
width=$(q '.panels.columnWidth | floor')
check "$width >= $default_x + 60" || fail "dragging the column's edge did not widen it ($default_x -> $width)"
set -- $(viewport)
[ "$1" = "$width" ] || fail "the viewport does not start at the column's edge ($1 vs $width)"
# Fold away with the keys (cursor over the viewport), back with the arrow in the menu bar.
to 800 400
xdotool key ctrl+backslash
wait_frames 2
set -- $(viewport)
[ "$(q .panels.collapsed)" = true ] || fail "Ctrl+Backslash did not fold the side column"
[ "$1" = 0 ] && [ "$3" = 1280 ] || fail "with the column folded the viewport is $3 x $4 at $1, not the full width"
# A press and a release a frame apart, as a hand's click at this machine's frame rate.
click_frames() { xdotool mousedown 1; wait_frames 1; xdotool mouseup 1; }
to 196 10
wait_frames 1
click_frames
wait_frames 2
set -- $(viewport)
[ "$(q .panels.collapsed)" = false ] || fail "the menu bar's arrow did not bring the column back"
[ "$1" = "$width" ] || fail "the column came back at $1, not $width"
click_frames
wait_frames 2
[ "$(q .panels.collapsed)" = true ] || fail "a second click on the arrow did not fold the column"
xdotool windowsize "$window" 1100 700
wait_frames 3
[ "$(q '.window.size | join("x")')" = 1100x700 ] || fail "after xdotool windowsize the window is $(q '.window.size | join("x")')"
xdotool key ctrl+q
wait "$pid" || fail "the editor did not quit cleanly"
pid=
[ -f "$XDG_CONFIG_HOME/fraktal/editor.ini" ] || fail "no ini in \$XDG_CONFIG_HOME/fraktal"

start "$presets/mandelbulb.json"
[ "$(q '.window.size | join("x")')" = 1100x700 ] || fail "the window came back at $(q '.window.size | join("x")'), not 1100x700"
[ "$(q .panels.collapsed)" = true ] || fail "the folded column came back unfolded"
set -- $(viewport)
[ "$3" = 1100 ] || fail "after the restart the folded column's viewport is $3 wide, not 1100"
to 600 400
xdotool key ctrl+backslash
wait_frames 2
[ "$(q '.panels.columnWidth | floor')" = "$width" ] || fail "the column came back $(q '.panels.columnWidth') wide, not $width"
echo "restart: window $(q '.window.size | join("x")'), column $(q '.panels.columnWidth') wide, viewport $(viewport)"
stop

# On/off parameters are checkboxes: Add c's julia in the Juliabulb (node 2; on in the preset),
# at the default layout (a fresh config).
rm -rf "$XDG_CONFIG_HOME"
start "$presets/juliabulb.json"
julia() { q '.document.formula.nodes[1].params.julia // false'; }
[ "$(q '.document.formula.nodes[1].block')" = add_c ] || fail "node 2 of juliabulb.json is not add_c"
[ "$(julia)" = true ] || fail "juliabulb.json does not load with julia on ($(julia))"
to 100 262
wait_frames 1
click_frames
wait_frames 2
[ "$(q .selectedNode)" = 1 ] || fail "clicking the second row of the node list selected node $(q .selectedNode)"
# The Formula panel scrolled to its end, so that Add c's last parameters are in full view.
to 150 400
xdotool click --repeat 10 --delay 30 5
wait_frames 3
set -- $(widget_centre julia)
[ $# -eq 2 ] || { fail "the state file records no widget for Add c's julia"; set -- 0 0; }
to "$1" "$2"
wait_frames 2
[ "$(q .tooltip)" = "$(declared_help "$presets/../formulas/add_c.hpp" julia)" ] ||
    fail "the julia checkbox's tooltip reads '$(q .tooltip)'"
depth=$(q .undoDepth)
click_frames
wait_frames 3
[ "$(julia)" = false ] || fail "a click on the julia checkbox at $1,$2 left it $(julia)"
[ "$(q .undoDepth)" = $((depth + 1)) ] || fail "a click on the checkbox made $(($(q .undoDepth) - depth)) undo steps, not 1"
echo "julia checkbox: off after a click, undo label '$(q .undoLabel)'"
echo "$(q .undoLabel)" | grep -q julia || fail "the undo label '$(q .undoLabel)' does not name julia"
to 800 400
wait_frames 1
xdotool key ctrl+z
wait_frames 3
[ "$(julia)" = true ] || fail "Ctrl+Z after the click left julia $(julia)"
[ "$(q .undoDepth)" = "$depth" ] || fail "one Ctrl+Z went from $((depth + 1)) to $(q .undoDepth) undo steps"
stop

[ $failures -eq 0 ] && echo "editor_layout_xvfb_test: all OK" || { echo "editor_layout_xvfb_test: $failures failure(s)"; exit 1; }
