#include <gtest/gtest.h>

#include "core/preset.hpp"

using namespace fraktal;

TEST(Formula, Smoke) {
    const Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/menger.json");
    EXPECT_EQ(p.formula.nodes.size(), 4u);
}
