// A value typed into a slider outside its range (app/editor/widgets/value_clamp.hpp): clamped
// to the nearer end, named with what was typed and what it became, and reported once, when the
// artist leaves the field, for the number they ended with.
#include <gtest/gtest.h>

#include <vector>

#include "app/editor/widgets/value_clamp.hpp"

namespace fraktal::editor {
namespace {

TEST(ValueClamp, ValuesOutsideTheRangeGoToTheNearerEnd) {
    double below = 0.0;
    const auto low = clampIntoRange("Bound radius", std::span(&below, 1), 0.01, 100.0);
    ASSERT_TRUE(low);
    EXPECT_EQ(below, 0.01);
    EXPECT_EQ(*low, (ClampNotice{"Bound radius", 0.0, 0.01, 0.01, 100.0, false}));
    EXPECT_EQ(clampMessage(*low), "Bound radius: 0 is outside 0.01 .. 100, set to 0.01");

    double above = 1e9;
    const auto high = clampIntoRange("Iterations", std::span(&above, 1), 1, 250, true);
    ASSERT_TRUE(high);
    EXPECT_EQ(above, 250.0);
    EXPECT_EQ(clampMessage(*high), "Iterations: 1000000000 is outside 1 .. 250, set to 250");

    // Inside, and at either end: nothing to say, nothing changed.
    for (double inside : {0.01, 3.5, 100.0}) {
        double v = inside;
        EXPECT_FALSE(clampIntoRange("Bound radius", std::span(&v, 1), 0.01, 100.0)) << inside;
        EXPECT_EQ(v, inside);
    }
    // A range that is none (lo above hi) clamps nothing, as ImGui leaves such a slider free.
    double free = -5.0;
    EXPECT_FALSE(clampIntoRange("x", std::span(&free, 1), 1.0, 0.0));
    EXPECT_EQ(free, -5.0);
}

// A vector: every component is brought in, the first one outside is named.
TEST(ValueClamp, AVectorIsClampedWholeAndItsFirstStrayComponentNamed) {
    std::vector<double> v = {0.5, 7.0, -9.0};
    const auto n = clampIntoRange("normal", v, -1.0, 1.0);
    ASSERT_TRUE(n);
    EXPECT_EQ(v, (std::vector<double>{0.5, 1.0, -1.0}));
    EXPECT_EQ(n->typed, 7.0);
    EXPECT_EQ(n->clamped, 1.0);
    EXPECT_EQ(clampMessage(*n), "normal: 7 is outside -1 .. 1, set to 1");
}

TEST(ValueClamp, TheVisibleLabelDropsImGuisHiddenId) {
    EXPECT_EQ(visibleLabel("Bound radius"), "Bound radius");
    EXPECT_EQ(visibleLabel("Width##export"), "Width");
    EXPECT_EQ(visibleLabel("##v"), "");
}

// Typing "100" into a 0 .. 10 slider: "1" and "10" are inside, "100" is clamped; nothing is said
// until the artist leaves the field, then once, naming 100.
TEST(ValueClamp, TheNoticeWaitsForTheArtistToLeaveTheField) {
    ClampReports r;
    const ClampNotice hundred{"scale", 100.0, 10.0, 0.0, 10.0, false};
    r.drawn(7, std::nullopt, true, false);  // "1"
    r.drawn(7, std::nullopt, true, false);  // "10"
    r.drawn(7, hundred, true, false);       // "100"
    EXPECT_FALSE(r.take());
    r.drawn(7, std::nullopt, false, false);  // a frame with no key
    EXPECT_FALSE(r.take());
    r.drawn(7, std::nullopt, false, true);  // Enter
    EXPECT_EQ(r.take(), hundred);
    EXPECT_FALSE(r.take()) << "reported once";
    r.drawn(7, std::nullopt, false, true);
    EXPECT_FALSE(r.take()) << "leaving it again says nothing new";
}

// A clamped "-" typed on into "-0.5", inside the range: nothing to report. Another slider's
// frames do not touch the one being typed into.
TEST(ValueClamp, TypingBackIntoTheRangeWithdrawsTheNotice) {
    ClampReports r;
    r.drawn(3, ClampNotice{"AO strength", -1.0, 0.0, 0.0, 4.0, false}, true, false);
    r.drawn(9, std::nullopt, false, false);
    r.drawn(9, std::nullopt, false, true);
    r.drawn(3, std::nullopt, true, false);
    r.drawn(3, std::nullopt, false, true);
    EXPECT_FALSE(r.take());

    r.drawn(3, ClampNotice{"AO strength", 9.0, 4.0, 0.0, 4.0, false}, true, false);
    r.drawn(9, std::nullopt, true, true);  // another slider edited and left: not this one's notice
    EXPECT_FALSE(r.take());
    r.drawn(3, std::nullopt, false, true);
    const std::optional<ClampNotice> nine = r.take();
    ASSERT_TRUE(nine);
    EXPECT_EQ(nine->typed, 9.0);
}

}  // namespace
}  // namespace fraktal::editor
