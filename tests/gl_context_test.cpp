// Headless OpenGL: a 4.5 core context through EGL with no display, and a clear message (not a
// crash) when none can be had.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "test_support.hpp"

using namespace fraktal;

TEST(GlContext, HeadlessCoreContextWithoutADisplay) {
    test::glContext();
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_FALSE(test::glContext().renderer().empty());
}

TEST(GlContext, NoContextGivesAReasonAndAnInstallHint) {
    // With no EGL vendor library, every way to a display fails.
    const test::CliRun r = test::runCli("check --rays 4 " + (test::sourceDir() / "presets/menger.json").string(),
                                        "env -u DISPLAY __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_EQ(r.exitCode, 0) << r.output;  // the preset is sound; only the GLSL check is skipped
    EXPECT_NE(r.output.find("GLSL: not checked (cannot open an EGL display"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("apt-get install"), std::string::npos) << r.output;
}
