// A scrolled panel whose content gets shorter keeps its scroll (app/editor/widgets/scroll_keep.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "app/editor/widgets/scroll_keep.hpp"

namespace fraktal::editor {
namespace {

// Dear ImGui's rule for a window's scroll on the next frame: at most the content's height less
// what the window shows (imgui.cpp, Begin: ScrollMax).
float nextScroll(float scroll, float contentHeight, float shownHeight) {
    return std::min(scroll, std::max(0.0f, contentHeight - shownHeight));
}

// A window showing 400 px of content, from its top at 0 on the screen: content at y lies at
// y - scroll on the screen. Returns the next frame's scroll after content of `height` is drawn
// with the padding the rule adds.
float frameWithPadding(float scroll, float height, float shown = 400.0f) {
    const float contentBottom = height - scroll;  // on the screen
    const float pad = paddingKeepingScroll(contentBottom, shown, scroll);
    return nextScroll(scroll, height + pad, shown);
}

TEST(ScrollKeep, ShorterContentLeavesTheRowsWhereTheyWere) {
    // Scrolled to the end of 900 px of content; a click makes it 810 px.
    const float scroll = 500.0f;
    EXPECT_EQ(nextScroll(scroll, 810.0f, 400.0f), 410.0f);  // without the rule: 90 px jump
    EXPECT_EQ(frameWithPadding(scroll, 810.0f), scroll);
    // Frame after frame it stays: the padding is worked out again from the kept scroll.
    float s = scroll;
    for (int frame = 0; frame < 5; ++frame) s = frameWithPadding(s, 810.0f);
    EXPECT_EQ(s, scroll);
}

TEST(ScrollKeep, ThePaddingShrinksAsTheArtistScrollsUp) {
    // Kept at 500 over 810 px of content: 90 px of blank space below.
    EXPECT_FLOAT_EQ(paddingKeepingScroll(810.0f - 500.0f, 400.0f, 500.0f), 90.0f);
    // Scrolled up by 60: 30 px; by 90 or more: none, the content's own end is back in view.
    EXPECT_FLOAT_EQ(paddingKeepingScroll(810.0f - 440.0f, 400.0f, 440.0f), 30.0f);
    EXPECT_FLOAT_EQ(paddingKeepingScroll(810.0f - 410.0f, 400.0f, 410.0f), 0.0f);
    EXPECT_FLOAT_EQ(paddingKeepingScroll(810.0f - 100.0f, 400.0f, 100.0f), 0.0f);
}

TEST(ScrollKeep, NothingIsAddedUnscrolledOrWithLongerContent) {
    EXPECT_EQ(paddingKeepingScroll(200.0f, 400.0f, 0.0f), 0.0f);  // short content, not scrolled
    EXPECT_EQ(paddingKeepingScroll(900.0f, 400.0f, 100.0f), 0.0f);
    EXPECT_EQ(frameWithPadding(100.0f, 1200.0f), 100.0f);
}

TEST(ScrollKeep, AWindowMadeTallerStillShowsMoreOfTheContent) {
    // Scrolled to the end (500 over 900 px), the window grows from 400 to 500 px: ImGui takes the
    // scroll back to 400 so that the content fills the window; the padding does not hold it.
    const float grown = nextScroll(500.0f, 900.0f, 500.0f);
    EXPECT_EQ(grown, 400.0f);
    EXPECT_EQ(paddingKeepingScroll(900.0f - grown, 500.0f, grown), 0.0f);
    EXPECT_EQ(frameWithPadding(grown, 900.0f, 500.0f), 400.0f);
}

}  // namespace
}  // namespace fraktal::editor
