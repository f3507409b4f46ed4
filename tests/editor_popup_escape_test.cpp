// Escape closes the menu or popup in front, and only that (app/editor/input/popup_escape.hpp).
#include <gtest/gtest.h>

#include "app/editor/input/popup_escape.hpp"

namespace fraktal::editor {
namespace {

TEST(PopupEscape, ClosesTheMenuInFront) {
    EXPECT_EQ(popupsLeftOpenByEscape({false}, false), 0);
    // A submenu closes first; its menu stays for the next Escape.
    EXPECT_EQ(popupsLeftOpenByEscape({false, false}, false), 1);
    // A popup opened over a modal dialog closes, the dialog stays.
    EXPECT_EQ(popupsLeftOpenByEscape({true, false}, false), 1);
}

TEST(PopupEscape, LeavesAModalDialogToItsOwnCancel) {
    EXPECT_EQ(popupsLeftOpenByEscape({true}, false), 1);
    EXPECT_EQ(popupsLeftOpenByEscape({false, true}, false), 2);
}

TEST(PopupEscape, EndsAnEditBeforeClosingAnything) {
    EXPECT_EQ(popupsLeftOpenByEscape({false}, true), 1);
    EXPECT_EQ(popupsLeftOpenByEscape({}, false), 0);
}

}  // namespace
}  // namespace fraktal::editor
