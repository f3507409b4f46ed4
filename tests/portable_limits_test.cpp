// Every GL program fraktal links stays within what every OpenGL 4.5 driver provides
// (core/gl/portable_limits.hpp), as its owner configures it, and compiles with glslang, the
// reference compiler, whose default limits are the same minimum maxima. llvmpipe, which these
// tests run on, gives more than that minimum; NVIDIA's driver does not (8 image units).
#include "core/gl/portable_limits.hpp"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "app/editor/viewport/ocio_display_pass.hpp"
#include "core/gl/de_probe.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_renderer.hpp"
#include "core/render/path_tracer.hpp"
#include "core/render/still_renderer.hpp"
#include "core/scene/scene_import.hpp"
#include "core/shader_library.hpp"
#include "core/viewport/viewport_programs.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

const char* extensionOf(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER: return ".vert";
        case GL_FRAGMENT_SHADER: return ".frag";
        default: return ".comp";
    }
}

// glslangValidator on one stage's source: its output, empty when it compiled. The source is
// written in a folder of this process's own, so that parallel runs (ctest -j, gtest shards),
// which write the same names, never validate each other's files.
std::string glslangErrors(const gl::StageSource& stage, const std::string& name) {
    static const test::Sandbox sandbox("fraktal_portable_limits_test_");
    const auto& dir = sandbox.dir;
    std::string file = name;
    for (char& c : file)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const auto path = dir / (file + extensionOf(stage.stage));
    std::ofstream(path) << stage.text;
    FILE* pipe = popen((std::string(FRAKTAL_GLSLANG) + " " + path.string() + " 2>&1").c_str(), "r");
    std::string out;
    char buf[512];
    while (pipe && fgets(buf, sizeof buf, pipe)) out += buf;
    const int status = pipe ? pclose(pipe) : -1;
    return status == 0 ? "" : out.empty() ? "glslangValidator failed with no output" : out;
}

// The programs checked so far, by their stages' sources: glslang runs once per distinct source.
struct Survey {
    std::set<std::string> compiled;
    int programs = 0;

    void check(const gl::Program& program, const std::string& owner, bool withGlslang) {
        ASSERT_TRUE(program) << owner << ": no program";
        ++programs;
        const std::vector<std::string> over = gl::portableLimitViolations(program);
        for (const std::string& v : over) ADD_FAILURE() << owner << ", program " << program.name() << ": " << v;
        if (!withGlslang) return;
        for (const gl::StageSource& stage : program.stages()) {
            if (!compiled.insert(stage.text).second) continue;
            const std::string errors = glslangErrors(stage, program.name());
            EXPECT_EQ(errors, "") << owner << ", program " << program.name() << " (" << extensionOf(stage.stage)
                                  << ") with glslang";
        }
    }
};

// A compute program from one shader body, linked through gl::compileCompute.
gl::Program computeProgram(const std::string& body) {
    ShaderSource s;
    s.programName = "limits_probe.comp";
    s.text = "#version 450 core\n" + body;
    return gl::compileCompute(s);
}

// What linking `body` throws (empty when it links).
std::string linkError(const std::string& body) {
    try {
        computeProgram(body);
        return "";
    } catch (const std::runtime_error& e) {
        return e.what();
    }
}

}  // namespace

// The viewport's passes, the still renderer, the path tracer and the DE probe for every shipped
// 3D preset, the 2D renderer in both precisions for every 2D preset, and the editor's OCIO
// display pass for every view of the shipped config.
TEST(PortableLimits, EveryProgramFraktalLinksIsWithinOpenGL45) {
    test::glContext();
    Survey survey;
    // glslang sees every variant of every program once, for two formulas (an escape-time and an
    // IFS one); the limits are checked on every preset, whose formulas change the uniforms.
    const std::set<std::string> glslangPresets = {"mandelbulb.json", "menger.json"};
    for (const auto& path : test::shippedPresets()) {
        const Preset preset = loadPreset(path);
        const std::string name = path.filename().string();
        const bool withGlslang = glslangPresets.count(name) != 0;
        const viewport::ViewportPrograms viewportPrograms(preset.formula);
        for (const gl::Program* p : viewportPrograms.all()) survey.check(*p, name + " viewport", withGlslang);
        survey.check(gl::StillRenderer(preset.formula, 64).program(), name + " still", withGlslang);
        survey.check(gl::PathTracer(preset.formula, 8, 8).program(), name + " path tracer", withGlslang);
        survey.check(gl::DEProbe(preset.formula).program(), name + " DE probe", withGlslang);
    }
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "presets/2d")) {
        const PlanePreset preset = loadPlanePreset(entry.path());
        for (const PlanePrecision precision : {PlanePrecision::Double, PlanePrecision::Float}) {
            PlaneRenderer renderer;
            renderer.prepare(preset.formula, precision);
            survey.check(renderer.program(), entry.path().filename().string() + " 2D", true);
        }
    }
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const OCIO::ConstConfigRcPtr config = color.config();
    for (int d = 0; d < config->getNumDisplays(); ++d) {
        const std::string display = config->getDisplay(d);
        for (int v = 0; v < config->getNumViews(display.c_str()); ++v) {
            editor::OcioDisplayPass pass;
            const std::string view = config->getView(display.c_str(), v);
            pass.configure(color, {color.resolveSpace("scene_linear"), display, view});
            survey.check(pass.program(), "OCIO display " + display + " / " + view, true);
        }
    }
    std::printf("%d programs within OpenGL 4.5's limits\n", survey.programs);
    // 27 3D presets x 15 programs, 5 2D presets x 2, at least 3 views.
    EXPECT_GE(survey.programs, int(test::shippedPresets().size()) * 15 + 10 + 3);
}

// A whole-DE estimator (an imported frag) brings its own code, globals and loops into every
// program fraktal links for the formula: those stay within the limits too, and glslang accepts
// them (the code as renamed and bounded by the generator).
TEST(PortableLimits, ImportedFragProgramsAreWithinOpenGL45) {
    test::glContext();
    Survey survey;
    for (const char* name : {"menger.frag", "init_bulb.frag", "annotations.frag"}) {
        const Preset preset = importSceneFile(test::sourceDir() / "tests/data/frag_import" / name).preset;
        ASSERT_TRUE(preset.formula.estimator.block->wholeDE) << name;
        const viewport::ViewportPrograms viewportPrograms(preset.formula);
        for (const gl::Program* p : viewportPrograms.all()) survey.check(*p, std::string(name) + " viewport", true);
        survey.check(gl::StillRenderer(preset.formula, 64).program(), std::string(name) + " still", true);
        survey.check(gl::PathTracer(preset.formula, 8, 8).program(), std::string(name) + " path tracer", true);
        survey.check(gl::DEProbe(preset.formula).program(), std::string(name) + " DE probe", true);
    }
    EXPECT_GE(survey.programs, 3 * 15);
}

// Each viewport pass binds its own images at units 0.. (core/viewport/pass_images.hpp): no pass
// has more than 8, and the images a pass binds are the ones its shader declares.
TEST(PortableLimits, ViewportPassesBindTheirImagesWithinEightUnits) {
    test::glContext();
    const viewport::ViewportPrograms p(loadPreset(test::sourceDir() / "presets/mandelbulb.json").formula);
    const auto units = [](const viewport::PassImages& images) {
        std::vector<std::string> names;
        for (const viewport::StateImage* image : images.units()) names.push_back(image->uniform);
        std::sort(names.begin(), names.end());
        return names;
    };
    using Names = std::vector<std::string>;
    // The passes with the most images: the first march of a new view and the moving accumulation.
    EXPECT_EQ(units(p.marchFromStart.images), (Names{"u_centre", "u_colourPoint", "u_cone", "u_depth", "u_image",
                                                     "u_rayInfo", "u_rayState", "u_sampleColor"}));
    EXPECT_EQ(units(p.accumulateMoving.images), (Names{"u_accum", "u_centre", "u_colourPoint", "u_image", "u_rayInfo",
                                                       "u_sampleColor", "u_samplePosition"}));
    EXPECT_EQ(units(p.reprojectClaim.images), (Names{"u_depth"}));
    EXPECT_EQ(units(p.reprojectWrite.images), (Names{"u_depth", "u_reprojCarried", "u_reprojColor"}));
    EXPECT_EQ(units(p.reprojectBlockClaim.images), units(p.reprojectClaim.images));
    EXPECT_EQ(units(p.reprojectBlockWrite.images), units(p.reprojectWrite.images));
    EXPECT_EQ(units(p.resolve.images), (Names{"u_image", "u_samplePosition", "u_shown"}));
    for (const gl::Program* program : p.all()) {
        for (const gl::ImageUniform& image : gl::activeImageUniforms(program->id())) {
            GLint unit = -1;
            glGetUniformiv(program->id(), image.location, &unit);
            EXPECT_GE(unit, 0) << program->name();
            EXPECT_LT(unit, gl::PortableLimits::imageUnits) << program->name();
        }
    }
}

// The check fails where a driver with only the minimum would: each resource over its limit is
// refused when linking, naming the program and the resource.
TEST(PortableLimits, LinkingRefusesWhatADriverWithTheMinimumWouldRefuse) {
    test::glContext();
    const std::string imageAt10 = linkError(R"(layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 10) uniform writeonly image2D u_far;
void main() { imageStore(u_far, ivec2(gl_GlobalInvocationID.xy), vec4(1.0)); })");
    EXPECT_NE(imageAt10.find("limits_probe.comp"), std::string::npos) << imageAt10;
    EXPECT_NE(imageAt10.find("image uniform u_far at unit 10 (OpenGL 4.5 guarantees units 0-7)"), std::string::npos)
        << imageAt10;

    std::string nineImages = "layout(local_size_x = 8, local_size_y = 8) in;\n";
    std::string stores;
    for (int i = 0; i < 9; ++i) {
        nineImages += "layout(r32f, binding = " + std::to_string(i % 8) + ") uniform writeonly image2D u_i" +
                      std::to_string(i) + ";\n";
        stores += "imageStore(u_i" + std::to_string(i) + ", ivec2(0), vec4(1.0));";
    }
    const std::string nine = linkError(nineImages + "void main() {" + stores + "}");
    EXPECT_NE(nine.find("compute stage: 9 image uniforms (OpenGL 4.5 guarantees 8)"), std::string::npos) << nine;

    const std::string storage = linkError(R"(layout(local_size_x = 64) in;
layout(std430, binding = 8) buffer Far { uint far[]; };
void main() { far[gl_GlobalInvocationID.x] = 1u; })");
    EXPECT_NE(storage.find("storage block Far at binding 8 (OpenGL 4.5 guarantees bindings 0-7)"), std::string::npos)
        << storage;

    const std::string sampler = linkError(R"(layout(local_size_x = 64) in;
layout(binding = 16) uniform sampler2D u_table;
layout(std430, binding = 0) buffer Out { vec4 outs[]; };
void main() { outs[gl_GlobalInvocationID.x] = texelFetch(u_table, ivec2(0), 0); })");
    EXPECT_NE(sampler.find("sampler uniform u_table at unit 16 (OpenGL 4.5 guarantees units 0-15)"), std::string::npos)
        << sampler;

    // Mesa itself refuses a work group or shared memory over the minimum (its limits are the
    // minimum there); the check says the same where a driver allows more (NVIDIA: 48 KiB shared).
    const std::string group = linkError(R"(layout(local_size_x = 64, local_size_y = 32) in;
layout(std430, binding = 0) buffer Out { uint outs[]; };
void main() { outs[gl_LocalInvocationIndex] = 1u; })");
    EXPECT_NE(group.find("limits_probe.comp"), std::string::npos) << group;
    EXPECT_NE(group.find("1024"), std::string::npos) << group;

    const std::string shared = linkError(R"(layout(local_size_x = 64) in;
shared vec4 tile[2304];  // 36 KiB
layout(std430, binding = 0) buffer Out { vec4 outs[]; };
void main() {
    tile[gl_LocalInvocationIndex] = vec4(1.0);
    barrier();
    outs[gl_GlobalInvocationID.x] = tile[63u - gl_LocalInvocationIndex];
})");
    EXPECT_NE(shared.find("limits_probe.comp"), std::string::npos) << shared;
    EXPECT_NE(shared.find("36864"), std::string::npos) << shared;

    // The default block's components are the tests' to check, not linking's (portable_limits.hpp: why).
    const gl::Program manyUniforms = computeProgram(R"(layout(local_size_x = 64) in;
uniform vec4 u_table[129];
layout(std430, binding = 0) buffer Out { vec4 outs[]; };
void main() { outs[gl_GlobalInvocationID.x] = u_table[gl_GlobalInvocationID.x % 129u]; })");
    const std::vector<std::string> components = gl::portableLimitViolations(manyUniforms);
    ASSERT_EQ(components.size(), 1u);
    EXPECT_EQ(components[0], "compute stage: 516 default-block uniform components (OpenGL 4.5 guarantees 512)");

    // Within every limit: links.
    EXPECT_EQ(linkError(R"(layout(local_size_x = 32, local_size_y = 32) in;
shared vec4 tile[2048];  // 32 KiB
layout(rgba32f, binding = 7) uniform writeonly image2D u_last;
void main() {
    tile[gl_LocalInvocationIndex] = vec4(1.0);
    barrier();
    imageStore(u_last, ivec2(gl_GlobalInvocationID.xy), tile[1023u - gl_LocalInvocationIndex]);
})"),
              "");
}

TEST(PortableLimits, SharedMemoryIsMeasuredFromTheSource) {
    EXPECT_EQ(gl::sharedMemoryBytes("void main() {}"), 0);
    // std430: a vec3 takes 16 bytes, a mat4 four columns of 16; comments do not count.
    EXPECT_EQ(gl::sharedMemoryBytes("shared vec4 a[64];\nshared float b, c[3];\n// shared vec4 d[1000];\n"
                                    "shared vec3 e; shared mat4 f[2];"),
              64 * 16 + 4 + 12 + 16 + 2 * 64);
    // What cannot be measured is said so, not taken as nothing.
    EXPECT_EQ(gl::sharedMemoryBytes("struct S { float x; };\nshared S items[4];"), std::nullopt);
    EXPECT_EQ(gl::sharedMemoryBytes("const int N = 4;\nshared float items[N];"), std::nullopt);
}
