// The Fragmentarium / FragM .frag parse layer (core/import/frag_file.hpp): preprocessing,
// annotations, presets, the function finder and the errors. The frags under tests/data/frag/ are
// written for these tests in FragM's dialect.
#include "core/import/frag_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/json_reader.hpp"

namespace fraktal::frag {
namespace {

namespace fs = std::filesystem;

fs::path fragDataDir() { return fs::path(FRAKTAL_TEST_DIR) / "data" / "frag"; }

// The test frags' own MathUtils stand-in, given as a built-in include.
FragOptions fragTestOptions() {
    FragOptions options;
    options.includeDirs = {fragDataDir() / "include"};
    options.builtinIncludes["MathUtils.frag"] =
        "#donotrun\n"
        "// built-in stand-in\n"
        "mat3 rotationMatrix3(vec3 v, float angle) {\n"
        "\tfloat c = cos(radians(angle));\n"
        "\tfloat s = sin(radians(angle));\n"
        "\treturn mat3(c + (1.0 - c) * v.x * v.x, (1.0 - c) * v.x * v.y - s * v.z, (1.0 - c) * v.x * v.z + s * v.y,\n"
        "\t\t(1.0 - c) * v.x * v.y + s * v.z, c + (1.0 - c) * v.y * v.y, (1.0 - c) * v.y * v.z - s * v.x,\n"
        "\t\t(1.0 - c) * v.x * v.z - s * v.y, (1.0 - c) * v.y * v.z + s * v.x, c + (1.0 - c) * v.z * v.z);\n"
        "}\n";
    return options;
}

FragFile loadTestFrag(const std::string& name) { return loadFragFile(fragDataDir() / name, fragTestOptions()); }

// A folder of the test's own, removed at the end.
struct FragSandbox {
    fs::path dir;
    explicit FragSandbox(const std::string& prefix)
        : dir(fs::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~FragSandbox() { fs::remove_all(dir); }
    fs::path write(const std::string& name, const std::string& text) const {
        fs::create_directories((dir / name).parent_path());
        std::ofstream(dir / name, std::ios::binary) << text;
        return dir / name;
    }
};

// The PresetError that parsing `text` (named `name` in `box`) throws; fails the test when none.
PresetError fragErrorOf(const std::string& text, const fs::path& path = "test.frag", const FragOptions& options = {}) {
    try {
        parseFragFile(text, path, options);
    } catch (const PresetError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return PresetError("", "", "");
}

// The 0-based line of `glsl` holding `needle` (-1 when none).
int fragGlslLineOf(const FragFile& f, const std::string& needle) {
    const size_t at = f.glsl.find(needle);
    if (at == std::string::npos) return -1;
    return int(std::count(f.glsl.begin(), f.glsl.begin() + long(at), '\n'));
}

TEST(FragFile, SliderAnnotationsOfEveryShape) {
    const FragFile f = loadTestFrag("box_fold.frag");
    const FragUniform* iterations = f.findUniform("Iterations");
    ASSERT_NE(iterations, nullptr);
    EXPECT_EQ(iterations->type, "int");
    EXPECT_EQ(iterations->kind, UniformKind::Slider);
    EXPECT_EQ(iterations->minimum, std::vector<double>{0});
    EXPECT_EQ(iterations->value, std::vector<double>{12});
    EXPECT_EQ(iterations->maximum, std::vector<double>{50});
    EXPECT_EQ(iterations->tooltip, "Iterations of the fold");
    EXPECT_EQ(iterations->group, "Box");
    EXPECT_EQ(iterations->lock, Lock::None);

    const FragUniform* scale = f.findUniform("Scale");
    ASSERT_NE(scale, nullptr);
    EXPECT_EQ(scale->value, std::vector<double>{2.0});
    EXPECT_EQ(scale->minimum, std::vector<double>{-3});
    EXPECT_EQ(scale->lock, Lock::Locked);
    EXPECT_EQ(f.findUniform("FixedRadius")->lock, Lock::NotLocked);
    EXPECT_EQ(f.findUniform("MinRadius")->tooltip, "");  // no comment line just before it

    const FragUniform* offset = f.findUniform("Offset4");
    ASSERT_NE(offset, nullptr);
    EXPECT_EQ(offset->kind, UniformKind::Slider);
    EXPECT_EQ(offset->minimum, (std::vector<double>{-1, -1, -1, -1}));
    EXPECT_EQ(offset->value, (std::vector<double>{0, 0, 0, 0}));
    EXPECT_EQ(offset->maximum, (std::vector<double>{1, 1, 1, 1}));
    const FragUniform* twist = f.findUniform("Twist");
    ASSERT_NE(twist, nullptr);
    EXPECT_EQ(twist->value, (std::vector<double>{0.5, 0.25}));

    const FragUniform* tiny = f.findUniform("Tiny");
    ASSERT_NE(tiny, nullptr);
    EXPECT_TRUE(tiny->logarithmic);
    EXPECT_DOUBLE_EQ(tiny->minimum[0], 1e-5);
    EXPECT_DOUBLE_EQ(tiny->value[0], 1e-3);

    const FragFile bulb = loadTestFrag("bulb_rotated.frag");
    const FragUniform* julia = bulb.findUniform("JuliaC");
    ASSERT_NE(julia, nullptr);
    EXPECT_EQ(julia->type, "vec3");
    EXPECT_EQ(julia->value, (std::vector<double>{0.2, -0.1, 0.3}));
    EXPECT_EQ(julia->group, "Bulb");
    EXPECT_EQ(bulb.findUniform("RotAxis")->group, "Rotation");
    EXPECT_EQ(bulb.findUniform("RotAngle")->tooltip, "Angle of the turn, in degrees");
    EXPECT_EQ(bulb.where(julia->where), (fragDataDir() / "bulb_rotated.frag").string() + ":19");
}

TEST(FragFile, CheckboxColourMenuAndFileAnnotations) {
    const FragFile f = loadTestFrag("box_fold.frag");
    const FragUniform* fixed = f.findUniform("Fixed");
    ASSERT_NE(fixed, nullptr);
    EXPECT_EQ(fixed->kind, UniformKind::Checkbox);
    EXPECT_TRUE(fixed->checked);  // TRUE, in any case
    EXPECT_EQ(fixed->lock, Lock::AlwaysLocked);
    const FragFile bulb = loadTestFrag("bulb_rotated.frag");
    EXPECT_EQ(bulb.findUniform("Julia")->kind, UniformKind::Checkbox);
    EXPECT_FALSE(bulb.findUniform("Julia")->checked);

    const FragUniform* colour = f.findUniform("BoxColor");
    ASSERT_NE(colour, nullptr);
    EXPECT_EQ(colour->kind, UniformKind::Color);
    EXPECT_EQ(colour->value, (std::vector<double>{0.8, 0.5, 0.25}));
    EXPECT_EQ(colour->tooltip, "Colour of the box");

    const FragUniform* glow = f.findUniform("BoxGlow");
    ASSERT_NE(glow, nullptr);
    EXPECT_EQ(glow->kind, UniformKind::FloatColor);
    EXPECT_EQ(glow->minimum, std::vector<double>{0});
    EXPECT_EQ(glow->value, std::vector<double>{0.3});
    EXPECT_EQ(glow->maximum, std::vector<double>{1});
    EXPECT_EQ(glow->colour, (std::vector<double>{1.0, 0.9, 0.5}));
    EXPECT_EQ(glow->lock, Lock::NotLockable);

    const FragUniform* menu = f.findUniform("FoldKind");
    ASSERT_NE(menu, nullptr);
    EXPECT_EQ(menu->kind, UniformKind::Menu);
    EXPECT_EQ(menu->menuDefault, 1);
    EXPECT_EQ(menu->menuItems, (std::vector<std::string>{"Box", "Sphere", "Both"}));
    EXPECT_EQ(menu->tooltip, "The fold to use");

    const FragUniform* file = f.findUniform("Palette");
    ASSERT_NE(file, nullptr);
    EXPECT_EQ(file->kind, UniformKind::File);
    EXPECT_EQ(file->file, "palette.png");

    // The raytracer's annotations, with FragM's trailing ';' after the ']'.
    const FragUniform* ao = f.findUniform("AO");
    ASSERT_NE(ao, nullptr);
    EXPECT_EQ(ao->kind, UniformKind::FloatColor);
    EXPECT_EQ(ao->value, std::vector<double>{0.7});
    EXPECT_EQ(f.findUniform("Detail")->value, std::vector<double>{-2.3});
    EXPECT_EQ(f.findUniform("NormalBackStep")->lock, Lock::Locked);
    EXPECT_EQ(f.findUniform("Detail")->group, "Raytracer");
    EXPECT_EQ(f.findUniform("Detail")->tooltip, "Distance to the surface, as a power of ten of the ray length");
}

TEST(FragFile, AnnotationsAreStrippedFromTheGlsl) {
    const FragFile f = loadTestFrag("box_fold.frag");
    EXPECT_EQ(f.glsl.find("slider["), std::string::npos);
    EXPECT_EQ(f.glsl.find("color["), std::string::npos);
    EXPECT_EQ(f.glsl.find("menu["), std::string::npos);
    EXPECT_EQ(f.glsl.find("checkbox["), std::string::npos);
    EXPECT_NE(f.glsl.find("uniform vec4 BoxGlow;\n"), std::string::npos);
    EXPECT_NE(f.glsl.find("uniform int FoldKind;\n"), std::string::npos);
    // FragM's own directives stay as comments; presets leave the GLSL.
    EXPECT_NE(f.glsl.find("// #group Box\n"), std::string::npos);
    EXPECT_EQ(f.glsl.find("#preset"), std::string::npos);
    EXPECT_EQ(f.glsl.find("Iterations = 14"), std::string::npos);
    EXPECT_EQ(f.glsl.find("#include"), std::string::npos);
}

TEST(FragFile, PlainUniformsAreRecordedToo) {
    const FragFile f = loadTestFrag("bulb_rotated.frag");
    const FragUniform* time = f.findUniform("time");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->kind, UniformKind::Plain);
    EXPECT_EQ(time->type, "float");
    EXPECT_NE(f.glsl.find("uniform float time;"), std::string::npos);
    const FragUniform* pixelSize = f.findUniform("pixelSize");
    ASSERT_NE(pixelSize, nullptr);
    EXPECT_EQ(pixelSize->kind, UniformKind::Plain);

    const FragFile list = parseFragFile(
        "uniform float a, b[3];\nuniform vec3 c = vec3(1.0);\nfloat DE(vec3 p) { return a; }\n", "list.frag");
    ASSERT_EQ(list.uniforms.size(), 3u);
    EXPECT_EQ(list.uniforms[1].name, "b");
    EXPECT_EQ(list.uniforms[1].arraySize, "[3]");
    EXPECT_EQ(list.uniforms[2].name, "c");
}

TEST(FragFile, DirectivesAreRecorded) {
    const FragFile f = loadTestFrag("bulb_rotated.frag");
    ASSERT_EQ(f.info.size(), 3u);  // two of its own, one of 3D.frag's
    EXPECT_EQ(f.info[0].argument, "A power bulb turned by a rotation computed once per frame in init().");
    EXPECT_FALSE(f.doNotRun);
    EXPECT_EQ(f.provides, std::set<std::string>{"providesInit"});
    ASSERT_EQ(f.camera.size(), 1u);
    EXPECT_EQ(f.camera[0].argument, "3D");
    ASSERT_EQ(f.buffer.size(), 1u);
    EXPECT_EQ(f.buffer[0].argument, "RGBA32F");
    ASSERT_EQ(f.bufferShaders.size(), 1u);
    EXPECT_EQ(f.bufferShaders[0].argument, "BufferShader.frag");
    EXPECT_EQ(f.files[size_t(f.bufferShaders[0].where.file)].includeName, "3D.frag");
    const auto pi =
        std::find_if(f.defines.begin(), f.defines.end(), [](const FragDefine& d) { return d.name == "PI"; });
    ASSERT_NE(pi, f.defines.end());
    EXPECT_EQ(pi->value, "3.141592653589793");

    const FragFile slicer = loadTestFrag("slicer_style.frag");
    EXPECT_EQ(slicer.provides, std::set<std::string>{"providesColor"});
    EXPECT_TRUE(loadTestFrag("include/3D.frag").doNotRun);

    const FragFile replaced = parseFragFile(
        "#replace \"Radius\" \"R\"\nuniform float Radius; slider[0,1,2]\nfloat DE(vec3 p) { return Radius; }\n",
        "r.frag");
    ASSERT_EQ(replaced.replacements.size(), 1u);
    EXPECT_NE(replaced.findUniform("R"), nullptr);
    EXPECT_NE(replaced.glsl.find("return R;"), std::string::npos);
}

TEST(FragFile, VertexSectionsAreKeptApart) {
    const FragFile f = loadTestFrag("slicer_style.frag");
    EXPECT_NE(f.vertex.find("void computeSpin()"), std::string::npos);
    EXPECT_NE(f.vertex.find("gl_Position = gl_Vertex;"), std::string::npos);  // 3D.frag's
    EXPECT_EQ(f.glsl.find("computeSpin"), std::string::npos);
    EXPECT_EQ(f.glsl.find("gl_Position"), std::string::npos);
    const FragUniform* spin = f.findUniform("Spin");
    ASSERT_NE(spin, nullptr);
    EXPECT_TRUE(spin->inVertex);
    EXPECT_TRUE(f.findUniform("Eye")->inVertex);
    EXPECT_EQ(f.findUniform("Eye")->lock, Lock::NotLockable);
    EXPECT_FALSE(f.findUniform("Spacing")->inVertex);
    ASSERT_EQ(f.vertex.size() > 0, true);
    const int spinLine = int(std::count(f.vertex.begin(), f.vertex.begin() + long(f.vertex.find("computeSpin")), '\n'));
    EXPECT_EQ(f.where(f.vertexLines[size_t(spinLine)]), (fragDataDir() / "slicer_style.frag").string() + ":10");
}

TEST(FragFile, IncludesResolveNextToTheFileThenIncludeDirsThenBuiltins) {
    const FragFile f = loadTestFrag("bulb_rotated.frag");
    ASSERT_EQ(f.files.size(), 4u);
    EXPECT_EQ(f.files[1].includeName, "MathUtils.frag");
    EXPECT_TRUE(f.files[1].builtin);
    EXPECT_EQ(f.files[1].name, "built-in MathUtils.frag");
    EXPECT_EQ(f.files[2].path, fragDataDir() / "include" / "DE-Raytracer.frag");
    EXPECT_EQ(f.files[3].path, fragDataDir() / "include" / "3D.frag");  // next to DE-Raytracer.frag

    // The including file's folder wins over the include dirs, and those over the built-ins.
    FragSandbox box("fraktal_frag_order_");
    box.write("main/a.frag", "#include \"x.frag\"\n#include \"y.frag\"\n#include \"z.frag\"\n");
    box.write("main/x.frag", "float fromNextTo;\n");
    box.write("dir/x.frag", "float fromDirX;\n");
    box.write("dir/y.frag", "float fromDir;\n");
    FragOptions options;
    options.includeDirs = {box.dir / "dir"};
    options.builtinIncludes = {
        {"x.frag", "float builtinX;"}, {"y.frag", "float builtinY;"}, {"z.frag", "float builtinZ;"}};
    const FragFile order = loadFragFile(box.dir / "main/a.frag", options);
    EXPECT_NE(order.glsl.find("fromNextTo"), std::string::npos);
    EXPECT_NE(order.glsl.find("fromDir;"), std::string::npos);
    EXPECT_NE(order.glsl.find("builtinZ"), std::string::npos);
    EXPECT_EQ(order.glsl.find("fromDirX"), std::string::npos);
    EXPECT_EQ(order.glsl.find("builtinX"), std::string::npos);
    EXPECT_EQ(order.glsl.find("builtinY"), std::string::npos);
}

TEST(FragFile, SourceMapFollowsTwoLevelsOfIncludes) {
    const FragFile f = loadTestFrag("box_fold.frag");
    ASSERT_EQ(f.glsl.size() > 0, true);
    ASSERT_EQ(size_t(std::count(f.glsl.begin(), f.glsl.end(), '\n')), f.glslLines.size());
    // box_fold.frag -> shared/fold_helpers.frag -> shared/fold_constants.frag (next to fold_helpers).
    const int constant = fragGlslLineOf(f, "const float FOLD_LIMIT_DEFAULT");
    ASSERT_GE(constant, 0);
    EXPECT_EQ(f.where(f.glslSource(constant)), (fragDataDir() / "shared" / "fold_constants.frag").string() + ":3");
    const int fold = fragGlslLineOf(f, "void boxFold(");
    EXPECT_EQ(f.where(f.glslSource(fold)), (fragDataDir() / "shared" / "fold_helpers.frag").string() + ":9");
    const int de = fragGlslLineOf(f, "float DE(vec3 p)");
    EXPECT_EQ(f.where(f.glslSource(de)), (fragDataDir() / "box_fold.frag").string() + ":25");
    // The line after an include continues in the including file.
    const int group = fragGlslLineOf(f, "// #group Box");
    EXPECT_EQ(f.where(f.glslSource(group)), (fragDataDir() / "box_fold.frag").string() + ":5");
    // The group falls back to the default after an include ends, as in FragM.
    const FragFile g =
        parseFragFile("#include \"g.frag\"\nuniform float After; slider[0,1,2]\n", "m.frag",
                      FragOptions{{}, {{"g.frag", "#group Inner\nuniform float Inside; slider[0,1,2]\n"}}});
    EXPECT_EQ(g.findUniform("Inside")->group, "Inner");
    EXPECT_EQ(g.findUniform("After")->group, "");
}

TEST(FragFile, PresetsKeepOrderValuesTuplesAndLocks) {
    const FragFile f = loadTestFrag("bulb_rotated.frag");
    ASSERT_EQ(f.presets.size(), 2u);
    EXPECT_EQ(f.presets[0].name, "Default");
    EXPECT_EQ(f.presets[1].name, "Julia");
    const FragPreset& def = f.presets[0];
    const PresetValue* eye = def.find("Eye");
    ASSERT_NE(eye, nullptr);
    EXPECT_EQ(eye->raw, "1.65,-1.2,0.28");
    EXPECT_EQ(eye->numbers, (std::vector<double>{1.65, -1.2, 0.28}));
    EXPECT_EQ(eye->lock, Lock::None);
    const PresetValue* power = def.find("Power");
    ASSERT_NE(power, nullptr);
    EXPECT_EQ(power->raw, "8 Locked");
    EXPECT_EQ(power->text, "8");
    EXPECT_EQ(power->numbers, std::vector<double>{8});
    EXPECT_EQ(power->lock, Lock::Locked);
    const PresetValue* juliaC = def.find("JuliaC");
    EXPECT_EQ(juliaC->lock, Lock::NotLocked);
    EXPECT_EQ(juliaC->numbers, (std::vector<double>{0.2, -0.1, 0.3}));
    const PresetValue* julia = f.presets[1].find("Julia");
    ASSERT_TRUE(julia->boolean.has_value());
    EXPECT_TRUE(*julia->boolean);
    EXPECT_TRUE(julia->numbers.empty());
    EXPECT_EQ(f.presets[1].find("Bailout")->lock, Lock::Locked);
    EXPECT_EQ(f.where(def.where), (fragDataDir() / "bulb_rotated.frag").string() + ":62");
    EXPECT_EQ(f.where(power->where), (fragDataDir() / "bulb_rotated.frag").string() + ":72");

    const FragFile box = loadTestFrag("box_fold.frag");
    const PresetValue* tiny = box.presets[0].find("Tiny");
    EXPECT_TRUE(tiny->logarithmic);
    EXPECT_EQ(tiny->numbers, std::vector<double>{0.001});
    EXPECT_EQ(box.presets[0].find("Fixed")->lock, Lock::AlwaysLocked);
    EXPECT_EQ(box.presets[0].find("BoxGlow")->numbers, (std::vector<double>{1, 0.9, 0.5, 0.3}));

    // FragM's preset lines: comments skipped, easing curves apart, a later key wins, a line that
    // is not `key = value` warned about and skipped, a value of text kept as text.
    const FragFile odd = parseFragFile(
        "float DE(vec3 p) { return 1.0; }\n#preset P\n// note\n#comment\nA = 1\nA = 2 Locked;\nnot a pair\n"
        "Eye:0:1:0:0:1:30:0:0:0:0:0\nTex = images/sky.png\n#endpreset\n",
        "odd.frag");
    ASSERT_EQ(odd.presets.size(), 1u);
    EXPECT_EQ(odd.presets[0].find("A")->numbers, std::vector<double>{2});
    EXPECT_EQ(odd.presets[0].find("A")->lock, Lock::Locked);
    EXPECT_EQ(odd.presets[0].easing.size(), 1u);
    EXPECT_EQ(odd.presets[0].find("Tex")->text, "images/sky.png");
    EXPECT_TRUE(odd.presets[0].find("Tex")->numbers.empty());
    ASSERT_EQ(odd.warnings.size(), 1u);
    EXPECT_EQ(odd.warnings[0].where.line, 7);
}

TEST(FragFile, DefaultPresetFollowsFragMsRule) {
    // The first name in sorted order that contains "default" in any case: "A default of sorts"
    // sorts before "Default".
    const FragFile box = loadTestFrag("box_fold.frag");
    ASSERT_NE(box.defaultPreset(), nullptr);
    EXPECT_EQ(box.defaultPreset()->name, "A default of sorts");
    // "Default" sorts before "KeyFrame.001", "Zeta" and "default-wide" (upper case first).
    const FragFile slicer = loadTestFrag("slicer_style.frag");
    EXPECT_EQ(slicer.defaultPreset()->name, "Default");
    EXPECT_TRUE(slicer.findPreset("KeyFrame.001")->keyFrame());
    EXPECT_FALSE(slicer.findPreset("Default")->keyFrame());
    EXPECT_EQ(loadTestFrag("bulb_rotated.frag").defaultPreset()->name, "Default");
    // None without such a name; a later block of a name replaces the earlier one.
    EXPECT_EQ(parseFragFile("#preset Start\nA = 1\n#endpreset\n", "n.frag").defaultPreset(), nullptr);
    const FragFile twice =
        parseFragFile("#preset Default\nA = 1\n#endpreset\n#preset Default\nA = 2\n#endpreset\n", "t.frag");
    ASSERT_EQ(twice.presets.size(), 2u);
    EXPECT_EQ(twice.defaultPreset()->find("A")->numbers, std::vector<double>{2});
}

TEST(FragFile, FunctionsAreFoundPastCommentsAndBraces) {
    const FragFile f = loadTestFrag("bulb_rotated.frag");
    const FragFunction* de = f.deFunction();
    ASSERT_NE(de, nullptr);
    EXPECT_EQ(de->returnType, "float");
    EXPECT_EQ(de->parameters, "vec3 pos");
    EXPECT_TRUE(f.functionSource(*de).starts_with("float DE(vec3 pos) {"));
    EXPECT_TRUE(f.functionSource(*de).ends_with("return 0.5 * log(r) * r / dr;\n}"));
    EXPECT_EQ(f.where(f.glslSource(de->firstLine)), (fragDataDir() / "bulb_rotated.frag").string() + ":46");
    EXPECT_EQ(f.where(f.glslSource(de->lastLine)), (fragDataDir() / "bulb_rotated.frag").string() + ":60");

    const FragFunction* power = f.findFunction("bulbPower");
    ASSERT_NE(power, nullptr);
    EXPECT_EQ(power->returnType, "void");
    EXPECT_EQ(power->parameters, "inout vec3 z, float r, inout float dr");
    EXPECT_EQ(f.findFunction("fakeFunction"), nullptr);     // inside a /* comment */
    EXPECT_NE(f.findFunction("rotationMatrix3"), nullptr);  // from the built-in include
    EXPECT_NE(f.findFunction("color"), nullptr);            // from the include dir

    // providesInit is defined: 3D.frag's `void init() {}` in its #else is inactive, so the
    // frag's own init() is the one definition; the #ifdef branch's prototype is seen.
    int inits = 0, prototypes = 0;
    for (const auto& fn : f.functions)
        if (fn.name == "init") (fn.definition ? inits : prototypes)++;
    EXPECT_EQ(inits, 1);
    EXPECT_EQ(prototypes, 1);
    EXPECT_NE(f.functionSource(*f.findFunction("init")).find("rotationMatrix3"), std::string::npos);

    // The globals the DE and init() use.
    const auto turn =
        std::find_if(f.globals.begin(), f.globals.end(), [](const FragGlobal& g) { return g.text == "mat3 turn"; });
    EXPECT_NE(turn, f.globals.end());
    const auto trap = std::find_if(f.globals.begin(), f.globals.end(),
                                   [](const FragGlobal& g) { return g.text.starts_with("vec4 orbitTrap = vec4("); });
    EXPECT_NE(trap, f.globals.end());

    // Without providesInit, 3D.frag's empty init() is the active one.
    const FragFile slicer = loadTestFrag("slicer_style.frag");
    ASSERT_NE(slicer.findFunction("init"), nullptr);
    EXPECT_EQ(slicer.functionSource(*slicer.findFunction("init")), "void init() {}");
    const FragFunction* sde = slicer.deFunction();
    ASSERT_NE(sde, nullptr);
    EXPECT_EQ(sde->parameters, "vec3 pos, int type");
    EXPECT_NE(slicer.findFunction("baseColor"), nullptr);

    // Structs, prototypes, #if 0 and braces on their own lines.
    const FragFile s = parseFragFile(
        "struct Ray { vec3 o; vec3 d; };\n"
        "float helper(float x);\n"
        "#if 0\n"
        "float DE(vec3 p) { return 0.0; }\n"
        "#endif\n"
        "float helper(float x)\n{\n  if (x > 0.0) { return x; }\n  return -x;\n}\n"
        "float DE(in vec3 p)\n{\n  return helper(p.x);\n}\n",
        "s.frag");
    ASSERT_EQ(s.functions.size(), 3u);
    EXPECT_FALSE(s.functions[0].definition);
    EXPECT_EQ(s.functions[1].name, "helper");
    EXPECT_EQ(s.functions[1].firstLine, 5);
    EXPECT_EQ(s.functions[1].lastLine, 9);
    ASSERT_NE(s.deFunction(), nullptr);
    EXPECT_EQ(s.deFunction()->firstLine, 10);
    EXPECT_EQ(s.globals.size(), 1u);
    EXPECT_TRUE(s.globals[0].text.starts_with("struct Ray"));
    // No DE: a vec3 DE returning a vec3, or one taking a float, does not count.
    EXPECT_EQ(parseFragFile("vec3 DE(vec3 p) { return p; }\nfloat DE(float x) { return x; }\n", "n.frag").deFunction(),
              nullptr);
}

TEST(FragFile, ConditionalsPickTheActiveFunctionsAndDefines) {
    const std::string text =
        "#version 330\n#define A 2\n#define B A\n"
        "#if __VERSION__ >= 400\nfloat newGlsl() { return 0.0; }\n"
        "#elif (B * 3 == 6) && !defined(C)\nfloat middle() { return 1.0; }\n#define providesColor\n"
        "#else\nfloat last() { return 2.0; }\n#define providesInit\n#endif\n"
        "#ifndef A\nfloat notA() { return 3.0; }\n#endif\n"
        "#if defined A || defined(Z)\nfloat either() { return 4.0; }\n#endif\n"
        "#if UNKNOWN_NAME\nfloat zero() { return 5.0; }\n#endif\n"
        "float DE(vec3 p) { return middle(); }\n";
    const FragFile f = parseFragFile(text, "c.frag");
    std::vector<std::string> names;
    for (const auto& fn : f.functions) names.push_back(fn.name);
    EXPECT_EQ(names, (std::vector<std::string>{"middle", "either", "DE"}));
    EXPECT_EQ(f.provides, std::set<std::string>{"providesColor"});
    EXPECT_TRUE(f.warnings.empty());
    // The caller's GLSL version decides __VERSION__ when it gives one.
    FragOptions at450;
    at450.glslVersion = 450;
    EXPECT_NE(parseFragFile(text, "c.frag", at450).findFunction("newGlsl"), nullptr);
    // An expression it cannot read: its first branch counts, with a warning naming the line.
    const FragFile odd = parseFragFile("\n#if A +\nfloat a() { return 1.0; }\n#endif\n", "o.frag");
    EXPECT_NE(odd.findFunction("a"), nullptr);
    ASSERT_EQ(odd.warnings.size(), 1u);
    EXPECT_EQ(odd.where(odd.warnings[0].where), "o.frag:2");
}

// Every error names the file and the line where the fault is.
void expectFragError(const PresetError& e, const std::string& file, int line, const std::string& reasonPart) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.field(), "line " + std::to_string(line)) << e.what();
    EXPECT_NE(e.reason().find(reasonPart), std::string::npos) << e.what();
}

TEST(FragFile, ErrorsNameFileAndLine) {
    expectFragError(fragErrorOf("float a;\n/* open\nfloat b;\n"), "test.frag", 2, "never closed");
    expectFragError(fragErrorOf("float a;\n#preset Default\nA = 1\n"), "test.frag", 2, "no #endpreset");
    expectFragError(fragErrorOf("\nuniform vec3 V; slider[(0,0,0),(1,1),(2,2,2)]\n"), "test.frag", 2,
                    "three tuples of 3");
    expectFragError(fragErrorOf("uniform vec3 V; slider[(0,0,0),(1,1,1)]\n"), "test.frag", 1, "three tuples");
    expectFragError(fragErrorOf("uniform vec2 V; slider[(0,0),(1,x),(2,2)]\n"), "test.frag", 1, "vec2 slider");
    expectFragError(fragErrorOf("uniform int N; slider[0,2.5,10]\n"), "test.frag", 1, "whole numbers");
    expectFragError(fragErrorOf("uniform float F; slider[0,1]\n"), "test.frag", 1, "three numbers");
    expectFragError(fragErrorOf("uniform float F; slider[0,1,2\n"), "test.frag", 1, "no closing ]");
    expectFragError(fragErrorOf("uniform float F; checkbox[true]\n"), "test.frag", 1, "checkbox on a float");
    expectFragError(fragErrorOf("uniform bool B; checkbox[maybe]\n"), "test.frag", 1, "true or false");
    expectFragError(fragErrorOf("uniform vec4 C; color[1,1,1]\n"), "test.frag", 1, "six numbers");
    expectFragError(fragErrorOf("uniform float C; color[1,1,1]\n"), "test.frag", 1, "vec3 or a vec4");
    expectFragError(fragErrorOf("uniform int M; menu[x, a;b]\n"), "test.frag", 1, "menu");
    expectFragError(fragErrorOf("uniform float F; knob[0,1,2]\n"), "test.frag", 1, "unknown annotation");
    expectFragError(fragErrorOf("uniform float F; slider[0,1,2] Lockd\n"), "test.frag", 1, "'Lockd'");
    expectFragError(fragErrorOf("uniform float F slider[0,1,2]\n"), "test.frag", 1, "';' is missing");
    expectFragError(fragErrorOf("#vertex\nvoid main() {}\n"), "test.frag", 1, "no #endvertex");
    expectFragError(fragErrorOf("#endvertex\n"), "test.frag", 1, "without #vertex");
    expectFragError(fragErrorOf("#include <MathUtils.frag>\n"), "test.frag", 1, "in quotes");
    expectFragError(fragErrorOf("#replace \"a\"\n"), "test.frag", 1, "#replace");
    // Braces that do not balance: the DE's '{' that is never closed, a stray '}'.
    expectFragError(fragErrorOf("float a;\nfloat DE(vec3 p) {\n  if (p.x > 0.0) {\n  return 1.0;\n}\n"), "test.frag", 2,
                    "DE()");
    expectFragError(fragErrorOf("float DE(vec3 p) { return 1.0; }\n}\n"), "test.frag", 2, "without a '{'");
}

TEST(FragFile, IncludeErrorsNameTheIncludingFile) {
    FragSandbox box("fraktal_frag_errors_");
    // Not found, two levels down: the message names the file that has the #include and its line.
    box.write("a.frag", "float a;\n#include \"b.frag\"\n");
    box.write("b.frag", "// b\n\n#include \"missing.frag\"\n");
    FragOptions options;
    options.includeDirs = {box.dir / "nowhere"};
    options.builtinIncludes["other.frag"] = "";
    try {
        loadFragFile(box.dir / "a.frag", options);
        ADD_FAILURE() << "no error";
    } catch (const PresetError& e) {
        expectFragError(e, (box.dir / "b.frag").string(), 3, "\"missing.frag\" not found");
        EXPECT_NE(e.reason().find((box.dir / "nowhere").string()), std::string::npos) << e.what();
        EXPECT_NE(e.reason().find("built-in"), std::string::npos) << e.what();
    }
    // A cycle a -> c -> d -> c.
    box.write("c.frag", "#include \"d.frag\"\n");
    box.write("d.frag", "float d;\n#include \"c.frag\"\n");
    box.write("top.frag", "#include \"c.frag\"\n");
    try {
        loadFragFile(box.dir / "top.frag");
        ADD_FAILURE() << "no error";
    } catch (const PresetError& e) {
        expectFragError(e, (box.dir / "d.frag").string(), 2, "include cycle");
        EXPECT_NE(
            e.reason().find("c.frag -> " + (box.dir / "d.frag").string() + " -> " + (box.dir / "c.frag").string()),
            std::string::npos)
            << e.what();
    }
    // A file including itself, and a cycle through built-ins.
    box.write("self.frag", "#include \"self.frag\"\n");
    EXPECT_THROW(loadFragFile(box.dir / "self.frag"), PresetError);
    FragOptions loop;
    loop.builtinIncludes = {{"p.frag", "#include \"q.frag\"\n"}, {"q.frag", "\n#include \"p.frag\"\n"}};
    expectFragError(fragErrorOf("#include \"p.frag\"\n", "m.frag", loop), "built-in q.frag", 2, "include cycle");
    // An error inside an included file names that file.
    box.write("bad_inner.frag", "float x;\nuniform float F; slider[0,1]\n");
    box.write("bad_outer.frag", "#include \"bad_inner.frag\"\n");
    try {
        loadFragFile(box.dir / "bad_outer.frag");
        ADD_FAILURE() << "no error";
    } catch (const PresetError& e) {
        expectFragError(e, (box.dir / "bad_inner.frag").string(), 2, "slider");
    }
    // A diamond (the same file twice, no cycle) is not an error: FragM includes it twice.
    box.write("leaf.frag", "float leaf;\n");
    box.write("l.frag", "#include \"leaf.frag\"\n");
    box.write("r.frag", "#include \"leaf.frag\"\n");
    box.write("diamond.frag", "#include \"l.frag\"\n#include \"r.frag\"\n");
    const FragFile diamond = loadFragFile(box.dir / "diamond.frag");
    EXPECT_EQ(diamond.globals.size(), 2u);
    EXPECT_EQ(diamond.files.size(), 4u);
}

TEST(FragFile, BadInputNeverCrashes) {
    // Every prefix and many corruptions of a real frag either parse or throw PresetError.
    std::ifstream in(fragDataDir() / "bulb_rotated.frag", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(text.size(), 1000u);
    const FragOptions options = fragTestOptions();
    const fs::path path = fragDataDir() / "bulb_rotated.frag";
    int parsed = 0, refused = 0;
    auto attempt = [&](const std::string& t) {
        try {
            parseFragFile(t, path, options);
            ++parsed;
        } catch (const PresetError&) {
            ++refused;
        }
    };
    for (size_t n = 0; n <= text.size(); n += 7) attempt(text.substr(0, n));
    std::mt19937 rng(53);
    const std::string alphabet = "{}()[];,/*#\"\n =.0123456789abcxyzslider";
    for (int k = 0; k < 400; ++k) {
        std::string t = text;
        for (int m = 0; m < 4; ++m) t[rng() % t.size()] = alphabet[rng() % alphabet.size()];
        attempt(t);
    }
    EXPECT_GT(parsed, 0);
    EXPECT_GT(refused, 0);
    // Empty text, one huge line, deep nesting of braces.
    attempt("");
    attempt(std::string(100000, '{'));
    attempt(std::string(100000, '}'));
    attempt(std::string(200000, 'x'));
}

TEST(FragFile, EveryTestFragParsesAndEachRunnableOneHasADe) {
    int runnable = 0, includes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(fragDataDir())) {
        if (!entry.is_regular_file() || !isFragPath(entry.path())) continue;
        SCOPED_TRACE(entry.path().string());
        FragFile f;
        try {
            f = loadFragFile(entry.path(), fragTestOptions());
        } catch (const PresetError& e) {
            ADD_FAILURE() << e.what();
            continue;
        }
        EXPECT_TRUE(f.warnings.empty()) << f.where(f.warnings[0].where) << ": " << f.warnings[0].message;
        if (f.doNotRun) {
            ++includes;
            continue;
        }
        ++runnable;
        EXPECT_NE(f.deFunction(), nullptr);
        EXPECT_FALSE(f.presets.empty());
        EXPECT_NE(f.defaultPreset(), nullptr);
    }
    EXPECT_GE(runnable, 3);
    EXPECT_GE(includes, 4);
}

TEST(FragFile, NumbersAndPaths) {
    EXPECT_EQ(parseFragNumber("1"), 1.0);
    EXPECT_EQ(parseFragNumber(" -0.5 "), -0.5);
    EXPECT_EQ(parseFragNumber(".5"), 0.5);
    EXPECT_EQ(parseFragNumber("5."), 5.0);
    EXPECT_EQ(parseFragNumber("+2"), 2.0);
    EXPECT_EQ(parseFragNumber("1e-3"), 1e-3);
    EXPECT_FALSE(parseFragNumber(""));
    EXPECT_FALSE(parseFragNumber("1,5"));
    EXPECT_FALSE(parseFragNumber("nan"));
    EXPECT_FALSE(parseFragNumber("+-1"));
    EXPECT_TRUE(isFragPath("a/b/Mandelbulb.FRAG"));
    EXPECT_FALSE(isFragPath("a.fract"));
    EXPECT_STREQ(lockName(Lock::AlwaysLocked), "AlwaysLocked");
    EXPECT_STREQ(uniformKindName(UniformKind::FloatColor), "floatcolor");
}

}  // namespace
}  // namespace fraktal::frag
