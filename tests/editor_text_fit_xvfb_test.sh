#!/bin/sh
# Text that fits, at 1280x800 and at 1920x1080, under Xvfb with real input (xdotool): on the
# Mandelbulb with a fresh config (the default layout), the Formula panel and each of the Scene
# panel's tabs clicked in turn, then the shortcut help (F1), then the export dialog (F12) with its
# command and log opened. After each step the state file's clippedText, every label, line of text,
# table cell and combo choice the editor cut at the edge of its window, cell or box
# (app/editor/widgets/text_fit.hpp), must be empty. The Presets tab's thumbnails scroll in their own
# region: the wheel over them moves the thumbnails and leaves the tab bar where it was.
# Usage: editor_text_fit_xvfb_test.sh FRAKTAL PRESET_DIR
set -eu
xvfb_screen=1920x1080x24 . "$(dirname "$0")/editor_xvfb_helpers.sh"
fraktal=$1
presets=$2

# expect_fits WHAT: fails, listing them, when the last frame cut any text.
expect_fits() {
    wait_frames 3
    cut=$(q '.clippedText | map("\(.window): \(.text) (\(.hidden | floor) px)") | join("; ")')
    if [ -n "$cut" ]; then fail "$size, $1: text cut: $cut"; else echo "$size, $1: nothing cut"; fi
}

for size in 1280x800 1920x1080; do
    rm -rf "$XDG_CONFIG_HOME"
    start "$presets/mandelbulb.json"
    if [ "$size" != 1280x800 ]; then
        xdotool windowsize "$window" ${size%x*} ${size#*x}
        wait_for '.window.size | join("x")' "$size"
    fi
    [ "$(q '.window.size | join("x")')" = "$size" ] || fail "the window is $(q '.window.size | join("x")'), not $size"
    for tab in Camera Render Shading Lights Presets; do
        click "tab:$tab"
        [ "$(q .sceneTab)" = "$tab" ] || fail "$size: clicking the $tab tab shows $(q .sceneTab)"
        expect_fits "Formula panel and the $tab tab"
    done
    # The thumbnails scroll under the tab bar: the wheel over them keeps the tabs in place.
    tabs=$(q '.widgets["tab:Presets"][1]')
    thumbs=$(q '.widgets["child:Presets thumbnails"] | tojson')
    first=$(q '.widgets["thumbnail:1"][1]')
    [ "$thumbs" != null ] || fail "$size: the Presets tab draws no thumbnail region"
    if [ "$thumbs" != null ]; then
        wheel_over "child:Presets thumbnails" 5
        [ "$(q '.widgets["tab:Presets"][1]')" = "$tabs" ] ||
            fail "$size: scrolling the thumbnails moved the tab bar from y $tabs to $(q '.widgets["tab:Presets"][1]')"
        check "$(q '.widgets["thumbnail:1"][1]') < $first" ||
            fail "$size: the wheel over the thumbnails left the first at y $first"
    fi
    set -- $(viewport_centre)
    to "$1" "$2"
    wait_frames 2
    xdotool key F1
    wait_for .shortcutHelp true
    [ "$(q .shortcutHelp)" = true ] || fail "$size: F1 did not open the shortcut help"
    expect_fits "shortcut help"
    xdotool key F1
    wait_for .shortcutHelp false
    xdotool key F12
    wait_for .exportDialog.shown true
    [ "$(q .exportDialog.shown)" = true ] || fail "$size: F12 did not open the export dialog"
    expect_fits "export dialog"
    click "export:Command and log"
    expect_fits "export dialog with its command and log"
    stop
done

[ $failures -eq 0 ] && echo "editor_text_fit_xvfb_test: all OK" || { echo "editor_text_fit_xvfb_test: $failures failure(s)"; exit 1; }
