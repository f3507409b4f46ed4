#!/bin/sh
# Starts the real editor under Xvfb (Mesa llvmpipe) for every shipped preset (3D and 2D), draws a few
# frames, saves a screenshot of the whole window and checks it: the viewport (the middle of the
# window) is not blank, and the panels are drawn (the side column's Formula and Scene panels hold
# the panel background with text on it). The screenshots stay in OUT_DIR (a CI artifact).
# Usage: editor_xvfb_test.sh FRAKTAL PRESET_DIR OUT_DIR
set -eu
fraktal=$1
presets=$2
out=$3
mkdir -p "$out"
# A private HOME: the editor's ini and recent list must not leak in or out.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT

# Standard deviation (0..1) and mean of a region WxH+X+Y of a PNG, via ImageMagick.
stats() { convert "$1" -crop "$2" +repage -colorspace Gray -format "%[fx:standard_deviation] %[fx:mean]" info:; }
# Share of pixels in a region brighter than 60% (text on the dark panels).
bright() { convert "$1" -crop "$2" +repage -colorspace Gray -threshold 60% -format "%[fx:mean]" info:; }
check() { awk "BEGIN { exit !($1) }"; }

failures=0
# 3D presets, then the 2D ones (presets/2d: the editor switches to its 2D view and panels).
for preset in "$presets"/*.json "$presets"/2d/*.json; do
    name=$(basename "$preset" .json)
    case $preset in "$presets"/2d/*) name="2d_$name" ;; esac
    shot="$out/editor_$name.png"
    rm -f "$shot"
    if ! HOME="$home" xvfb-run -a -s "-screen 0 1280x800x24" "$fraktal" edit "$preset" --frames 3 --screenshot "$shot"; then
        echo "FAIL $name: the editor exited with an error"; failures=$((failures + 1)); continue
    fi
    size=$(identify -format "%wx%h" "$shot")
    [ "$size" = "1280x800" ] || { echo "FAIL $name: screenshot is $size, not 1280x800"; failures=$((failures + 1)); continue; }
    # The viewport lies right of the side column (x 360..1280 at the default layout, below the menu).
    set -- $(stats "$shot" 400x600+450+120)
    viewport_sd=$1
    # Panels: dark background (mean < 0.25) with some text (bright pixels) in both: Formula above
    # (y 21..520 at the default layout), Scene below.
    set -- $(stats "$shot" 300x440+10+40)
    left_mean=$2
    set -- $(stats "$shot" 300x230+10+560)
    right_mean=$2
    left_text=$(bright "$shot" 300x440+10+40)
    right_text=$(bright "$shot" 300x230+10+560)
    echo "$name: viewport sd $viewport_sd; left panel mean $left_mean text $left_text; right panel mean $right_mean text $right_text"
    ok=1
    check "$viewport_sd > 0.04" || { echo "FAIL $name: the viewport is blank (sd $viewport_sd)"; ok=0; }
    check "$left_mean < 0.25 && $left_text > 0.005" || { echo "FAIL $name: formula panel not drawn"; ok=0; }
    check "$right_mean < 0.25 && $right_text > 0.005" || { echo "FAIL $name: scene panel not drawn"; ok=0; }
    [ $ok = 1 ] || failures=$((failures + 1))
done

# No display: a clear message pointing to `fraktal render`, and a non-zero exit.
set +e
msg=$(env -u DISPLAY -u WAYLAND_DISPLAY HOME="$home" "$fraktal" edit "$presets/mandelbulb.json" 2>&1)
rc=$?
set -e
if [ $rc -eq 0 ] || ! echo "$msg" | grep -q "fraktal render"; then
    echo "FAIL: without a display the editor must exit non-zero and point to fraktal render (rc $rc): $msg"
    failures=$((failures + 1))
fi

[ $failures -eq 0 ] && echo "editor_xvfb_test: all presets OK" || { echo "editor_xvfb_test: $failures failure(s)"; exit 1; }
