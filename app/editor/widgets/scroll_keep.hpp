// A scrolled panel keeps its scroll when its content gets shorter. Dear ImGui clamps a window's
// scroll to the content's height of the last frame, so a click that shortens what lies below
// (selecting a node with fewer parameters, a shorter help text) scrolled the whole panel back
// under the pointer, and the next click landed on another row. The panel instead ends with
// blank space down to the bottom of what it shows; the space shrinks as the artist scrolls up.
#pragma once

#include <algorithm>

namespace fraktal::editor {

// The blank height to add under content ending at `contentBottom` so that a window scrolled by
// `scrollY` and showing content down to `shownBottom` (both in screen coordinates) keeps that
// scroll. Unscrolled, nothing is added: the content may shrink freely.
inline float paddingKeepingScroll(float contentBottom, float shownBottom, float scrollY) {
    if (scrollY <= 0.0f) return 0.0f;
    return std::max(0.0f, shownBottom - contentBottom);
}

}  // namespace fraktal::editor
