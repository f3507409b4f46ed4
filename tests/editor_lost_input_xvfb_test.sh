#!/bin/sh
# No lost input, at the default 1280x800 window, with real X input (xdotool) under Xvfb:
# 1. Escape closes the menu or popup in front (the Edit menu, the Render tab's mode combo, the Add
#    object popup): the state file says no popup is open, the screen where it was shows the panel
#    again, and the very next click (a Scene tab) takes effect.
# 2. The split between the Formula and the Scene panel drags on the first press, just above and
#    just below the line, after a click in the Scene panel has brought that panel's focus.
# 3. In a scrolled Formula panel, selecting a node whose parameters take less room leaves the
#    rows where they were, on the screen too, and the next click selects the row aimed at.
# Usage: editor_lost_input_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
. "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

shot() { import -window root "$home/$1.png"; }
# differ A B GEOMETRY: how many pixels of GEOMETRY (WxH+X+Y) differ between screenshots A and B.
differ() {
    convert "$home/$1.png" -crop "$3" +repage "$home/$1.crop.png"
    convert "$home/$2.png" -crop "$3" +repage "$home/$2.crop.png"
    compare -metric AE "$home/$1.crop.png" "$home/$2.crop.png" null: 2>&1 || true
}
# The rectangle of widget NAME as WxH+X+Y, grown by PAD pixels on each side.
geometry() { q ".widgets[\"$1\"] | map(floor) | \"\\(.[2] + 2 * $2)x\\(.[3] + 2 * $2)+\\(.[0] - $2)+\\(.[1] - $2)\""; }

# --- 1. Escape, then one click ---
start "$presets/mandelbulb.json"
# escape_then_click NAME OPENER REGION TAB: clicks OPENER (a widget the state file names), checks
# that a popup opened over REGION (WxH+X+Y), presses Escape, checks that it closed, then clicks
# the Scene tab TAB once.
escape_then_click() {
    set -- $(centre "$2") "$1" "$3" "$4"
    to "$1" "$2"
    wait_frames 2
    shot before
    xdotool mousedown 1
    wait_frames 1
    xdotool mouseup 1
    wait_for .popupOpen true 10
    wait_frames 2
    shot open
    opened=$(differ before open "$4")
    [ "$(q .popupOpen)" = true ] || fail "$3: no popup open after the click (state file)"
    check "$opened > 1000" || fail "$3: the popup did not show over $4 ($opened pixels changed)"
    xdotool key Escape
    wait_for .popupOpen false 10
    wait_frames 2
    shot closed
    left=$(differ before closed "$4")
    echo "$3: $opened pixels changed by the popup, $left left after Escape"
    [ "$(q .popupOpen)" = false ] || fail "$3: Escape left the popup open (state file)"
    check "$left < 100" || fail "$3: after Escape the popup still shows over $4 ($left pixels differ)"
    set -- $(centre "tab:$5") "$5" "$3"
    to "$1" "$2"
    wait_frames 1
    xdotool mousedown 1
    wait_frames 1
    xdotool mouseup 1
    wait_frames 3
    [ "$(q .sceneTab)" = "$3" ] && return
    fail "$4: the first click after Escape, on the $3 tab, was lost (in front: $(q .sceneTab))"
    # A second click, so that the next steps start from the tab they expect.
    click "tab:$3"
}
wait_for '.widgets["menu:Edit"] != null' true
# The Edit menu drops over the top of the Formula panel.
escape_then_click "Edit menu" menu:Edit 160x50+40+22 Render
wait_for '.widgets["Render mode"] != null' true
set -- $(q '.widgets["Render mode"] | map(floor) | join(" ")')
escape_then_click "Render mode combo" "Render mode" "${3}x40+${1}+$(($2 + $4 + 2))" Shading
# The Formula panel scrolled to its end, the Objects header opened there, scrolled to the end
# again: the Add object button in view.
scroll_formula() {
    to 150 300
    wait_frames 1
    xdotool click --repeat 12 --delay 30 "$1"
    wait_frames 4
}
scroll_formula 5
click header:Objects
scroll_formula 5
wait_for '.widgets["button:Add object"] != null' true
set -- $(q '.widgets["button:Add object"] | map(floor) | join(" ")')
escape_then_click "Add object popup" "button:Add object" "120x40+$(($1 + 4))+$(($2 + $4 + 4))" Lights
escape_then_click "Edit menu again" menu:Edit 160x50+40+22 Camera
stop

# --- 2. The split, after a click in the Scene panel ---
rm -rf "$XDG_CONFIG_HOME"  # the default layout, as each story starts from
start "$presets/mandelbulb.json"
# drag_split OFFSET: clicks the Render tab (the Scene panel clicked last), then drags from OFFSET
# pixels below the split (negative: above) 60 px up; the split must follow, on the screen too.
drag_split() {
    click tab:Render
    top=$(q '.viewport[1] | floor')
    h0=$(q '.panels.formulaHeight | floor')
    tab0=$(q '.widgets["tab:Render"][1] | floor')
    band=$(geometry tab:Render 0)
    shot split_before
    drag_frames 200 $((top + h0 + $1)) 0 -60 4
    wait_frames 3
    h1=$(q '.panels.formulaHeight | floor')
    # The Scene panel focused again, so that its tab is drawn as before, 60 px higher.
    click tab:Render
    tab1=$(q '.widgets["tab:Render"][1] | floor')
    shot split_after
    set -- $(q '.widgets["tab:Render"] | map(floor) | join(" ")') "$1"
    echo "split dragged from $5 px off the line: Formula panel $h0 -> $h1 px high, Render tab at y $tab0 -> $tab1"
    check "$h1 <= $h0 - 50 && $h1 >= $h0 - 70" || fail "a drag of the split from $5 px off it changed the Formula panel's height $h0 -> $h1, not by -60"
    [ "$tab1" -eq $((tab0 - 60)) ] || fail "the Scene panel's Render tab is at y $tab1 after the drag, not $((tab0 - 60))"
    convert "$home/split_before.png" -crop "$band" +repage "$home/tab_before.png"
    convert "$home/split_after.png" -crop "${band%%+*}+${1}+${2}" +repage "$home/tab_after.png"
    same=$(compare -metric AE "$home/tab_before.png" "$home/tab_after.png" null: 2>&1 || true)
    check "$same < 50" || fail "the screen does not show the Render tab 60 px higher ($same pixels differ)"
}
drag_split 2
drag_split -2
stop

# --- 3. A node selected in the scrolled Formula panel ---
# The first node, the tetrahedral KIFS, has the most parameters; the Menger fold (3) fewer.
rm -rf "$XDG_CONFIG_HOME"
start "$presets/hybrid_kifs_menger.json"
[ "$(q .selectedNode)" = 0 ] || fail "hybrid_kifs_menger.json opens with node $(q .selectedNode) selected, not 1"
# The split dragged 100 px down: scrolled to its end, the panel shows every row. The Formula
# panel's title bar is clicked first, so that the drag works with or without story 2's rule.
to 100 28
wait_frames 1
xdotool click 1
wait_frames 2
drag_frames 200 $(($(q '.viewport[1] + .panels.formulaHeight | floor') - 2)) 0 100 5
wait_frames 2
unscrolled=$(q '.widgets["row:estimator"][1] | floor')
scroll_formula 5
row_y() { q ".widgets[\"button:Del $1\"] // empty | .[1] + .[3] / 2 | floor"; }
est0=$(q '.widgets["row:estimator"][1] | floor')
y3=$(row_y 3)
y5=$(row_y 5)
[ -n "$y3" ] && [ -n "$y5" ] || { fail "the state file records no Del buttons of the node rows"; exit 1; }
echo "Formula panel $(q .panels.formulaHeight) px high, scrolled by $((unscrolled - est0)) px; rows 3 and 5 at y $y3, $y5"
check "$est0 < $unscrolled - 100" || fail "the Formula panel did not scroll (the estimator's row at y $unscrolled, then $est0)"
check "$y3 > 50" || fail "row 3 (y $y3) is not in view"
# The estimator's row on the screen, taken with the pointer over the viewport (a row's tooltip
# would cover it): the clicks below do not select it.
rows=$(geometry row:estimator 0)
set -- $(viewport_centre)
to "$1" "$2"
wait_frames 2
shot rows_before
to 120 "$y3"
wait_frames 1
xdotool mousedown 1
wait_frames 1
xdotool mouseup 1
wait_frames 2
set -- $(viewport_centre)
to "$1" "$2"
wait_frames 3
shot rows_after
est1=$(q '.widgets["row:estimator"][1] | floor')
moved=$(differ rows_before rows_after "$rows")
echo "selecting node 3 in the scrolled panel: estimator row at y $est0 -> $est1, $moved pixels changed under it"
[ "$(q .selectedNode)" = 2 ] || fail "the click at y $y3 selected node $(q .selectedNode), not 3"
[ "$est1" = "$est0" ] || fail "selecting node 3 moved the node list from y $est0 to $est1"
check "$moved < 50" || fail "selecting node 3 moved the rows on the screen ($moved pixels changed in $rows)"
# The next click, at the place node 5's row was, selects node 5.
to 120 "$y5"
wait_frames 1
xdotool mousedown 1
wait_frames 1
xdotool mouseup 1
wait_frames 3
[ "$(q .selectedNode)" = 4 ] || fail "the next click, at node 5's row (y $y5), selected node $(($(q .selectedNode) + 1))"
# Scrolling back up still reaches the top.
scroll_formula 4
check "$(q '.widgets["row:estimator"][1] | floor') > $est0" || fail "the panel does not scroll back up"
stop

[ "$failures" -eq 0 ] || { echo "editor_lost_input_xvfb_test: $failures failure(s)"; exit 1; }
echo "PASS editor_lost_input_xvfb_test"
