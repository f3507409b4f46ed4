// Reading compile logs and refusals (core/glsl_log.hpp) without a GL context, so that the
// sanitizer build runs them too: each driver's log form gives its line and message, and a
// refusal of a block's GLSL names its line. glsl_error_lines_test.cpp compiles on the driver.
#include "core/glsl_log.hpp"

#include <gtest/gtest.h>

#include "core/custom_block.hpp"

using namespace fraktal;

// Mesa's, NVIDIA's and glslang's forms give the line and the message; other lines are none.
TEST(GlslErrorLines, ParsesEachDriversLogForm) {
    const std::vector<ShaderLogMessage> m = parseShaderLog(
        "0:10012(7): error: `foo' undeclared\n"
        "0(10013) : error C1008: undefined variable \"bar\"\r\n"
        "ERROR: 0:10014: 'baz' : undeclared identifier\n"
        "ERROR: 1 compilation errors.  No code generated.\n"
        "\n"
        "0:5003: warning: unused\n");
    ASSERT_EQ(m.size(), 4u);
    EXPECT_EQ(m[0].line, 10012);
    EXPECT_EQ(m[0].text, "error: `foo' undeclared");
    EXPECT_EQ(m[1].line, 10013);
    EXPECT_EQ(m[1].text, "error C1008: undefined variable \"bar\"");
    EXPECT_EQ(m[2].line, 10014);
    EXPECT_EQ(m[2].text, "error: 'baz' : undeclared identifier");
    EXPECT_EQ(m[3].line, 5003);
}

// A refusal of the block's GLSL names its line; a refusal of another field names none.
TEST(GlslErrorLines, ValidationRefusalsNameTheirLine) {
    EXPECT_EQ(validationSourceErrors("glsl: line 3: loops ('for') are not allowed"),
              (std::vector<SourceError>{{3, "loops ('for') are not allowed"}}));
    EXPECT_EQ(validationSourceErrors("glsl: unbalanced '{'"), (std::vector<SourceError>{{0, "unbalanced '{'"}}));
    EXPECT_TRUE(validationSourceErrors("params[0].name: 'p' is reserved").empty());

    // CustomBlock::validate's own refusals, of a whole DE and of a node block.
    CustomBlock::Definition whole;
    whole.id = "refused_de";
    whole.category = Category::Estimator;
    whole.wholeDE = true;
    whole.glsl = "float DE(vec3 p) {\n    return length(p) - 1.0;\n}\nuniform float stray;\n";
    const std::vector<SourceError> wholeErrors = validationSourceErrors(CustomBlock::validate(whole));
    ASSERT_EQ(wholeErrors.size(), 1u) << CustomBlock::validate(whole);
    EXPECT_EQ(wholeErrors[0].line, 4);
    CustomBlock::Definition node;
    node.id = "refused_fold";
    node.glsl = "\np.xyz = abs(p.xyz);\nfor (int i = 0; i < 3; ++i) p.x += 1.0;\n";
    const std::vector<SourceError> nodeErrors = validationSourceErrors(CustomBlock::validate(node));
    ASSERT_EQ(nodeErrors.size(), 1u) << CustomBlock::validate(node);
    EXPECT_EQ(nodeErrors[0].line, 3);
}
