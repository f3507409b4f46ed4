// Dynamic resolution's controller (core/viewport/resolution_control.hpp) against a simulated
// renderer whose frame costs a fixed part plus a part proportional to the pixels. No GL.
#include "core/viewport/resolution_control.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace fraktal::viewport {
namespace {

// A frame of the simulated renderer: fixedMs + fullPixelMs * scale^2, times noise in [1 - n, 1 + n].
struct SimulatedRenderer {
    double fixedMs, fullPixelMs, noise = 0.0;
    std::mt19937 random{7};
    double frameMs(double scale) {
        std::uniform_real_distribution<double> u(1.0 - noise, 1.0 + noise);
        return (fixedMs + fullPixelMs * scale * scale) * u(random);
    }
};

// Runs `frames` moving frames; returns the scales chosen.
std::vector<double> drive(ResolutionController& c, SimulatedRenderer& r, int frames) {
    std::vector<double> scales;
    double last = 0.0;
    for (int i = 0; i < frames; ++i) {
        const double s = c.next(true, last);
        scales.push_back(s);
        last = r.frameMs(s);
    }
    return scales;
}

TEST(ResolutionControl, ConvergesToTheScaleThatHoldsTheTarget) {
    // 8 ms fixed, 200 ms for a full frame's pixels: 33 ms holds at scale sqrt(25 / 200) = 0.354.
    ResolutionController c;
    SimulatedRenderer r{8.0, 200.0};
    const std::vector<double> scales = drive(c, r, 60);
    EXPECT_EQ(scales.front(), 1.0);  // nothing measured yet
    const double settled = scales.back();
    EXPECT_LE(r.frameMs(settled), 33.0);
    // The largest step that still holds the target: one step more would not.
    EXPECT_GT(r.frameMs(settled + c.control().step), 33.0 * 0.9);
    for (size_t i = 20; i < scales.size(); ++i) EXPECT_EQ(scales[i], settled) << "frame " << i;
}

TEST(ResolutionControl, NoisyFramesDoNotMakeItOscillate) {
    ResolutionController c;
    SimulatedRenderer r{6.0, 150.0, 0.15};
    const std::vector<double> scales = drive(c, r, 300);
    int changes = 0;
    double lo = 1.0, hi = 0.0;
    for (size_t i = 50; i < scales.size(); ++i) {
        changes += scales[i] != scales[i - 1];
        lo = std::min(lo, scales[i]);
        hi = std::max(hi, scales[i]);
    }
    EXPECT_LE(changes, 25) << "scale changes in 250 noisy frames";
    EXPECT_LE(hi - lo, 2.0 * c.control().step + 1e-9);
    // Most frames hold the target.
    SimulatedRenderer exact{6.0, 150.0};
    EXPECT_LE(exact.frameMs(scales.back()), 33.0 * 1.15);
}

// A loaded machine: 14 ms fixed, 600 ms for a full frame's pixels; a quarter-size frame takes
// 51.5 ms, so the scale goes below a quarter to hold the target, and never below the floor.
TEST(ResolutionControl, UnderLoadItGoesBelowAQuarter) {
    ResolutionController c;
    SimulatedRenderer r{14.0, 600.0};
    const double settled = drive(c, r, 60).back();
    EXPECT_LT(settled, 0.25);
    EXPECT_GE(settled, c.control().minScale);
    EXPECT_LE(r.frameMs(settled), 33.0);
}

TEST(ResolutionControl, ReactsToASlowFrameAtOnceAndRecovers) {
    ResolutionController c;
    SimulatedRenderer r{4.0, 80.0};
    const double settled = drive(c, r, 40).back();
    EXPECT_GT(settled, 0.5);
    const double afterSlow = c.next(true, 500.0);  // one frame took 500 ms
    EXPECT_LT(afterSlow, settled);
    EXPECT_EQ(afterSlow, c.control().minScale);
    const double recovered = drive(c, r, 80).back();
    EXPECT_GE(recovered, settled - c.control().step);
}

TEST(ResolutionControl, FullResolutionAtRestAndTheMotionScaleComesBack) {
    ResolutionController c;
    SimulatedRenderer r{8.0, 200.0};
    const double moving = drive(c, r, 40).back();
    ASSERT_LT(moving, 1.0);
    double s = 0.0;
    for (int i = 0; i < c.control().restFrames; ++i) {
        EXPECT_TRUE(c.moving());
        s = c.next(false, 0.0);
    }
    EXPECT_FALSE(c.moving());
    EXPECT_EQ(s, 1.0);
    EXPECT_EQ(c.next(false, 400.0), 1.0);    // a slow frame at rest changes nothing
    EXPECT_EQ(c.next(true, 400.0), moving);  // nor what the next motion starts with
}

TEST(ResolutionControl, NoTargetMeansFullResolution) {
    ResolutionController c(ResolutionControl{0.0});
    SimulatedRenderer r{8.0, 200.0};
    for (double s : drive(c, r, 10)) EXPECT_EQ(s, 1.0);
}

}  // namespace
}  // namespace fraktal::viewport

// At rest a frame marches every unfinished ray by its steps: against a simulated renderer whose
// frame costs a fixed part plus a part per step, the steps settle where the frame holds the
// target (a heavy formula: one step's worth is all that fits, never less than one step), a light
// formula gets the whole cap, a fixed part over the target gets twice its time for the march
// (not one step: that frame would be hardly shorter and the view would settle far later), and
// the steps grow at most twice a frame.
namespace fraktal::viewport {
TEST(ResolutionControl, StepsAtRestFitTheFrameTimeTarget) {
    struct Case {
        double fixedMs, msPerStep;
        int settleAt;  // the steps it must settle at
    };
    constexpr double target = 50.0;
    // kleinian-like (900 ms for 30 steps), a medium one, a light one; a loaded machine whose
    // fixed part is over the target, with a light and with a heavy formula.
    for (const Case c :
         {Case{5.0, 30.0, 1}, Case{5.0, 2.0, 22}, Case{2.0, 0.5, 30}, Case{300.0, 10.0, 30}, Case{100.0, 20.0, 10}}) {
        SCOPED_TRACE(c.msPerStep);
        RestSteps control;
        int steps = 30;
        for (int frame = 0; frame < 40; ++frame) {
            const int next = control.next(steps, c.fixedMs + c.msPerStep * steps, target, 30);
            EXPECT_GE(next, 1);
            EXPECT_LE(next, 30);
            EXPECT_LE(next, 2 * steps);
            steps = next;
        }
        EXPECT_NEAR(steps, c.settleAt, 1);
        if (c.settleAt < 30) {
            EXPECT_NEAR(control.msPerStep(), c.msPerStep, 1e-9) << "the part per step";
        }
        const double frameMs = c.fixedMs + c.msPerStep * steps;
        if (c.settleAt > 1 && c.settleAt < 30) {
            EXPECT_LE(frameMs, std::max(target, 3 * c.fixedMs) * 1.1);
        }
    }
    EXPECT_EQ(RestSteps{}.next(3, 900.0, 0.0, 30), 30) << "no target: the settings' steps";
    EXPECT_EQ(RestSteps{}.next(1, 1.0, 50.0, 30), 2) << "growth at most twice a frame";
}
}  // namespace fraktal::viewport
