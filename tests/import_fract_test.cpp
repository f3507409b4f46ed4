// Mandelbulber2 settings files: the parser, the mapping onto blocks, `fraktal import` as a person
// runs it, and a fixed set of Mandelbulber2's own example files rendered by both programs, whose
// silhouettes must agree (or whose refusal must name its reason). Mandelbulber2 comes from
// scripts/install-deps.sh; its masks are computed here, never stored.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <thread>

#include "bench/import/silhouette.hpp"
#include "core/image/png_writer.hpp"
#include "core/import/fract_import.hpp"
#include "core/import/mb2_sequence.hpp"
#include "core/random_vec.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

namespace fs = std::filesystem;
using mb2::FractFile;
using mb2::parseFractFile;

const std::string kHeader = "# Mandelbulber settings file\n# version 2.20\n# only modified parameters\n";

mb2::FractImport importText(const std::string& body) {
    return mb2::importFract(parseFractFile(kHeader + body, "t.fract"));
}

std::vector<std::string> blockIds(const Formula& f) {
    std::vector<std::string> ids;
    for (const Node& n : f.nodes) ids.emplace_back(n.block->id);
    return ids;
}

double param(const Node& n, std::string_view name, int component = 0) {
    return n.values[size_t(n.block->paramIndex(name))][component];
}

bool mentions(const std::vector<mb2::ImportItem>& items, const std::string& where, const std::string& what) {
    for (const auto& item : items)
        if (item.where == where && item.what.find(what) != std::string::npos) return true;
    return false;
}

TEST(FractFile, ReadsLocaleDecimalsVectorsColoursAndBooleans) {
    const FractFile f = parseFractFile(kHeader +
                                           "[main_parameters]\ncamera 1,5 -2,25 0,125;\nfov 1,2;\nbackground_color_1 "
                                           "ffff 8000 0000;\nlegacy_coordinate_system true;\n[fractal_1]\npower 7;\n",
                                       "t.fract");
    EXPECT_EQ(f.version, "2.20");
    EXPECT_EQ(*mb2::parseVector(f.find("main_parameters", "camera")->value), vec3(1.5, -2.25, 0.125));
    EXPECT_DOUBLE_EQ(*mb2::parseNumber(f.find("main_parameters", "fov")->value), 1.2);
    const vec3 c = *mb2::parseColour(f.find("main_parameters", "background_color_1")->value);
    EXPECT_DOUBLE_EQ(c.x, 1.0);
    EXPECT_NEAR(c.y, 0.5, 1e-4);
    EXPECT_EQ(mb2::parseBoolean(f.find("main_parameters", "legacy_coordinate_system")->value), true);
    EXPECT_EQ(f.find("fractal_1", "power")->line, 10);
    EXPECT_FALSE(mb2::parseVector("1 2"));
    EXPECT_FALSE(mb2::parseNumber("1,2,3"));
}

TEST(FractFile, RefusesOtherFormatsAndBadLinesByName) {
    try {
        parseFractFile("Mandelbulber 1.2110000000000001;\nimage_width 800;\n", "old.fract");
        FAIL() << "a v1.21 file was read";
    } catch (const PresetError& e) {
        EXPECT_EQ(e.file(), "old.fract");
        EXPECT_NE(e.reason().find("v1.21 format"), std::string::npos) << e.what();
    }
    try {
        parseFractFile(kHeader + "[main_parameters]\nN 250;\ncamera 1 2 3\n", "bad.fract");
        FAIL() << "a line without ';' was read";
    } catch (const PresetError& e) {
        EXPECT_NE(e.field().find("line 6"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseFractFile("{\"format\": \"fraktal-preset\"}", "x.fract"), PresetError);
    EXPECT_THROW(parseFractFile(kHeader + "[main_parameters]\nN 250;\nN 100;\n", "twice.fract"), PresetError);
    // A value that is not a number names its parameter.
    try {
        importText("[main_parameters]\nN many;\n");
        FAIL();
    } catch (const PresetError& e) {
        EXPECT_NE(e.field().find("N"), std::string::npos);
        EXPECT_NE(e.reason().find("many"), std::string::npos);
    }
}

TEST(FractImport, DefaultsAreMandelbulber2sOwn) {
    // A file with no formula line is Mandelbulber2's default: a power-9 Mandelbulb (not fraktal's
    // 8), c added, the log DE, bailout 10, 250 iterations, its default camera and fov 1.
    const mb2::FractImport r = importText("[main_parameters]\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula), (std::vector<std::string>{"mandelbulb_sine", "add_c"}));
    EXPECT_EQ(param(r.preset.formula.nodes[0], "power"), 9.0);
    EXPECT_EQ(r.preset.formula.estimator.block->id, "escape_log");
    EXPECT_EQ(r.preset.formula.bailout, 10.0);
    EXPECT_EQ(r.preset.formula.iterations, 250);
    EXPECT_EQ(r.preset.camera.position, vec3(3, -6, 2));
    EXPECT_NEAR(r.preset.camera.fovY, 2.0 * glm::degrees(std::atan(0.5)), 1e-9);
    EXPECT_FALSE(r.preset.camera.flipVertical);
}

TEST(FractImport, ReflectionsAreTracedOnlyWhereTheMaterialReflects) {
    // The toolbar's nine files turn raytraced_reflections on at reflectance 0: Mandelbulber2
    // traces no reflected ray there (render_worker.cpp, `if (reflect > 0.0f)`), so fraktal marches
    // none either; a reflecting material keeps its share of the mirror image.
    EXPECT_EQ(importText("[main_parameters]\nraytraced_reflections true;\n").preset.shading.reflection, 0.0);
    EXPECT_EQ(importText("[main_parameters]\nmat1_reflectance 0,4;\n").preset.shading.reflection, 0.0);
    EXPECT_DOUBLE_EQ(
        importText("[main_parameters]\nraytraced_reflections true;\nmat1_reflectance 0,4;\n").preset.shading.reflection,
        0.4);
    EXPECT_EQ(
        importText("[main_parameters]\nraytraced_reflections true;\nmat1_reflectance 3;\n").preset.shading.reflection,
        1.0);
}

TEST(FractImport, MengerSpongeIsMengerRotateAboutItsCorner) {
    // abs, sort, z *= s, x and y less 2, z less 2 above 1: the corner 2 / (s - 1); DE (r - 2) / dr.
    const mb2::FractImport r = importText("[main_parameters]\nformula_1 7;\n[fractal_1]\ntransf_scale_3 2,5;\n");
    ASSERT_TRUE(r.faithful());
    ASSERT_EQ(blockIds(r.preset.formula), std::vector<std::string>{"menger_rotate"});
    const Node& n = r.preset.formula.nodes[0];
    EXPECT_DOUBLE_EQ(param(n, "scale"), 2.5);
    EXPECT_NEAR(param(n, "offset", 2), 2.0 / 1.5, 1e-12);
    EXPECT_EQ(r.preset.formula.estimator.block->id, "escape_linear");
    EXPECT_EQ(param(r.preset.formula.estimator, "offset"), 2.0);
    EXPECT_EQ(r.preset.formula.bailout, 10.0);
}

TEST(FractImport, HybridSlotsRunOnTheirPhasesOfTheCycle) {
    // Slot 1 (Mandelbox) twice, slot 2 (Mandelbulb) once: a cycle of 3, the box's nodes twice.
    const mb2::FractImport r = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 2;\nformula_iterations_1 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const auto ids = blockIds(r.preset.formula);
    // box_fold, sphere_fold, scale, add_c twice; mandelbulb_sine, add_c.
    ASSERT_EQ(ids.size(), 4u + 4u + 2u);
    for (size_t i = 0; i < ids.size(); ++i) {
        const Node& n = r.preset.formula.nodes[i];
        EXPECT_EQ(n.period, 3);
        EXPECT_EQ(n.phase, i < 4 ? 0 : i < 8 ? 1 : 2) << ids[i];
    }
    EXPECT_EQ(ids[4], "box_fold");
    EXPECT_EQ(ids[8], "mandelbulb_sine");
    // Linear for 2 of 3 iterations: the DE function most of the cycle uses; the larger bailout.
    EXPECT_EQ(r.preset.formula.estimator.block->id, "escape_linear");
    EXPECT_EQ(r.preset.formula.bailout, 100.0);
}

// Mandelbulber2's sequence, worked by hand from CreateSequence: slot 2 stops after iteration 3
// (its stop is inclusive); from then on the skip lands on slot 1 every time.
TEST(Mb2Sequence, SlotsOutsideTheirWindowAreSkipped) {
    mb2::SlotSequencing s;
    s.hybrid = true;
    s.runs[0] = s.runs[1] = true;
    s.count.fill(1);
    s.last.fill(250);
    s.last[1] = 3;
    const std::vector<int> expected{0, 1, 0, 1, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(mb2::slotOfEachIteration(s, 10), expected);
    const auto stretches = mb2::periodicStretches(expected, kMaxPeriod);
    // Alternation up to iteration 4 or 5, then slot 1 alone: three pattern entries.
    ASSERT_EQ(stretches.size(), 2u);
    EXPECT_EQ(stretches[0].start, 0);
    EXPECT_EQ(stretches[0].pattern, (std::vector<int>{0, 1}));
    EXPECT_GE(stretches[0].stop, 4);
    EXPECT_LE(stretches[0].stop, 5);
    EXPECT_EQ(stretches[1].start, stretches[0].stop);
    EXPECT_EQ(stretches[1].stop, 10);
    EXPECT_EQ(stretches[1].pattern, (std::vector<int>{0}));
    // "Slot 1 once, then slot 2 for 250 iterations": a first-iteration pre-transform.
    mb2::SlotSequencing pre = s;
    pre.last[1] = 250;
    pre.count[1] = 250;
    const std::vector<int> once = mb2::slotOfEachIteration(pre, 250);
    EXPECT_EQ(once[0], 0);
    EXPECT_EQ(std::count(once.begin(), once.end(), 1), 249);
    EXPECT_EQ(mb2::periodicStretches(once, kMaxPeriod).size(), 2u);
}

// The stretches cover every sequence exactly: random counts, windows and repeat points.
TEST(Mb2Sequence, StretchesReproduceEverySequence) {
    std::mt19937 random(11);
    for (int trial = 0; trial < 300; ++trial) {
        mb2::SlotSequencing s;
        s.hybrid = true;
        s.repeatFrom = 1 + int(random() % 3);
        for (int k = 0; k < 4; ++k) {
            s.runs[size_t(k)] = random() % 4 != 0;
            s.count[size_t(k)] = random() % 5 == 0 ? 40 : 1 + int(random() % 4);
            s.first[size_t(k)] = random() % 3 == 0 ? int(random() % 10) : 0;
            s.last[size_t(k)] = random() % 3 == 0 ? int(random() % 30) : 250;
        }
        const std::vector<int> sequence = mb2::slotOfEachIteration(s, 60);
        std::vector<int> rebuilt;
        int expectedStart = 0;
        for (const auto& stretch : mb2::periodicStretches(sequence, kMaxPeriod)) {
            ASSERT_EQ(stretch.start, expectedStart);
            ASSERT_LE(stretch.pattern.size(), size_t(kMaxPeriod));
            for (int i = stretch.start; i < stretch.stop; ++i)
                rebuilt.push_back(stretch.pattern[size_t(i - stretch.start) % stretch.pattern.size()]);
            expectedStart = stretch.stop;
        }
        EXPECT_EQ(rebuilt, sequence) << "trial " << trial;
    }
}

// On every iteration the imported nodes that run are exactly the slot Mandelbulber2's sequence
// names, in order: a window on slot 2, a long count on slot 3, a rotation of its own window.
TEST(FractImport, NodeSchedulesFollowTheSequenceIterationByIteration) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nN 40;\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 2;\nformula_3 1002;\n"
        "formula_start_iteration_2 2;\nformula_stop_iteration_2 9;\nformula_iterations_3 20;\n"
        "[fractal_1]\nmandelbox_main_rotation_enabled false;\n[fractal_3]\ntransf_rotation 10 0 0;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    mb2::SlotSequencing s;
    s.hybrid = true;
    s.runs[0] = s.runs[1] = s.runs[2] = true;
    s.count.fill(1);
    s.count[2] = 20;
    s.last.fill(250);
    s.first[1] = 2;
    s.last[1] = 9;
    const std::vector<int> sequence = mb2::slotOfEachIteration(s, 40);
    // Each slot's first block: box_fold (mandelbox), mandelbulb_sine, rotate (transf_rotation).
    const char* firstBlock[] = {"box_fold", "mandelbulb_sine", "rotate"};
    for (int i = 0; i < 40; ++i) {
        std::vector<std::string> running;
        for (const Node& n : r.preset.formula.nodes)
            if (n.runsOn(i)) running.emplace_back(n.block->id);
        ASSERT_FALSE(running.empty()) << "iteration " << i;
        EXPECT_EQ(running.front(), firstBlock[sequence[size_t(i)]]) << "iteration " << i;
    }
    EXPECT_LE(r.preset.formula.nodes.size(), size_t(kMaxNodes));
}

TEST(FractImport, NamesWhatItCannotExpressWithItsSlot) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 75;\nformula_weight_1 0,5;\n"
        "primitive_torus_1_enabled true;\nprimitive_torus_1_radius_lpow 2;\n[fractal_2]\n");
    EXPECT_FALSE(r.faithful());
    EXPECT_TRUE(mentions(r.unsupported, "slot 2 (abox_mod2)", "no fraktal blocks")) << r.unsupported.size();
    EXPECT_TRUE(mentions(r.unsupported, "slot 1 (mandelbox)", "formula_weight_1 0,5: a blend"));
    EXPECT_TRUE(mentions(r.unsupported, "main", "primitive torus 1: a torus measured in another norm"));
    // Values outside a block's range.
    const mb2::FractImport bulb = importText("[main_parameters]\n[fractal_1]\nalpha_angle_offset 200;\npower 40;\n");
    EXPECT_TRUE(mentions(bulb.unsupported, "slot 1 (mandelbulb)", "mandelbulb_sine.phi_offset 200 is outside"));
    EXPECT_TRUE(mentions(bulb.unsupported, "slot 1 (mandelbulb)", "mandelbulb_sine.power 40 is outside"));
}

// The bulb's angle offsets (degrees, added before the power: beta on the latitude, alpha on the
// azimuth) are the sine bulb's theta_offset and phi_offset.
// White's power-2 bulb (mandelbulb_power2) is the latitude bulb with z mirrored; Kaleidoscopic
// IFS in Menger sponge mode closes with the Menger scale; box_fold_bulb_pow2 is a box fold, the
// fixed sphere fold, scale 2 and that bulb with z times its factor.
TEST(FractImport, PowerTwoBulbMengerModeAndBoxFoldBulb) {
    const mb2::FractImport white = importText("[main_parameters]\nformula_1 3;\n");
    ASSERT_TRUE(white.faithful());
    EXPECT_EQ(blockIds(white.preset.formula), (std::vector<std::string>{"mandelbulb_sine", "axis_scale", "add_c"}));
    EXPECT_EQ(white.preset.formula.nodes[1].values[0], vec3(1.0, 1.0, -1.0));
    // The step itself against Mandelbulber2's formula at a point: x' = (x^2 - y^2)(1 - z^2 / rho^2),
    // y' = 2xy (1 - z^2 / rho^2), z' = -2 z rho.
    const vec3 q(0.3, -0.7, 0.4);
    P4 p{q, 1.0};
    for (int k = 0; k < 2; ++k)
        white.preset.formula.nodes[size_t(k)].block->apply(p, q, white.preset.formula.nodes[size_t(k)].args());
    const double rho2 = q.x * q.x + q.y * q.y, t = 1.0 - q.z * q.z / rho2;
    EXPECT_NEAR(p.xyz.x, (q.x * q.x - q.y * q.y) * t, 1e-12);
    EXPECT_NEAR(p.xyz.y, 2.0 * q.x * q.y * t, 1e-12);
    EXPECT_NEAR(p.xyz.z, -2.0 * q.z * std::sqrt(rho2), 1e-12);

    const mb2::FractImport menger =
        importText("[main_parameters]\nformula_1 10;\n[fractal_1]\nIFS_menger_sponge_mode true;\nIFS_scale 3;\n");
    ASSERT_TRUE(menger.faithful()) << menger.unsupported.front().text();
    EXPECT_EQ(menger.preset.formula.nodes.back().block->id, "menger_scale");

    const mb2::FractImport box =
        importText("[main_parameters]\nformula_1 16;\n[fractal_1]\nboxfold_bulbpow2_z_factor 3;\n");
    ASSERT_TRUE(box.faithful());
    EXPECT_EQ(blockIds(box.preset.formula),
              (std::vector<std::string>{"box_fold", "sphere_fold", "scale", "mandelbulb_sine", "axis_scale", "add_c"}));
    EXPECT_EQ(box.preset.formula.nodes[4].values[0], vec3(1.0, 1.0, -3.0));
    EXPECT_EQ(box.preset.formula.bailout, 10000.0);
}

// A box cut (limits_enabled) around a power formula: the box combine with the log estimate as the
// fractal's part.
TEST(FractImport, LimitBoxCutsALogEstimate) {
    const mb2::FractImport r =
        importText("[main_parameters]\nlimits_enabled true;\nlimit_min -1 -1 -1;\nlimit_max 1 1 0;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "box_combine");
    EXPECT_EQ(param(e, "log_part"), 1.0);
    EXPECT_EQ(param(e, "intersect"), 1.0);
    EXPECT_EQ(e.values[size_t(e.block->paramIndex("size"))], vec3(1.0, 1.0, 0.5));
    // Inside the bulb and the box: inside; inside the bulb above the cut: outside.
    Formula f = r.preset.formula;
    EXPECT_LE(distanceEstimate(f, vec3(0.0, 0.0, -0.1)), 0.0);
    EXPECT_GT(distanceEstimate(f, vec3(0.0, 0.0, 0.2)), 0.0);
}

// Everything else the combine estimators cannot hold becomes the formula's objects, in file
// order: the primitives' boolean operators (0 AND, 1 OR, 2 SUB) as intersect, join and carve, their
// rotation as the turn Mandelbulber2 measures in (M (p - position)), "empty" as hollow; the limit
// box intersects them all, last, whatever the DE function.
TEST(FractImport, PrimitivesAndTheLimitBoxBecomeObjects) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 103;\nlimits_enabled true;\nlimit_min -2 -2 -1;\nlimit_max 2 2 3;\n"
        "primitive_sphere_1_enabled true;\nprimitive_sphere_1_position 1 0 0;\nprimitive_sphere_1_radius 0,5;\n"
        "primitive_cylinder_1_enabled true;\nprimitive_cylinder_1_rotation 0 90 0;\n"
        "primitive_cylinder_1_height 3;\nprimitive_cylinder_1_empty true;\nprimitive_cylinder_1_boolean_operator 2;\n"
        "primitive_torus_1_enabled true;\nprimitive_torus_1_boolean_operator 0;\nprimitive_torus_1_tube_radius 0,3;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(r.preset.formula.estimator.block->id, "pseudo_kleinian_de");
    const std::vector<SceneObject>& objects = r.preset.formula.objects;
    ASSERT_EQ(objects.size(), 4u);
    std::vector<std::string> kinds;
    for (const SceneObject& o : objects) kinds.emplace_back(o.block->id);
    EXPECT_EQ(kinds, (std::vector<std::string>{"cylinder", "sphere", "torus", "box"}));
    EXPECT_EQ(objects[0].operation, ObjectOperation::Carve);
    EXPECT_TRUE(objects[0].hollow);
    EXPECT_EQ(objects[1].operation, ObjectOperation::Join);
    EXPECT_EQ(objects[1].center, vec3(1.0, 0.0, 0.0));
    EXPECT_EQ(objects[2].operation, ObjectOperation::Intersect);
    EXPECT_EQ(objects[3].operation, ObjectOperation::Intersect);
    EXPECT_EQ(objects[3].center, vec3(0.0, 0.0, 1.0));
    EXPECT_EQ(objects[3].values[0], vec3(2.0, 2.0, 2.0));
    // The cylinder turned by Ry(90): its axis along x in the world.
    const glm::dmat3 m(glm::rotate(glm::dmat4(1.0), glm::radians(90.0), vec3(0, 1, 0)));
    for (const vec3& p : test::randomPoints(200, 2.0, 41)) {
        const vec3 q = m * p;
        const double mb2 = std::abs(std::max(std::abs(q.z) - 1.5, std::hypot(q.x, q.y) - 1.0));
        EXPECT_NEAR(objects[0].distanceAt(p), mb2, 1e-9);
    }
    // A cone and one that carves the fractal from itself are named.
    const mb2::FractImport refused = importText(
        "[main_parameters]\nprimitive_cone_1_enabled true;\nprimitive_sphere_1_enabled true;\n"
        "primitive_sphere_1_boolean_operator 3;\n");
    EXPECT_TRUE(mentions(refused.unsupported, "main", "primitive cone 1: a cone beside the fractal"));
    EXPECT_TRUE(mentions(refused.unsupported, "main", "primitive sphere 1: boolean operator 3"));
    // A repeated object repeats in its own frame, after the turn (primitives.cpp: M (p - position),
    // then CVector3::mod): cells 2 wide along the turned x, centred on the position.
    const mb2::FractImport repeated = importText(
        "[main_parameters]\nformula_1 103;\nprimitive_box_1_enabled true;\nprimitive_box_1_repeat 2 0 0;\n"
        "primitive_box_1_position 0 1 0;\nprimitive_box_1_rotation 0 0 90;\nprimitive_box_1_size 1 1 1;\n");
    ASSERT_TRUE(repeated.faithful()) << repeated.unsupported.front().text();
    ASSERT_EQ(repeated.preset.formula.objects.size(), 1u);
    const SceneObject& box = repeated.preset.formula.objects[0];
    EXPECT_EQ(box.repeat, vec3(2.0, 0.0, 0.0));
    const glm::dmat3 rz(glm::rotate(glm::dmat4(1.0), glm::radians(90.0), vec3(0, 0, 1)));
    for (const vec3& p : test::randomPoints(200, 3.0, 42)) {
        vec3 q = rz * (p - vec3(0.0, 1.0, 0.0));
        q.x -= 2.0 * std::floor(q.x / 2.0 + 0.5);
        const vec3 outside = glm::abs(q) - vec3(0.5);
        const double mb2 =
            length(glm::max(outside, vec3(0.0))) + std::min(std::max(outside.x, std::max(outside.y, outside.z)), 0.0);
        EXPECT_NEAR(box.distanceAt(p), mb2, 1e-9);
    }
}

// A primitive's colour is its material's surface colour where that material does not colour from
// the palette (display-referred 16-bit hex, taken to linear as the light's colour is); a
// palette-coloured material leaves the object grey and says so.
TEST(FractImport, PrimitiveTakesItsMaterialsSurfaceColour) {
    const std::string primitives =
        "[main_parameters]\nformula_1 103;\nprimitive_sphere_1_enabled true;\nprimitive_sphere_1_material_id 2;\n"
        "mat2_surface_color ffff 8000 0000;\nprimitive_box_1_enabled true;\n";
    const mb2::FractImport own = importText(primitives + "mat2_use_colors_from_palette false;\n");
    ASSERT_TRUE(own.faithful()) << own.unsupported.front().text();
    const std::vector<SceneObject>& objects = own.preset.formula.objects;
    ASSERT_EQ(objects.size(), 2u);
    const SceneObject& sphere = objects[0].block->id == "sphere" ? objects[0] : objects[1];
    const SceneObject& box = objects[0].block->id == "sphere" ? objects[1] : objects[0];
    EXPECT_NEAR(sphere.color.x, 1.0, 1e-9);
    EXPECT_NEAR(sphere.color.y, std::pow((32768.0 / 65535.0 + 0.055) / 1.055, 2.4), 2e-3);
    EXPECT_EQ(sphere.color.z, 0.0);
    EXPECT_EQ(box.color, vec3(kDefaultObjectColor));
    EXPECT_TRUE(mentions(own.approximated, "primitive box 1", "palette"));
    EXPECT_FALSE(mentions(own.approximated, "primitive sphere 1", "palette"));

    const mb2::FractImport palette = importText(primitives);
    for (const SceneObject& o : palette.preset.formula.objects) EXPECT_EQ(o.color, vec3(kDefaultObjectColor));
    EXPECT_TRUE(mentions(palette.approximated, "primitive sphere 1", "palette"));
}

// Mandelbulber2 makes a pixel of its own rays alone (a box); the import keeps that footprint with
// the reconstruction filter's narrowest radius, where a preset of fraktal's own keeps the default.
TEST(FractImport, PixelsKeepMandelbulber2sFootprint) {
    const mb2::FractImport r = importText("[main_parameters]\nformula_1 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(r.preset.render.filterRadius, 0.5);
    EXPECT_GT(Preset{}.render.filterRadius, 0.5);
}

// The hit threshold: one pixel footprint over detail_level, times the step factor (fraktal's
// threshold applies to the scaled estimate), divided by the largest power only where that power
// is a spherical one or the Bristorbrot, whose derivatives bound a stretch that Mandelbulber2's
// leaves out; the other powers keep Mandelbulber2's threshold (bench/import/README.md: riemann_sphere_msltoe_v2
// 0.79 divided, 0.97 not).
TEST(FractImport, HitThresholdIsDividedOnlyByPowersThatBoundTheirStretch) {
    const std::string look = "DE_factor 0,5;\ndetail_level 2;\n";
    const mb2::FractImport bulb = importText("[main_parameters]\nformula_1 2;\n" + look + "[fractal_1]\npower 9;\n");
    EXPECT_EQ(bulb.preset.formula.nodes.front().block->id, "mandelbulb_sine");
    EXPECT_DOUBLE_EQ(bulb.preset.render.detail, 0.5 / 2.0 / 9.0);
    // The Bristorbrot, whose derivative is its Jacobian's largest singular value, above 2 r off
    // the x axis; the quaternion, drawn with it without the cross terms, where that value is 2 r,
    // Mandelbulber2's own.
    const mb2::FractImport bristorbrot = importText("[main_parameters]\nformula_1 21;\n" + look);
    EXPECT_EQ(bristorbrot.preset.formula.nodes.front().block->id, "bristorbrot");
    EXPECT_DOUBLE_EQ(bristorbrot.preset.render.detail, 0.5 / 2.0 / 2.0);
    const mb2::FractImport quaternion = importText("[main_parameters]\nformula_1 5;\n" + look);
    EXPECT_EQ(quaternion.preset.formula.nodes.front().block->id, "bristorbrot");
    EXPECT_DOUBLE_EQ(quaternion.preset.render.detail, 0.5 / 2.0);
    for (const char* id : {"129", "139", "800"}) {  // coastalbrot, riemann_sphere_msltoe_v2, mandelbulb_eye
        const mb2::FractImport other = importText(std::string("[main_parameters]\nformula_1 ") + id + ";\n" + look);
        ASSERT_TRUE(other.faithful()) << id << ": " << other.unsupported.front().text();
        EXPECT_GT(other.preset.formula.nodes.front().block->degreeAt(other.preset.formula.nodes.front().args()), 1.0)
            << id;
        EXPECT_DOUBLE_EQ(other.preset.render.detail, 0.5 / 2.0) << id;
    }
}

// constant_DE_threshold: Mandelbulber2's hit threshold is DE_thresh in world units wherever the
// point is (CalcDistThresh, render_worker.cpp); fraktal's, per pixel footprint, is taken so that it
// is that length at the target, in an image of the file's size: here 1e-4 at 2 units from the
// camera, a footprint there 2 x 2 tan(fovY / 2) / 600, times the step factor; the threshold follows
// DE_thresh. Where that is coarser than a footprint over detail_level, the latter is kept.
TEST(FractImport, ConstantHitThresholdIsWorldUnitsAtTheTarget) {
    const std::string scene =
        "[main_parameters]\nformula_1 8;\nDE_factor 0,5;\ndetail_level 2;\nimage_height 600;\n"
        "camera 0 -2 0;\ntarget 0 0 0;\nconstant_DE_threshold true;\n";
    const mb2::FractImport r = importText(scene + "DE_thresh 0,0001;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const double footprint = 2.0 * r.preset.camera.pixelAngle(600.0, r.preset.render.width);
    EXPECT_NEAR(r.preset.render.detail, 0.5 * 1e-4 / footprint, 1e-12);
    EXPECT_TRUE(mentions(r.approximated, "detail", "constant_DE_threshold"));
    const mb2::FractImport coarser = importText(scene + "DE_thresh 0,0004;\n");
    EXPECT_NEAR(coarser.preset.render.detail, 4.0 * r.preset.render.detail, 1e-12);
    EXPECT_DOUBLE_EQ(importText(scene + "DE_thresh 0,01;\n").preset.render.detail, 0.5 / 2.0);
    // In iteration_threshold_mode Mandelbulber2's threshold is one footprint whatever it says.
    const mb2::FractImport inside = importText(scene + "DE_thresh 0,0001;\niteration_threshold_mode true;\n");
    EXPECT_DOUBLE_EQ(inside.preset.render.detail, 0.5 * 0.5);
    EXPECT_FALSE(mentions(inside.approximated, "detail", "constant_DE_threshold"));
    // A free-flying camera, its target on it, has no distance to hold it at: one footprint over
    // detail_level.
    std::string targetless = scene + "DE_thresh 0,0001;\n";
    targetless.replace(targetless.find("target 0 0 0"), 12, "target 0 -2 0");
    EXPECT_DOUBLE_EQ(importText(targetless).preset.render.detail, 0.5 / 2.0);
    // Without it, one footprint over detail_level.
    const mb2::FractImport perPixel = importText("[main_parameters]\nformula_1 8;\nDE_factor 0,5;\ndetail_level 2;\n");
    EXPECT_DOUBLE_EQ(perPixel.preset.render.detail, 0.5 / 2.0);
}

// Mandelbulber2's boolean mode (calculate_distance.cpp, nine_fractals.cpp): each enabled slot is
// a fractal of its own, with its own Julia constant, constant factor and default bailout, placed
// by formula_position, _rotation, _repeat and _scale (measured at M (p - position) / scale), and
// combined with what the slots before it made by boolean_operator of the slot before (0 AND, 1 OR,
// 2 SUB).
TEST(FractImport, BooleanModeCombinesTheSlotsAsPlacedFractals) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nboolean_operators true;\nformula_1 8;\nformula_2 2;\nformula_3 7;\nN 12;\n"
        "boolean_operator_1 2;\nboolean_operator_2 0;\nformula_position_2 0,5 0 0;\nformula_rotation_2 0 0 90;\n"
        "formula_scale_2 0,5;\nformula_repeat_3 3 0 0;\njulia_mode_2 true;\njulia_c_2 0,1 0,2 0,3;\n"
        "julia_mode true;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    EXPECT_EQ(blockIds(f).front(), "box_fold");
    EXPECT_EQ(f.estimator.block->id, "escape_linear");
    ASSERT_EQ(f.fractals.size(), 2u);
    EXPECT_EQ(f.fractals[0].operation, ObjectOperation::Carve);
    EXPECT_EQ(f.fractals[1].operation, ObjectOperation::Intersect);
    EXPECT_TRUE(mentions(r.approximated, "slot 2", "carved exactly"));
    // The bulb with its own Julia constant (the global julia_mode is the first slot's alone: off).
    const Formula& bulb = f.fractals[0].formula;
    EXPECT_EQ(blockIds(bulb), (std::vector<std::string>{"mandelbulb_sine", "add_c"}));
    const Node& addC = bulb.nodes[1];
    EXPECT_EQ(addC.values[size_t(addC.block->paramIndex("julia"))].x, 1.0);
    EXPECT_EQ(addC.values[size_t(addC.block->paramIndex("julia_c"))], vec3(0.1, 0.2, 0.3));
    EXPECT_TRUE(std::none_of(f.nodes.begin(), f.nodes.end(), [](const Node& n) {
        return n.block->id == "add_c" && n.values[size_t(n.block->paramIndex("julia"))].x > 0.5;
    }));
    EXPECT_EQ(bulb.iterations, 12);
    EXPECT_EQ(f.fractals[1].formula.iterations, 12);
    const glm::dmat3 rz(glm::rotate(glm::dmat4(1.0), glm::radians(90.0), vec3(0, 0, 1)));
    for (const vec3& p : test::randomPoints(100, 2.0, 43)) {
        const vec3 local = bulb.placement.localFromWorld(p);
        const vec3 mb2 = rz * (p - vec3(0.5, 0.0, 0.0)) / 0.5;
        EXPECT_NEAR(length(local - mb2), 0.0, 1e-12);
    }
    EXPECT_EQ(f.fractals[1].formula.placement.repeat, vec3(3.0, 0.0, 0.0));
    // An operator Mandelbulber2 does not have is named.
    const mb2::FractImport refused =
        importText("[main_parameters]\nboolean_operators true;\nformula_1 8;\nformula_2 2;\nboolean_operator_1 4;\n");
    EXPECT_TRUE(mentions(refused.unsupported, "main", "boolean_operator_1 4"));
}

// Mandelbulber2's water beside a fractal: the water combine, its frame turned as the file's
// rotation turns it (180 degrees about x: solid above the plane through the position), its
// height relative to the wave length; files before 2.13 name it amplitude, and up to 2.12 give it
// in world units. Waves raised by the objects around are refused by name.
TEST(FractImport, WaterBesideTheFractal) {
    const std::string water =
        "[main_parameters]\nformula_1 8;\nprimitive_water_1_enabled true;\nprimitive_water_1_position 0 0 -1;\n"
        "primitive_water_1_rotation 180 0 -60;\nprimitive_water_1_length 0,5;\nprimitive_water_1_iterations 7;\n";
    const mb2::FractImport r = importText(water + "primitive_water_1_relative_amplitude 0,1;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "water_combine");
    EXPECT_EQ(param(e, "wave_length"), 0.5);
    EXPECT_EQ(param(e, "amplitude"), 0.1);
    EXPECT_EQ(param(e, "iterations"), 7.0);
    EXPECT_EQ(param(e, "log_part"), 0.0);
    // The turn Mandelbulber2 builds (z by -60, then x by 180) as one: the plane's normal points down.
    const vec3 axis = e.values[size_t(e.block->paramIndex("axis"))];
    const double angle = param(e, "angle");
    const vec3 up(0, 0, 1), k = normalize(axis);
    const double co = std::cos(glm::radians(angle)), s = std::sin(glm::radians(angle));
    const vec3 turned = up * co + glm::cross(k, up) * s + k * dot(k, up) * (1.0 - co);
    EXPECT_NEAR(turned.z, -1.0, 1e-9);
    // Far from the box: water above z = -1 (beyond the waves' reach of 0.1 x 0.5 x 4.3), none below.
    EXPECT_LT(distanceEstimate(r.preset.formula, vec3(6.0, 6.0, -0.5)), 0.0);
    EXPECT_GT(distanceEstimate(r.preset.formula, vec3(6.0, 6.0, -1.5)), 0.0);

    const std::string legacy = "# Mandelbulber settings file\n# version 2.12\n# only modified parameters\n";
    const mb2::FractImport old =
        mb2::importFract(parseFractFile(legacy + water + "primitive_water_1_amplitude 0,05;\n", "legacy.fract"));
    ASSERT_TRUE(old.faithful()) << old.unsupported.front().text();
    EXPECT_DOUBLE_EQ(param(old.preset.formula.estimator, "amplitude"), 0.1);

    const mb2::FractImport waves = importText(water + "primitive_water_1_wave_from_objects_enable true;\n");
    EXPECT_TRUE(mentions(waves.unsupported, "main", "primitive water 1: waves from the objects"));
}

// Makin's hypercomplex set runs its own 4D orbit in the hypercomplex_mandelbrot estimator, from
// c = (point, initial_waxis), N iterations, escaping at the bailout: a point is inside (estimate
// 0) exactly where Mandelbulber2's orbit, iterated here, stays within the bailout.
TEST(FractImport, HypercomplexRunsItsOwnOrbit) {
    const mb2::FractImport r = importText("[main_parameters]\nformula_1 4;\nN 20;\ninitial_waxis 0,3;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_TRUE(r.preset.formula.nodes.empty());
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "hypercomplex_mandelbrot");
    EXPECT_EQ(param(e, "orbit"), 20.0);
    EXPECT_EQ(param(e, "slice"), 0.3);
    EXPECT_EQ(param(e, "escape"), 10.0);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        double x = point.x, y = point.y, z = point.z, w = 0.3;
        bool escaped = false;
        for (int i = 0; i < 20 && !escaped; ++i) {
            const double nx = x * x - y * y - z * z - w * w + point.x, ny = 2.0 * x * y - 2.0 * w * z + point.y,
                         nz = 2.0 * x * z - 2.0 * y * w + point.z, nw = 2.0 * x * w - 2.0 * y * z + 0.3;
            x = nx, y = ny, z = nz, w = nw;
            escaped = x * x + y * y + z * z + w * w >= 100.0;
        }
        inside += !escaped;
        EXPECT_EQ(distanceEstimate(r.preset.formula, point) > 0.0, escaped)
            << point.x << " " << point.y << " " << point.z;
    }
    EXPECT_GT(inside, 50);
    // Beside other slots the 4D orbit has no place in the node list.
    const mb2::FractImport hybrid =
        importText("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 4;\nformula_2 8;\n");
    EXPECT_TRUE(mentions(hybrid.unsupported, "slot 1 (hypercomplex)", "a 4D orbit beside other slots"));
}

// Julia mode: the hypercomplex Julia set of julia_c times the constant factor, the orbit written
// out as Mandelbulber2 runs it (q -> q^2 + (julia_c, 0) from (point, initial_waxis)).
TEST(FractImport, HypercomplexJuliaAddsItsConstant) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 4;\nN 12;\njulia_mode true;\njulia_c -0,5 0,1 0;\nfractal_constant_factor 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "hypercomplex_julia");
    EXPECT_EQ(param(e, "constant", 0), -1.0);
    EXPECT_EQ(param(e, "constant", 1), 0.2);
    std::mt19937 random(4);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        double x = point.x, y = point.y, z = point.z, w = 0.0;
        bool escaped = false;
        for (int i = 0; i < 12 && !escaped; ++i) {
            const double nx = x * x - y * y - z * z - w * w - 1.0, ny = 2.0 * x * y - 2.0 * w * z + 0.2,
                         nz = 2.0 * x * z - 2.0 * y * w, nw = 2.0 * x * w - 2.0 * y * z;
            x = nx, y = ny, z = nz, w = nw;
            escaped = x * x + y * y + z * z + w * w >= 100.0;
        }
        inside += !escaped;
        EXPECT_EQ(distanceEstimate(r.preset.formula, point) > 0.0, escaped)
            << point.x << " " << point.y << " " << point.z;
    }
    EXPECT_GT(inside, 20);
}

// The dIFS formulas and transforms: shape steps whose least distance is the difs estimate. The
// donut measures its torus before its step, over the derivative after it (|factor| w + 1); the
// transforms divide by w + 1; the grids are measured in transf_rotation's frame (a turn there and
// back). The delta DE method, under which Mandelbulber2 draws |z| as the distance, is refused.
TEST(FractImport, DifsShapesCloseWithTheLeastShapeDistance) {
    const mb2::FractImport donut = importText(
        "[main_parameters]\nformula_1 610;\n[fractal_1]\ndonut_factor 2;\ndonut_number 3;\n"
        "donut_ring_thickness 0,101;\n");
    ASSERT_TRUE(donut.faithful()) << donut.unsupported.front().text();
    EXPECT_EQ(donut.preset.formula.estimator.block->id, "difs");
    ASSERT_EQ(blockIds(donut.preset.formula), (std::vector<std::string>{"difs_torus", "msltoe_donut"}));
    const Node& torus = donut.preset.formula.nodes[0];
    EXPECT_EQ(param(torus, "thickness"), 0.101);
    EXPECT_EQ(param(torus, "w_scale"), 2.0);
    EXPECT_EQ(param(torus, "w_offset"), 1.0);
    // At a point outside the tube, one iteration: the torus over 2 + 1.
    Formula one = donut.preset.formula;
    one.iterations = 1;
    const vec3 x(0.4, 0.3, 0.5);
    const double ring = length(glm::dvec2(length(glm::dvec2(x.x, x.y)) - 1.0, x.z)) - 0.101;
    EXPECT_NEAR(distanceEstimate(one, x), ring / 3.0 * one.deFactor, 1e-12);

    const mb2::FractImport grid = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 1613;\n[fractal_2]\n"
        "transf_rotation_enabled true;\ntransf_rotation 0 0 30;\ntransf_scale_1 0,25;\n"
        "transf_function_enabledJ_false true;\n");
    ASSERT_TRUE(grid.faithful()) << grid.unsupported.front().text();
    EXPECT_EQ(grid.preset.formula.estimator.block->id, "difs");
    const std::vector<std::string> ids = blockIds(grid.preset.formula);
    const auto at = std::find(ids.begin(), ids.end(), "difs_grid");
    ASSERT_NE(at, ids.end());
    ASSERT_TRUE(at != ids.begin() && at + 1 != ids.end());
    EXPECT_EQ(*(at - 1), "rotate");
    EXPECT_EQ(*(at + 1), "rotate");
    const Node& g = grid.preset.formula.nodes[size_t(at - ids.begin())];
    EXPECT_EQ(param(g, "cell"), 0.25);
    EXPECT_EQ(param(g, "square_bars"), 1.0);
    EXPECT_EQ(param(g, "w_offset"), 1.0);

    const mb2::FractImport delta = importText("[main_parameters]\nformula_1 610;\ndelta_DE_method 1;\n");
    EXPECT_TRUE(mentions(delta.unsupported, "main", "the dIFS DE function with the delta DE method"));
}

// The settings `body` (after [main_parameters]) are refused, `where` naming `what`.
void expectRefused(const std::string& body, const std::string& where, const std::string& what) {
    EXPECT_TRUE(mentions(importText("[main_parameters]\n" + body).unsupported, where, what)) << body;
}

// A file under Mandelbulber2's examples/ imports with nothing refused.
void expectExampleImports(const std::string& file) {
    const fs::path examples = "/usr/share/mandelbulber2/examples";
    ASSERT_TRUE(fs::exists(examples)) << "Mandelbulber2's examples are missing: scripts/install-deps.sh installs them";
    const mb2::FractImport r = mb2::importFract(mb2::loadFractFile(examples / file));
    EXPECT_TRUE(r.faithful()) << file << ": " << r.unsupported.front().text();
}

// A dIFS formula's membership against Mandelbulber2's orbit written out: `distance(point)` is the
// least shape distance along the orbit (the point inside where it is at most 0), on 2000 random
// points of [-extent, extent]^3 drawn from `seed`. At most 1 % differ, and 1 % to 99 % are inside.
void expectDifsMembershipFollows(const Formula& f, double extent, unsigned seed,
                                 const std::function<double(const vec3&)>& distance) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-extent, extent);
    int inside = 0, differ = 0;
    const int points = 2000;
    for (int k = 0; k < points; ++k) {
        const vec3 point = randomVec3(u, random);
        const bool in = distance(point) <= 0.0;
        inside += in;
        differ += evaluate(f, point).inside != in;
    }
    std::printf("%s: %d of %d inside, %d differ\n", f.nodes.front().block->id.data(), inside, points, differ);
    EXPECT_LE(differ, points / 100);
    EXPECT_GT(inside, points / 100);
    EXPECT_LT(inside, points - points / 100);
}

// Mandelbulber2's dIFS cylinder, sphere and torus formulas: the shape measured where each iteration
// starts, then |x| and |y|, the diagonal fold, the scale about the reverse offsets (x and y less 2)
// varying with option K, offset_001. A point is inside where some shape distance along its orbit
// is negative, whatever the divisors: fraktal's membership follows a replica of
// DIFSCylinderIteration, DIFSSphereIteration and DIFSTorusIteration (fractal_formulas.cpp) on
// random points, and the first iteration's estimate is Mandelbulber2's, the shape over DE |s| + 1.
TEST(FractImport, DifsCylinderSphereAndTorusFollowMandelbulber2) {
    struct Case {
        const char* body;
        double (*shape)(const vec3& z, int i);  // the shape's distance at the iteration's start
        double vary, limit;
    };
    const Case cases[] = {
        {"formula_1 603;\nN 6;\n[fractal_1]\ntransf_radius_1 0,6;\ntransf_offsetA_1 1,5;\ntransf_scale_0 0,1;\n"
         "transf_function_enabledM_false true;\ntransf_stop_iterations_M 3;\ntransf_function_enabledK_false true;\n"
         "transf_scale_vary_0 0,3;\ntransf_scaleC_1 0,5;\ntransf_function_enabled_false true;\n"
         "transf_function_enabledCx_false true;\n",
         [](const vec3& z, int i) {
             const double radial = length(glm::dvec2(z.x, z.y)), capped = std::abs(z.z) - 1.5;
             const double side = radial - 0.6 + 0.1 * (i < 3 ? z.z : std::abs(z.z));
             return length(glm::dvec2(std::max(side, 0.0), std::max(capped, 0.0))) +
                    std::min(std::max(side, capped), 0.0);
         },
         0.3, 0.5},
        {"formula_1 604;\nN 6;\n[fractal_1]\ntransf_offsetR_1 0,8;\ntransf_scale_2 2,35;\n",
         [](const vec3& z, int) { return length(z) - 0.8; }, 0.0, 1.0},
        // DIFSTorusIteration: the sphere's folds and scale, its torus about z.
        {"formula_1 606;\nN 6;\n[fractal_1]\ntransf_offsetT_1 0,9;\ntransf_offset_05 0,35;\ntransf_scale_2 2,35;\n",
         [](const vec3& z, int) { return length(glm::dvec2(length(glm::dvec2(z.x, z.y)) - 0.9, z.z)) - 0.35; }, 0.0,
         1.0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.body);
        const mb2::FractImport r = importText(std::string("[main_parameters]\n") + c.body);
        ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
        const Formula& f = r.preset.formula;
        EXPECT_EQ(f.estimator.block->id, "difs");
        // The sphere's and the torus's folds and scale are the same.
        const bool sphere = std::string(c.body).find("604") != std::string::npos ||
                            std::string(c.body).find("606") != std::string::npos;
        const double s = sphere ? 2.35 : 2.0;
        expectDifsMembershipFollows(f, 1.5, 9, [&](const vec3& point) {
            vec3 z = point;
            double de = 1.0, a = 0.0, dist = 1000.0;
            for (int i = 0; i < f.iterations; ++i) {
                const vec3 start = z;
                z = vec3(std::abs(z.x), std::abs(z.y), z.z);
                if (!sphere && z.x > z.y) std::swap(z.x, z.y);
                const double use = a + s;
                z = (z - vec3(2.0, 2.0, 0.0)) * use + vec3(2.0, 2.0, 0.0) + vec3(0.0, 0.0, 1.0);
                de = de * std::abs(use) + 1.0;
                a -= c.vary * (std::abs(a) - c.limit);
                dist = std::min(dist, c.shape(start, i) / de);
                if (length(z) > f.bailout) break;
            }
            return dist;
        });
        Formula one = f;
        one.iterations = 1;
        const vec3 x(0.9, -0.4, 1.8);
        EXPECT_NEAR(distanceEstimate(one, x), c.shape(x, 0) / (s + 1.0) * one.deFactor, 1e-12);
    }
    // Option I measures a torus beside the cylinder, in its own window.
    const mb2::FractImport torus = importText(
        "[main_parameters]\nformula_1 603;\n[fractal_1]\ntransf_function_enabledI_false true;\n"
        "transf_start_iterations_I 2;\ntransf_offsetT_1 0,7;\n");
    ASSERT_TRUE(torus.faithful()) << torus.unsupported.front().text();
    const Node& ring = torus.preset.formula.nodes.front();
    EXPECT_EQ(ring.block->id, "difs_torus");
    EXPECT_EQ(ring.start, 2);
    EXPECT_EQ(param(ring, "ring_radius"), 0.7);
    EXPECT_EQ(param(ring, "w_scale"), 2.0);
    // The dIFS torus formula's own torus in its window; about x, stretched or switched off, refused.
    const mb2::FractImport windowed =
        importText("[main_parameters]\nformula_1 606;\n[fractal_1]\ntransf_start_iterations 3;\n");
    ASSERT_TRUE(windowed.faithful()) << windowed.unsupported.front().text();
    EXPECT_EQ(windowed.preset.formula.nodes.front().block->id, "difs_torus");
    EXPECT_EQ(windowed.preset.formula.nodes.front().start, 3);
    expectRefused("formula_1 606;\n[fractal_1]\ntransf_function_enabledSw_false true;\n", "slot 1 (difs_torus)",
                  "the torus about x");
    expectRefused("formula_1 606;\n[fractal_1]\ntransf_function_enabledM_false true;\n", "slot 1 (difs_torus)",
                  "the stretched torus");
    expectRefused("formula_1 606;\n[fractal_1]\ntransf_function_enabledM false;\n", "slot 1 (difs_torus)",
                  "the torus switched off");
}

// Mandelbulber2's dIFS diagonal boxes: folds, the scale about the reverse offsets, offset_001 and
// the turn, then the box measured where the iteration ends, over DE |s| + 1. fraktal's membership
// follows DIFSBoxDiagonalV1Iteration and V3 (formula/opencl of 2.20) written out on random points,
// and the first iteration's estimate is Mandelbulber2's.
TEST(FractImport, DifsBoxDiagonalsFollowMandelbulber2) {
    struct Case {
        const char* body;
        vec3 (*folds)(vec3 z, int i);  // the iteration up to the scale
        double s, e, f;                // the scale and the reverse offsets
        vec3 offset, size;
        double turn;  // degrees about z, option R (RotateZ of SetRotation2: x' = x cos - y sin)
    };
    const Case cases[] = {
        // V1: x and y swapped where x > y, |x|, |y| (from iteration 1), x and y less 0.8 and 0.6, the
        // fold about x = -0.3 (option C), scale 2.2 about (0.5, 0.2), offset_001, a turn of 30 degrees about z.
        {"formula_1 600;\nN 8;\n[fractal_1]\ntransf_addition_constantA_111 0,8 0,6 1;\n"
         "transf_start_iterations_X 1;\ntransf_function_enabledC_false true;\ntransf_offsetC_0 -0,3;\n"
         "transf_scale_2 2,2;\ntransf_offsetE_0 0,5;\ntransf_offsetF_0 0,2;\ntransf_offset_001 0 0,1 0,9;\n"
         "transf_addition_constant_111 0,7 0,5 0,9;\ntransf_function_enabledR_false true;\n"
         "transf_rotation 0 0 30;\n",
         [](vec3 z, int i) {
             if (z.x > z.y) std::swap(z.x, z.y);
             if (i >= 1) z.x = std::abs(z.x);
             z.y = std::abs(z.y);
             z -= vec3(0.8, 0.6, 0.0);
             if (z.x < -0.3) z.x = std::abs(z.x + 0.3) - 0.3;
             return z;
         },
         2.2, 0.5, 0.2, vec3(0.0, 0.1, 0.9), vec3(0.7, 0.5, 0.9), 30.0},
        // V3: surfBox_offset1A_111 subtracted (option A), |x|, |y|, |z|, swapped where y > x, Tglad's
        // fold at (0.5, 0.4, 0.6) (option I), the fold about y = 0.1 (D), swapped again (Cy); scale
        // 1.8, offset_001 from iteration 2 (window H).
        {"formula_1 602;\nN 8;\n[fractal_1]\ntransf_function_enabledA_false true;\n"
         "surfBox_offset1A_111 0,2 0,1 0,3;\ntransf_function_enabledAz_false true;\n"
         "transf_function_enabledCx_false true;\ntransf_function_enabledI_false true;\n"
         "transf_offsetA_000 0,5 0,4 0,6;\ntransf_function_enabledD_false true;\ntransf_offsetD_0 0,1;\n"
         "transf_function_enabledCy_false true;\ntransf_scale_2 1,8;\ntransf_offset_001 0 0 0,5;\n"
         "transf_start_iterations_H 2;\ntransf_addition_constant_111 0,5 0,6 0,4;\n",
         [](vec3 z, int) {
             z -= vec3(0.2, 0.1, 0.3);
             z = glm::abs(z);
             if (z.y > z.x) std::swap(z.x, z.y);
             const vec3 a(0.5, 0.4, 0.6);
             z = glm::abs(z + a) - glm::abs(z - a) - z;
             if (z.y < 0.1) z.y = std::abs(z.y - 0.1) + 0.1;
             if (z.y > z.x) std::swap(z.x, z.y);
             return z;
         },
         1.8, 0.0, 0.0, vec3(0.0, 0.0, 0.5), vec3(0.5, 0.6, 0.4), 0.0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.body);
        const mb2::FractImport r = importText(std::string("[main_parameters]\n") + c.body);
        ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
        const Formula& f = r.preset.formula;
        EXPECT_EQ(f.estimator.block->id, "difs");
        const bool v3 = std::string(c.body).find("602") != std::string::npos;
        const double cs = std::cos(glm::radians(c.turn)), sn = std::sin(glm::radians(c.turn));
        auto iterate = [&](vec3 z, int i) {
            z = c.folds(z, i);
            const vec3 centre(c.e, c.f, 0.0);
            z = (z - centre) * c.s + centre;
            if (!v3 || i >= 2) z += c.offset;
            return vec3(cs * z.x - sn * z.y, sn * z.x + cs * z.y, z.z);
        };
        auto box = [&](const vec3& z) { return length(glm::max(glm::abs(z) - c.size, vec3(0.0))); };
        expectDifsMembershipFollows(f, 2.0, 11, [&](const vec3& point) {
            vec3 z = point;
            double de = 1.0, dist = 1000.0;
            for (int i = 0; i < f.iterations; ++i) {
                z = iterate(z, i);
                de = de * std::abs(c.s) + 1.0;
                dist = std::min(dist, box(z) / de);
                if (length(z) > f.bailout) break;
            }
            return dist;
        });
        Formula one = f;
        one.iterations = 1;
        const vec3 x(1.3, -0.4, 1.9);
        EXPECT_NEAR(distanceEstimate(one, x), box(iterate(x, 0)) / (c.s + 1.0) * one.deFactor, 1e-9);
    }
    // Option Y measures the box where the iteration starts, over the derivative after the scale.
    const mb2::FractImport start =
        importText("[main_parameters]\nformula_1 600;\n[fractal_1]\ntransf_function_enabledY_false true;\n");
    ASSERT_TRUE(start.faithful()) << start.unsupported.front().text();
    const Node& first = start.preset.formula.nodes.front();
    EXPECT_EQ(first.block->id, "difs_box");
    EXPECT_EQ(param(first, "w_scale"), 2.0);
    EXPECT_EQ(param(first, "w_offset"), 1.0);
    // The curved box and V3's polygonal fold are refused by name.
    expectRefused("formula_1 600;\n[fractal_1]\ntransf_function_enabledT_false true;\n",
                  "slot 1 (difs_box_diagonal_v1)", "curved");
    expectRefused("formula_1 602;\n[fractal_1]\ntransf_function_enabledP_false true;\n",
                  "slot 1 (difs_box_diagonal_v3)", "polygonal fold");
}

// Mandelbulber2's example files of the dIFS diagonal boxes import with nothing refused, the one with
// a water surface beside the dIFS estimate too.
TEST(FractImport, DifsBoxDiagonalExamplesImport) {
    const std::string gm = "Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/";
    for (const std::string& file :
         {gm + "DIFS Box DiagV1 pseudoKl.fract", gm + "DIFS Box DiagV3 asurf.fract",
          gm + "DIFS Box DiagV3 complex primitive.fract", gm + "DIFS Box DiagV1 complex primitive.fract",
          std::string("../formula/img/difs_box_diagonal_v1.fract")})
        expectExampleImports(file);
}

// Mandelbulber2's dIFS box (difs_box_v1) against DIFSBoxV1Iteration (fractal_formulas.cpp of 2.20)
// written out: |x| from iteration 1 (option Ax), Tglad's fold of x and y at 0.8 and 0.6 (option Cx,
// on by default), transf_addition_constantA_111 taken off on iteration 2 (B), the polygonal fold of
// 5 sides (P), x and y swapped where x > y (Cx_false), the fold about x = -0.3 (C), the swap again
// (Cy), scale 2.2 about (0.5, 0.2), offset_001, a turn of 30 degrees about z; then the box measured
// where the iteration ends, its x and y half-sizes plus 0.05 z^2 (option T) and less 0.1 z from
// iteration 2 (M), over DE |s| + 1. Membership on random points, and the first iteration's estimate.
TEST(FractImport, DifsBoxV1FollowsMandelbulber2) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 601;\nN 8;\n[fractal_1]\ntransf_function_enabledAx_false true;\n"
        "transf_start_iterations_X 1;\ntransf_addition_constantA_111 0,8 0,6 1;\n"
        "transf_function_enabledB_false true;\ntransf_start_iterations_B 2;\ntransf_stop_iterations_B 3;\n"
        "transf_function_enabledP_false true;\ntransf_int_6 5;\ntransf_function_enabledCx_false true;\n"
        "transf_function_enabledC_false true;\ntransf_offsetC_0 -0,3;\ntransf_function_enabledCy_false true;\n"
        "transf_scale_2 2,2;\ntransf_offsetE_0 0,5;\ntransf_offsetF_0 0,2;\ntransf_offset_001 0 0,1 0,9;\n"
        "transf_addition_constant_111 0,7 0,5 0,9;\ntransf_function_enabledT_false true;\ntransf_scale_0 0,05;\n"
        "transf_function_enabledM_false true;\ntransf_scaleA_0 0,1;\ntransf_start_iterations_M 2;\n"
        "transf_function_enabledR_false true;\ntransf_rotation 0 0 30;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    EXPECT_EQ(f.estimator.block->id, "difs");
    const double cs = std::cos(glm::radians(30.0)), sn = std::sin(glm::radians(30.0));
    const double pi = 3.14159265358979323846;
    auto iterate = [&](vec3 z, int i) {
        if (i >= 1) z.x = std::abs(z.x);
        z.x = std::abs(z.x + 0.8) - std::abs(z.x - 0.8) - z.x;
        z.y = std::abs(z.y + 0.6) - std::abs(z.y - 0.6) - z.y;
        if (i == 2) z -= vec3(0.8, 0.6, 1.0);
        z.x = std::abs(z.x);
        const double psi = std::abs(std::fmod(std::atan(z.y / z.x) + pi / 5, pi / (0.5 * 5)) - pi / 5);
        const double len = std::sqrt(z.x * z.x + z.y * z.y);
        z.x = std::cos(psi) * len;
        z.y = std::sin(psi) * len;
        if (z.x > z.y) std::swap(z.x, z.y);
        if (z.x < -0.3) z.x = std::abs(z.x + 0.3) - 0.3;
        if (z.x > z.y) std::swap(z.x, z.y);
        const vec3 centre(0.5, 0.2, 0.0);
        z = (z - centre) * 2.2 + centre + vec3(0.0, 0.1, 0.9);
        return vec3(cs * z.x - sn * z.y, sn * z.x + cs * z.y, z.z);
    };
    auto box = [](const vec3& z, int i) {
        const double widen = 0.05 * z.z * z.z - (i >= 2 ? 0.1 * z.z : 0.0);
        return length(glm::max(glm::abs(z) - (vec3(0.7, 0.5, 0.9) + vec3(widen, widen, 0.0)), vec3(0.0)));
    };
    expectDifsMembershipFollows(f, 2.0, 12, [&](const vec3& point) {
        vec3 z = point;
        double de = 1.0, dist = 1000.0;
        for (int i = 0; i < f.iterations; ++i) {
            z = iterate(z, i);
            de = de * 2.2 + 1.0;
            dist = std::min(dist, box(z, i) / de);
            if (length(z) > f.bailout) break;
        }
        return dist;
    });
    Formula one = f;
    one.iterations = 1;
    const vec3 x(1.3, -0.4, 1.9);
    EXPECT_NEAR(distanceEstimate(one, x), box(iterate(x, 0), 0) / 3.2 * one.deFactor, 1e-9);
    // Option Y measures the box where the iteration starts, its sides curved there too.
    const mb2::FractImport start = importText(
        "[main_parameters]\nformula_1 601;\n[fractal_1]\ntransf_function_enabledY_false true;\n"
        "transf_function_enabledT_false true;\ntransf_scale_0 0,2;\n");
    ASSERT_TRUE(start.faithful()) << start.unsupported.front().text();
    const Node& first = start.preset.formula.nodes.front();
    EXPECT_EQ(first.block->id, "difs_box");
    EXPECT_EQ(param(first, "w_scale"), 2.0);
    EXPECT_EQ(param(first, "curve"), 0.2);
    // The least distance less an offset (option E) and a polygon of 40 sides are refused by name.
    expectRefused("formula_1 601;\n[fractal_1]\ntransf_function_enabledE_false true;\ntransf_offsetB_0 0,1;\n",
                  "slot 1 (difs_box_v1)", "less an offset");
    expectRefused("formula_1 601;\n[fractal_1]\ntransf_function_enabledP_false true;\ntransf_int_6 40;\n",
                  "slot 1 (difs_box_v1)", "polygonal fold of other than 1 to 32 sides");
    // The flower (polygonal fold, curved sides, a varying scale), formula/img's file and the dIFS
    // cylinder with its polygonal fold import.
    const std::string gm = "Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/";
    for (const std::string& file : {gm + "DIFS BoxV1 flower.fract", gm + "DIFS Cylinder complex primitive.fract",
                                    std::string("../formula/img/difs_box_v1.fract")})
        expectExampleImports(file);
}

// Water beside the dIFS estimate (Mandelbulber2 joins its water with whatever its DE function gives:
// calculate_distance.cpp): the water combine over the least shape distance along the orbit, so the
// estimate is the lesser of the dIFS estimate and the water's. The dIFS example with water imports.
TEST(FractImport, WaterBesideTheDifsEstimate) {
    const std::string body =
        "[main_parameters]\nformula_1 600;\nprimitive_water_1_enabled true;\n"
        "primitive_water_1_position 0 0 -6;\n";
    const mb2::FractImport r = importText(body);
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "water_combine");
    EXPECT_EQ(param(e, "difs_part"), 1.0);
    EXPECT_EQ(param(e, "log_part"), 0.0);
    // Without the water the dIFS estimate alone; far above the water (its waves reach 0.1 x 0.2 x
    // 4.3 at most) the two agree, and below it the water's is the lesser.
    const mb2::FractImport dry = importText("[main_parameters]\nformula_1 600;\n");
    ASSERT_EQ(dry.preset.formula.estimator.block->id, "difs");
    for (const vec3& p : test::randomPoints(200, 1.5, 7))
        EXPECT_NEAR(distanceEstimate(r.preset.formula, p), distanceEstimate(dry.preset.formula, p), 1e-9);
    EXPECT_LT(distanceEstimate(r.preset.formula, vec3(0.3, -0.2, -7.0)), 0.0);
    expectExampleImports("difs_tree.fract");
}

// Mandelbulber2's 4D transforms after a 3D formula: with the fourth coordinate 0 throughout they
// are 3D steps (Tglad's fold per axis with a negative limit, the conditional abs add, the weight
// on chosen iterations as a scale there); one that would move w off 0 is refused.
TEST(FractImport, FourDTransformsOnAnOrbitWhoseFourthCoordinateStaysZero) {
    const std::string menger = "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 7;\nformula_2 ";
    const mb2::FractImport tglad =
        importText(menger + "1045;\n[fractal_2]\ntransf_addition_constant_0000 0,2 -0,1 0,3 0,5;\n");
    ASSERT_TRUE(tglad.faithful()) << tglad.unsupported.front().text();
    const std::vector<std::string> ids = blockIds(tglad.preset.formula);
    const auto fold = std::find(ids.begin(), ids.end(), "box_fold_general");
    ASSERT_NE(fold, ids.end());
    const Node& n = tglad.preset.formula.nodes[size_t(fold - ids.begin())];
    EXPECT_EQ(param(n, "low", 1), -0.1);
    EXPECT_EQ(param(n, "high", 1), -0.1);
    // Tglad's fold at a negative limit, |y - 0.1| - |y + 0.1| - y, on a point.
    P4 p{vec3(0.3, 0.05, -2.0), 1.0};
    n.block->apply(p, vec3(0.0), n.args());
    EXPECT_NEAR(p.xyz.y, std::abs(0.05 - 0.1) - std::abs(0.05 + 0.1) - 0.05, 1e-12);
    EXPECT_NEAR(p.xyz.z, std::abs(-2.0 + 0.3) - std::abs(-2.0 - 0.3) + 2.0, 1e-12);

    const mb2::FractImport weight = importText(
        "[main_parameters]\nformula_1 1041;\nformula_2 7;\nhybrid_fractal_enable true;\n[fractal_1]\n"
        "transf_scale 2;\ntransf_int_A 2;\ntransf_offset 0,5;\n");
    ASSERT_TRUE(weight.faithful()) << weight.unsupported.front().text();
    int scales = 0;
    for (const Node& k : weight.preset.formula.nodes)
        if (k.block->id == "scale") {
            ++scales;
            if (k.runsOn(2) && !k.runsOn(4)) {
                EXPECT_DOUBLE_EQ(param(k, "scale"), 2.5 / 2.0);
            }
        }
    EXPECT_EQ(scales, 2);

    const mb2::FractImport moved = importText(menger + "1042;\n[fractal_2]\ntransf_offset_0000 0 0 0 0,1;\n");
    EXPECT_TRUE(mentions(moved.unsupported, "slot 2 (transf_spherical_fold4d)", "moves w off 0"));
    // An offset in x, y and z is the sphere fold's own.
    const mb2::FractImport offCentre = importText(menger + "1042;\n[fractal_2]\ntransf_offset_0000 0,1 0 -0,2 0;\n");
    ASSERT_TRUE(offCentre.faithful()) << offCentre.unsupported.front().text();
    int sphereFolds = 0;
    for (const Node& k : offCentre.preset.formula.nodes)
        if (k.block->id == "sphere_fold") {
            ++sphereFolds;
            EXPECT_DOUBLE_EQ(param(k, "offset", 0), 0.1);
            EXPECT_DOUBLE_EQ(param(k, "offset", 2), -0.2);
        }
    EXPECT_EQ(sphereFolds, 1);
}

// A red-cyan anaglyph (stereo_mode 2) imports as the view from between the eyes, listed as
// approximated; pairs side by side (0) or one above the other (1) are other pictures, refused.
TEST(FractImport, RedCyanStereoIsDrawnFromBetweenTheEyes) {
    const std::string body = "[main_parameters]\nstereo_enabled true;\nstereo_eye_distance 0,003;\n";
    const mb2::FractImport anaglyph = importText(body + "stereo_mode 2;\n");
    ASSERT_TRUE(anaglyph.faithful()) << anaglyph.unsupported.front().text();
    EXPECT_TRUE(mentions(anaglyph.approximated, "camera", "stereo_mode red-cyan: one view from between the eyes"));
    const mb2::FractImport plain = importText("[main_parameters]\n");
    EXPECT_EQ(anaglyph.preset.camera.position, plain.preset.camera.position);
    for (const char* mode : {"0", "1"}) {
        const mb2::FractImport pair = importText(body + "stereo_mode " + mode + ";\n");
        EXPECT_TRUE(mentions(pair.unsupported, "main",
                             std::string("stereo pairs side by side or one above the "
                                         "other (stereo_mode ") +
                                 mode + ")"));
    }
}

// The generalized fold box: its polyhedron's fold, the Mandelbox's sphere fold, rotation and scale.
TEST(FractImport, GeneralizedFoldBoxIsThePolyhedralFold) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 37;\n[fractal_1]\nmandelbox_generalized_fold_type 5;\n"
        "mandelbox_scale -1,5;\nmandelbox_folding_min_radius 0,1;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    ASSERT_EQ(blockIds(r.preset.formula),
              (std::vector<std::string>{"generalized_box_fold", "sphere_fold", "scale", "add_c"}));
    EXPECT_EQ(param(r.preset.formula.nodes[0], "type"), 5.0);
    EXPECT_EQ(param(r.preset.formula.nodes[0], "solid"), 1.0);
    EXPECT_EQ(param(r.preset.formula.nodes[2], "scale"), -1.5);
    const mb2::FractImport melted = importText("[main_parameters]\nformula_1 37;\n[fractal_1]\nmandelbox_melt 0,2;\n");
    EXPECT_TRUE(mentions(melted.unsupported, "slot 1 (generalized_fold_box)", "a melted generalized fold"));
}

// Aexion's set runs its own 4D orbit in the aexion estimator: a point is inside (estimate 0)
// exactly where Mandelbulber2's AexionIteration, written out here, stays within the bailout for N
// iterations; cadd and the analytic derivative's scale and offset come from the slot.
TEST(FractImport, AexionRunsItsOwnOrbit) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 19;\nN 14;\nuse_default_bailout false;\nbailout 50;\n[fractal_1]\ncadd "
        "-1,2;\nanalyticDE_offset_1 0,2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_TRUE(r.preset.formula.nodes.empty());
    const Node& e = r.preset.formula.estimator;
    ASSERT_EQ(e.block->id, "aexion");
    EXPECT_EQ(param(e, "orbit"), 14.0);
    EXPECT_EQ(param(e, "escape"), 50.0);
    EXPECT_EQ(param(e, "cadd"), -1.2);
    EXPECT_EQ(param(e, "scale"), 1.0);
    EXPECT_EQ(param(e, "offset"), 0.2);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        auto fold = [](const vec3& v) {
            return std::array<double, 4>{std::abs(v.x + v.y + v.z) - 1.2, std::abs(-v.x - v.y + v.z) - 1.2,
                                         std::abs(-v.x + v.y - v.z) - 1.2, std::abs(v.x - v.y - v.z) - 1.2};
        };
        const std::array<double, 4> c = fold(point);
        auto [x, y, z, w] = c;
        bool escaped = false;
        for (int i = 0; i < 14 && !escaped; ++i) {
            const double nx = x * x - y * y + 2.0 * w * z + c[0], ny = y * y - x * x + 2.0 * w * z + c[1],
                         nz = z * z - w * w + 2.0 * x * y + c[2], nw = w * w - z * z + 2.0 * x * y + c[3];
            x = nx, y = ny, z = nz, w = nw;
            escaped = std::sqrt(x * x + y * y + z * z + w * w) > 50.0;
        }
        inside += !escaped;
        EXPECT_EQ(distanceEstimate(r.preset.formula, point) > 0.0, escaped)
            << point.x << " " << point.y << " " << point.z;
    }
    EXPECT_GT(inside, 20);  // 31 of 2000: the set is thin
    const mb2::FractImport julia = importText("[main_parameters]\nformula_1 19;\njulia_mode true;\n");
    EXPECT_TRUE(mentions(julia.unsupported, "slot 1 (aexion)", "julia_mode: a aexion Julia set"));
}

// Benesi's power 2 is its block then c; the pine tree adds c itself (y and z swapped, scaled per
// axis) and turns about x. An orbit escapes exactly where Mandelbulber2's BenesiPineTreeIteration,
// written out here, passes the bailout within N iterations.
TEST(FractImport, BenesiPowersAndThePineTree) {
    const mb2::FractImport benesi = importText("[main_parameters]\nformula_1 20;\n");
    ASSERT_TRUE(benesi.faithful()) << benesi.unsupported.front().text();
    EXPECT_EQ(blockIds(benesi.preset.formula), (std::vector<std::string>{"benesi_pow2", "add_c"}));
    const mb2::FractImport pine = importText(
        "[main_parameters]\nformula_1 66;\nN 9;\n[fractal_1]\ntransf_constant_multiplier_100 1 0,5 0,75;\n"
        "transf_angle_0 30;\n");
    ASSERT_TRUE(pine.faithful()) << pine.unsupported.front().text();
    EXPECT_EQ(blockIds(pine.preset.formula), (std::vector<std::string>{"benesi_pine_tree"}));
    const double bailout = pine.preset.formula.bailout;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        const vec3 c = point * vec3(1.0, 0.5, 0.75);
        vec3 z = point;
        bool escaped = false;
        for (int i = 0; i < 9 && !escaped; ++i) {
            const vec3 zz = z * z;
            const double t = zz.y + zz.z > 0.0 ? 2.0 * z.x / std::sqrt(zz.y + zz.z) : 1.0;
            z = vec3(zz.x - zz.y - zz.z + c.x, 2.0 * t * z.y * z.z + c.z, t * (zz.y - zz.z) + c.y);
            const double beta = glm::radians(30.0), y = z.y;
            z.y = y * std::cos(beta) + z.z * std::sin(beta);
            z.z = -y * std::sin(beta) + z.z * std::cos(beta);
            escaped = length(z) > bailout;
        }
        inside += !escaped;
        EXPECT_EQ(evaluate(pine.preset.formula, point).escaped, escaped) << point.x << " " << point.y << " " << point.z;
    }
    EXPECT_GT(inside, 40);  // 73 of 2000
}

// Whether each of 2000 points of [-extent, extent]^3 escapes by Mandelbulber2's orbit written out
// (`escapes`) against fraktal's membership of formula f: at most 1 % may differ (a fold's edge), and
// 1 % to 99 % are inside.
void expectEscapesFollow(const Formula& f, double extent, const std::string& what,
                         const std::function<bool(const vec3&)>& escapes) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-extent, extent);
    int inside = 0, differ = 0;
    const int points = 2000;
    for (int k = 0; k < points; ++k) {
        const vec3 point = randomVec3(u, random);
        const bool escaped = escapes(point);
        inside += !escaped;
        differ += evaluate(f, point).escaped != escaped;
    }
    std::printf("%s: %d of %d inside, %d differ\n", what.c_str(), inside, points, differ);
    EXPECT_LE(differ, points / 100);
    EXPECT_GT(inside, points / 100);
    EXPECT_LT(inside, points - points / 100);
}

// A formula imported from a settings file's body, against Mandelbulber2's own iteration written out
// here in double (`step`, from fractal_formulas.cpp, with c added where Mandelbulber2 adds it):
// its blocks, and an orbit from each of 2000 points escapes where the written-out one passes the
// bailout within N iterations. Points on the edge of the set may go either way where fraktal
// writes a step differently (V2's lift with tan, sin / (1 + cos) there): at most 1 % differ, and
// at least 1 % lie on each side.
struct OrbitCase {
    const char* body;
    std::vector<std::string> blocks;
    vec3 (*step)(const vec3& z, const vec3& c);
    double extent = 1.5;  // points are drawn from [-extent, extent]^3
    // In place of `step` where a part runs on some iterations only (i counts from 0).
    vec3 (*stepAt)(const vec3& z, const vec3& c, int i) = nullptr;
    // Where the import refuses the file for what lies outside the step (the nodes are still
    // written): what every refusal names.
    const char* refusal = nullptr;
};
void expectOrbitsFollowMandelbulber2(const OrbitCase& c) {
    SCOPED_TRACE(c.body);
    const mb2::FractImport r = importText(std::string("[main_parameters]\n") + c.body);
    if (c.refusal) {
        EXPECT_FALSE(r.faithful());
        for (const mb2::ImportItem& item : r.unsupported)
            EXPECT_NE(item.what.find(c.refusal), std::string::npos) << item.text();
    } else {
        ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    }
    const std::vector<std::string> blocks = blockIds(r.preset.formula);
    EXPECT_EQ(blocks, c.blocks);
    const Formula& f = r.preset.formula;
    expectEscapesFollow(f, c.extent, blocks.front(), [&](const vec3& point) {
        vec3 z = point;
        for (int i = 0; i < f.iterations; ++i) {
            z = c.stepAt ? c.stepAt(z, point, i) : c.step(z, point);
            if (!(length(z) <= f.bailout)) return true;
        }
        return false;
    });
}

// msltoe's three Riemann spheres, each with values off its defaults (no c: Mandelbulber2 adds none).
TEST(FractImport, RiemannSpheresFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 72;\nN 4;\n[fractal_1]\ntransf_scale 1,1;\ntransf_offsetA_0 0,3;\ntransf_offsetB_0 -0,2;\n"
         "transf_addition_constant 0 0 0,1;\n",
         {"riemann_sphere", "translate"},
         [](const vec3& v, const vec3&) {
             const double r = length(v);
             const vec3 z = v * (1.1 / r);
             const double q = 1.0 / (1.0 - z.z), s0 = z.x * q, t0 = z.y * q;
             const double p = std::min(1.0 + s0 * s0 + t0 * t0, 36.0);
             const double s = std::abs(std::sin(3.14159265358979 * s0 + 0.3)),
                          t = std::abs(std::sin(3.14159265358979 * t0 - 0.2));
             const double radius = -0.25 + std::pow(r * r, p);
             return vec3(2.0 * s, 2.0 * t, -1.0 + s * s + t * t) * (radius / (1.0 + s * s + t * t)) + vec3(0, 0, 0.1);
         }},
        {"formula_1 71;\nN 8;\n[fractal_1]\ntransf_scale 0,9;\ntransf_constant_multiplier_441 3 4 1,5;\n",
         {"riemann_sphere_v1"},
         [](const vec3& v, const vec3&) {
             const double r = length(v);
             const vec3 z = v * (0.9 / r);
             const double q = 1.0 / (1.0 - z.z);
             vec3 t(z.x * q, z.y * q, 0.0);
             t.z = (r - 1.5) * (1.0 + t.x * t.x + t.y * t.y);
             t.x -= std::floor(t.x + 0.5), t.y -= std::floor(t.y + 0.5);
             return t * vec3(3.0, 4.0, 1.5);
         }},
        {"formula_1 139;\nN 3;\n[fractal_1]\ntransf_scale_08 0,7;\ntransf_scaleA_1 1,25;\ntransf_offset_010 0,1 1,2 "
         "0;\n",
         {"riemann_sphere_v2"},
         [](const vec3& v, const vec3&) {
             const double r = length(v);
             const vec3 z = v * (0.7 / r);
             double rx = z.x / (z.y - 1.0), rz = z.z / (z.y - 1.0);
             const double theta = 8.0 * std::atan2(2.0 * rx, rx * rx - 1.0) * 1.25;
             const double phi = 8.0 * std::atan2(2.0 * rz, rz * rz - 1.0);
             rx = std::sin(theta) / (1.0 + std::cos(theta));
             rz = std::sin(phi) / (1.0 + std::cos(phi));
             const double rxz = rx * rx + rz * rz, d = 2.0 / (rxz + 1.0);
             return vec3(rx * d, (rxz - 1.0) * 0.5 * d, rz * d) * (r * r * r * r) + vec3(0.1, 1.2, 0.0);
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    // A rotation of V1's projected plane happens inside its step: refused by name.
    const mb2::FractImport turned =
        importText("[main_parameters]\nformula_1 71;\n[fractal_1]\ntransf_rotation_enabled true;\n");
    EXPECT_TRUE(mentions(turned.unsupported, "slot 1 (riemann_sphere_msltoe_v1)", "inside the step"));
}

// aboxMod1 (its fold at the folding value, the sphere fold of squared radii, the scale, c with x
// and y exchanged) and mandelbulb_abs_power2 (the buffalo step between rotations and offsets, in
// their windows), each with values off its defaults, against the iteration written out.
TEST(FractImport, AboxMod1AndAbsPower2FollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 64;\nN 12;\n[fractal_1]\nmandelbox_folding_value 1,5;\ntransf_scale_1 0,8;\n"
         "transf_minimum_radius_0 0,2;\nmandelbox_scale -1,7;\n",
         {"plane_fold", "plane_fold", "plane_fold", "box_fold_axes", "sphere_fold", "scale", "add_c_axes"},
         [](const vec3& v, const vec3& c) {
             vec3 z = v;
             const vec3 value(1.5, 1.5, 1.5 * 0.8);
             for (int k = 0; k < 3; ++k) z[k] = value[k] - std::abs(std::abs(z[k]) - value[k]);
             const double rr = dot(z, z);
             if (rr < 0.2)
                 z *= 1.0 / 0.2;
             else if (rr < 1.0)
                 z *= 1.0 / rr;
             return z * -1.7 + vec3(c.y, c.x, c.z);
         },
         3.0},
        {"formula_1 137;\nN 10;\n[fractal_1]\nbuffalo_abs_x true;\nbuffalo_preabs_z true;\ntransf_rotation_enabled "
         "true;\ntransf_rotation 0 -33 -40;\ntransf_stop_iterations_R 2;\ntransf_offset_000 0,2 -0,1 0;\n"
         "transf_start_iterations_M 1;\n",
         {"rotate", "plane_fold", "mandelbulb_sine", "axis_scale", "plane_fold", "translate", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = v;
             if (i < 2)
                 z = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(-40.0), vec3(0, 0, 1))) *
                     glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(-33.0), vec3(0, 1, 0))) * z;
             z.z = std::abs(z.z);
             const double x2 = z.x * z.x, y2 = z.y * z.y, temp = 1.0 - z.z * z.z / (x2 + y2);
             z = vec3(std::abs((x2 - y2) * temp), 2.0 * z.x * z.y * temp, -2.0 * z.z * std::sqrt(x2 + y2));
             if (i >= 1) z += vec3(0.2, -0.1, 0.0);
             return z + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Coastalbrot, the Mandelbulb eye, msltoe's sym2 mod and donut and the smooth Mandelbox, each
// with values off its defaults.
TEST(FractImport, CoastalbrotEyeMsltoeAndSmoothMandelboxFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 129;\nN 5;\n",
         {"coastalbrot", "add_c"},
         [](const vec3& z, const vec3& c) {
             const double r = length(z);
             return glm::sin(glm::sin(glm::sin(3.14159265358979 / 3 + z * 3.14159265358979))) * std::pow(r, 8.7) + c;
         }},
        {"formula_1 800;\nN 6;\n[fractal_1]\nbuffalo_preabs_z true;\nbuffalo_abs_x true;\ntransf_scaleB_1 0,2;\n"
         "transf_scaleC_1 1,6;\ntransf_scale_1 1,5;\ntransf_addition_constantA_000 0,3 0,1 -0,1;\n",
         {"mandelbulb_eye", "add_c"},
         [](const vec3& v, const vec3& c) {
             const vec3 z(v.x, v.y, std::abs(v.z));
             const double rr = dot(z, z), t = std::sqrt(z.x * z.x + z.y * z.y);
             const double theta = std::atan2(t, z.z) * 0.2 + std::atan2(t, -z.z) * 1.6;
             const double phi = std::atan2(z.y, z.x) * 1.5 + std::atan2(-z.y, z.x);
             const vec3 w(rr * std::sin(theta) * std::cos(phi), rr * std::sin(theta) * std::sin(phi),
                          rr * std::cos(theta));
             return vec3(std::abs(w.x), w.y, w.z) + vec3(0.3, 0.1, -0.1) + c;
         },
         1.2},
        {"formula_1 51;\nN 6;\n[fractal_1]\ntransf_scale 1,2;\ntransf_offset 0,1;\ntransf_scale_1 0,9;\n"
         "transf_addition_constant 0 0,2 0;\n",
         {"msltoe_sym2_mod", "add_c"},
         [](const vec3& v, const vec3& c) {
             vec3 z = std::abs(v.y) < std::abs(v.z) ? vec3(v.x, v.z, v.y) : v;
             if (z.y > z.z) z.x = -z.x;
             const vec3 z2 = z * z;
             const double zr = 1.0 - z2.z / (z2.x + z2.y + z2.z);
             vec3 t((z2.x - z2.y) * zr, 2.0 * z.x * z.y * zr * 1.2, 2.0 * z.z * std::sqrt(z2.x + z2.y));
             t += vec3(0.0, 0.2, 0.0);
             t *= 1.0 + 0.1 / -length(t);
             return t * 0.9 + c;
         }},
        {"formula_1 82;\nN 4;\n[fractal_1]\ndonut_number 6;\ndonut_factor 2,5;\ndonut_ring_thickness 0,2;\n",
         {"msltoe_donut"},
         [](const vec3& z, const vec3&) {
             const double sector = 2.0 * 3.14159265358979 / 6.0;
             const double R2 = 1.0 - std::sqrt(z.x * z.x + z.y * z.y);
             const double t = R2 * R2 + z.z * z.z - 0.04;
             const double theta2 = sector * std::round(std::atan2(z.y, z.x) / sector);
             if (!(t > 0.03)) return z / t;
             const double c1 = std::cos(theta2), s1 = std::sin(theta2);
             const double x1 = c1 * z.x + s1 * z.y - 1.0, y1 = -s1 * z.x + c1 * z.y;
             return 2.5 * vec3(x1, z.z, y1);
         }},
        {"formula_1 17;\nN 8;\n[fractal_1]\nmandelbox_sharpness 2,5;\nmandelbox_scale -1,8;\n",
         {"mandelbox_smooth_fold", "scale", "add_c"},
         [](const vec3& v, const vec3& c) {
             auto greater = [](double a, double b) { return 1.0 / (1.0 + std::exp(2.5 * (b - a))); };
             auto less = [](double a, double b) { return 1.0 / (1.0 + std::exp(2.5 * (a - b))); };
             vec3 z = v;
             for (int k = 0; k < 3; ++k) {
                 const double k1 = greater(z[k], 1.0), k2 = less(z[k], -1.0);
                 z[k] = z[k] * (1.0 - k1) + (2.0 - z[k]) * k1;
                 z[k] = z[k] * (1.0 - k2) + (-2.0 - z[k]) * k2;
             }
             const double r2 = dot(z, z), rk1 = less(r2, 0.25), rk21 = (1.0 - rk1) * less(r2, 1.0);
             z = z * (1.0 - rk1) + z * (4.0 * rk1);
             z = z * (1.0 - rk21) + z * (1.0 / r2 * rk21);
             return z * -1.8 + c;
         },
         3.0},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Mandelbulber2's smooth sort of a pair (MengerSmoothIteration): a - t, b + t.
void smoothSort(double& a, double& b, double weight, double k) {
    double t = a - b;
    t = weight * (t - std::sqrt(t * t + k));
    a -= t;
    b += t;
}

vec3 mb2RotateVector(const vec3& degrees, const vec3& v);

// The signed multiple of c of msltoe's sym3 family (transf_addCpixel_enabled_false), as
// MsltoeSym3ModIteration and its mods write it: z + sign(z) |c| m.
vec3 mb2SignedMultipleOfC(const vec3& z, const vec3& c, const vec3& m) {
    const vec3 k = glm::abs(c) * m;
    auto sign = [](double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; };
    return z + vec3(sign(z.x) * k.x, sign(z.y) * k.y, sign(z.z) * k.z);
}

// msltoe's sym3 mod with its stretch, the signed c and the quaternion fold in window A; mod3's
// sector turn (Mandelbulber2's loop); mod2's two charts; sym4 mod's weighted swaps, per-axis scale
// and rotation. mod2, mod3 and sym4 mod take no 1 for c (the derivative_tweak after add_c).
TEST(FractImport, MsltoeSym3AndSym4ModsFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 68;\nN 6;\n[fractal_1]\ntransf_scale 1,2;\ntransf_scale_0 0,7;\ntransf_addition_constant 0 0,1 0;\n"
         "transf_addCpixel_enabled_false true;\ntransf_constant_multiplier_000 0,1 0,2 0,1;\n"
         "transf_function_enabled_false true;\ntransf_start_iterations_A 2;\n",
         {"msltoe_sym3_mod", "add_c_symmetric", "bristorbrot", "add_c"},
         nullptr,
         1.0,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = std::abs(v.y) < std::abs(v.z) ? vec3(v.x, v.z, v.y) : v;
             if (z.y > z.z) z.x = -z.x, z.z = -z.z;
             const vec3 z2 = z * z;
             const double v3 = z2.x + z2.y + z2.z + 0.7 * 0.7 * z2.y * z2.z;
             const double zr = 1.0 - z2.z / v3;
             vec3 t((z2.x - z2.y) * zr, 2.0 * z.x * z.y * zr * 1.2, 2.0 * z.z * std::sqrt(z2.x + z2.y));
             t = mb2SignedMultipleOfC(t + vec3(0.0, 0.1, 0.0), c, vec3(0.1, 0.2, 0.1));
             if (i >= 2) t = vec3(t.x * t.x - t.y * t.y - t.z * t.z, t.x * t.y, t.x * t.z) * vec3(1.0, 2.0, 2.0);
             return t + c;
         }},
        {"formula_1 81;\nN 6;\n[fractal_1]\ntransf_scale 0,9;\ntransf_offset 0,1;\ntransf_scale_1 1,1;\n",
         {"msltoe_sym3_mod", "add_c", "derivative_tweak"},
         [](const vec3& v, const vec3& c) {
             const double pi = 3.14159265358979;
             vec3 z = v;
             double psi = std::atan2(z.z, z.y) + pi * 2.0, psi2 = 0.0;
             while (psi > pi / 8.0) {
                 psi -= pi / 4.0;
                 psi2 -= pi / 4.0;
             }
             const double cs = std::cos(psi2), sn = std::sin(psi2);
             z = vec3(z.x, z.y * cs - z.z * sn, z.y * sn + z.z * cs);
             const vec3 zs = z * z;
             const double zs2 = zs.x + zs.y, zsd = 1.0 - zs.z / (zs2 + zs.z);
             const vec3 z1((zs.x - zs.y) * zsd, 2.0 * z.x * z.y * zsd * 0.9, 2.0 * z.z * std::sqrt(zs2));
             vec3 t(z1.x, z1.y * cs + z1.z * sn, -z1.y * sn + z1.z * cs);
             t *= 1.0 + 0.1 / -length(t);
             return t * 1.1 + c;
         }},
        {"formula_1 80;\nN 6;\n[fractal_1]\ntransf_scale_0 0,5;\ntransf_addCpixel_enabled_false true;\n"
         "transf_constant_multiplier_000 0,1 0,1 0,1;\ntransf_function_enabledy false;\n",
         {"msltoe_sym3_mod2", "add_c_symmetric", "add_c", "derivative_tweak"},
         [](const vec3& z, const vec3& c) {
             const vec3 z2 = z * z;
             const double r = z2.x + z2.y + z2.z, r1 = std::sqrt(r + 0.5 * z2.y * z2.z);
             vec3 t;
             if (z2.z < z2.y) {
                 const double theta = 2.0 * std::atan2(z.y, z.x), phi = 2.0 * std::asin(z.z / r1);
                 t = vec3(r * std::cos(theta) * std::cos(phi), r * std::sin(theta) * std::cos(phi), -r * std::sin(phi));
             } else {
                 const double theta = 2.0 * std::atan2(z.z, z.x), phi = 2.0 * std::asin(z.y / r1);
                 t = vec3(r * std::cos(theta) * std::cos(phi), -r * std::sin(phi), r * std::sin(theta) * std::cos(phi));
             }
             // c's abs taken on x and z only (transf_function_enabledy false).
             const vec3 k = vec3(std::abs(c.x), c.y, std::abs(c.z)) * 0.1;
             auto sign = [](double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; };
             return t + vec3(sign(t.x) * k.x, sign(t.y) * k.y, sign(t.z) * k.z) + c;
         }},
        {"formula_1 69;\nN 6;\n[fractal_1]\ntransf_constant_multiplier_111 1,2 0,9 1;\ntransf_scale3D_111 1 1,1 0,9;\n"
         "transf_addition_constant 0,1 0 0;\ntransf_rotation_enabled true;\ntransf_rotation 10 0 -15;\n",
         {"msltoe_sym4_fold", "axis_scale", "bristorbrot", "translate", "rotate", "add_c", "derivative_tweak"},
         [](const vec3& v, const vec3& c) {
             vec3 z = v;
             if (std::abs(z.x) < std::abs(z.z) * 1.2) std::swap(z.x, z.z);
             if (std::abs(z.x) < std::abs(z.y) * 0.9) std::swap(z.x, z.y);
             if (std::abs(z.y) < std::abs(z.z) * 1.0) std::swap(z.y, z.z);
             if (z.x * z.z < 0.0) z.z = -z.z;
             if (z.x * z.y < 0.0) z.y = -z.y;
             z *= vec3(1.0, 1.1, 0.9);
             const vec3 t(z.x * z.x - z.y * z.y - z.z * z.z, 2.0 * z.x * z.y, 2.0 * z.x * z.z);
             return mb2RotateVector(vec3(10.0, 0.0, -15.0), t + vec3(0.1, 0.0, 0.0)) + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Ide's formulas with their multipliers (ides damps x and z under 2.5, ides2 keeps the point) and
// Aexion's octopus with its scales, the abs of x and z only, a turn, an offset and c signed by the
// point: Mandelbulber2 adds c only where that option says.
// IdesIteration and Ides2Iteration with the multipliers (1.4, 1.7, 0.4) and the subtracted (0.8, 0.5, 0.7).
vec3 mb2Ides(vec3 z, bool damp) {
    if (damp && std::abs(z.x) < 2.5) z.x *= 0.9;
    if (damp && std::abs(z.z) < 2.5) z.z *= 0.9;
    const vec3 z2 = z * z, m(1.4, 1.7, 0.4), s(0.8, 0.5, 0.7);
    return vec3(m.x * z2.x - s.x * (z2.y + z2.z), m.y * z.x * z.y * z.z, m.z * z2.z - s.z * (z2.x + z2.y)) +
           (damp ? vec3(0.0) : z);
}

TEST(FractImport, IdesAndAexionsOctopusFollowMandelbulber2sOrbits) {
    const char* values =
        "[fractal_1]\ntransf_addition_constant_0555 0,8 0,5 0,7;\n"
        "transf_constant_multiplier_121 1,4 1,7 0,4;\n";
    const std::string idesBody = std::string("formula_1 39;\nN 6;\n") + values;
    const std::string ides2Body = std::string("formula_1 40;\nN 6;\n") + values;
    const OrbitCase cases[] = {
        {idesBody.c_str(), {"ides", "add_c"}, [](const vec3& z, const vec3& c) { return mb2Ides(z, true) + c; }},
        {ides2Body.c_str(), {"ides", "add_c"}, [](const vec3& z, const vec3& c) { return mb2Ides(z, false) + c; }},
        {"formula_1 63;\nN 6;\n[fractal_1]\ntransf_scale3D_111 0,6 1,1 1;\ntransf_function_enabledAy false;\n"
         "transf_rotation_enabled true;\ntransf_rotation 0 20 0;\ntransf_addition_constant 0,1 0 -0,2;\n"
         "transf_addCpixel_enabled_false true;\ntransf_constant_multiplier_000 1 1 1;\n",
         {"aexion_octopus", "rotate", "translate", "add_c_symmetric"},
         [](const vec3& z, const vec3& c) {
             vec3 t(z.x * z.z * 0.6, (z.x * z.x - z.z * z.z) * 1.1, z.y);
             t.x = std::abs(t.x), t.z = std::abs(t.z);
             t = mb2RotateVector(vec3(0.0, 20.0, 0.0), t) + vec3(0.1, 0.0, -0.2);
             return mb2SignedMultipleOfC(t, c, vec3(1.0));
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Benesi's T1 pine tree (T1's |v| scaled per axis in Benesi's frame, less its offset; the pine
// tree's square plus c with y and z exchanged, times its multipliers; the Julia offset) and msltoe's
// toroidal bulb with its pre-scale on the first iteration and its spherical offset, as
// BenesiT1PineTreeIteration and MsltoeToroidalIteration write them. Mandelbulber2 adds no other c
// to the pine tree.
TEST(FractImport, BenesiT1PineTreeAndTheToroidalBulbFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 67;\nN 6;\n[fractal_1]\ntransf_scale3D_222 2,1 1,9 2;\n"
         "transf_constant_multiplier_100 1 0,5 0,3;\ntransf_constant_julia_mode true;\ntransf_offset_000 0,1 0 0;\n",
         {"benesi_t1", "derivative_tweak", "benesi_pine_tree", "translate"},
         [](const vec3& v, const vec3& point) {
             const double s23 = std::sqrt(2.0 / 3.0), s13 = std::sqrt(1.0 / 3.0), s12 = std::sqrt(0.5);
             vec3 z = v;
             double tempXZ = z.x * s23 - z.z * s13;
             z = vec3((tempXZ - z.y) * s12, (tempXZ + z.y) * s12, z.x * s13 + z.z * s23);
             z = glm::abs(z) * vec3(2.1, 1.9, 2.0);
             tempXZ = (z.y + z.x) * s12;
             z = vec3(z.z * s13 + tempXZ * s23, (z.y - z.x) * s12, z.z * s23 - tempXZ * s13);
             z -= vec3(2.0, 0.0, 0.0);
             const vec3 zz = z * z;
             double t = 1.0;
             if (zz.y + zz.z > 0.0) t = 2.0 * z.x / std::sqrt(zz.y + zz.z);
             const double temp = z.z;
             z = vec3(zz.x - zz.y - zz.z, 2.0 * t * z.y * temp, t * (zz.y - zz.z));
             const vec3 c = point * vec3(1.0, 0.5, 0.3);
             z += vec3(c.x, c.z, c.y);
             return z + vec3(0.1, 0.0, 0.0);
         }},
        {"formula_1 86;\nN 6;\n[fractal_1]\ntransf_function_enabled_false true;\ntransf_scale3D_111 1,2 1 0,9;\n"
         "transf_minimum_radius_05 0,4;\ntransf_pwr_4 2;\ntransf_pwr_8 5;\npower 4;\n"
         "transf_function_enabledAx_false true;\ntransf_offset 0,1;\ntransf_scale 1,1;\n",
         {"axis_scale", "msltoe_toroidal", "derivative_tweak", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = i < 1 ? v * vec3(1.2, 1.0, 0.9) : v;
             double theta = std::atan2(z.y, z.x);
             const double x1 = 0.4 * std::cos(theta), y1 = 0.4 * std::sin(theta);
             const double rr = (z.x - x1) * (z.x - x1) + (z.y - y1) * (z.y - y1) + z.z * z.z;
             const double phi = std::asin(z.z / std::sqrt(rr)) * 5.0, rp = std::pow(rr, 2.0);
             theta *= 4.0;
             const double around = 0.4 + rp * std::cos(phi);
             z = vec3(around * std::cos(theta), around * std::sin(theta), -rp * std::sin(phi));
             z *= 1.0 + 0.1 / -length(z);
             return z * 1.1 + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// RiemannBulbMsltoeMod2Iteration of 2.20 written out, with the given radius, smooth inside or not,
// and wrap or sine outside (its other values Mandelbulber2's defaults but the multiplier 1.7).
vec3 mb2RiemannBulb(vec3 z, bool smoothInside, bool wrap, bool sine) {
    const double radius2 = 0.6, rr = dot(z, z);
    if (rr < radius2 * radius2) {
        if (smoothInside) return z * (radius2 * ((rr * 0.1) + 0.4) * 1.18 * 1.0 / rr);
        return z * vec3(0.9, 1.1, 1.0);
    }
    z *= vec3(1.7);
    const double shift = 1.0, r1 = z.x * z.x + (z.y - shift) * (z.y - shift) + z.z * z.z;
    z = vec3(z.x / r1, (z.y - shift) / r1, z.z / r1) * 3.0;
    z.y += 1.5;
    if (wrap) z.x -= std::round(z.x), z.z -= std::round(z.z);
    if (sine) {
        z.x = std::abs(std::sin(3.14159265358979 * z.x * 0.8));
        z.z = std::abs(std::sin(3.14159265358979 * z.z * 0.8));
    }
    return z;
}

// msltoe's Riemann bulb mod 2 both ways inside and outside (no c: Mandelbulber2 adds none).
TEST(FractImport, RiemannBulbFollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 85;\nN 6;\n[fractal_1]\ntransf_minimum_radius_05 0,6;\ntransf_constant_multiplier_222 1,7 1,7 "
         "1,7;\n",
         {"riemann_bulb"},
         [](const vec3& z, const vec3&) { return mb2RiemannBulb(z, true, true, false); }},
        {"formula_1 85;\nN 6;\n[fractal_1]\ntransf_minimum_radius_05 0,6;\ntransf_constant_multiplier_222 1,7 1,7 "
         "1,7;\n"
         "transf_function_enabled false;\ntransf_constant_multiplier_111 0,9 1,1 1;\ntransf_function_enabledx false;\n"
         "transf_function_enabledx_false true;\ntransf_scale_1 0,8;\n",
         {"riemann_bulb"},
         [](const vec3& z, const vec3&) { return mb2RiemannBulb(z, false, false, true); }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// MandelbulbMultiIteration's bulb (and MandelbulbMulti2Iteration's) written out: the axes of v in
// the order's vector, theta0 and phi0 by asin or acos and atan or atan2 plus the offsets (in
// degrees), the sine or cosine form, its horizontal factor of theta0 where `unscaled`.
vec3 mb2MultiBulb(const vec3& z, const vec3& v, double power, bool asin, bool atan2, bool cosine, bool unscaled,
                  double scaleA, double scaleB, double beta, double alpha) {
    const double pi = 3.14159265358979, r = length(z);
    const double th0 = beta * pi / 180.0 + (asin ? std::asin(v.x / r) : std::acos(v.x / r));
    const double ph0 = alpha * pi / 180.0 + (atan2 ? std::atan2(v.y, v.z) : std::atan(v.y / v.z));
    const double rp = std::pow(r, power), th = th0 * power * scaleA, ph = ph0 * power * scaleB;
    if (cosine) {
        const double sinth = std::sin(unscaled ? th0 : th);
        return rp * vec3(sinth * std::sin(ph), std::cos(ph) * sinth, std::cos(th));
    }
    const double costh = std::cos(unscaled ? th0 : th);
    return rp * vec3(costh * std::cos(ph), std::sin(ph) * costh, std::sin(th));
}

// The multi bulb: axis order xzy, asin and atan of the quotient (Mandelbulber2's default), its
// scales and offsets; the cosine form with the horizontal factor unscaled and acos, atan2, the abs
// of y first. The multi2 bulb: Mandelbulber2's zyx numbering (1: zxy), x and y exchanged from the
// second iteration, z negated, an offset and a turn on the first three iterations.
TEST(FractImport, MultiBulbsFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 65;\nN 6;\n[fractal_1]\npower 3;\nmandelbulbMulti_acos_or_asin asin;\n"
         "mandelbulbMulti_order_of_xyz xzy;\ntransf_scaleA_1 0,9;\ntransf_scaleB_1 1,1;\nbeta_angle_offset 10;\n"
         "alpha_angle_offset -20;\n",
         {"mandelbulb_multi", "add_c"},
         [](const vec3& z, const vec3& c) {
             return mb2MultiBulb(z, vec3(z.x, z.z, z.y), 3.0, true, false, false, false, 0.9, 1.1, 10.0, -20.0) + c;
         }},
        {"formula_1 65;\nN 6;\n[fractal_1]\npower 4;\nmandelbulbMulti_atan_or_atan2 atan2;\n"
         "transf_function_enabledx_false true;\ntransf_function_enabledy_false true;\n"
         "transf_function_enabled_false true;\ntransf_function_enabledAy_false true;\n",
         {"plane_fold", "mandelbulb_multi", "add_c"},
         [](const vec3& v, const vec3& c) {
             const vec3 z(v.x, std::abs(v.y), v.z);
             return mb2MultiBulb(z, z, 4.0, false, true, true, true, 1.0, 1.0, 0.0, 0.0) + c;
         }},
        {"formula_1 118;\nN 6;\n[fractal_1]\npower 3;\nsinTan2Trig_order_of_zyx 1;\n"
         "transf_function_enabledK_false true;\ntransf_function_enabledD_false true;\ntransf_start_iterations_D 1;\n"
         "transf_function_enabledBz_false true;\ntransf_addition_constant 0,1 0 0;\n"
         "transf_function_enabledR_false true;\ntransf_rotation 0 0 30;\ntransf_stop_iterations_R 3;\n",
         {"mandelbulb_multi", "rotate", "axis_scale", "axis_scale", "translate", "rotate", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = mb2MultiBulb(v, vec3(v.z, v.x, v.y), 3.0, true, true, false, false, 1.0, 1.0, 0.0, 0.0);
             if (i >= 1) std::swap(z.x, z.y);
             z.z = -z.z;
             z += vec3(0.1, 0.0, 0.0);
             if (i < 3) z = mb2RotateVector(vec3(0.0, 0.0, 30.0), z);
             return z + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// eiffie's msltoe, the smooth Menger sponge and its mod 1 (the corner and z's fold centre given
// differently, the sorts weighted, the box offset after).
TEST(FractImport, EiffieMsltoeAndTheSmoothMengersFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 70;\nN 6;\n[fractal_1]\ntransf_scale 1,1;\ntransf_addition_constant -0,3 0 0;\n",
         {"eiffie_msltoe", "add_c"},
         [](const vec3& v, const vec3& c) {
             const double psi =
                 std::abs(std::fmod(std::atan2(v.z, v.y) + 3.14159265358979 * 9.0 / 8.0, 3.14159265358979 / 4.0) -
                          3.14159265358979 / 8.0);
             const double yz = std::sqrt(v.y * v.y + v.z * v.z);
             const vec3 z(v.x, std::cos(psi) * yz, std::sin(psi) * yz), z2 = z * z;
             const double m = 1.0 - z2.z / (z2.x + z2.y + z2.z);
             return vec3((z2.x - z2.y) * m, 2.0 * z.x * z.y * m * 1.1, 2.0 * z.z * std::sqrt(z2.x + z2.y)) +
                    vec3(-0.3, 0.0, 0.0) + c;
         }},
        {"formula_1 113;\nN 5;\n[fractal_1]\ntransf_offset_0005 0,01;\n",
         {"menger_smooth"},
         [](const vec3& v, const vec3&) {
             const double k = 0.01, sc1 = 2.0, sc2 = 2.0 / 3.0;
             vec3 z = glm::sqrt(v * v + k);
             smoothSort(z.x, z.y, 0.5, k);
             smoothSort(z.x, z.z, 0.5, k);
             smoothSort(z.y, z.z, 0.5, k);
             z.z = -std::sqrt((z.z - 0.5 * sc2) * (z.z - 0.5 * sc2) + k) + 0.5 * sc2;
             return vec3(3.0 * z.x - sc1, 3.0 * z.y - sc1, 3.0 * z.z);
         }},
        {"formula_1 114;\nN 5;\n[fractal_1]\ntransf_scale_05 0,45;\ntransf_constant_multiplier_111 1 2 1;\n"
         "transf_function_enabledx_false true;\ntransf_addition_constantA_000 0,2 0 0;\n",
         {"menger_smooth", "abs_add_conditional"},
         [](const vec3& v, const vec3&) {
             const double k = 0.005;
             vec3 z = glm::abs(v);
             smoothSort(z.x, z.y, 0.45, k);
             smoothSort(z.x, z.z, 0.45, 2.0 * k);
             smoothSort(z.y, z.z, 0.45, k);
             z.z = -std::sqrt((z.z - 1.0 / 3.0) * (z.z - 1.0 / 3.0) + k) + 1.0 / 3.0;
             z = vec3(3.0 * z.x - 2.0, 3.0 * z.y - 2.0, 3.0 * z.z);
             return vec3(glm::sign(z.x) * 0.2 + z.x, z.y, z.z);
         }},
        // Option F's offset abs in place of the rounded one.
        {"formula_1 114;\nN 5;\n[fractal_1]\ntransf_function_enabled false;\ntransf_function_enabledF_false true;\n"
         "transf_offset 0,3;\n",
         {"menger_smooth"},
         [](const vec3& v, const vec3&) {
             const double k = 0.005;
             vec3 z = glm::abs(v) + 0.3;
             smoothSort(z.x, z.y, 0.5, k);
             smoothSort(z.x, z.z, 0.5, k);
             smoothSort(z.y, z.z, 0.5, k);
             z.z = -std::sqrt((z.z - 1.0 / 3.0) * (z.z - 1.0 / 3.0) + k) + 1.0 / 3.0;
             return vec3(3.0 * z.x - 2.0, 3.0 * z.y - 2.0, 3.0 * z.z);
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Knighty's cross Menger KIFS: the mirrors, y about 1/2, the scale about (sqrt(3)/2, 3/2, 3/2),
// the offset and option P's x abs with its offsets.
vec3 mengerCrossStep(const vec3& v, bool absX) {
    const double s34 = std::sqrt(3.0) / 2.0, s12 = std::sqrt(0.5);
    vec3 z(absX ? std::abs(v.x) : v.x, std::abs(v.y), std::abs(v.z));
    double l = z.x * s34 - z.y * 0.5;
    if (l < 0.0) {
        z.x -= s34 * (2.0 * l);
        z.y -= -l;
    }
    if (z.y < 0.0) z.y = -z.y;
    l = (-z.y + z.z) * s12;
    if (l < 0.0) {
        z.y -= -s12 * (2.0 * l);
        z.z -= s12 * (2.0 * l);
    }
    if (z.y < 0.5) z.y -= 2.0 * (z.y - 0.5);
    return z * 3.0 - vec3(s34, 1.5, 1.5) * 2.0;
}
// The platonic solid transform: v times A theta(F v) + rho sqrt(|v|), Mandelbulber2's
// TransfPlatonicSolidIteration with aux.r = |v|, in its first mode and its second.
TEST(FractImport, PlatonicSolidScalesByMandelbulber2sWave) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 56;\nformula_2 7;\n[fractal_1]\n"
        "platonic_solid_frequency 0,3;\nplatonic_solid_amplitude 1,9;\nplatonic_solid_rhoMul 0,7;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Node* step = nullptr;
    for (const Node& n : r.preset.formula.nodes)
        if (n.block->id == "platonic_solid") step = &n;
    ASSERT_NE(step, nullptr);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int k = 0; k < 100; ++k) {
        const vec3 v = randomVec3(u, random);
        const double f = 0.3, theta = std::cos(f * v.x) * std::sin(f * v.y) + std::cos(f * v.y) * std::sin(f * v.z) +
                                      std::cos(f * v.z) * std::sin(f * v.x);
        const vec3 expected = v * (theta * 1.9 + std::sqrt(length(v)) * 0.7);
        P4 p{v, 1.0};
        step->block->apply(p, v, step->args());
        EXPECT_NEAR(length(p.xyz - expected), 0.0, 1e-12);
    }
    // Its second mode: sqrt(r) blended towards r by transf_scale_1 (option Ax), the wave's abs (Az).
    const mb2::FractImport second = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 56;\nformula_2 7;\n[fractal_1]\n"
        "transf_function_enabled_false true;\ntransf_function_enabledy_false true;\n"
        "transf_function_enabledAx_false true;\ntransf_function_enabledAz_false true;\ntransf_scale_1 0,4;\n"
        "platonic_solid_rhoMul 0,7;\n");
    ASSERT_TRUE(second.faithful()) << second.unsupported.front().text();
    const Node& blended = second.preset.formula.nodes.front();
    ASSERT_EQ(blended.block->id, "platonic_solid");
    for (int k = 0; k < 100; ++k) {
        const vec3 v = randomVec3(u, random);
        const double theta =
            std::abs(std::cos(v.x) * std::sin(v.y) + std::cos(v.y) * std::sin(v.z) + std::cos(v.z) * std::sin(v.x));
        const double rho = std::sqrt(length(v)) + (length(v) - std::sqrt(length(v))) * 0.4;
        const vec3 expected = v * (theta + rho * 0.7);
        P4 p{v, 1.0};
        blended.block->apply(p, v, blended.args());
        EXPECT_NEAR(length(p.xyz - expected), 0.0, 1e-12);
    }
}

// The fold box mod 1: the general box fold, the box fold with z's limit scaled (from iteration
// 2), the Mandelbox sphere fold and the scale, then + c.
TEST(FractImport, FoldBoxMod1FollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 59;\nN 10;\n[fractal_1]\nmandelbox_scale -2,5;\ntransf_addition_constant_111 1 1 0;\n"
         "transf_addition_constantA_111 1 0,8 0;\ntransf_scale3D_111 0,7 0,7 0,7;\ntransf_function_enabled_false "
         "true;\n"
         "transf_scale_1 0,51;\ntransf_start_iterations_A 2;\n",
         {"box_fold_general", "box_fold_axes", "sphere_fold", "scale", "add_c"},
         nullptr,
         3.0,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = glm::abs(v + vec3(1.0, 1.0, 0.0)) - glm::abs(v - vec3(1.0, 0.8, 0.0)) - v * 0.7;
             if (i >= 2) {
                 const vec3 limit(1.0, 1.0, 0.51);
                 for (int k = 0; k < 3; ++k)
                     if (std::abs(z[k]) > limit[k]) z[k] = glm::sign(z[k]) * 2.0 * limit[k] - z[k];
             }
             const double r2 = dot(z, z);
             z *= r2 < 0.25 ? 4.0 : r2 < 1.0 ? 1.0 / r2 : 1.0;
             return z * -2.5 + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    const mb2::FractImport halfFold =
        importText("[main_parameters]\nformula_1 59;\n[fractal_1]\ntransf_function_enabledAy false;\n");
    EXPECT_TRUE(mentions(halfFold.unsupported, "slot 1 (fold_box_mod1)", "one of its limits left out"));
}

// Mandelbulber2's Sierpinski tetrahedron: the full tetra fold, and the reversed one after it.
vec3 tetraFold(vec3 z, bool reversed) {
    auto sort = [&] {
        if (z.x - z.y < 0.0) std::swap(z.x, z.y);
        if (z.x - z.z < 0.0) std::swap(z.x, z.z);
        if (z.y - z.z < 0.0) std::swap(z.y, z.z);
    };
    auto sums = [&] {
        if (z.x + z.y < 0.0) z = vec3(-z.y, -z.x, z.z);
        if (z.x + z.z < 0.0) z = vec3(-z.z, z.y, -z.x);
        if (z.y + z.z < 0.0) z = vec3(z.x, -z.z, -z.y);
    };
    if (reversed) {
        sums();
        sort();
    } else {
        sort();
        sums();
    }
    return z;
}
TEST(FractImport, Sierpinski3dFollowsMandelbulber2sOrbits) {
    const std::vector<std::string> folds(6, "plane_fold");
    std::vector<std::string> both(12, "plane_fold");
    const OrbitCase cases[] = {
        {"formula_1 110;\nN 6;\n",
         [&] {
             std::vector<std::string> ids = folds;
             ids.insert(ids.end(), {"scale", "translate"});
             return ids;
         }(),
         [](const vec3& v, const vec3&) { return tetraFold(v, false) * 2.0 - vec3(1.0); }},
        {"formula_1 110;\nN 6;\n[fractal_1]\ntransf_function_enabled_false true;\ntransf_scaleA_2 1,8;\n"
         "transf_offset_111 1 0,8 1;\ntransf_start_iterations_C 2;\n",
         [&] {
             std::vector<std::string> ids = both;
             ids.insert(ids.end(), {"scale", "translate"});
             return ids;
         }(),
         nullptr, 1.5,
         [](const vec3& v, const vec3&, int i) {
             const vec3 z = tetraFold(tetraFold(v, false), true) * 1.8;
             return i >= 2 ? z - vec3(1.0, 0.8, 1.0) : z;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

TEST(FractImport, MengerCrossKifsFollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 98;\nN 5;\n",
         {"plane_fold", "plane_fold", "plane_fold", "plane_fold", "plane_fold", "plane_fold", "scale"},
         [](const vec3& v, const vec3&) { return mengerCrossStep(v, false); }},
        {"formula_1 98;\nN 5;\n[fractal_1]\ntransf_function_enabledz_false true;\ntransf_offset_000 0,1 0 -0,2;\n"
         "transf_function_enabledP_false true;\ntransf_offset 0,3;\ntransf_offset_0 -0,1;\n",
         {"plane_fold", "plane_fold", "plane_fold", "plane_fold", "plane_fold", "plane_fold", "plane_fold", "scale",
          "translate", "translate", "plane_fold", "translate"},
         [](const vec3& v, const vec3&) {
             vec3 z = mengerCrossStep(v, true) + vec3(0.1, 0.0, -0.2);
             z.x = std::abs(z.x + 0.3) - 0.1;
             return z;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    const mb2::FractImport before =
        importText("[main_parameters]\nformula_1 98;\n[fractal_1]\ntransf_function_enabled_false true;\n");
    EXPECT_TRUE(mentions(before.unsupported, "slot 1 (menger_cross_kifs)", "the cross step before"));
}

// Mandelbulber2's Mandelbox then Menger (two Menger steps an iteration from iteration 1, each
// adding c) and the abox mod Kali V2 with z left unfolded (its constant added before and after
// the rotation).
TEST(FractImport, MandelboxMengerAndAboxModKaliV2FollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 91;\nN 5;\n[fractal_1]\nmandelbox_scale -1,9;\ntransf_int_1 2;\ntransf_start_iterations_M 1;\n"
         "transf_function_enabledx_false true;\n",
         {"box_fold_axes", "sphere_fold", "scale", "menger_rotate", "add_c", "menger_rotate", "add_c", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = glm::clamp(v, -1.0, 1.0) * 2.0 - v;
             const double r2 = dot(z, z);
             z *= r2 < 0.25 ? 4.0 : r2 < 1.0 ? 1.0 / r2 : 1.0;
             z *= -1.9;
             for (int k = 0; k < 2 && i >= 1; ++k) {
                 z = glm::abs(z);
                 if (z.x < z.y) std::swap(z.x, z.y);
                 if (z.x < z.z) std::swap(z.x, z.z);
                 if (z.y < z.z) std::swap(z.y, z.z);
                 z = z * 3.0 - vec3(2.0, 2.0, 0.0);
                 if (z.z > 1.0) z.z -= 2.0;
                 z += c;
             }
             return z + c;
         }},
        {"formula_1 135;\nN 6;\n[fractal_1]\ntransf_function_enabledM false;\ntransf_maxR2_1 1,5;\n"
         "transf_scale_015 2;\ntransf_rotation 26 0 0;\ntransf_rotation_enabled true;\n"
         "transf_addition_constant 0,1 0 0;\n",
         {"plane_fold", "plane_fold", "axis_scale", "translate", "sphere_fold", "scale", "translate", "rotate",
          "translate", "add_c"},
         [](const vec3& v, const vec3& c) {
             vec3 z(0.5 - std::abs(v.x), 0.5 - std::abs(v.y), v.z);
             const double rr = dot(z, z);
             z *= 2.0 * (rr < 0.25 ? 1.5 / 0.25 : rr < 1.5 ? 1.5 / rr : 1.0);
             z += vec3(0.1, 0.0, 0.0);
             const double a = glm::radians(26.0);
             z = vec3(z.x, std::cos(a) * z.y - std::sin(a) * z.z, std::sin(a) * z.y + std::cos(a) * z.z);
             return z + vec3(0.1, 0.0, 0.0) + c;
         }},
        // The multiple of c signed by the point from iteration 2 (window C), c's abs on x and z.
        {"formula_1 135;\nN 6;\n[fractal_1]\ntransf_scale_015 2;\ntransf_addCpixel_enabled_false true;\n"
         "transf_constant_multiplier_000 0,2 -0,3 0,1;\ntransf_function_enabledy false;\n"
         "transf_start_iterations_C 2;\n",
         {"abs_fold", "scale", "translate", "sphere_fold", "scale", "add_c_symmetric", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             vec3 z = vec3(0.5) - glm::abs(v);
             const double rr = dot(z, z);
             z *= 2.0 * (rr < 0.25 ? 4.0 : rr < 1.0 ? 1.0 / rr : 1.0);
             if (i >= 2) {
                 const vec3 k = vec3(std::abs(c.x), c.y, std::abs(c.z)) * vec3(0.2, -0.3, 0.1);
                 z += vec3(glm::sign(z.x) * k.x, glm::sign(z.y) * k.y, glm::sign(z.z) * k.z);
             }
             return z + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// mandelbox_offset: the sphere fold's radii measured from the origin, its scaling about -offset
// (Mandelbulber2's Mandelbox, and the 4D spherical fold's transf_offset_0000 whose w stays 0).
TEST(FractImport, SphereFoldOffTheOriginFollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 8;\nN 10;\n[fractal_1]\nmandelbox_offset 0,2 -0,1 0,3;\n",
         {"box_fold", "sphere_fold", "scale", "add_c"},
         [](const vec3& v, const vec3& c) {
             const vec3 offset(0.2, -0.1, 0.3);
             vec3 z = glm::clamp(v, -1.0, 1.0) * 2.0 - v;
             const double r2 = dot(z, z);
             z = (z + offset) * (r2 < 0.25 ? 4.0 : r2 < 1.0 ? 1.0 / r2 : 1.0) - offset;
             return z * 2.0 + c;
         },
         5.0},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Buddhi's Mandelbulb 2, lkmitch's quadratic and the buffalo bulb (z's abs before, x's after,
// z not mirrored).
TEST(FractImport, QuadraticBulbsFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 13;\nN 6;\n",
         {"mandelbulb2", "add_c"},
         [](const vec3& v, const vec3& c) {
             const double r = length(v);
             vec3 z = v;
             auto square = [&z](int a, int b) {
                 const double pair = std::sqrt(z[a] * z[a] + z[b] * z[b]);
                 z /= pair;
                 const double t = z[a] * z[a] - z[b] * z[b];
                 z[b] = 2.0 * z[a] * z[b];
                 z[a] = t;
                 z *= pair;
             };
             square(0, 1);
             square(1, 2);
             square(0, 2);
             return z * r + c;
         }},
        {"formula_1 49;\nN 6;\n",
         {"lkmitch", "add_c"},
         [](const vec3& z, const vec3& c) {
             return vec3(z.x * z.x - 2.0 * z.y * z.z, z.z * z.z + 2.0 * z.x * z.y, z.y * z.y - 2.0 * z.x * z.z) + c;
         }},
        // c times a factor per axis (add_c_axes).
        {"formula_1 49;\nN 6;\nfractal_constant_factor 1 0,5 0,8;\n",
         {"lkmitch", "add_c_axes"},
         [](const vec3& z, const vec3& c) {
             return vec3(z.x * z.x - 2.0 * z.y * z.z, z.z * z.z + 2.0 * z.x * z.y, z.y * z.y - 2.0 * z.x * z.z) +
                    c * vec3(1.0, 0.5, 0.8);
         }},
        // Quick Dudley's, its mod's multipliers (the DE tweak a derivative_tweak), Makin's 3D-2.
        {"formula_1 48;\nN 6;\n",
         {"quick_dudley", "add_c"},
         [](const vec3& z, const vec3& c) {
             return vec3(z.x * z.x - 2.0 * z.y * z.z, z.z * z.z + 2.0 * z.x * z.y, z.y * z.y + 2.0 * z.x * z.z) + c;
         }},
        {"formula_1 84;\nN 6;\n[fractal_1]\ntransf_constant_multiplier_111 0,75 1,6 1,2;\n"
         "transf_constant_multiplier_222 1,3 2,8 2,5;\nanalyticDE_scale_1 0,8;\n",
         {"quick_dudley", "derivative_tweak", "add_c"},
         [](const vec3& z, const vec3& c) {
             return vec3(z.x * z.x * 0.75 - 1.3 * z.y * z.z, z.z * z.z * 1.6 + 2.8 * z.x * z.y,
                         z.y * z.y * 1.2 + 2.5 * z.z * z.x) +
                    c;
         }},
        {"formula_1 50;\nN 6;\n",
         {"makin3d2", "add_c"},
         [](const vec3& z, const vec3& c) {
             return vec3(z.x * z.x + 2.0 * z.y * z.z, -z.y * z.y - 2.0 * z.x * z.z, -z.z * z.z + 2.0 * z.x * z.y) + c;
         }},
        // Mandelbulb 3: its derivative takes no 1 for c (the derivative_tweak takes add_c's back).
        {"formula_1 14;\nN 6;\n",
         {"mandelbulb3", "add_c", "derivative_tweak"},
         [](const vec3& v, const vec3& c) {
             const double r = length(v);
             vec3 z = v;
             const double sign2 = z.x < 0.0 ? -1.0 : 1.0;
             double tempR = std::sqrt(z.x * z.x + z.y * z.y);
             z *= 1.0 / tempR;
             double temp = z.x * z.x - z.y * z.y;
             z.y = 2.0 * z.x * z.y;
             z.x = temp;
             z *= tempR;
             const double sign = z.x < 0.0 ? -1.0 : 1.0;
             tempR = std::sqrt(z.x * z.x + z.z * z.z);
             z *= 1.0 / tempR;
             temp = z.x * z.x - z.z * z.z;
             z.z = 2.0 * z.x * z.z * sign2;
             z.x = temp * sign;
             z *= tempR;
             return z * r + c;
         }},
        // Mandelbulb 4 at power 3 with its three offsets: Mandelbulber2's matrix I Rx Ry Rz
        // (CRotationMatrix's RotateX, RotateY, RotateZ, each multiplying on the right).
        {"formula_1 15;\nN 6;\n[fractal_1]\npower 3;\nalpha_angle_offset 10;\nbeta_angle_offset -20;\n"
         "gamma_angle_offset 30;\n",
         {"mandelbulb4", "add_c"},
         [](const vec3& z, const vec3& c) {
             const double pi = 3.14159265358979, n = 3.0, rp = std::pow(length(z), n - 1.0);
             const double angZ = std::atan2(z.y, z.x) + 10.0 * pi / 180.0;
             const double angY = std::atan2(z.z, z.x) - 20.0 * pi / 180.0;
             const double angX = std::atan2(z.z, z.y) + 30.0 * pi / 180.0;
             auto rot = [](int axis, double a) {
                 const double s = std::sin(a), co = std::cos(a);
                 glm::dmat3 m(1.0);  // column-major: m[column][row]
                 const int i = (axis + 1) % 3, j = (axis + 2) % 3;
                 m[i][i] = co, m[j][j] = co;
                 m[j][i] = -s, m[i][j] = s;  // row i, column j: -s; row j, column i: s
                 return m;
             };
             // RotateY's rot.m31 = -s, m13 = s: the same pattern with i = z, j = x.
             const glm::dmat3 matrix = rot(0, angX * (n - 1.0)) * rot(1, angY * (n - 1.0)) * rot(2, angZ * (n - 1.0));
             return matrix * z * rp + c;
         }},
        {"formula_1 41;\nN 6;\n[fractal_1]\nbuffalo_preabs_z true;\nbuffalo_abs_x true;\nbuffalo_pos_z true;\n",
         {"plane_fold", "mandelbulb_sine", "plane_fold", "add_c"},
         [](const vec3& v, const vec3& c) {
             const vec3 z(v.x, v.y, std::abs(v.z));
             const double x2 = z.x * z.x, y2 = z.y * z.y, t = 1.0 - z.z * z.z / (x2 + y2);
             return vec3(std::abs((x2 - y2) * t), 2.0 * z.x * z.y * t, 2.0 * z.z * std::sqrt(x2 + y2)) + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// Mandelbulber2's six axis orders (0 xyz, 1 xzy, 2 yxz, 3 yzx, 4 zxy, 5 zyx), as its switch writes them.
vec3 mb2Ordered(const vec3& z, int order) {
    switch (order) {
        case 1: return vec3(z.x, z.z, z.y);
        case 2: return vec3(z.y, z.x, z.z);
        case 3: return vec3(z.y, z.z, z.x);
        case 4: return vec3(z.z, z.x, z.y);
        case 5: return vec3(z.z, z.y, z.x);
        default: return z;
    }
}

// Benesi's power 2 as BenesiIteration and the "original pwr2" part of BenesiPwr2MandelbulbIteration
// write it (formula/opencl/benesi.cl, benesi_pwr2_mandelbulb.cl of 2.20).
vec3 mb2BenesiSquare(const vec3& z, const vec3& c) {
    const vec3 zz = z * z;
    const double rrYZ = zz.y + zz.z, lenYZ = std::sqrt(rrYZ), temp = zz.x - rrYZ;
    const double sign = c.x > 0.0 ? 1.0 : c.x < 0.0 ? -1.0 : 0.0;
    const double x = z.x < lenYZ ? temp : -sign * temp;
    const double k = -1.0 / lenYZ * 2.0 * std::abs(z.x);
    return vec3(x, k * (zz.y - zz.z), k * 2.0 * z.y * z.z);
}

// Kali's multi Mandelbulb as MandelbulbKaliMultiIteration writes it (axis orders, acos or asin, the
// sine or cosine form of each point; atan2 both times, no offsets or scales).
vec3 mb2KaliMulti(const vec3& z0, int order, int order2, bool asin1, bool asin2, bool sine1, bool sine2, double power) {
    const double r = length(z0);
    vec3 v = mb2Ordered(z0, order);
    double th0 = asin1 ? std::asin(v.x / r) : std::acos(v.x / r);
    double ph0 = std::atan2(v.y, v.z);
    th0 *= power;
    vec3 z = sine1 ? r * vec3(std::cos(th0) * std::sin(ph0), std::cos(ph0) * std::cos(th0), std::sin(th0))
                   : r * vec3(std::sin(th0) * std::cos(ph0), std::sin(ph0) * std::sin(th0), std::cos(th0));
    v = mb2Ordered(z, order2);
    if (asin2)
        th0 += std::asin(v.x / r);
    else
        th0 = std::acos(v.x / r);
    ph0 += std::atan2(v.y, v.z);
    ph0 *= power * 0.5;
    const double zp = std::pow(r, power);
    return sine2 ? zp * vec3(std::cos(th0) * std::sin(ph0), std::cos(ph0) * std::cos(th0), std::sin(th0))
                 : zp * vec3(std::sin(th0) * std::cos(ph0), std::sin(ph0) * std::sin(th0), std::cos(th0));
}

// The scator square as ScatorPower2Iteration writes it (formula/opencl/scator_power2.cl of 2.20).
vec3 mb2ScatorSquare(const vec3& z, bool imaginary, const vec3& multiplier) {
    const vec3 zz = z * z;
    const double s = imaginary ? -1.0 : 1.0;
    vec3 n(zz.x + s * zz.y + s * zz.z, z.x * z.y, z.x * z.z);
    n *= multiplier;
    n.x += zz.y * zz.z / zz.x;
    n.y *= 1.0 + s * zz.z / zz.x;
    n.z *= 1.0 + s * zz.y / zz.x;
    return n;
}

// Kali's multi Mandelbulb, Benesi's power-2 Mandelbulb, the scator square and the axis swap
// transform, with values off their defaults, against MandelbulbKaliMultiIteration,
// BenesiPwr2MandelbulbIteration, ScatorPower2Iteration and TransfZvectorAxisSwapIteration
// (formula/opencl/*.cl of 2.20) written out, c added where Mandelbulber2 adds it.
TEST(FractImport, KaliMultiBenesiPwr2ScatorAndAxisSwapFollowMandelbulber2sOrbits) {
    // Kali's multi: zxy, acos and atan2 first, the sine form; then xzy, asin (added to the first
    // theta) and atan2; power 5, the cosine form; c's x and y exchanged times 0.5, then c.
    const OrbitCase cases[] = {
        {"formula_1 93;\nN 6;\n[fractal_1]\nmandelbulbMulti_order_of_xyz 4;\nmandelbulbMulti_order_of_xyz_2 1;\n"
         "mandelbulbMulti_acos_or_asin_A 1;\nmandelbulbMulti_atan_or_atan2 1;\nmandelbulbMulti_atan_or_atan2_A 1;\n"
         "transf_function_enabledBx_false true;\ntransf_function_enabledx_false true;\ntransf_pwr_8 5;\n"
         "transf_addCpixel_enabled_false true;\nmandelbulbMulti_order_of_xyz_C 2;\n"
         "transf_constant_multiplierC_111 0,5 0,5 0,5;\n",
         {"mandelbulb_kali_multi", "add_c_axes", "add_c"},
         [](const vec3& z, const vec3& c) {
             return mb2KaliMulti(z, 4, 1, false, true, true, false, 5.0) + 0.5 * vec3(c.y, c.x, c.z) + c;
         }},
        // The second measurement with the first's choices: zxy, asin, atan2, both sine forms, power 8.
        {"formula_1 93;\nN 6;\n[fractal_1]\nmandelbulbMulti_acos_or_asin asin;\nmandelbulbMulti_atan_or_atan2 "
         "atan2;\nmandelbulbMulti_order_of_xyz zxy;\nmandelbulbMulti_order_of_xyz_2 zyx;\n"
         "transf_function_enabledBx_false true;\ntransf_function_enabledz_false true;\n",
         {"mandelbulb_kali_multi", "add_c"},
         [](const vec3& z, const vec3& c) { return mb2KaliMulti(z, 4, 4, true, true, true, true, 8.0) + c; }},
        // Benesi's T1 (its frame, |v| per axis scaled, back, less the offset), then his power 2 and c
        // times (1, 0.5, 0); no other c.
        {"formula_1 105;\nN 8;\n[fractal_1]\ntransf_scale3D_222 1,5 1,8 2;\ntransf_offset_200 0,5 0,1 0;\n"
         "transf_constant_multiplierA_100 1 0,5 0;\n",
         {"benesi_t1", "benesi_pow2", "add_c_axes"},
         [](const vec3& v, const vec3& c) {
             const double s12 = std::sqrt(0.5), s13 = std::sqrt(1.0 / 3.0), s23 = std::sqrt(2.0 / 3.0);
             double tempXZ = v.x * s23 - v.z * s13;
             vec3 z((tempXZ - v.y) * s12, (tempXZ + v.y) * s12, v.x * s13 + v.z * s23);
             z = glm::abs(z) * vec3(1.5, 1.8, 2.0);
             tempXZ = (z.y + z.x) * s12;
             z = vec3(z.z * s13 + tempXZ * s23, (z.y - z.x) * s12, z.z * s23 - tempXZ * s13) - vec3(0.5, 0.1, 0.0);
             return mb2BenesiSquare(z, c) + c * vec3(1.0, 0.5, 0.0);
         }},
        // The real scator, its multiplier off the default, c per axis on the formula's own window E
        // (Mandelbulber2 adds no other c); its derivative's +1 as a tweak. The orbits escape by |v|
        // here, as fraktal's do: files are refused for Mandelbulber2's scator magnitude.
        {"formula_1 173;\nN 8;\n[fractal_1]\ntransf_constant_multiplier_122 1,3 2 2;\n"
         "transf_addCpixel_enabled_false true;\ntransf_constant_multiplier_111 1 0,5 0,5;\n",
         {"scator_power2", "derivative_tweak", "add_c_axes"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3& c, int) {
             return mb2ScatorSquare(z, false, vec3(1.3, 2.0, 2.0)) + c * vec3(1.0, 0.5, 0.5);
         },
         "the scator magnitude"},
        // The imaginary scator alone (no c): the orbit stays inside about the unit ball.
        {"formula_1 173;\nN 8;\n[fractal_1]\ntransf_function_enabled_false true;\nanalyticDE_enabled_false true;\n"
         "analyticDE_offset_1 0;\n",
         {"scator_power2"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3&, int) { return mb2ScatorSquare(z, true, vec3(1.0, 2.0, 2.0)); },
         "the scator magnitude"},
        // The axis swap (yxz, x negated: a rotation; the 45-degree turn from iteration 3) before
        // Benesi's power 2 and c, one each iteration in turn.
        {"hybrid_fractal_enable true;\nformula_1 1022;\nformula_2 20;\nN 10;\n[fractal_1]\n"
         "mandelbulbMulti_order_of_xyz yxz;\ntransf_function_enabled_false true;\ntransf_function_enabledx_false "
         "true;\ntransf_start_iterations 3;\n",
         {"rotate", "rotate", "benesi_pow2", "add_c"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 1) return mb2BenesiSquare(z, c) + c;
             vec3 v(-z.y, z.x, z.z);
             if (i >= 3) v = vec3(std::sqrt(0.5) * (v.x - v.y), std::sqrt(0.5) * (v.y + v.x), v.z);
             return v;
         }},
        // xzy reverses handedness: a rotation and the mirror through the origin.
        {"hybrid_fractal_enable true;\nformula_1 1022;\nformula_2 20;\nN 10;\n[fractal_1]\n"
         "mandelbulbMulti_order_of_xyz 1;\n",
         {"rotate", "axis_scale", "benesi_pow2", "add_c"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3& c, int i) {
             return i % 2 == 1 ? mb2BenesiSquare(z, c) + c : vec3(z.x, z.z, z.y);
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    // The formula's own c reordered anew each iteration is refused by name.
    const mb2::FractImport alternate = importText(
        "[main_parameters]\nformula_1 93;\n[fractal_1]\ntransf_addCpixel_enabled_false true;\n"
        "transf_alternate_enabled_false true;\n");
    EXPECT_TRUE(mentions(alternate.unsupported, "slot 1 (mandelbulb_kali_multi)", "reordered anew"));
    const mb2::FractImport prism =
        importText("[main_parameters]\nformula_1 105;\n[fractal_1]\ntransf_function_enabledP_false true;\n");
    EXPECT_TRUE(mentions(prism.unsupported, "slot 1 (benesi_pwr2_mandelbulb)", "prism fold"));
}

// The Mandelbulb whose power varies with the iteration against MandelbulbVaryPowerV1Iteration
// (formula/opencl/mandelbulb_vary_power_v1.cl of 2.20) written out: power 6 before iteration 1,
// 6 + (-2) (i - 1) / 4 on iterations 1 to 4, 4 from 5 on; the angle offsets before the power; c.
TEST(FractImport, MandelbulbVaryPowerFollowsMandelbulber2sOrbits) {
    const OrbitCase c{
        "formula_1 78;\nN 8;\n[fractal_1]\npower 6;\ntransf_offset_0 -2;\ntransf_start_iterations_250 1;\n"
        "transf_stop_iterations 5;\nbeta_angle_offset 10;\nalpha_angle_offset -20;\n",
        {"mandelbulb_sine", "mandelbulb_sine", "mandelbulb_sine", "mandelbulb_sine", "mandelbulb_sine",
         "mandelbulb_sine", "add_c"},
        nullptr,
        1.5,
        [](const vec3& z, const vec3& c, int i) {
            double n = 6.0;
            if (i >= 1 && i < 5) n += -2.0 * (i - 1) / 4.0;
            if (i >= 5) n += -2.0;
            const double r = length(z);
            const double th = (std::asin(z.z / r) + glm::radians(10.0)) * n;
            const double ph = (std::atan2(z.y, z.x) + glm::radians(-20.0)) * n;
            return std::pow(r, n) * vec3(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)) + c;
        }};
    expectOrbitsFollowMandelbulber2(c);
    // A stop below the start: MandelbulbVaryPowerV1Iteration's ramp needs start <= i < stop, which no
    // iteration meets, and from the stop on it adds the whole offset, whatever the start. So the
    // power is 6 before iteration 2 and 4 from it on; the same where the stop equals the start (3).
    for (const auto& [start, stop] : {std::pair{5, 2}, std::pair{3, 3}}) {
        static int switchAt;
        switchAt = stop;
        expectOrbitsFollowMandelbulber2(
            {("formula_1 78;\nN 8;\n[fractal_1]\npower 6;\ntransf_offset_0 -2;\ntransf_start_iterations_250 " +
              std::to_string(start) + ";\ntransf_stop_iterations " + std::to_string(stop) + ";\n")
                 .c_str(),
             {"mandelbulb_sine", "mandelbulb_sine", "add_c"},
             nullptr,
             1.5,
             [](const vec3& z, const vec3& c, int i) {
                 const double n = i >= switchAt ? 4.0 : 6.0;
                 const double r = length(z);
                 const double th = std::asin(z.z / r) * n, ph = std::atan2(z.y, z.x) * n;
                 return std::pow(r, n) * vec3(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)) +
                        c;
             }});
    }
    // A ramp over more nodes than the import writes is refused by name.
    expectRefused(
        "formula_1 78;\n[fractal_1]\ntransf_offset_0 1;\ntransf_start_iterations_250 0;\n"
        "transf_stop_iterations 40;\n",
        "slot 1 (mandelbulb_vary_power_v1)", "varied over 40 iterations");
    expectExampleImports("mandelbulb_vary_power_001.fract");
}

// A hybrid's slot of weight 0 is an identity (compute_fractal.cpp of 2.20 calls no formula for it
// and blends the point back to where the iteration started, c and all): the power-9 bulb (Mandelbulber2's default) and
// c on even iterations, the point left as it is on odd ones, where the Mandelbox of weight 0 runs. Its formula needs no
// blocks (an abox_mod2 of weight 0 is not refused), and the Mandelbox-Menger morph, whose Mandelbox and IFS slots are
// at weight 0 between its keyframes, imports.
TEST(FractImport, ASlotOfWeightZeroIsAnIdentity) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 2;\nformula_2 8;\nformula_weight_2 0;\nN 8;\n",
         {"mandelbulb_sine", "add_c"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 1) return z;
             const double r = length(z);
             const double th = std::asin(z.z / r) * 9.0, ph = std::atan2(z.y, z.x) * 9.0;
             return std::pow(r, 9.0) * vec3(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)) + c;
         }});
    EXPECT_TRUE(importText("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 2;\nformula_2 75;\n"
                           "formula_weight_2 0;\n")
                    .faithful());
    expectExampleImports("mandelbox_menger_morph.fract");
}

// menger_middle_mod against MengerMiddleModIteration (formula/opencl/menger_middle_mod.cl of 2.20)
// written out: |v + (0.1, 0, 0)| sorted, Tglad's fold with its two limits and mirror, times 0.9,
// the Menger scale 3, x and y less 2 and 1.6, z less 2 above 1, then c times 0.5 (option
// addCpixel; Mandelbulber2 adds no other c).
TEST(FractImport, MengerMiddleModFollowsMandelbulber2sOrbits) {
    const OrbitCase c{
        "formula_1 95;\nN 6;\n[fractal_1]\ntransf_addition_constantA_000 0,1 0 0;\n"
        "transf_function_enabledBy_false true;\ntransf_addition_constant_111 1,1 1,3 0,7;\n"
        "transf_addition_constantA_111 1,1 0,5 1,3;\ntransf_scale3D_111 1 0,7 1;\ntransf_scaleA_1 0,9;\n"
        "transf_constant_multiplier_111 1 0,8 1;\ntransf_addCpixel_enabled_false true;\n"
        "transf_constant_multiplierC_111 0,5 0,5 0,5;\n",
        {"translate", "abs_fold", "menger_fold", "box_fold_general", "scale", "menger_scale", "add_c_axes"},
        [](const vec3& v, const vec3& c) {
            vec3 z = glm::abs(v + vec3(0.1, 0.0, 0.0));
            if (z.x < z.y) std::swap(z.x, z.y);
            if (z.x < z.z) std::swap(z.x, z.z);
            if (z.y < z.z) std::swap(z.y, z.z);
            const vec3 low(1.1, 1.3, 0.7), high(1.1, 0.5, 1.3), mirror(1.0, 0.7, 1.0);
            z = glm::abs(z + low) - glm::abs(z - high) - z * mirror;
            z *= 0.9 * 3.0;
            z.x -= 2.0;
            z.y -= 1.6;
            if (z.z > 1.0) z.z -= 2.0;
            return z + 0.5 * c;
        }};
    expectOrbitsFollowMandelbulber2(c);
    // The box fold after the Menger fold and Tglad's fold with a term left undefined are refused.
    expectRefused("formula_1 95;\n[fractal_1]\ntransf_function_enabledBx_false true;\n", "slot 1 (menger_middle_mod)",
                  "box fold");
    expectRefused(
        "formula_1 95;\n[fractal_1]\ntransf_function_enabledBy_false true;\ntransf_function_enabledAy false;\n",
        "slot 1 (menger_middle_mod)", "left undefined");
    expectExampleImports("menger middle mod.fract");
}

// menger_octo against MengerOctoIteration (fractal_formulas.cpp of 2.20) written out: the
// octahedral fold's four conditional reflections, |x|, the scale 1.8 about (1.2, 0.1, 0), then
// the Menger step of scale 2.8 (|z| sorted, x and y less 2 and 1.8, z less 2 above 1), the
// addition constant and the weight 0.95 (Mandelbulber2 adds no c).
TEST(FractImport, MengerOctoFollowsMandelbulber2sOrbits) {
    const OrbitCase c{
        "formula_1 115;\nN 6;\n[fractal_1]\ntransf_offset_100 1,2 0,1 0;\ntransf_scale_2 1,8;\n"
        "transf_scale_3 2,8;\ntransf_constant_multiplier_111 1 0,9 1;\ntransf_addition_constant 0,05 0 -0,1;\n"
        "transf_function_enabled_false true;\ntransf_scale_1 0,95;\n",
        {"octahedral_fold", "plane_fold", "scale", "abs_fold", "menger_fold", "menger_scale", "translate", "scale"},
        [](const vec3& v, const vec3&) {
            vec3 z = v;
            if (z.x + z.y < 0.0) z = vec3(-z.y, -z.x, z.z);
            if (z.x + z.z < 0.0) z = vec3(-z.z, z.y, -z.x);
            if (z.x - z.y < 0.0) z = vec3(z.y, z.x, z.z);
            if (z.x - z.z < 0.0) z = vec3(z.z, z.y, z.x);
            z.x = std::abs(z.x);
            z = z * 1.8 - vec3(1.2, 0.1, 0.0) * (1.8 - 1.0);
            z = glm::abs(z);
            if (z.x - z.y < 0.0) std::swap(z.y, z.x);
            if (z.x - z.z < 0.0) std::swap(z.z, z.x);
            if (z.y - z.z < 0.0) std::swap(z.z, z.y);
            z *= 2.8;
            z.x -= 2.0;
            z.y -= 1.8;
            if (z.z > 1.0) z.z -= 2.0;
            z += vec3(0.05, 0.0, -0.1);
            return z * 0.95;
        }};
    expectOrbitsFollowMandelbulber2(c);
    // The box offset, the sphere fold and weights that add a named iteration's point are refused.
    expectRefused("formula_1 115;\n[fractal_1]\ntransf_function_enabledx_false true;\n", "slot 1 (menger_octo)",
                  "box offset");
    expectRefused("formula_1 115;\n[fractal_1]\ntransf_function_enabledS_false true;\n", "slot 1 (menger_octo)",
                  "sphere fold");
    expectRefused("formula_1 115;\n[fractal_1]\ntransf_function_enabled_false true;\ntransf_offsetA_0 0,5;\n",
                  "slot 1 (menger_octo)", "iteration weights");
    expectExampleImports("menger octo 001.fract");
}

// Mandelbulber2's rotationMatrix of a rotation in degrees applied to v (CRotationMatrix of
// algebra.cpp in 2.20: SetRotation2 multiplies RotateZ, RotateY, RotateX in that order onto the
// identity, each the right-handed turn about its axis; RotateVector is the matrix times v).
vec3 mb2RotateVector(const vec3& degrees, const vec3& v) {
    const vec3 a = degrees * (M_PI / 180.0);
    const glm::dmat3 rz(std::cos(a.z), std::sin(a.z), 0.0, -std::sin(a.z), std::cos(a.z), 0.0, 0.0, 0.0, 1.0);
    const glm::dmat3 ry(std::cos(a.y), 0.0, -std::sin(a.y), 0.0, 1.0, 0.0, std::sin(a.y), 0.0, std::cos(a.y));
    const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(a.x), std::sin(a.x), 0.0, -std::sin(a.x), std::cos(a.x));
    return rz * ry * rx * v;
}

// ifs_xy against IfsXYIteration (fractal_formulas.cpp of 2.20) written out, with GM ifs_xy's
// options and windows: the box size off from iteration 2 (option Bx_false), |y|, the pentagonal
// fold on iteration 0 only, x and y swapped where y > x, the box size off again from iteration 3,
// x reflected below -0.3 and y below 0.5, x less 0.6 and y less 0.7, the scale 1.8, the offset
// added and the turn (Mandelbulber2 adds no c).
TEST(FractImport, IfsXyFollowsMandelbulber2sOrbits) {
    const OrbitCase c{
        "formula_1 150;\nN 12;\n[fractal_1]\ntransf_addition_constant_0555 0,5 0,5 0,4;\n"
        "transf_function_enabledAy_false true;\ntransf_function_enabledBx_false true;\n"
        "transf_start_iterations_B 2;\ntransf_function_enabledCx_false true;\ntransf_int_3 5;\n"
        "transf_stop_iterations_J 1;\ntransf_start_iterations_I 3;\ntransf_function_enabledx_false true;\n"
        "transf_offset_0 -0,3;\ntransf_offset_1 0,6;\ntransf_offsetA_1 0,7;\ntransf_offset_111 0,57 0,67 0,2;\n"
        "transf_rotation 19 -6 0;\ntransf_scale_2 1,8;\n",
        {"translate", "plane_fold", "poly_fold", "plane_fold", "translate", "plane_fold", "plane_fold", "translate",
         "translate", "scale", "derivative_tweak", "translate", "rotate"},
        nullptr,
        1.2,
        [](const vec3& v, const vec3&, int i) {
            const vec3 box(0.5, 0.5, 0.4);
            vec3 z = v;
            if (i >= 2) z -= box;
            z.y = std::abs(z.y);
            if (i < 1) {
                z.x = std::abs(z.x);
                const double poly = 5.0;
                const double psi =
                    std::abs(std::fmod(std::atan(z.y / z.x) + M_PI / poly, M_PI / (0.5 * poly)) - M_PI / poly);
                const double len = std::sqrt(z.x * z.x + z.y * z.y);
                z.x = std::cos(psi) * len;
                z.y = std::sin(psi) * len;
            }
            if (z.y > z.x) std::swap(z.x, z.y);
            if (i >= 3) z -= box;
            if (z.x < -0.3) z.x = std::abs(z.x + 0.3) - 0.3;
            if (z.y < 0.5) z.y = std::abs(z.y - 0.5) + 0.5;
            z.x -= 0.6;
            z.y -= 0.7;
            z *= 1.8;
            z += vec3(0.57, 0.67, 0.2);
            return mb2RotateVector(vec3(19.0, -6.0, 0.0), z);
        }};
    expectOrbitsFollowMandelbulber2(c);
    // The varying scale and a polygon of more than 32 sides are refused.
    expectRefused("formula_1 150;\n[fractal_1]\ntransf_function_enabledF_false true;\n", "slot 1 (ifs_xy)",
                  "scale varied");
    expectRefused("formula_1 150;\n[fractal_1]\ntransf_function_enabledCx_false true;\ntransf_int_3 40;\n",
                  "slot 1 (ifs_xy)", "polygonal fold");
    expectExampleImports("Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/ifs_xy.fract");
}

// Mandelbulber2's example files that use these formulas import with nothing refused, but for the
// scator files, the one whose formula adds c reordered anew each iteration and the hybrid with a
// partly reflecting IFS, each refused by its reason.
TEST(FractImport, KaliMultiBenesiPwr2ScatorAndAxisSwapExamplesImport) {
    const fs::path examples = "/usr/share/mandelbulber2/examples";
    ASSERT_TRUE(fs::exists(examples)) << "Mandelbulber2's examples are missing: scripts/install-deps.sh installs them";
    const std::string gm = "Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/";
    const std::string sj = "Sebastian Jennen collection - license Creative Commons  (CC-BY 4.0)/";
    const std::vector<std::string> files = {"benesi pwr2 mandelbulbs 001.fract", (gm + "mandelbulb_kali_p8.fract"),
                                            (gm + "transf_Zvec_axis_swap.fract")};
    for (const std::string& file : files) {
        const mb2::FractImport r = mb2::importFract(mb2::loadFractFile(examples / file));
        EXPECT_TRUE(r.faithful()) << file << ": " << r.unsupported.front().text();
    }
    // The scator files map onto the scator block and are refused for its magnitude alone.
    for (const std::string file : {"scator real pow2 menger sponge hybrid.fract", "../formula/img/scator_power2.fract",
                                   "Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/Scator Spikey "
                                   "Imaginary Pow2.fract"}) {
        const mb2::FractImport r = mb2::importFract(mb2::loadFractFile(examples / file));
        EXPECT_FALSE(r.faithful()) << file;
        for (const mb2::ImportItem& item : r.unsupported)
            EXPECT_NE(item.what.find("the scator magnitude"), std::string::npos) << file << ": " << item.text();
    }
    const mb2::FractImport kali = mb2::importFract(mb2::loadFractFile(examples / "mandelbulb_kali_multi 001.fract"));
    EXPECT_TRUE(mentions(kali.unsupported, "slot 1 (mandelbulb_kali_multi)", "reordered anew"));
    // Benesi's power-2 Mandelbulb maps here, beside a kaleidoscopic IFS whose planes of intensity 0
    // turn the point and reflect nothing (FractImport.KaleidoscopicIfsReflectsByItsIntensity).
    expectExampleImports(sj + "hybrid 03 - christmas ornaments.fract");
}

// The kaleidoscopic IFS against 2.20's KaleidoscopicIfsIteration (fractal_formulas.cpp) written
// out: each enabled plane turns the point by its rotation (SetRotation3: here RotateZ of 30
// degrees, x' = x cos - y sin) and then moves it by 2 (length - distance) times its intensity along
// its normal where the length falls under the distance: plane 0 reflects (intensity 1, x about
// 0.2), plane 1 only turns (intensity 0), plane 2 reflects (z about 0.1); then scale 2 about the
// offset (1, 0, 0). An intensity between 0 and 1 is refused.
TEST(FractImport, KaleidoscopicIfsReflectsByItsIntensity) {
    const OrbitCase c{
        "formula_1 10;\nN 6;\n[fractal_1]\nIFS_enabled_0 true;\nIFS_distance_0 0,2;\nIFS_enabled_1 true;\n"
        "IFS_direction_1 0 1 0;\nIFS_rotations_1 30 0 0;\nIFS_intensity_1 0;\nIFS_enabled_2 true;\n"
        "IFS_direction_2 0 0 1;\nIFS_distance_2 0,1;\n",
        {"plane_fold", "rotate", "plane_fold", "scale"},
        [](const vec3& v, const vec3&) {
            vec3 z = v;
            if (z.x < 0.2) z.x -= 2.0 * (z.x - 0.2);
            const double s = std::sin(glm::radians(30.0)), co = std::cos(glm::radians(30.0));
            z = vec3(z.x * co - z.y * s, z.x * s + z.y * co, z.z);
            if (z.z < 0.1) z.z -= 2.0 * (z.z - 0.1);
            return 2.0 * z - vec3(1.0, 0.0, 0.0);
        }};
    expectOrbitsFollowMandelbulber2(c);
    expectRefused("formula_1 10;\n[fractal_1]\nIFS_enabled_0 true;\nIFS_intensity_0 0,5;\n",
                  "slot 1 (kaleidoscopic_ifs)", "a partial reflection");
}

// The pseudo-Kleinian mod 1's general box fold (F: low (1, 0.8, 0.9), high (0.9, 1, 0.7), mirror 1,
// offset (0.3, 0, 0)), then its clamp-style fold (C: box (0.9, 0.8, 1), inverting inside squared
// radius 2), as PseudoKleinianMod1Iteration writes them.
vec3 boxFoldThenClampStyleFold(vec3 z) {
    const vec3 low(1.0, 0.8, 0.9), high(0.9, 1.0, 0.7);
    for (int k = 0; k < 3; ++k) z[k] = std::abs(z[k] + low[k]) - std::abs(z[k] - high[k]) - z[k];
    z += vec3(0.3, 0.0, 0.0);
    const vec3 size(0.9, 0.8, 1.0);
    z = glm::clamp(z, -size, size) * 2.0 - z;
    return z * std::max(2.0 / dot(z, z), 1.0);
}

// The pseudo-Kleinian mod 1 and Amazing Surf against Mandelbulber2 2.20's PseudoKleinianMod1Iteration
// and AmazingSurfIteration written out (fractal_formulas.cpp).
TEST(FractImport, PseudoKleinianMod1AndAmazingSurfFollowMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        // The clamp-style fold (C) on every iteration, its conditional form (B) on iteration 1, the
        // added constant, then the Menger step (M) on iterations 2 and 3 with its own constant; no c.
        {"formula_1 104;\nN 8;\nuse_default_bailout false;\nbailout 4;\n[fractal_1]\ntransf_addition_constant_0777 0,9 "
         "0,8 1;\ntransf_minimum_radius_05 0,8;\n"
         "transf_function_enabledAy_false true;\ntransf_start_iterations_B 1;\ntransf_stop_iterations_B 2;\n"
         "transf_addition_constant 0,1 0 -0,05;\ntransf_function_enabledM_false true;\ntransf_start_iterations_M 2;\n"
         "transf_stop_iterations_M 4;\ntransf_addition_constantA_000 0 0,2 0;\n",
         {"pseudo_kleinian", "pseudo_kleinian", "translate", "menger_rotate", "translate"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3&, int i) {
             const vec3 size(0.9, 0.8, 1.0);
             vec3 z = v;
             auto invert = [](vec3& z) { z *= std::max(0.8 / dot(z, z), 1.0); };
             z = glm::clamp(z, -size, size) * 2.0 - z;
             invert(z);
             if (i == 1) {
                 for (int k = 0; k < 3; ++k) {
                     if (z[k] > size[k]) z[k] = size[k] * 2.0 - z[k];
                     if (z[k] < -size[k]) z[k] = -size[k] * 2.0 - z[k];
                 }
                 invert(z);
             }
             z += vec3(0.1, 0.0, -0.05);
             if (i >= 2 && i < 4) {
                 z = glm::abs(z);
                 if (z.x < z.y) std::swap(z.x, z.y);
                 if (z.x < z.z) std::swap(z.x, z.z);
                 if (z.y < z.z) std::swap(z.y, z.z);
                 z *= 3.0;
                 z.x -= 2.0, z.y -= 2.0;
                 if (z.z > 1.0) z.z -= 2.0;
                 z += vec3(0.0, 0.2, 0.0);
             }
             return z;
         }},
        // The prism fold (P, iteration 0 by default) at scale 0.9 shifted by gap (0.2, 0, 0), the general box fold (F)
        // with
        // its own low and high limits and its offset, then the clamp-style fold (C) inverting inside
        // squared radius 2; the Menger step stays off (its option is transf_function_enabledM_false,
        // not the std DE's transf_function_enabled); no c.
        {"formula_1 104;\nN 8;\nuse_default_bailout false;\nbailout 3;\n[fractal_1]\n"
         "transf_function_enabledP_false true;\ntransf_scale 0,9;\ntransf_constant_multiplier_000 0,2 0 0;\n"
         "transf_function_enabledF_false true;\ntransf_offsetF_000 1 0,8 0,9;\ntransf_offset_000 0,9 1 0,7;\n"
         "transf_offsetA_000 0,3 0 0;\ntransf_addition_constant_0777 0,9 0,8 1;\ntransf_minimum_radius_05 2;\n",
         {"prism_fold", "box_fold_general", "pseudo_kleinian"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3&, int i) {
             const double s34 = std::sqrt(0.75), s3 = std::sqrt(3.0);
             if (i > 0) return boxFoldThenClampStyleFold(v);  // the prism fold's window: iteration 0
             vec3 z(v.x, std::abs(v.y), std::abs(v.z));
             const double t = std::max(0.0, (z.x * -s34 + z.y * 0.5) * 0.9);
             z.x += t * s3;
             z.y = std::abs(z.y - t);
             if (z.y > z.z) std::swap(z.y, z.z);
             z -= vec3(0.2, 0.0, 0.0) * vec3(s34, 1.5, 1.5);
             if (z.z > z.x) std::swap(z.z, z.x);
             if (z.x > 0.0) z.y = std::max(0.0, z.y), z.z = std::max(0.0, z.z);
             return boxFoldThenClampStyleFold(z);
         }},
        // Amazing Surf with the whole sphere fold (share 1): m = 1.7 / (r^2 below sqrt(0.3) ? sqrt(0.3) :
        // min(r^2, 1)), then c with x and y swapped times (0.5, 0.3, 0.2), then c with x and y
        // swapped again (compute_fractal.cpp).
        {"formula_1 73;\nN 10;\n[fractal_1]\ntransf_addition_constant_111 1,2 0,9 1;\ntransf_minimum_radius_05 0,3;\n"
         "mandelbox_scale 1,7;\ntransf_addCpixel_enabled_false true;\ntransf_constant_multiplier_111 0,5 0,3 0,2;\n",
         {"amazing_surf", "add_c_axes", "add_c_axes"},
         [](const vec3& v, const vec3& c) {
             vec3 z = v;
             z.x = std::abs(z.x + 1.2) - std::abs(z.x - 1.2) - z.x;
             z.y = std::abs(z.y + 0.9) - std::abs(z.y - 0.9) - z.y;
             const double rr = dot(z, z), inner = std::sqrt(0.3);
             z *= 1.7 / (rr < inner ? inner : std::min(rr, 1.0));
             return z + vec3(c.y, c.x, c.z) * vec3(1.5, 1.3, 1.2);
         }},
        // Share 0 with the cylinder fold: the point keeps its length through the sphere fold (the
        // nodes written; refused for the derivative, which takes the fold's factor whole).
        {"formula_1 73;\nN 12;\nuse_default_bailout false;\nbailout 3;\n[fractal_1]\ntransf_addition_constant_111 1,4 "
         "1,1 1;\ntransf_scale_1 0;\n"
         "transf_function_enabled_false true;\n",
         {"box_fold_axes", "add_c_axes"},
         [](const vec3& v, const vec3& c) {
             vec3 z = v;
             z.x = std::abs(z.x + 1.4) - std::abs(z.x - 1.4) - z.x;
             z.y = std::abs(z.y + 1.1) - std::abs(z.y - 1.1) - z.y;
             return z + vec3(c.y, c.x, c.z);
         },
         1.5,
         nullptr,
         "the sphere fold's factor"},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    // Amazing Surf's factor blended otherwise, or its cylinder fold with the whole factor, and the
    // mod 1's z scaled inside its fold are refused by name.
    expectRefused("formula_1 73;\n[fractal_1]\ntransf_scale_1 0,5;\n", "slot 1 (amazing_surf)", "blended with 1");
    expectRefused("formula_1 73;\n[fractal_1]\ntransf_function_enabled_false true;\n", "slot 1 (amazing_surf)",
                  "the cylinder fold");
    expectRefused("formula_1 104;\n[fractal_1]\ntransf_scaleB_1 0,5;\n", "slot 1 (pseudo_kleinian_mod1)",
                  "z scaled inside");
}

// Mandelbulber2's example files that use the pseudo-Kleinian mod 1 and Amazing Surf import with
// nothing refused, but for the Amazing Surf whose point takes none of its sphere fold's factor.
TEST(FractImport, PseudoKleinianMod1AndAmazingSurfExamplesImport) {
    for (const char* file : {"pseudo kleinian mod 001.fract", "monte carlo global illumination.fract"})
        expectExampleImports(file);
    const fs::path surf = fs::path("/usr/share/mandelbulber2/examples") / "amazing_surf 001.fract";
    const mb2::FractImport shareZero = mb2::importFract(mb2::loadFractFile(surf));
    EXPECT_FALSE(shareZero.faithful());
    for (const mb2::ImportItem& item : shareZero.unsupported)
        EXPECT_TRUE(item.where == "slot 1 (amazing_surf)" && item.what.starts_with("transf_scale_1 0")) << item.text();
}

// mancoast's modulus Mandelbulb against 2.20's ModulusMandelbulbIteration (fractal_formulas.cpp)
// written out: the Mandelbulb of power 5 on the latitude asin(z / r) with its angle offsets (beta
// 10 degrees on the latitude, alpha -20 on the azimuth), y replaced by fmod(y, 2), then c. Then
// Daniel Luchansky's two pseudo-Kleinian hybrids with it import.
TEST(FractImport, ModulusMandelbulbFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"formula_1 131;\nN 6;\n[fractal_1]\npower 5;\nbeta_angle_offset 10;\nalpha_angle_offset -20;\n",
         {"mandelbulb_sine", "axis_remainder", "add_c"},
         [](const vec3& z, const vec3& c) {
             const double r = length(z);
             const double th = (std::asin(z.z / r) + glm::radians(10.0)) * 5.0;
             const double ph = (std::atan2(z.y, z.x) + glm::radians(-20.0)) * 5.0;
             const double rp = std::pow(r, 5.0);
             return vec3(std::cos(th) * std::cos(ph) * rp, std::fmod(std::cos(th) * std::sin(ph) * rp, 2.0),
                         std::sin(th) * rp) +
                    c;
         }});
    const std::string dl = "Daniel Luchansky collection - license Creative Commons -CC-BY 4.0/";
    for (const char* file : {"pseuklein x mod mandelbulb.fract", "pseuklein x mod mandelbulb 002.fract"})
        expectExampleImports(dl + file);
}

// The turn in 4D's six planes as Mandelbulber2's 4D formulas write it (Abox4dIteration and
// Quaternion4dIteration, option R, in fractal_formulas.cpp of 2.20): the planes xy, yz, xz by
// `angles`, then xw, yw, zw by `anglesW` (degrees), each (u, v) -> (u cos a + v sin a, -u sin a + v cos a).
void mb2Turn4d(glm::dvec4& z, const vec3& angles, const vec3& anglesW) {
    const int planes[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    for (int k = 0; k < 6; ++k) {
        const double a = glm::radians(k < 3 ? angles[k] : anglesW[k - 3]);
        const double x = z[planes[k][0]], y = z[planes[k][1]];
        z[planes[k][0]] = x * std::cos(a) + y * std::sin(a);
        z[planes[k][1]] = -x * std::sin(a) + y * std::cos(a);
    }
}

// abox4d against 2.20's Abox4dIteration (fractal_formulas.cpp) written out in four dimensions: w
// plus the Cpara parabola -0.3 + 0.2 i + 0.001 (-4) i^2, Tglad's fold per axis at (1.1, 0.9, 1, 1.2),
// the sphere fold of squared radii 0.2 and 0.9 measured on (|v|^2)^0.8 and scaling about
// -(0.1, 0, -0.05, 0.2), the scale -2.5, the turns in the six planes (10, -20, 30 and 5, -15, 25
// degrees) from iteration 2 on (option R), the constant (0.1, 0, 0, -0.2), then c = (point, 0):
// where the 4D orbit escapes past the bailout (100) against fraktal's membership.
// The varying scale and an inner radius above the fixed one are refused by name, and so is c added
// to an orbit that starts off w = 0; both example files import.
TEST(FractImport, Abox4dFollowsMandelbulber2sOrbits) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 116;\nN 8;\n[fractal_1]\nCpara_enabledParab_false true;\n"
        "Cpara_parab_offset0 -0,3;\nCpara_parab_slope 0,2;\nCpara_parab_scale -4;\n"
        "transf_offset_1111 1,1 0,9 1 1,2;\ntransf_offset_0000 0,1 0 -0,05 0,2;\ntransf_minR2_p25 0,2;\n"
        "transf_maxR2_1 0,9;\nmandelbox_vary_rpower 0,8;\nmandelbox_scale -2,5;\n"
        "transf_function_enabledR_false true;\ntransf_rotation44a 10 -20 30;\ntransf_rotation44b 5 -15 25;\n"
        "transf_start_iterations_R 2;\ntransf_addition_constant_0000 0,1 0 0 -0,2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula),
              (std::vector<std::string>{"abox_fold4d", "scale", "rotate4d", "translate", "add_c"}));
    using D4 = glm::dvec4;
    auto escapes = [](const vec3& point) {
        D4 z(point, 0.0);
        for (int i = 0; i < 8; ++i) {
            z.w += -0.3 + 0.2 * i + 0.001 * -4.0 * i * i;
            const D4 limit(1.1, 0.9, 1.0, 1.2), offset(0.1, 0.0, -0.05, 0.2);
            for (int k = 0; k < 4; ++k) z[k] = std::abs(z[k] + limit[k]) - std::abs(z[k] - limit[k]) - z[k];
            const double rr = std::pow(dot(z, z), 0.8);
            z += offset;
            if (rr < 0.2)
                z *= 0.9 / 0.2;
            else if (rr < 0.9)
                z *= 0.9 / rr;
            z -= offset;
            z *= -2.5;
            if (i >= 2) mb2Turn4d(z, vec3(10.0, -20.0, 30.0), vec3(5.0, -15.0, 25.0));
            z += D4(0.1, 0.0, 0.0, -0.2) + D4(point, 0.0);
            if (glm::length(z) > 100.0) return true;
        }
        return false;
    };
    expectEscapesFollow(r.preset.formula, 4.0, "abox4d", escapes);

    expectRefused("formula_1 116;\n[fractal_1]\nmandelbox_vary_scale_vary 0,1;\n", "slot 1 (abox4d)",
                  "varies with the iteration");
    expectRefused("formula_1 116;\n[fractal_1]\ntransf_minR2_p25 1,5;\n", "slot 1 (abox4d)", "jumps");
    expectRefused("formula_1 116;\ninitial_waxis 0,2;\n", "slot 1 (abox4d)", "c's fourth coordinate");
    EXPECT_TRUE(
        importText("[main_parameters]\nformula_1 116;\ninitial_waxis 0,2;\ndont_add_c_constant_1 true;\n").faithful());
    expectExampleImports("Robert Pancoast collection - license Creative Commons (CC-BY 4.0)/Abox4D8K.fract");
    expectExampleImports("Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/aBox 4D.fract");
}

// QuaternionIteration and BristorbrotIteration (fractal_quaternion.cpp, fractal_bristorbrot.cpp of
// 2.20) carry aux.DE -> 2 r aux.DE and take no 1 for c, where add_c adds one: the import takes it
// back. Written out for the quaternion (whose Jacobian's largest singular value is 2 r on the
// slice), its running derivative is Mandelbulber2's aux.DE at every iteration, and its point
// Mandelbulber2's z.
TEST(FractImport, QuaternionDerivativeIsMandelbulber2sWithoutTheOneForC) {
    for (const char* id : {"5", "21"}) {
        const mb2::FractImport r = importText(std::string("[main_parameters]\nformula_1 ") + id + ";\n");
        ASSERT_TRUE(r.faithful()) << id << ": " << r.unsupported.front().text();
        EXPECT_EQ(blockIds(r.preset.formula), (std::vector<std::string>{"bristorbrot", "add_c", "derivative_tweak"}))
            << id;
    }
    const mb2::FractImport r = importText("[main_parameters]\nformula_1 5;\n");
    for (const vec3& point : {vec3(0.3, -0.4, 0.5), vec3(-0.7, 0.2, 0.1), vec3(0.1, 0.6, -0.3)}) {
        P4 p{point, 1.0};
        vec3 z = point;
        double de = 1.0;
        for (int i = 0; i < 4; ++i) {
            for (const Node& n : r.preset.formula.nodes) n.block->apply(p, point, n.args());
            de *= 2.0 * glm::length(z);
            z = vec3(z.x * z.x - z.y * z.y - z.z * z.z, 2.0 * z.x * z.y, 2.0 * z.x * z.z) + point;
            EXPECT_NEAR(p.w, de, 1e-7 * de) << "iteration " << i;  // the closed-form eigenvalue
            EXPECT_NEAR(glm::length(p.xyz - z), 0.0, 1e-9 * glm::length(z)) << "iteration " << i;
        }
    }
}

// quaternion4d against 2.20's Quaternion4dIteration (fractal_formulas.cpp) written out in 4D:
// (x^2 - y^2 - z^2 - w^2, x y, x z, w) times (1.1, 1.8, 2.1, 0.5), plus (0.1, -0.2, 0.05, 0.3), the
// turn in the six planes from iteration 2 (option R), then c = (point, 0); the bailout on the 4D
// length. Its example imports, and initial_waxis starts w where c is not added.
TEST(FractImport, Quaternion4dFollowsMandelbulber2sOrbits) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 79;\nN 8;\n[fractal_1]\ntransf_constant_multiplier_1220 1,1 1,8 2,1 0,5;\n"
        "transf_addition_constant_0000 0,1 -0,2 0,05 0,3;\ntransf_function_enabledR_false true;\n"
        "transf_rotation44a 10 -20 30;\ntransf_rotation44b 5 -15 25;\ntransf_start_iterations_R 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula),
              (std::vector<std::string>{"quaternion4d", "rotate4d", "add_c", "derivative_tweak"}));
    const double bailout = r.preset.formula.bailout;
    using D4 = glm::dvec4;
    auto escapes = [bailout](const vec3& point) {
        D4 z(point, 0.0);
        for (int i = 0; i < 8; ++i) {
            z = D4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, z.x * z.y, z.x * z.z, z.w) * D4(1.1, 1.8, 2.1, 0.5) +
                D4(0.1, -0.2, 0.05, 0.3);
            if (i >= 2) mb2Turn4d(z, vec3(10.0, -20.0, 30.0), vec3(5.0, -15.0, 25.0));
            z += D4(point, 0.0);
            if (glm::length(z) > bailout) return true;
        }
        return false;
    };
    expectEscapesFollow(r.preset.formula, 1.5, "quaternion4d", escapes);
    // With Mandelbulber2's multipliers the running derivative grows as Mandelbulber2's aux.DE, by 2 |q|
    // (q the 4D point), and w becomes the offset's w.
    const mb2::FractImport plain = importText(
        "[main_parameters]\nformula_1 79;\ninitial_waxis 0,2;\ndont_add_c_constant_1 true;\n[fractal_1]\n"
        "transf_addition_constant_0000 0 0 0 -0,65;\n");
    ASSERT_TRUE(plain.faithful()) << plain.unsupported.front().text();
    EXPECT_EQ(blockIds(plain.preset.formula), (std::vector<std::string>{"start_w", "quaternion4d"}));
    P4 p{vec3(0.3, -0.4, 0.5), 1.5};
    p.pointW = 0.2;
    plain.preset.formula.nodes[1].block->apply(p, vec3(0.0), plain.preset.formula.nodes[1].args());
    EXPECT_NEAR(p.w, 1.5 * 2.0 * std::sqrt(0.09 + 0.16 + 0.25 + 0.04), 1e-12);
    EXPECT_NEAR(p.pointW, -0.65, 1e-12);
    EXPECT_NEAR(p.xyz.x, 0.09 - 0.16 - 0.25 - 0.04, 1e-12);
    EXPECT_NEAR(p.xyz.y, 2.0 * 0.3 * -0.4, 1e-12);
    // c is added without the derivative's +1, as Mandelbulber2's 2 r DE takes none: after add_c
    // and the tweak, the running derivative is 2 |q| times what it was.
    const mb2::FractImport withC = importText("[main_parameters]\nformula_1 79;\n");
    ASSERT_TRUE(withC.faithful()) << withC.unsupported.front().text();
    P4 q{vec3(0.3, -0.4, 0.5), 1.5};
    for (const Node& n : withC.preset.formula.nodes) n.block->apply(q, vec3(0.1, 0.2, 0.3), n.args());
    EXPECT_NEAR(q.w, 1.5 * 2.0 * std::sqrt(0.5), 1e-12);
    expectExampleImports("quaternion4D_001.fract");
}

// AmazingSurfMod2Iteration, AboxMod11Iteration and AboxModKaliV2Iteration (2.20,
// fractal_formulas.cpp) add 1 to the running derivative themselves, aux.DE |m| + 1, so
// Mandelbulber2's derivative is the same whether c is added, a Julia constant is, or nothing
// (dont_add_c): fraktal's add_c adds the 1 only with c, and the other two take it from a
// derivative_tweak. abox_mod_kali_v2 at (0.3, -0.2, 0.1): the fold
// 0.5 - |z| gives (0.2, 0.3, 0.4), r^2 0.29 inside the fold's shell, m = 1.5 / 0.29.
TEST(FractImport, SurfAndKaliBoxAddTheirOneToTheDerivativeWithoutC) {
    const vec3 z(0.3, -0.2, 0.1), c(0.1, 0.2, 0.3);
    auto derivative = [&](const mb2::FractImport& r) {
        P4 p{z, 1.5};
        for (const Node& n : r.preset.formula.nodes) n.block->apply(p, c, n.args());
        return p.w;
    };
    for (const char* formula : {"135", "132", "119"}) {
        SCOPED_TRACE(formula);
        const std::string slot = std::string("[main_parameters]\nformula_1 ") + formula + ";\n";
        const mb2::FractImport withC = importText(slot);
        const mb2::FractImport julia = importText(slot + "julia_mode true;\njulia_c 0,2 0,1 0;\n");
        const mb2::FractImport none = importText(slot + "dont_add_c_constant_1 true;\n");
        for (const mb2::FractImport* r : {&withC, &julia, &none})
            ASSERT_TRUE(r->faithful()) << r->unsupported.front().text();
        EXPECT_EQ(blockIds(withC.preset.formula).back(), "add_c");
        EXPECT_EQ(blockIds(julia.preset.formula).back(), "derivative_tweak");
        EXPECT_EQ(blockIds(none.preset.formula).back(), "derivative_tweak");
        EXPECT_NEAR(derivative(julia), derivative(withC), 1e-12);
        EXPECT_NEAR(derivative(none), derivative(withC), 1e-12);
        if (formula == std::string("135")) {
            EXPECT_NEAR(derivative(withC), 1.5 * 1.5 / 0.29 + 1.0, 1e-12);
        }
    }
}

// visual.bermarte's Mandelbulb against 2.20's MandelbulbBermarteIteration (fractal_formulas.cpp)
// written out, c added: |x| first (option Ax_false); the latitude asin(z / r) plus 10 degrees times
// 4 x 1.2 and the azimuth atan2(y, x) less 20 degrees, the point of those at r in the sine form
// (cos t sin f, cos f cos t, sin t); |x| and |z| (Ay off); then asin(z / r) less 5 degrees and
// atan2(y, x) times 4 x 0.8, r^4 times the point of those; |x| (Bx_false). The second case takes
// both measurements by acos and atan of the quotient, in the cosine form, power 3. Its example
// imports; a DE tweak off the default derivative is refused by name.
TEST(FractImport, MandelbulbBermarteFollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 94;\nN 6;\n[fractal_1]\ntransf_pwr_8 4;\ntransf_scaleA_1 1,2;\ntransf_scaleB_1 0,8;\n"
         "beta_angle_offset 10;\nalpha_angle_offset -20;\ntransf_beta_angle_offset -5;\n"
         "transf_function_enabledAx_false true;\ntransf_function_enabledAy false;\n"
         "transf_function_enabledBx_false true;\n",
         {"plane_fold", "mandelbulb_bermarte", "plane_fold", "add_c"},
         [](const vec3& v, const vec3& c) {
             vec3 z(std::abs(v.x), v.y, v.z);
             const double r = length(z);
             double th = (std::asin(z.z / r) + glm::radians(10.0)) * 4.0 * 1.2;
             double ph = std::atan2(z.y, z.x) + glm::radians(-20.0);
             z = r * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th));
             z.x = std::abs(z.x);
             z.z = std::abs(z.z);
             th = std::asin(z.z / r) + glm::radians(-5.0);
             ph = std::atan2(z.y, z.x) * 4.0 * 0.8;
             z = std::pow(r, 4.0) * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th));
             z.x = std::abs(z.x);
             return z + c;
         }},
        {"formula_1 94;\nN 6;\n[fractal_1]\ntransf_pwr_8 3;\ntransf_function_enabled_false true;\n"
         "transf_function_enabledx_false true;\n",
         {"mandelbulb_bermarte", "add_c"},
         [](const vec3& v, const vec3& c) {
             const double r = length(v);
             double th = std::acos(v.z / r) * 3.0, ph = std::atan(v.y / v.x);
             vec3 z = r * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th));
             z = glm::abs(z);
             th = std::acos(z.z / r);
             ph = std::atan(z.y / z.x) * 3.0;
             return std::pow(r, 3.0) * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th)) + c;
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    // Luca GN's inverse cylindrical coordinates (TransfInvCylindricalIteration written out: (x cos(s
    // y), x sin(s y), z_scale z) times scale_all, no c) before the default bulb of power 4, one each
    // iteration in turn, as the mechanical-ribs example alternates them; Mandelbulber2's +1 a
    // derivative tweak.
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1053;\nformula_2 94;\nN 10;\n[fractal_1]\ntransf_scale_1 0,8;\n"
         "transf_scaleA_1 1,1;\ntransf_scaleC_1 0,9;\n[fractal_2]\ntransf_pwr_8 4;\n",
         {"inv_cylindrical", "derivative_tweak", "mandelbulb_bermarte", "add_c"},
         nullptr,
         1.5,
         [](const vec3& v, const vec3& c, int i) {
             if (i % 2 == 0) return vec3(v.x * std::cos(0.8 * v.y), v.x * std::sin(0.8 * v.y), 0.9 * v.z) * 1.1;
             const double r = length(v);
             double th = std::asin(v.z / r) * 4.0, ph = std::atan2(v.y, v.x);
             vec3 z = glm::abs(r * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th)));
             th = std::asin(z.z / r);
             ph = std::atan2(z.y, z.x) * 4.0;
             return std::pow(r, 4.0) * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th)) + c;
         }});
    // The transform carries Mandelbulber2's derivative, |scale_all| (its bound, max(1, |s x|) times
    // that, made the estimate far from mechanical-ribs 30 times smaller: bench/import/README.md).
    const mb2::FractImport cylindrical =
        importText("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 1053;\nformula_2 94;\n");
    ASSERT_TRUE(cylindrical.faithful()) << cylindrical.unsupported.front().text();
    EXPECT_EQ(param(cylindrical.preset.formula.nodes.front(), "mb2_derivative"), 1.0);
    expectRefused(
        "formula_1 8;\nformula_2 1053;\nhybrid_fractal_enable true;\n[fractal_2]\n"
        "transf_function_enabled_false true;\n",
        "slot 2 (transf_inv_cylindrical)", "x cos(y) in place of the radius");
    // The derivative takes Mandelbulber2's n r^(n-1).
    const mb2::FractImport plain = importText("[main_parameters]\nformula_1 94;\n[fractal_1]\ntransf_pwr_8 5;\n");
    ASSERT_TRUE(plain.faithful()) << plain.unsupported.front().text();
    const Node& bulb = plain.preset.formula.nodes.front();
    ASSERT_EQ(bulb.block->id, "mandelbulb_bermarte");
    P4 p{vec3(0.3, -0.4, 0.5), 1.5};
    bulb.block->apply(p, vec3(0.0), bulb.args());
    EXPECT_NEAR(p.w, 1.5 * 5.0 * std::pow(std::sqrt(0.5), 4.0), 1e-12);
    EXPECT_NEAR(length(p.xyz), std::pow(std::sqrt(0.5), 5.0), 1e-12);
    expectRefused("formula_1 94;\n[fractal_1]\nanalyticDE_enabled_false true;\nanalyticDE_scale_1 1,5;\n",
                  "slot 1 (mandelbulb_bermarte)", "running derivative");
    expectExampleImports("mandelbulb_bermarte 001.fract");
    expectExampleImports(
        "Sebastian Jennen collection - license Creative Commons  (CC-BY 4.0)/inverse-reciprocal-iqbulb "
        "mechanical-ribs.fract");
}

// Kali's Mandelbulb against 2.20's MandelbulbKaliIteration (fractal_formulas.cpp) written out: |y|
// first (options Ay), the latitude acos(z / r) plus 10 degrees times 4 x 0.9 and the azimuth atan(y
// / x), the point of those angles at r, then its latitude plus -5 degrees and its azimuth atan(y /
// x) times 4 x 1.2, r^4 times the point of those, then c. An azimuth offset is refused by name;
// mandelbulb_kali 001 imports.
TEST(FractImport, MandelbulbKaliFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"formula_1 92;\nN 6;\n[fractal_1]\ntransf_pwr_8 4;\ntransf_scaleA_1 0,9;\ntransf_scaleB_1 1,2;\n"
         "beta_angle_offset 10;\ntransf_beta_angle_offset -5;\ntransf_function_enabled_false true;\n"
         "transf_function_enabledAy_false true;\n",
         {"plane_fold", "mandelbulb_kali_multi", "add_c"},
         [](const vec3& v, const vec3& c) {
             vec3 z(v.x, std::abs(v.y), v.z);
             const double r = length(z);
             double th = (std::acos(z.z / r) + glm::radians(10.0)) * 4.0 * 0.9;
             double ph = std::atan(z.y / z.x);
             z = r * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th));
             th = std::acos(z.z / r) + glm::radians(-5.0);
             ph = std::atan(z.y / z.x) * 4.0 * 1.2;
             return std::pow(r, 4.0) * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th)) + c;
         }});
    expectRefused("formula_1 92;\n[fractal_1]\nalpha_angle_offset 20;\n", "slot 1 (mandelbulb_kali)", "azimuth offset");
    expectExampleImports("mandelbulb_kali 001.fract");
}

// The rotation whose angles vary with the iteration, in a hybrid with the power-2 bulb, against
// 2.20's TransfRotationVaryV1Iteration and MandelbulbIteration (fractal_formulas.cpp) written out:
// on the even iterations i the point turns about x, then y, then z (right-handed, as
// RotateAroundVectorByAngle) by (10, 0, -15) degrees before iteration 2, plus (30, -20, 10) (i - 2)
// / 4 on iterations 2 to 5, plus all of it from 6 on; on the odd ones the bulb and c. Membership on
// 2000 points; a ramp whose nodes fraktal cannot hold is refused, and Graeme McLaren's
// abox_mod11_rotVaryV1 (its ramp over 20 iterations, on every other one) imports.
TEST(FractImport, RotationVaryFollowsMandelbulber2sOrbits) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 1036;\nformula_2 2;\nN 10;\n[fractal_1]\n"
        "transf_rotation 10 0 -15;\ntransf_offset_000 30 -20 10;\ntransf_start_iterations_250 2;\n"
        "transf_stop_iterations 6;\n[fractal_2]\npower 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    auto escapes = [&f](const vec3& point) {
        vec3 z = point;
        for (int i = 0; i < f.iterations; ++i) {
            if (i % 2 == 0) {
                vec3 degrees(10.0, 0.0, -15.0);
                if (i >= 2) degrees += vec3(30.0, -20.0, 10.0) * (i < 6 ? (i - 2) / 4.0 : 1.0);
                for (int axis = 0; axis < 3; ++axis) {
                    vec3 k(0.0);
                    k[axis] = 1.0;
                    const double a = glm::radians(degrees[axis]);
                    z = z * std::cos(a) + glm::cross(k, z) * std::sin(a) + k * dot(k, z) * (1.0 - std::cos(a));
                }
            } else {
                const double rr = length(z), th = std::asin(z.z / rr) * 2.0, ph = std::atan2(z.y, z.x) * 2.0;
                z = rr * rr * vec3(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)) + point;
            }
            if (!(length(z) <= f.bailout)) return true;
        }
        return false;
    };
    expectEscapesFollow(f, 1.5, "transf_rotation_vary_v1", escapes);
    // A node an iteration of the ramp: over 200 iterations more than fraktal holds.
    expectRefused(
        "hybrid_fractal_enable true;\nformula_1 1036;\nformula_2 2;\nformula_iterations_1 2;\n[fractal_1]\n"
        "transf_offset_000 1 0 0;\ntransf_start_iterations_250 0;\ntransf_stop_iterations 200;\n",
        "main", "a sequence of more than 64 nodes");
    expectExampleImports(
        "Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/abox_mod11_rotVaryV1.fract");
}

// Mandelbulber2's box folds with a folding value other than twice the limit against 2.20's
// BoxFolding (the global fold of the main parameters, limit 1.5 and value 3.3) and
// MandelboxIteration (limit 1, value 2.3) written out: x above the limit becomes value - x, below
// minus the limit -value - x; then the Mandelbox's sphere fold (0.5, 1), its scale 2 and c. Robert
// Pancoast's hybrid77 (a global fold of limit 3 and value 6.3) imports.
TEST(FractImport, BoxFoldsWithTheirOwnValueFollowMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"formula_1 8;\nN 10;\nbox_folding true;\nbox_folding_limit 1,5;\nbox_folding_value 3,3;\n[fractal_1]\n"
         "mandelbox_folding_value 2,3;\n",
         {"box_fold_value", "box_fold_value", "sphere_fold", "scale", "add_c"},
         [](const vec3& v, const vec3& c) {
             vec3 z = v;
             auto fold = [&z](double limit, double value) {
                 for (int k = 0; k < 3; ++k) {
                     if (z[k] > limit)
                         z[k] = value - z[k];
                     else if (z[k] < -limit)
                         z[k] = -value - z[k];
                 }
             };
             fold(1.5, 3.3);
             fold(1.0, 2.3);
             const double rr = dot(z, z);
             z *= rr < 0.25 ? 4.0 : rr < 1.0 ? 1.0 / rr : 1.0;
             return z * 2.0 + c;
         },
         8.0});
    // At twice the limit it is the plain box fold.
    const mb2::FractImport plain = importText(
        "[main_parameters]\nformula_1 8;\nbox_folding true;\nbox_folding_limit 1,5;\nbox_folding_value 3;\n");
    EXPECT_EQ(blockIds(plain.preset.formula).front(), "box_fold");
    expectExampleImports("Robert Pancoast collection - license Creative Commons (CC-BY 4.0)/hybrid77.fract");
}

// Mandelbulber2's MandelbulbIteration at power 2 (fractal_formulas.cpp of 2.20), before c.
vec3 mb2MandelbulbPower2(const vec3& z) {
    const double r = length(z), th = std::asin(z.z / r) * 2.0, ph = std::atan2(z.y, z.x) * 2.0;
    return r * r * vec3(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th));
}

// Graeme McLaren's sine and cosine maximum on all three axes (its own periods, the product halved,
// each over |v| + 1), alternating with a power-2 bulb, against Mandelbulber2's
// TransfSinAndCosMaxIteration and MandelbulbIteration written out; combo4 types 1 to 4 keep v
// in the four ways, and only with enabledM.
TEST(FractImport, SinAndCosMaxFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1084;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\n"
         "transf_function_enabledAy_false true;\ntransf_function_enabledAz_false true;\n"
         "transf_constant_multiplierA_111 3 4 5;\ntransf_constant_multiplierB_111 5 6 7;\ntransf_scaleC_1 0,5;\n"
         "transf_scale 0,8;\ntransf_function_enabled_false true;\n[fractal_2]\npower 2;\n",
         {"sin_cos_max", "mandelbulb_sine", "add_c"},
         nullptr,
         3.0,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(z) + c;
             const vec3 a(3.0, 4.0, 5.0), b(5.0, 6.0, 7.0);
             vec3 m;
             for (int k = 0; k < 3; ++k) {
                 const double s = std::sin(z[k] * 2.0 * M_PI / a[k]), co = std::cos(z[k] * 2.0 * M_PI / b[k]);
                 m[k] = std::max(std::max(s, co), s * co * 0.5) / (std::abs(z[k]) + 1.0);
             }
             return m * 0.8;
         }});
    for (int type = 1; type <= 4; ++type)
        for (const bool on : {true, false}) {
            const mb2::FractImport r =
                importText("[main_parameters]\nformula_1 1084;\n[fractal_1]\ncombo4 type" + std::to_string(type) +
                           ";\ntransf_function_enabledM_false " + (on ? "true" : "false") + ";\n");
            ASSERT_FALSE(r.preset.formula.nodes.empty());
            const Node& n = r.preset.formula.nodes.front();
            EXPECT_EQ(n.values[size_t(n.block->paramIndex("keep"))].x, on ? type : 0);
        }
}

// One plane of TransfPolyFoldSymMultiIteration (fractal_formulas.cpp of 2.20) as Mandelbulber2
// writes it: the sector from atan(a / b) (atan2 with the whole turn), truncated, turns (a, b) by
// its multiple of 2 pi / order, and an odd sector mirrors b.
void mb2PolyFoldSym(double& a, double& b, int order, bool wholeTurn) {
    const double div2Pi = double(order) / (2.0 * M_PI);
    const int sector = int(-div2Pi * (wholeTurn ? std::atan2(a, b) : std::atan(a / b)));
    const double angle = double(sector / div2Pi);
    const double temp = a;
    a = a * std::cos(angle) - b * std::sin(angle);
    b = temp * std::sin(angle) + b * std::cos(angle);
    if (sector & 1) b = -b;
}

// transf_poly_fold_sym_multi before the power-2 bulb in a hybrid: |y|, the fold of 5 sectors in
// the xy plane (atan) and in the zx plane over the whole turn, the addition constant and the
// analytic tweak's offset, against Mandelbulber2's iteration written out.
TEST(FractImport, PolyFoldSymMultiFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1081;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\ntransf_function_enabledy_false true;\ntransf_int_6 5;\ntransf_function_enabledCz_false true;\n"
         "transf_function_enabledAz_false true;\ntransf_addition_constant 0,1 0 -0,05;\nanalyticDE_offset_0 0,2;\n"
         "[fractal_2]\npower 2;\n",
         {"plane_fold", "poly_fold_sym", "poly_fold_sym", "translate", "derivative_tweak", "mandelbulb_sine", "add_c"},
         nullptr,
         2.0,
         [](const vec3& v, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(v) + c;
             vec3 z = v;
             z.y = std::abs(z.y);
             mb2PolyFoldSym(z.x, z.y, 5, false);
             mb2PolyFoldSym(z.z, z.x, 5, true);
             return z + vec3(0.1, 0.0, -0.05);
         }});
    // The tweak by the average stretch and a fold of more than 32 sectors are refused.
    expectRefused("formula_1 1081;\n[fractal_1]\nanalyticDE_enabled_false true;\n",
                  "slot 1 (transf_poly_fold_sym_multi)", "average stretch");
    expectRefused("formula_1 1081;\n[fractal_1]\ntransf_int_6 40;\n", "slot 1 (transf_poly_fold_sym_multi)", "sectors");
}

// transf_spherical_fold_parab before the power-2 bulb in a hybrid, against
// TransfSphericalFoldParabIteration (fractal_formulas.cpp of 2.20) written out: the sphere fold
// (option S), then |z|^2 moved by -0.2, the shift and the scale 1.1, the parabolas from 2.5 at
// the centre to 1 at 1.4 (the shift taken back in the outer band only, as Mandelbulber2 does),
// and the scale 0.6.
TEST(FractImport, SphericalFoldParabFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1073;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\ntransf_function_enabledS_false true;\ntransf_minR2_p25 0,5;\ntransf_maxR2_1 1;\n"
         "transf_offset_0 -0,2;\nmandelbox_offset 0 0,3 0;\ntransf_scale 1,1;\ntransf_scale_4 1,5;\n"
         "transf_scale_1 1,4;\ntransf_scaleA_1 0,6;\n[fractal_2]\npower 2;\n",
         {"sphere_fold", "sphere_fold_parabolic", "scale", "derivative_tweak", "mandelbulb_sine", "add_c"},
         nullptr,
         2.0,
         [](const vec3& v, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(v) + c;
             vec3 z = v;
             double rr = dot(z, z);
             if (rr < 0.5)
                 z *= 1.0 / 0.5;
             else if (rr < 1.0)
                 z *= 1.0 / rr;
             const vec3 offset(0.0, 0.3, 0.0);
             rr = dot(z, z);
             z += offset;
             z *= 1.1;
             const double maxScale = 1.5, maxR2 = 1.4, halfMax = 0.5 * maxR2;
             const double factor = (maxScale - 1.0) * 0.5 / (halfMax * halfMax);
             rr += -0.2;
             if (rr < halfMax) {
                 z *= maxScale - rr * rr * factor;
             } else if (rr < maxR2) {
                 z *= 1.0 + (maxR2 - rr) * (maxR2 - rr) * factor;
                 z -= offset;
             }
             return z * 0.6;
         }});
    // The derivative: Mandelbulber2's (w |scale| + 1) m, then the last scale's |0.9| and 1.
    const mb2::FractImport r = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 1073;\nformula_2 2;\n[fractal_1]\n"
        "transf_scale_4 2,5;\ntransf_scaleA_1 0,9;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    P4 p{vec3(0.2, -0.1, 0.3), 1.5};
    ASSERT_GE(r.preset.formula.nodes.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
        const Node& n = r.preset.formula.nodes[k];
        n.block->apply(p, vec3(0.0), n.args());
    }
    const double rr = 0.04 + 0.01 + 0.09, factor = 1.5 * 0.5 / 0.25;
    EXPECT_NEAR(p.w, ((1.5 + 1.0) * (2.5 - rr * rr * factor)) * 0.9 + 1.0, 1e-12);
    // The reflection of m about |p|^2 and a varying scale are refused.
    expectRefused("formula_1 1073;\n[fractal_1]\ntransf_function_enabledAx_false true;\n",
                  "slot 1 (transf_spherical_fold_parab)", "reflected");
    expectRefused("formula_1 1073;\n[fractal_1]\ntransf_function_enabledX_false true;\ntransf_scale_vary_0 0,1;\n",
                  "slot 1 (transf_spherical_fold_parab)", "varied");
}

// CollatzIteration and CollatzModIteration written out (the axis not normalised in
// RotateAroundVectorByAngle); Mandelbulber2 adds no c.
vec3 mb2Collatz(const vec3& z, const vec3& b, double s4, const vec3& a, double s2, double angle, double s) {
    const double t = 3.14159265358979 * angle;
    const vec3 turned = z * std::cos(t) + glm::cross(a, z) * std::sin(t) + a * dot(a, z) * (1.0 - std::cos(t));
    return (b + s4 * z - (a + s2 * z) * turned) * s;
}

TEST(FractImport, CollatzFollowsMandelbulber2sOrbits) {
    const OrbitCase cases[] = {
        {"formula_1 88;\nN 8;\n",
         {"collatz", "derivative_tweak"},
         [](const vec3& z, const vec3&) {
             const vec3 xV(1.0);
             vec3 temp = xV + z * 2.0;
             const double pi = 3.14159265358979;
             temp *= z * std::cos(pi) + glm::cross(xV, z) * std::sin(pi) + xV * dot(xV, z) * (1.0 - std::cos(pi));
             return (xV + z * 4.0 - temp) / 4.0;
         }},
        {"formula_1 89;\nN 8;\n[fractal_1]\ntransf_constant_multiplierB_111 1 0,8 1,1;\ntransf_scale_4 3,5;\n"
         "transf_constant_multiplier_111 1 1 0,6;\ntransf_scale_2 1,8;\ntransf_scale_1 0,5;\ntransf_scale_025 0,3;\n",
         {"collatz", "derivative_tweak"},
         [](const vec3& z, const vec3&) {
             return mb2Collatz(z, vec3(1.0, 0.8, 1.1), 3.5, vec3(1.0, 1.0, 0.6), 1.8, 0.5, 0.3);
         }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
}

// c turned by transf_rotation on iterations 2 to 5 (window G) and times its multipliers, added by
// transf_add_cpixel_rotated after the power-2 bulb (which adds its own c), against
// TransfAddCpixelRotatedIteration written out.
TEST(FractImport, AddCpixelRotatedFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 2;\nformula_2 1078;\nN 8;\n[fractal_1]\npower 2;\n[fractal_2]\n"
         "transf_rotation 20 -30 40;\ntransf_start_iterations_G 2;\ntransf_stop_iterations_G 6;\n"
         "transf_constant_multiplier_111 0,8 1,2 0,5;\n",
         {"mandelbulb_sine", "add_c", "add_c_axes", "add_c_axes", "add_c_axes"},
         nullptr,
         1.5,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 0) return mb2MandelbulbPower2(z) + c;
             const vec3 turned = i >= 2 && i < 6 ? mb2RotateVector(vec3(20.0, -30.0, 40.0), c) : c;
             return z + turned * vec3(0.8, 1.2, 0.5);
         }});
}

// Graeme McLaren's sine or cosine: the cosine on x and z, the sine on y, each axis multiplied,
// scaled twice and over |v| + 1, alternating with a power-2 bulb, against Mandelbulber2's
// TransfSinOrCosIteration and MandelbulbIteration written out; an axis left out becomes 0. The
// running derivative is Mandelbulber2's |scale| + 1 (mb2_derivative and a derivative tweak), or its
// analytic tweak's scale and offset.
TEST(FractImport, SinOrCosFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1082;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\ntransf_constant_multiplierC_111 0,9 0,7 -1,1;\ntransf_function_enabled_false true;\n"
         "transf_function_enabledAx_false true;\ntransf_function_enabledAz_false true;\ntransf_scale 1,68;\n"
         "[fractal_2]\npower 2;\n",
         {"sin_or_cos", "derivative_tweak", "mandelbulb_sine", "add_c"},
         nullptr,
         3.0,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(z) + c;
             const vec3 m(0.9, 0.7, -1.1);
             vec3 t(std::cos(z.x * m.x), std::sin(z.y * m.y), std::cos(z.z * m.z));
             t *= 1.68;
             for (int k = 0; k < 3; ++k) t[k] = t[k] * 1.68 / (std::abs(z[k]) + 1.0);
             return t;
         }});
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1082;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\ntransf_function_enabledAy false;\ntransf_scale 1,3;\n[fractal_2]\npower 2;\n",
         {"sin_or_cos", "derivative_tweak", "mandelbulb_sine", "add_c"},
         nullptr,
         3.0,
         [](const vec3& z, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(z) + c;
             return vec3(std::sin(z.x), 0.0, std::sin(z.z)) * 1.3;
         }});
    // The derivative: |scale| times the incoming one, plus 1; with the analytic tweak its own.
    for (const bool tweak : {false, true}) {
        const mb2::FractImport r = importText(
            std::string("[main_parameters]\nformula_1 1082;\n[fractal_1]\ntransf_scale -2;\n") +
            (tweak ? "analyticDE_enabled_false true;\nanalyticDE_scale_1 0,5;\nanalyticDE_offset_1 0,25;\n" : ""));
        ASSERT_GE(r.preset.formula.nodes.size(), 2u);
        P4 p{vec3(0.3, -0.4, 0.5), 1.5};
        for (size_t i = 0; i < 2; ++i) {
            const Node& n = r.preset.formula.nodes[i];
            n.block->apply(p, vec3(0.0), n.args());
        }
        EXPECT_NEAR(p.w, tweak ? 1.5 * 2.0 * 0.5 + 0.25 : 1.5 * 2.0 + 1.0, 1e-12);
    }
}

// Mandelbulber2's Vicsek written out (VicsekIteration of 2.20): the sphere fold and its scale
// (option S), |v| sorted, scaled, each axis shifted back above its threshold, x offset (option M),
// and the turn of 45 degrees about z (option X); the octahedral fold and iteration weights are
// refused.
vec3 mb2Vicsek(vec3 z, bool sphereFold, bool turn) {
    if (sphereFold) {
        const double rr = dot(z, z);
        if (rr < 0.5)
            z *= 1.0 / 0.5;
        else if (rr < 1.0)
            z *= 1.0 / rr;
        z *= 0.7;
    }
    z = glm::abs(z);
    if (z.x - z.y < 0.0) std::swap(z.y, z.x);
    if (z.x - z.z < 0.0) std::swap(z.z, z.x);
    if (z.y - z.z < 0.0) std::swap(z.z, z.y);
    z *= 2.8;
    const vec3 limit(1.2, 0.9, 1.1);
    if (z.x > limit.x * 0.5) z.x -= limit.x * 1.3;
    if (z.y > limit.y * 0.5) z.y -= limit.y;
    if (z.z > limit.z) z.z -= 2.0 * limit.z;
    z.x += 0.1;
    if (turn) z = vec3(std::sqrt(0.5) * (z.x - z.y), std::sqrt(0.5) * (z.y + z.x), z.z);
    return z;
}

TEST(FractImport, VicsekFollowsMandelbulber2sOrbits) {
    const char* vicsek =
        "[fractal_1]\ntransf_scale_3 2,8;\ntransf_offset_111 1,2 0,9 1,1;\ntransf_scaleA_1 1,3;\n"
        "transf_offset_0 0,1;\n";
    expectOrbitsFollowMandelbulber2({(std::string("formula_1 142;\nN 6;\n") + vicsek).c_str(),
                                     {"abs_fold", "menger_fold", "scale", "conditional_shift", "translate"},
                                     [](const vec3& z, const vec3&) { return mb2Vicsek(z, false, false); },
                                     2.0});
    expectOrbitsFollowMandelbulber2(
        {(std::string("formula_1 142;\nN 6;\n") + vicsek +
          "transf_function_enabledS_false true;\ntransf_minR2_p25 0,5;\ntransf_scale_08 0,7;\n"
          "transf_function_enabledX_false true;\n")
             .c_str(),
         {"sphere_fold", "scale", "abs_fold", "menger_fold", "scale", "conditional_shift", "translate", "rotate"},
         [](const vec3& z, const vec3&) { return mb2Vicsek(z, true, true); },
         2.0});
    expectRefused("formula_1 142;\n[fractal_1]\ntransf_function_enabledx_false true;\n", "slot 1 (vicsek)",
                  "the octahedral fold");
    expectRefused("formula_1 142;\n[fractal_1]\ntransf_function_enabled_false true;\ntransf_offsetA_0 0,5;\n",
                  "slot 1 (vicsek)", "iteration weights");
    // With no weights the iteration weight is the identity (formula/img vicsek switches it on).
    EXPECT_TRUE(
        importText("[main_parameters]\nformula_1 142;\n[fractal_1]\ntransf_function_enabled_false true;\n").faithful());
    expectExampleImports("Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/vicsek_001.fract");
}

// transf_rotation_folding written out (TransfRotationFoldingIteration of 2.20): the turn, |v + o| -
// o on x and y, Tglad's fold on x and y (z kept), the box fold at limit 1 value 2.2, the second
// turn; alternating with a power-2 bulb. The box fold on some axes only is refused.
TEST(FractImport, RotationFoldingFollowsMandelbulber2sOrbits) {
    expectOrbitsFollowMandelbulber2(
        {"hybrid_fractal_enable true;\nformula_1 1064;\nformula_2 2;\nN 8;\nuse_default_bailout false;\nbailout 3;\n"
         "[fractal_1]\ntransf_rotation 0 0 30;\ntransf_rotation2 20 0 0;\ntransf_offset_000 0,2 -0,1 0,3;\n"
         "transf_function_enabledz false;\ntransf_function_enabledAy_false true;\ntransf_offset_111 0,8 1,1 1;\n"
         "transf_function_enabledAz false;\ntransf_function_enabledAz_false true;\nmandelbox_folding_value 2,2;\n"
         "[fractal_2]\npower 2;\n",
         {"rotate", "plane_fold", "plane_fold", "box_fold_general", "box_fold_value", "rotate", "mandelbulb_sine",
          "add_c"},
         nullptr,
         3.0,
         [](const vec3& v, const vec3& c, int i) {
             if (i % 2 == 1) return mb2MandelbulbPower2(v) + c;
             vec3 z = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(30.0), vec3(0, 0, 1))) * v;
             const vec3 o(0.2, -0.1, 0.3), l(0.8, 1.1, 1.0);
             for (int k = 0; k < 2; ++k) z[k] = std::abs(z[k] + o[k]) - o[k];
             for (int k = 0; k < 2; ++k) z[k] = std::abs(z[k] + l[k]) - std::abs(z[k] - l[k]) - z[k];
             for (int k = 0; k < 3; ++k)
                 if (std::abs(z[k]) > 1.0) z[k] = (z[k] > 0.0 ? 2.2 : -2.2) - z[k];
             return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(20.0), vec3(1, 0, 0))) * z;
         }});
    expectRefused(
        "formula_1 1064;\n[fractal_1]\ntransf_function_enabledAz_false true;\ntransf_function_enabledBy false;\n",
        "slot 1 (transf_rotation_folding)", "the box fold with an axis left out");
}

// transf_rotation4d's turns in the xy, yz and xz planes are rotate4d's (its own test follows the 4D
// turn written out); at Mandelbulber2's defaults it is no step; a turn with w is refused, as it
// would move w off 0 beside formulas that leave w at 0.
TEST(FractImport, Rotation4dTurnsInTheSpaceOfTheOrbit) {
    const mb2::FractImport turned = importText(
        "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 7;\nformula_2 1069;\n[fractal_2]\n"
        "transf_rotation44a 14 -17 20;\n");
    ASSERT_TRUE(turned.faithful()) << turned.unsupported.front().text();
    const std::vector<std::string> ids = blockIds(turned.preset.formula);
    const auto at = std::find(ids.begin(), ids.end(), "rotate4d");
    ASSERT_NE(at, ids.end());
    const Node& turn = turned.preset.formula.nodes[size_t(at - ids.begin())];
    EXPECT_EQ(turn.values[size_t(turn.block->paramIndex("angles"))], vec3(14.0, -17.0, 20.0));
    EXPECT_EQ(turn.values[size_t(turn.block->paramIndex("angles_w"))], vec3(0.0));
    const mb2::FractImport plain =
        importText("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 7;\nformula_2 1069;\n");
    ASSERT_TRUE(plain.faithful()) << plain.unsupported.front().text();
    const std::vector<std::string> plainIds = blockIds(plain.preset.formula);
    EXPECT_EQ(std::find(plainIds.begin(), plainIds.end(), "rotate4d"), plainIds.end());
    expectRefused(
        "hybrid_fractal_enable true;\nformula_1 7;\nformula_2 1069;\n[fractal_2]\ntransf_rotation44b 0 -45 0;\n",
        "slot 2 (transf_rotation4d)", "a turn in a plane with w");
}

// Pseudo-Kleinian orbits stay bounded (no escape to compare): the orbit trap's least |v| over N
// iterations against Mandelbulber2's iteration written out (`step(z, i)`, i the iteration for its
// windows) for 2000 points; at most 1 % may differ (a fold's edge).
void expectTrapFollowsMandelbulber2(const char* body, const std::vector<std::string>& blocks,
                                    vec3 (*step)(const vec3& z, int i)) {
    SCOPED_TRACE(body);
    const mb2::FractImport r = importText(std::string("[main_parameters]\n") + body);
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula), blocks);
    std::mt19937 random(9);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int differ = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        vec3 z = point;
        double least = 1e20;
        for (int i = 0; i < r.preset.formula.iterations; ++i) {
            z = step(z, i);
            least = std::min(least, length(z));
        }
        const double got = evaluate(r.preset.formula, point).trap.value.w;
        differ += !(std::abs(got - least) <= 1e-9 * std::max(1.0, least));
    }
    std::printf("%s: %d of 2000 traps differ from Mandelbulber2's\n", blocks.back().c_str(), differ);
    EXPECT_LE(differ, 20);
}

// Benesi's frame (Mandelbulber2's SQRT_2_3 etc.) and back.
vec3 intoBenesiFrame(const vec3& z) {
    const double xz = z.x * std::sqrt(2.0 / 3.0) - z.z * std::sqrt(1.0 / 3.0);
    return vec3((xz - z.y) * std::sqrt(0.5), (xz + z.y) * std::sqrt(0.5),
                z.x * std::sqrt(1.0 / 3.0) + z.z * std::sqrt(2.0 / 3.0));
}
vec3 outOfBenesiFrame(const vec3& z) {
    const double xz = (z.y + z.x) * std::sqrt(0.5);
    return vec3(z.z * std::sqrt(1.0 / 3.0) + xz * std::sqrt(2.0 / 3.0), (z.y - z.x) * std::sqrt(0.5),
                z.z * std::sqrt(2.0 / 3.0) - xz * std::sqrt(1.0 / 3.0));
}
// The pseudo-Kleinian fold (clamp form) with size 0.55 into the box c.
vec3 pseudoKleinianFold(const vec3& z, const vec3& c) {
    const vec3 w = glm::clamp(z, -c, c) * 2.0 - z;
    return w * std::max(0.55 / dot(w, w), 1.0);
}

// The pseudo-Kleinian mod 2 (Benesi's box fold on iteration 3, both pseudo-Kleinian folds, the
// added constant, the box fold softened on iteration 0) and the std DE (Benesi's T1 on iteration
// 0, the general box fold, the pseudo-Kleinian fold; closed on r_xy).
TEST(FractImport, PseudoKleinianModsFollowMandelbulber2sOrbits) {
    expectTrapFollowsMandelbulber2(
        "formula_1 117;\nN 6;\n[fractal_1]\ntransf_addition_constant_0777 0,5 0,7 0,3;\n"
        "transf_function_enabledAy_false true;\ntransf_function_enabledF_false true;\ntransf_function_enabledx_false "
        "true;\ntransf_function_enabled_false true;\ntransf_minimum_radius_05 0,55;\ntransf_offsetA_000 0,6 0,6 0,7;\n"
        "transf_scale3D_000 0,3 0 0,6;\ntransf_scale3D_333 2,6 3 3;\ntransf_start_iterations_D 3;\n"
        "transf_stop_iterations_A 1;\ntransf_stop_iterationsTM_1 4;\ntransf_addition_constant 0,2 -0,1 0;\n",
        {"benesi_box_fold", "pseudo_kleinian", "pseudo_kleinian", "translate", "box_fold_soft", "box_fold_soft"},
        [](const vec3& v, int i) {
            const vec3 c(0.5, 0.7, 0.3), a(0.6, 0.6, 0.7);
            vec3 z = v;
            if (i == 3) {
                z = glm::abs(intoBenesiFrame(z)) * vec3(2.6, 3.0, 3.0);
                z = outOfBenesiFrame(glm::abs(z + 1.0) - glm::abs(z - 1.0) - z);
            }
            z = pseudoKleinianFold(pseudoKleinianFold(z, c), c) + vec3(0.2, -0.1, 0.0);
            z = glm::abs(z + a) - glm::abs(z - a) - z;
            if (i < 1) {
                const vec3 s(0.3, 0.0, 0.6);
                for (int k = 0; k < 3; ++k) {
                    double add = 0.0;
                    if (std::abs(z[k]) < a[k]) add = z[k] * z[k] / (2.0 * a[k]);
                    if (std::abs(z[k]) > a[k] && std::abs(z[k]) < 2.0 * a[k])
                        add = (2.0 * a[k] - std::abs(z[k])) * (2.0 * a[k] - std::abs(z[k])) / (2.0 * a[k]);
                    z[k] -= glm::sign(z[k]) * add * s[k];
                }
            }
            return z;
        });
    expectTrapFollowsMandelbulber2(
        "formula_1 101;\nN 6;\n[fractal_1]\ntransf_benesi_T1_enabled_false true;\ntransf_function_enabled false;\n"
        "transf_function_enabledF_false true;\ntransf_offset_000 0,01 0 0;\ntransf_offsetF_000 0,02 0 0;\n"
        "transf_addition_constantP_000 0,6 0,7 0,8;\n",
        {"benesi_t1", "box_fold_general", "pseudo_kleinian"}, [](const vec3& v, int i) {
            vec3 z = v;
            if (i < 1) z = outOfBenesiFrame(glm::abs(intoBenesiFrame(z)) * 2.0) - vec3(2.0, 0.0, 0.0);
            z = glm::abs(z + vec3(0.02, 0.0, 0.0)) - glm::abs(z - vec3(0.01, 0.0, 0.0)) - z;
            const vec3 c(0.7);
            const vec3 w = glm::clamp(z, -c, c) * 2.0 - z;
            return w * std::max(0.5 / dot(w, w), 1.0);
        });
    // The plain pseudo-Kleinian with its first iteration's inversion, the prism fold (iteration 0) and
    // Tglad's fold without z.
    expectTrapFollowsMandelbulber2(
        "formula_1 103;\nN 5;\n[fractal_1]\ntransf_sphere_inversion_enabled_false true;\ntransf_maxR2_1 0,8;\n"
        "transf_offset_000 0,1 0 0;\ntransf_function_enabledP_false true;\ntransf_scale 1,2;\n"
        "transf_constant_multiplier_000 0,1 0 0,2;\ntransf_function_enabledBy_false true;\ntransf_function_enabledBy "
        "false;\ntransf_addition_constant_111 0,9 0,8 1;\n",
        {"translate", "sphere_invert", "translate", "prism_fold", "box_fold_axes", "pseudo_kleinian"},
        [](const vec3& v, int i) {
            vec3 z = v;
            if (i < 1) {
                z += vec3(0.1, 0.0, 0.0);
                z *= 0.8 / dot(z, z);
                z -= vec3(0.1, 0.0, 0.0);
                z.y = std::abs(z.y);
                z.z = std::abs(z.z);
                const double t = std::max(0.0, (z.x * -std::sqrt(0.75) + z.y * 0.5) * 1.2);
                z.x -= t * -std::sqrt(3.0);
                z.y = std::abs(z.y - t);
                if (z.y > z.z) std::swap(z.y, z.z);
                z -= vec3(0.1, 0.0, 0.2) * vec3(std::sqrt(0.75), 1.5, 1.5);
                if (z.z > z.x) std::swap(z.z, z.x);
                if (z.x > 0.0) z.y = std::max(0.0, z.y), z.z = std::max(0.0, z.z);
            }
            const vec3 limit(0.9, 0.8, 1.0);
            const vec3 folded = glm::abs(z + limit) - glm::abs(z - limit) - z;
            z = vec3(folded.x, folded.y, z.z);
            const vec3 c(0.7);
            const vec3 w = glm::clamp(z, -c, c) * 2.0 - z;
            return w * std::max(0.5 / dot(w, w), 1.0);
        });
    const mb2::FractImport std = importText("[main_parameters]\nformula_1 101;\n");
    EXPECT_EQ(std.preset.formula.estimator.block->id, "escape_linear_xy");
}

// Jos Leys' Kleinian in Mandelbulber2's form closes with kleinian_de, Mandelbulber2's Jos-Kleinian DE
// function: the estimate at random points is Mandelbulber2's, min(min(y, a - y), tweak) /
// max(DE, offset), after its JosKleinianIteration written out here (the first iteration's sphere
// inversion included).
TEST(FractImport, JosKleinianIsMandelbulber2sStepAndDistance) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 122;\nN 7;\n[fractal_1]\ntransf_folding_value 1,9;\ntransf_offset 0,073;\n"
        "analyticDE_tweak_005 0,28;\nanalyticDE_offset_1 1,5;\ntransf_offset_111 1 1 0,8;\n"
        "transf_sphere_inversion_enabled_false true;\ntransf_maxR2_1 0,3;\ntransf_offset_000 0,2 -1,2 0;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    EXPECT_EQ(blockIds(f), (std::vector<std::string>{"translate", "sphere_invert", "translate", "jos_kleinian"}));
    EXPECT_EQ(f.estimator.block->id, "kleinian_de");
    const double a = 1.9, b = 0.073;
    const vec3 box(1.0, 1.0, 0.8);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int differ = 0;
    for (int k = 0; k < 2000; ++k) {
        const vec3 point = randomVec3(u, random);
        vec3 z = point;
        double de = 1.0;
        for (int i = 0; i < 7; ++i) {
            if (i < 1) {
                z += vec3(0.2, -1.2, 0.0);
                const double rr = dot(z, z);
                z *= 0.3 / rr;
                de *= 0.3 / rr;
                z -= vec3(0.2, -1.2, 0.0);
            }
            const vec3 size(2.0 * box.x, a * box.y, 2.0 * box.z), start(-box.x, -box.y + 1.0, -box.z);
            const vec3 w = z - start;
            z = w - size * glm::floor(w / size) + start;
            if (z.y >= a * (0.5 + 0.2 * std::sin(3.14159265358979 * (z.x + b * 0.5) / box.x))) z = vec3(-b, a, 0.0) - z;
            const double iR = 1.0 / dot(z, z);
            z *= -iR;
            z.x = -b - z.x;
            z.y = a + z.y;
            de *= std::abs(iR);
        }
        const double expected = std::min(std::min(z.y, a - z.y), 0.28) / std::max(de, 1.5);
        const double got = evaluate(f, point).distance / f.deFactor;
        differ += !(std::abs(got - expected) <= 1e-9 * std::max(1.0, std::abs(expected)));
    }
    std::printf("jos_kleinian: %d of 2000 estimates differ from Mandelbulber2's\n", differ);
    EXPECT_LE(differ, 20);  // points on a wrap's edge or the separation line may go either way
    const mb2::FractImport flat =
        importText("[main_parameters]\nformula_1 122;\n[fractal_1]\ntransf_spheres_enabled false;\n");
    EXPECT_TRUE(mentions(flat.unsupported, "main", "transf_spheres_enabled false"));
}

// transf_abs_add_conditional reads x's multiplier from transf_scale3D_000 and y's and z's from
// transf_offset_000, as Mandelbulber2 does.
TEST(FractImport, AbsAddConditionalReadsEachAxisWhereMandelbulber2Does) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 2;\nformula_2 1065;\nhybrid_fractal_enable true;\n[fractal_2]\n"
        "transf_function_enabledz false;\ntransf_offset_000 0,5 0,4 0,3;\ntransf_scale3D_000 0,2 0 0;\n"
        "transf_offset_111 1 2 1;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const auto node = std::find_if(r.preset.formula.nodes.begin(), r.preset.formula.nodes.end(),
                                   [](const Node& n) { return n.block->id == "abs_add_conditional"; });
    ASSERT_NE(node, r.preset.formula.nodes.end());
    EXPECT_EQ(node->values[0], vec3(1.0, 1.0, 0.0));
    EXPECT_EQ(node->values[1], vec3(1.0, 2.0, 1.0));
    EXPECT_EQ(node->values[2], vec3(0.2, 0.4, 0.3));
    // Its DE tweak (aux.DE *= analyticDE_scale_1) follows it as a derivative tweak: the point as it
    // was, the running derivative times the factor.
    const mb2::FractImport tweaked = importText(
        "[main_parameters]\nformula_1 2;\nformula_2 1065;\nhybrid_fractal_enable true;\n[fractal_2]\n"
        "analyticDE_scale_1 0,895;\n");
    ASSERT_TRUE(tweaked.faithful()) << tweaked.unsupported.front().text();
    const std::vector<Node>& nodes = tweaked.preset.formula.nodes;
    const auto step =
        std::find_if(nodes.begin(), nodes.end(), [](const Node& n) { return n.block->id == "abs_add_conditional"; });
    ASSERT_TRUE(step != nodes.end() && step + 1 != nodes.end());
    const Node& tweak = *(step + 1);
    ASSERT_EQ(tweak.block->id, "derivative_tweak");
    EXPECT_EQ(tweak.schedule(), step->schedule());
    P4 p{vec3(0.3, -0.2, 0.5), 2.0};
    tweak.block->apply(p, vec3(0.0), tweak.args());
    EXPECT_EQ(p.xyz, vec3(0.3, -0.2, 0.5));
    EXPECT_NEAR(p.w, 2.0 * 0.895, 1e-12);
    EXPECT_EQ(tweak.block->derivativeAt(tweak.args()), DerivativeBound::None);
    for (const mb2::ImportItem& item : tweaked.approximated)
        EXPECT_EQ(item.what.find("analyticDE_scale_1"), std::string::npos) << item.text();
}

// transf_diagonal_fold's swaps are plane folds through the diagonal planes; where the windowed
// variant is chosen each runs in its own window.
TEST(FractImport, DiagonalFoldSwapsArePlaneFolds) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 1098;\nformula_2 8;\nhybrid_fractal_enable true;\n[fractal_1]\n"
        "transf_function_enabledAx_false true;\ntransf_function_enabledAy_false true;\n"
        "transf_start_iterations_B 3;\ntransf_stop_iterations_B 5;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    std::vector<const Node*> folds;
    for (const Node& n : r.preset.formula.nodes)
        if (n.block->id == "plane_fold") folds.push_back(&n);
    ASSERT_EQ(folds.size(), 2u);
    EXPECT_EQ(folds[0]->values[0], vec3(-1.0, 1.0, 0.0));
    EXPECT_EQ(folds[1]->values[0], vec3(0.0, -1.0, 1.0));
    // A point with x > y comes out with them swapped; y and z are swapped only on the slot's
    // iterations in [3, 5) (the hybrid alternates: 4).
    P4 p{vec3(0.7, 0.2, -0.4), 1.0};
    folds[0]->block->apply(p, vec3(0.0), folds[0]->args());
    EXPECT_NEAR(p.xyz.x, 0.2, 1e-12);
    EXPECT_NEAR(p.xyz.y, 0.7, 1e-12);
    EXPECT_TRUE(folds[0]->runsOn(2) && folds[0]->runsOn(6));
    EXPECT_TRUE(folds[1]->runsOn(4));
    EXPECT_FALSE(folds[1]->runsOn(2) || folds[1]->runsOn(3) || folds[1]->runsOn(6));
}

// box_fold_bulb_pow2_v2: each part in its window (fold B, sphere fold S, scale C, power A), the
// power's z times the z factor; the sphere fold's offset is mandelbox_offset.
TEST(FractImport, BoxFoldBulbPow2V2RunsEachPartInItsWindow) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 125;\n[fractal_1]\ntransf_addition_constant_111 0,5 1 1;\n"
        "transf_scale 0,9;\ntransf_start_iterations_A 8;\ntransf_stop_iterations_A 9;\n"
        "transf_stop_iterations_C 12;\nboxfold_bulbpow2_z_factor 20;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    EXPECT_EQ(blockIds(f), (std::vector<std::string>{"box_fold_axes", "sphere_fold", "scale_vary", "mandelbulb_sine",
                                                     "axis_scale", "add_c"}));
    EXPECT_EQ(f.nodes[2].stop, 12);
    EXPECT_EQ(f.nodes[3].start, 8);
    EXPECT_EQ(f.nodes[3].stop, 9);
    EXPECT_EQ(f.nodes[4].values[0], vec3(1.0, 1.0, -20.0));
    EXPECT_EQ(f.nodes[1].values[2], vec3(0.0));
    const mb2::FractImport off =
        importText("[main_parameters]\nformula_1 125;\n[fractal_1]\nmandelbox_offset 0 0 0,2;\n");
    ASSERT_TRUE(off.faithful()) << off.unsupported.front().text();
    EXPECT_EQ(off.preset.formula.nodes[1].values[2], vec3(0.0, 0.0, 0.2));
    // V3 adds the octahedral fold with |x| and a scale about offset_100 (window D); a scale that
    // varies with the iteration is refused.
    const mb2::FractImport v3 = importText(
        "[main_parameters]\nformula_1 126;\n[fractal_1]\ntransf_function_enabledD_false true;\ntransf_scaleA_2 1,5;\n"
        "transf_stop_iterations_D 5;\n");
    ASSERT_TRUE(v3.faithful()) << v3.unsupported.front().text();
    EXPECT_EQ(blockIds(v3.preset.formula),
              (std::vector<std::string>{"box_fold", "sphere_fold", "scale_vary", "octahedral_fold", "plane_fold",
                                        "scale", "mandelbulb_sine", "axis_scale", "add_c"}));
    EXPECT_EQ(v3.preset.formula.nodes[5].stop, 5);
    EXPECT_EQ(v3.preset.formula.nodes[5].values[0].x, 1.5);
    // Its option F, a Menger step on an offset abs that shifts z only above 1, follows
    // Mandelbulber2's orbits (the power left out); the step that always shifts z is refused.
    const OrbitCase menger{
        "formula_1 126;\nN 6;\n[fractal_1]\ntransf_scale 2;\ntransf_function_enabledF_false true;\n"
        "transf_addition_constantA_000 0,1 0 -0,2;\ntransf_constant_multiplier_111 1 0,8 1;\n"
        "transf_stop_iterations_A 0;\n",
        {"box_fold", "sphere_fold", "scale_vary", "translate", "menger_rotate", "add_c"},
        nullptr,
        3.0,
        [](const vec3& v, const vec3& c, int) {
            vec3 z = glm::abs(v + 1.0) - glm::abs(v - 1.0) - v;
            const double rr = dot(z, z);
            z *= (rr < 0.25 ? 4.0 : rr < 1.0 ? 1.0 / rr : 1.0) * 2.0;
            z = glm::abs(z + vec3(0.1, 0.0, -0.2));
            if (z.x < z.y) std::swap(z.x, z.y);
            if (z.x < z.z) std::swap(z.x, z.z);
            if (z.y < z.z) std::swap(z.y, z.z);
            z *= 3.0;
            z.x -= 2.0;
            z.y -= 1.6;
            if (z.z > 1.0) z.z -= 2.0;
            return z + c;
        }};
    expectOrbitsFollowMandelbulber2(menger);
    const mb2::FractImport always = importText(
        "[main_parameters]\nformula_1 126;\n[fractal_1]\ntransf_function_enabledF_false true;\n"
        "transf_function_enabled false;\n");
    ASSERT_FALSE(always.faithful());
    EXPECT_NE(always.unsupported.front().text().find("shifts z at every point"), std::string::npos);
}

// The scale that varies with the iteration (Mandelbulber2's aux.actualScaleA): the offset a starts
// at 0, the scale is a + s, and a moves by vary (|a| - limit) in the update window only; with the
// reset option a becomes -vary (|a| - limit). box_fold_bulb_pow2_v2 with its power left out
// (window A empty), and amazing_surf_mod2, whose option F turns the update on.
TEST(FractImport, VaryingScaleFollowsMandelbulber2sOrbits) {
    static auto v2Step = [](const vec3& v, const vec3& c, int i, double vary, bool reset) {
        static double a = 0.0;
        if (i == 0) a = 0.0;
        vec3 z = glm::abs(v + 1.0) - glm::abs(v - 1.0) - v;
        const double rr = dot(z, z);
        z *= rr < 0.25 ? 4.0 : rr < 1.0 ? 1.0 / rr : 1.0;
        z *= a + 2.5;
        if (i >= 2 && i < 6) {
            const double change = vary * (std::abs(a) - 0.5);
            a = reset ? -change : a - change;
        }
        return z + c;
    };
    const OrbitCase cases[] = {
        {"formula_1 125;\nN 9;\n[fractal_1]\ntransf_scale 2,5;\ntransf_scale_vary_0 0,3;\ntransf_scaleB_1 0,5;\n"
         "transf_start_iterations_X 2;\ntransf_stop_iterations_X 6;\ntransf_stop_iterations_A 0;\n",
         {"box_fold", "sphere_fold", "scale_vary", "scale_vary", "scale_vary", "add_c"},
         nullptr,
         5.0,
         [](const vec3& v, const vec3& c, int i) { return v2Step(v, c, i, 0.3, false); }},
        {"formula_1 125;\nN 9;\n[fractal_1]\ntransf_scale 2,5;\ntransf_scale_vary_0 -0,4;\ntransf_scaleB_1 0,5;\n"
         "transf_start_iterations_X 2;\ntransf_stop_iterations_X 6;\ntransf_stop_iterations_A 0;\n"
         "transf_function_enabledM_false true;\n",
         {"box_fold", "sphere_fold", "scale_vary", "scale_vary", "scale_vary", "add_c"},
         nullptr,
         5.0,
         [](const vec3& v, const vec3& c, int i) { return v2Step(v, c, i, -0.4, true); }},
    };
    for (const OrbitCase& c : cases) expectOrbitsFollowMandelbulber2(c);
    // Without the option F amazing_surf_mod2 reads a, which nothing moves: a plain scale.
    const std::string surf = "[main_parameters]\nformula_1 132;\n[fractal_1]\ntransf_scale_vary_0 0,2;\n";
    const mb2::FractImport still = importText(surf);
    ASSERT_TRUE(still.faithful()) << still.unsupported.front().text();
    const mb2::FractImport varies = importText(surf + "transf_function_enabledF_false true;\n");
    ASSERT_TRUE(varies.faithful()) << varies.unsupported.front().text();
    auto updates = [](const Formula& f) {
        int n = 0;
        for (const Node& k : f.nodes) n += k.block->id == "scale_vary" && param(k, "update") > 0.5;
        return n;
    };
    EXPECT_EQ(updates(still.preset.formula), 0);
    EXPECT_EQ(updates(varies.preset.formula), 1);
}

// Mandelbulber2's fish eye and equirectangular cameras: fraktal's projections, 180 x fov degrees
// up (fov is the internal one before 2.21, 2 tan of half the degrees from 2.21 on).
TEST(FractImport, WideCamerasAreFraktalsProjections) {
    const mb2::FractImport fish = importText("[main_parameters]\nperspective_type fish_eye;\nfov 0,7;\n");
    ASSERT_TRUE(fish.faithful()) << fish.unsupported.front().text();
    EXPECT_EQ(fish.preset.camera.projection, Projection::FishEye);
    EXPECT_NEAR(fish.preset.camera.fovY, 126.0, 1e-9);
    const mb2::FractImport panorama = importText("[main_parameters]\nperspective_type 2;\n");
    ASSERT_TRUE(panorama.faithful()) << panorama.unsupported.front().text();
    EXPECT_EQ(panorama.preset.camera.projection, Projection::Equirectangular);
    EXPECT_NEAR(panorama.preset.camera.fovY, 180.0, 1e-9);
    const mb2::FractImport cut = importText("[main_parameters]\nperspective_type 3;\n");
    EXPECT_TRUE(mentions(cut.unsupported, "main", "perspective_type 3"));
}

// abox_mod11's parts keep their own windows: the tweak scale on iteration 0 only, the fold from 2.
TEST(FractImport, AboxMod11PartsRunInTheirWindows) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 119;\n[fractal_1]\ntransf_scaleG_1 0,9;\ntransf_start_iterations_B 2;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula),
              (std::vector<std::string>{"box_fold", "sphere_fold", "scale", "scale", "add_c"}));
    EXPECT_EQ(r.preset.formula.nodes[0].start, 2);
    EXPECT_EQ(r.preset.formula.nodes[0].stop, 250);
    EXPECT_EQ(param(r.preset.formula.nodes[3], "scale"), 0.9);
    EXPECT_EQ(r.preset.formula.nodes[3].start, 0);
    EXPECT_EQ(r.preset.formula.nodes[3].stop, 1);
}

// abox_mod11's scale varying with the iteration against 2.20's AboxMod11Iteration written out:
// actualScale = -1.6 + (-0.2) (|actualScale| - 1) at the start of each iteration, from -1.6 (the
// first slot's Mandelbox scale, compute_fractal.cpp), Tglad's fold at 1, the sphere fold of squared
// radii 0.15 and 1, z times actualScale, then c. A scale that starts from another slot's Mandelbox
// scale, or whose window leaves out iterations the formula varies it on, is refused by name; the
// example that varies it imports.
TEST(FractImport, AboxMod11VaryingScaleFollowsMandelbulber2sOrbits) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 119;\nN 10;\n[fractal_1]\nmandelbox_scale -1,6;\n"
        "mandelbox_vary_scale_vary -0,2;\ntransf_minR2_p25 0,15;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula), (std::vector<std::string>{"box_fold", "sphere_fold", "scale_vary", "add_c"}));
    const double bailout = r.preset.formula.bailout;
    expectEscapesFollow(r.preset.formula, 3.0, "abox_mod11", [bailout](const vec3& point) {
        vec3 z = point;
        double actualScale = -1.6;
        for (int i = 0; i < 10; ++i) {
            actualScale = -1.6 + -0.2 * (std::abs(actualScale) - 1.0);
            z = glm::abs(z + 1.0) - glm::abs(z - 1.0) - z;
            const double rr = dot(z, z);
            if (rr < 0.15)
                z *= 1.0 / 0.15;
            else if (rr < 1.0)
                z *= 1.0 / rr;
            z = z * actualScale + point;
            if (length(z) > bailout) return true;
        }
        return false;
    });
    expectRefused(
        "hybrid_fractal_enable true;\nformula_1 8;\nformula_2 119;\n[fractal_2]\nmandelbox_scale -1,6;\n"
        "mandelbox_vary_scale_vary -0,2;\n",
        "slot 2 (abox_mod11)", "starts from another slot's Mandelbox scale");
    expectRefused("formula_1 119;\n[fractal_1]\nmandelbox_vary_scale_vary -0,2;\ntransf_start_iterations_A 2;\n",
                  "slot 1 (abox_mod11)", "window A leaves out iterations");
    expectExampleImports("Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/abox_mod11_rotVary.fract");
}

// abox_mod11's sphere fold with transf_function_enabledy_false: its squared inner radius follows
// Mandelbulber2's Cpara curve, transf_minR2_p25 plus the linear stretches through para00, paraA,
// paraB and paraC at iterations 0, iterA, iterB and iterC (fractal_formulas.cpp
// AboxMod11Iteration), one sphere_fold per stretch. On every iteration the orbit runs, the fold
// that runs there scales a point as the fold with that iteration's radius does.
TEST(FractImport, CparaCurveGrowsTheSphereFoldsInnerRadius) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 119;\nN 40;\n[fractal_1]\ntransf_function_enabledy_false true;\n"
        "Cpara_para00 0,1;\nCpara_paraA 0,3;\nCpara_paraB 0,2;\nCpara_paraC 0,5;\nCpara_iterA 5;\nCpara_iterB 12;\n"
        "Cpara_iterC 30;\nCpara_enabledCurves false;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    std::vector<const Node*> folds;
    for (const Node& n : r.preset.formula.nodes)
        if (n.block->id == "sphere_fold") folds.push_back(&n);
    ASSERT_EQ(folds.size(), 3u);
    EXPECT_EQ(folds[0]->start, 0);
    EXPECT_EQ(folds[1]->start, 5);
    EXPECT_EQ(folds[2]->start, 12);
    EXPECT_EQ(folds[2]->stop, 40);         // the formula's N
    auto squaredInnerRadius = [](int i) {  // 0.25 + the curve, as Mandelbulber2 computes it
        if (i < 5) return 0.25 + 0.1 + i * (0.3 - 0.1) / 5.0;
        if (i < 12) return 0.25 + 0.3 + (i - 5) * (0.2 - 0.3) / 7.0;
        return 0.25 + 0.2 + (i - 12) * (0.5 - 0.2) / 18.0;
    };
    for (int i = 0; i < 40; ++i) {
        int running = 0;
        for (const Node* fold : folds) {
            if (!fold->runsOn(i)) continue;
            ++running;
            // A point inside the inner radius is scaled by Rf^2 / Rm^2 (here Rf^2 = 1).
            P4 p{vec3(0.01, 0.0, 0.0), 1.0};
            p.iteration = i;
            fold->block->apply(p, vec3(0.0), fold->args());
            EXPECT_NEAR(p.w, 1.0 / squaredInnerRadius(i), 1e-9) << "iteration " << i;
        }
        EXPECT_EQ(running, 1) << "iteration " << i;
    }
    // Without the flag the fold keeps transf_minR2_p25. Refused: a curve undefined where the orbit
    // runs (iterB = iterC, so the third stretch divides by 0), and one whose squared inner radius
    // passes the fixed one (Mandelbulber2's fold shrinks inside it there, fraktal's does not).
    const mb2::FractImport plain = importText("[main_parameters]\nformula_1 119;\n");
    ASSERT_TRUE(plain.faithful());
    EXPECT_EQ(param(plain.preset.formula.nodes[1], "min_r2_growth"), 0.0);
    const mb2::FractImport undefined = importText(
        "[main_parameters]\nformula_1 119;\n[fractal_1]\ntransf_function_enabledy_false true;\nCpara_iterB 20;\n"
        "Cpara_iterC 20;\n");
    EXPECT_TRUE(mentions(undefined.unsupported, "slot 1 (abox_mod11)", "Cpara: a curve undefined at iteration 20"));
    const mb2::FractImport passing = importText(
        "[main_parameters]\nformula_1 119;\n[fractal_1]\ntransf_function_enabledy_false true;\nCpara_paraA 3;\n");
    EXPECT_TRUE(mentions(passing.unsupported, "slot 1 (abox_mod11)", "outside [0, transf_maxR2_1 1]"));
}

// Mandelbulber2's 4D formulas carry the point's fourth coordinate from initial_waxis: a start_w
// node, then the 4D steps; r is measured in 4D for the bailout and the linear estimate. The
// imported formula's estimate equals Mandelbulber2's orbit written out here in 4D
// (fractal_formulas.cpp Menger4dIteration, Sierpinski4dIteration; compute_fractal.cpp: z.w and
// c.w start at initial_waxis, r = |z| in 4D, the IFS estimate (r - 2) / DE).
TEST(FractImport, FourDFormulasCarryTheFourthCoordinate) {
    using D4 = glm::dvec4;
    auto mandelbulber2 = [](const vec3& pos, double w0, int n, double bailout, auto&& step, double scale) {
        D4 z(pos, w0);
        double de = 1.0;
        for (int i = 0; i < n; ++i) {
            step(z, i);
            de *= scale;
            if (glm::length(z) > bailout) break;
        }
        return (glm::length(z) - 2.0) / de;
    };
    auto menger = [](D4& z, int) {
        z = glm::abs(z);
        if (z.x - z.y < 0.0) std::swap(z.y, z.x);
        if (z.x - z.z < 0.0) std::swap(z.z, z.x);
        if (z.y - z.z < 0.0) std::swap(z.z, z.y);
        if (z.x - z.w < 0.0) std::swap(z.w, z.x);
        if (z.y - z.w < 0.0) std::swap(z.w, z.y);
        if (z.z - z.w < 0.0) std::swap(z.w, z.z);
        const D4 offset(1.0, 1.0, 1.0, 0.40107);
        z.x = 3.0 * z.x - offset.x;
        z.y = 3.0 * z.y - offset.y;
        z.w = 3.0 * z.w - offset.w;
        z.z -= 0.5 * offset.z / 3.0;
        z.z = -std::abs(-z.z);
        z.z += 0.5 * offset.z / 3.0;
        z.z *= 3.0;
    };
    auto sierpinski = [](D4& z, int i) {
        auto mirror = [](double& a, double& b) {
            if (a + b < 0.0) {
                const double t = a;
                a = -b;
                b = -t;
            }
        };
        mirror(z.x, z.y);
        mirror(z.x, z.z);
        mirror(z.z, z.y);  // Mandelbulber2's third: z = -y, y = -z
        mirror(z.x, z.w);
        mirror(z.y, z.w);
        mirror(z.z, z.w);
        z *= 2.0;
        if (i >= 1) z -= D4(2.1, 1.0, 1.0, 1.0);  // window C from iteration 1
    };
    const mb2::FractImport m = importText(
        "[main_parameters]\nformula_1 111;\ninitial_waxis 0,333333;\nN 12;\n[fractal_1]\n"
        "transf_addition_constant_111d5 1 1 1 0,40107;\n");
    ASSERT_TRUE(m.faithful()) << m.unsupported.front().text();
    EXPECT_EQ(blockIds(m.preset.formula), (std::vector<std::string>{"start_w", "menger4d"}));
    const mb2::FractImport s = importText(
        "[main_parameters]\nformula_1 109;\ninitial_waxis -0,6;\nN 12;\n[fractal_1]\n"
        "transf_offset_1111 2,1 1 1 1;\ntransf_start_iterations_C 1;\n");
    ASSERT_TRUE(s.faithful()) << s.unsupported.front().text();
    EXPECT_EQ(blockIds(s.preset.formula), (std::vector<std::string>{"start_w", "sierpinski4d", "sierpinski4d"}));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int k = 0; k < 200; ++k) {
        const vec3 pos = randomVec3(u, rng);
        EXPECT_NEAR(evaluate(m.preset.formula, pos).distance / m.preset.formula.deFactor,
                    mandelbulber2(pos, 0.333333, 12, m.preset.formula.bailout, menger, 3.0), 1e-9)
            << pos.x << " " << pos.y << " " << pos.z;
        EXPECT_NEAR(evaluate(s.preset.formula, pos).distance / s.preset.formula.deFactor,
                    mandelbulber2(pos, -0.6, 12, s.preset.formula.bailout, sierpinski, 2.0), 1e-9)
            << pos.x << " " << pos.y << " " << pos.z;
    }
    // Beside a formula that leaves w aside, the fourth coordinate is refused; so is a 4D turn.
    const mb2::FractImport bulb = importText("[main_parameters]\nformula_1 2;\ninitial_waxis 0,5;\n");
    EXPECT_TRUE(mentions(bulb.unsupported, "main", "initial_waxis 0,5: a fourth coordinate beside formulas"));
    const mb2::FractImport turned =
        importText("[main_parameters]\nformula_1 111;\n[fractal_1]\ntransf_function_enabledR_false true;\n");
    EXPECT_TRUE(mentions(turned.unsupported, "slot 1 (menger4d)", "a turn in the six planes of 4D"));
}

// The whole scene's fractal_position, fractal_rotation and repeat place the formula: Mandelbulber2
// measures it at M ((p - position) mod repeat), M the rotation's matrix (compute_fractal.cpp),
// here 90 degrees about z: (x, y, z) -> (-y, x, z). In boolean mode, where each slot has a
// placement of its own, they are refused.
TEST(FractImport, FractalPositionRotationAndRepeatPlaceTheFormula) {
    const std::string body = "[main_parameters]\nformula_1 7;\n";
    const mb2::FractImport plain = importText(body);
    const mb2::FractImport placed =
        importText(body + "fractal_position 0,5 -1 0,25;\nfractal_rotation 0 0 90;\nrepeat 6 0 0;\n");
    ASSERT_TRUE(placed.faithful()) << placed.unsupported.front().text();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-8.0, 8.0);
    for (int k = 0; k < 100; ++k) {
        const vec3 p = randomVec3(u, rng) * vec3(1.0, 0.25, 0.25);
        vec3 q = p - vec3(0.5, -1.0, 0.25);
        q.x -= 6.0 * std::floor(q.x / 6.0 + 0.5);
        EXPECT_NEAR(evaluate(placed.preset.formula, p).distance,
                    evaluate(plain.preset.formula, vec3(-q.y, q.x, q.z)).distance, 1e-9)
            << p.x << " " << p.y << " " << p.z;
    }
    const mb2::FractImport boolean = importText(body + "boolean_operators true;\nfractal_rotation 0 0 90;\n");
    EXPECT_TRUE(mentions(boolean.unsupported, "main", "fractal_rotation 0 0 90: the whole scene's placement"));
}

// Amazing Surf mod 2: Tglad's fold with per-axis limits (the box fold per axis, z's fold when
// enabled), the sphere fold and scale in their windows; other fold types are named.
TEST(FractImport, AmazingSurfMod2FoldsPerAxisInItsWindows) {
    const mb2::FractImport r = importText(
        "[main_parameters]\nformula_1 132;\n[fractal_1]\ntransf_addition_constant_111 1 0,5 2;\n"
        "transf_start_iterations_M 3;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_EQ(blockIds(r.preset.formula),
              (std::vector<std::string>{"box_fold_axes", "sphere_fold", "scale_vary", "add_c"}));
    const Node& fold = r.preset.formula.nodes[0];
    EXPECT_EQ(fold.values[0], vec3(1.0, 0.5, 1.0));  // z unfolded: its limit unused
    EXPECT_EQ(param(fold, "fold_z"), 0.0);
    EXPECT_EQ(r.preset.formula.nodes[1].start, 3);
    // The per-axis fold is Tglad's: |v + L| - |v - L| - v on x and y, z as it was.
    const vec3 q(1.7, -0.9, 2.5);
    P4 p{q, 1.0};
    fold.block->apply(p, q, fold.args());
    EXPECT_NEAR(p.xyz.x, std::abs(q.x + 1.0) - std::abs(q.x - 1.0) - q.x, 1e-12);
    EXPECT_NEAR(p.xyz.y, std::abs(q.y + 0.5) - std::abs(q.y - 0.5) - q.y, 1e-12);
    EXPECT_EQ(p.xyz.z, q.z);
    const mb2::FractImport other =
        importText("[main_parameters]\nformula_1 132;\n[fractal_1]\naSurf3Folds_order_of_folds_1 type2;\n");
    EXPECT_TRUE(mentions(other.unsupported, "slot 1 (amazing_surf_mod2)", "a fold other than Tglad's"));
    // A second and third xy fold, each in its window (B, C), after the first.
    const mb2::FractImport three = importText(
        "[main_parameters]\nformula_1 132;\n[fractal_1]\ntransf_function_enabledAy_false true;\n"
        "transf_stop_iterations_B 5;\ntransf_function_enabledAz_false true;\ntransf_start_iterations_C 2;\n");
    ASSERT_TRUE(three.faithful()) << three.unsupported.front().text();
    EXPECT_EQ(blockIds(three.preset.formula),
              (std::vector<std::string>{"box_fold_axes", "box_fold_axes", "box_fold_axes", "sphere_fold", "scale_vary",
                                        "add_c"}));
    EXPECT_EQ(three.preset.formula.nodes[1].stop, 5);
    EXPECT_EQ(three.preset.formula.nodes[2].start, 2);
    // Its extra multiple of c comes first, per axis, in window H; turned by transf_rotation in
    // window G.
    const std::string extraC =
        "[main_parameters]\nformula_1 132;\n[fractal_1]\ntransf_addCpixel_enabled_false true;\n"
        "transf_constant_multiplier_111 0 0 -0,3;\ntransf_stop_iterations_H 4;\n";
    const mb2::FractImport extra = importText(extraC);
    ASSERT_TRUE(extra.faithful()) << extra.unsupported.front().text();
    const Node& first = extra.preset.formula.nodes[0];
    EXPECT_EQ(first.block->id, "add_c_axes");
    EXPECT_EQ(first.values[0], vec3(0.0, 0.0, -0.3));
    EXPECT_EQ(first.stop, 4);
    const mb2::FractImport turned =
        importText(extraC + "transf_rotation_enabled true;\ntransf_rotation 30 0 0;\ntransf_start_iterations_G 2;\n");
    ASSERT_TRUE(turned.faithful()) << turned.unsupported.front().text();
    EXPECT_EQ(blockIds(turned.preset.formula), (std::vector<std::string>{"add_c_axes", "add_c_axes", "box_fold_axes",
                                                                         "sphere_fold", "scale_vary", "add_c"}));
    const Node &plain = turned.preset.formula.nodes[0], &turning = turned.preset.formula.nodes[1];
    EXPECT_EQ(plain.stop, 2);
    EXPECT_EQ(param(plain, "turn_angle"), 0.0);
    EXPECT_EQ(turning.start, 2);
    EXPECT_EQ(turning.stop, 4);
    // The turned c is Mandelbulber2's rotationMatrix applied to c (SetRotation2 of 30 degrees
    // about x), times the multiplier.
    const vec3 c(0.3, -0.7, 0.4);
    P4 added{vec3(0.0), 1.0};
    turning.block->apply(added, c, turning.args());
    const vec3 turnedC = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(30.0), vec3(1, 0, 0))) * c;
    EXPECT_NEAR(added.xyz.z, -0.3 * turnedC.z, 1e-12);
    EXPECT_NEAR(added.xyz.x, 0.0, 1e-12);
}

// What changes the image a little is imported and listed, not refused.
TEST(FractImport, ListsWhatItMatchesApproximately) {
    const mb2::FractImport r =
        importText("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\ncheck_for_bailout_1 false;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    EXPECT_TRUE(mentions(r.approximated, "slot 1", "check_for_bailout off"));
}

// The surface of orbits bounded for N iterations is fraktal's hits only inside, for a box's
// linear estimate and a bulb's log one alike; without the mode the estimate's threshold stops rays.
TEST(FractImport, IterationThresholdModeHitsOnlyInside) {
    for (const char* formula : {"formula_1 8;\n", ""}) {
        SCOPED_TRACE(formula);
        const mb2::FractImport on =
            importText(std::string("[main_parameters]\n") + formula + "iteration_threshold_mode true;\n");
        ASSERT_TRUE(on.faithful()) << on.unsupported.front().text();
        EXPECT_EQ(on.preset.formula.hitRule, HitRule::InsideOnly);
        EXPECT_FALSE(mentions(on.approximated, "detail", "iteration_threshold_mode"));
        const mb2::FractImport off = importText(std::string("[main_parameters]\n") + formula);
        EXPECT_EQ(off.preset.formula.hitRule, HitRule::Surface);
    }
}

// Mandelbulber2's interior mode is fraktal's interior walls, with its march's step limit; beside the iteration
// threshold mode (whose hits it moves away: a ray that never stops) it is refused by name.
TEST(FractImport, InteriorModeHitsTheInteriorWalls) {
    for (const char* formula : {"formula_1 8;\n", ""}) {
        SCOPED_TRACE(formula);
        const mb2::FractImport on = importText(std::string("[main_parameters]\n") + formula + "interior_mode true;\n");
        ASSERT_TRUE(on.faithful()) << on.unsupported.front().text();
        EXPECT_EQ(on.preset.formula.hitRule, HitRule::InteriorWalls);
        EXPECT_EQ(on.preset.render.maxSteps, kMaxMarchSteps);  // a crossing of the set at a fifth of a threshold a step
        const mb2::FractImport both = importText(std::string("[main_parameters]\n") + formula +
                                                 "interior_mode true;\niteration_threshold_mode true;\n");
        EXPECT_FALSE(both.faithful());
        EXPECT_TRUE(mentions(both.unsupported, "main", "interior_mode with iteration_threshold_mode"));
        // The cut applies after the fractal's own estimate has taken the rule: an object, not a
        // combine estimator that would take the rule with it (the cut face would be drawn).
        const mb2::FractImport cut = importText(std::string("[main_parameters]\n") + formula +
                                                "interior_mode true;\nlimits_enabled true;\nlimit_min -10 -10 0;\n");
        ASSERT_TRUE(cut.faithful()) << cut.unsupported.front().text();
        EXPECT_NE(cut.preset.formula.estimator.block->id, "box_combine");
        ASSERT_EQ(cut.preset.formula.objects.size(), 1u);
        EXPECT_EQ(cut.preset.formula.objects[0].operation, ObjectOperation::Intersect);
    }
}

// Mandelbulber2 places its primitives in the world, fractal_rotation and fractal_position turn and
// move the fractal alone: beside a placement the plane is an object, not a combine estimator
// evaluated in the placed frame. Above the plane (world z = 50, far from the bulb) the estimate is
// positive; the plane turned 135 degrees with the fractal put that point inside it.
TEST(FractImport, PrimitivesStayInTheWorldBesideThePlacedFractal) {
    const mb2::FractImport r =
        importText("[main_parameters]\nfractal_rotation 0 -135 0;\nprimitive_plane_1_enabled true;\n");
    ASSERT_TRUE(r.faithful()) << r.unsupported.front().text();
    const Formula& f = r.preset.formula;
    EXPECT_EQ(f.estimator.block->id.find("combine"), std::string_view::npos) << f.estimator.block->id;
    ASSERT_EQ(f.objects.size(), 1u);
    const Evaluation above = evaluate(f, vec3(0.0, 0.0, 50.0));
    EXPECT_FALSE(above.inside);
    EXPECT_GT(above.distance, 1.0);
    const Evaluation below = evaluate(f, vec3(0.0, 0.0, -50.0));
    EXPECT_LT(below.distance, 0.0);
}

TEST(FractImport, BulbAngleOffsetsAreTheSineBulbsOffsets) {
    const mb2::FractImport r =
        importText("[main_parameters]\n[fractal_1]\nalpha_angle_offset 90;\nbeta_angle_offset -45;\npower 2;\n");
    ASSERT_TRUE(r.faithful());
    const Node& bulb = r.preset.formula.nodes.front();
    ASSERT_EQ(bulb.block->id, "mandelbulb_sine");
    EXPECT_EQ(bulb.values[size_t(bulb.block->paramIndex("power"))].x, 2.0);
    EXPECT_EQ(bulb.values[size_t(bulb.block->paramIndex("theta_offset"))].x, -45.0);
    EXPECT_EQ(bulb.values[size_t(bulb.block->paramIndex("phi_offset"))].x, 90.0);
}

TEST(FractImport, CameraFollowsTheFileVersionAndLegacyCoordinates) {
    const mb2::FractImport legacy = importText("[main_parameters]\nlegacy_coordinate_system true;\nfov 1,2;\n");
    EXPECT_TRUE(legacy.preset.camera.flipVertical);
    EXPECT_NEAR(legacy.preset.camera.fovY, glm::degrees(2.0 * std::atan(0.6)), 1e-9);
    // From 2.21 the file stores degrees.
    const mb2::FractImport degrees = mb2::importFract(
        parseFractFile("# Mandelbulber settings file\n# version 2.25\n[main_parameters]\nfov 61,9;\n", "new.fract"));
    EXPECT_DOUBLE_EQ(degrees.preset.camera.fovY, 61.9);
    // The flipped camera mirrors every ray top to bottom.
    Camera c = legacy.preset.camera;
    const vec3 up = c.rayDirection(0.0, 0.8, 1.0);
    c.flipVertical = false;
    const vec3 down = c.rayDirection(0.0, -0.8, 1.0);
    EXPECT_NEAR(length(up - down), 0.0, 1e-12);
}

// ---- `fraktal import` as a person runs it ----

// A sandbox named for this file's tests.
struct Sandbox : test::Sandbox {
    Sandbox() : test::Sandbox("fraktal_import_") {}
};

TEST(CliImport, RefusesWhatItCannotExpressAndWritesNothingUnlessLenient) {
    const Sandbox box;
    const std::string file = box.write(
        "hybrid.fract", kHeader + "[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 4;\n");
    const auto strict = test::runCli("import '" + file + "' -o '" + box.path("out.json") + "'");
    EXPECT_NE(strict.exitCode, 0);
    EXPECT_NE(strict.output.find("slot 2 (hypercomplex)"), std::string::npos) << strict.output;
    EXPECT_NE(strict.output.find("hybrid.fract"), std::string::npos) << strict.output;
    EXPECT_FALSE(fs::exists(box.path("out.json")));
    EXPECT_FALSE(fs::exists(box.path("out.json.tmp")));

    const auto lenient = test::runCli("import --lenient '" + file + "' -o '" + box.path("out.json") + "'");
    ASSERT_EQ(lenient.exitCode, 0) << lenient.output;
    const Preset p = loadPreset(box.path("out.json"));
    EXPECT_NE(p.description.find("Dropped"), std::string::npos);
    EXPECT_NE(p.description.find("slot 2 (hypercomplex)"), std::string::npos) << p.description;
    EXPECT_EQ(p.name, "hybrid");
}

TEST(CliImport, RendersAFractFileDirectlyAndChecksIt) {
    const Sandbox box;
    const std::string file = box.write("menger.fract", kHeader + "[main_parameters]\nformula_1 7;\nN 8;\n");
    const auto r = test::runCli("render '" + file + "' -o '" + box.path("m.exr") + "' --size 32x24 --spp 1 -q");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(box.path("m.exr")));
    const auto bad =
        test::runCli("render '" + box.write("bad.fract", "hello\n") + "' -o '" + box.path("b.exr") + "' -q");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("not a Mandelbulber2 settings file"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(box.path("b.exr")));
}

// ---- Against Mandelbulber2 itself ----

// The hit masks and their agreement as bench/import measures them (bench/import/silhouette.hpp).
using silhouette::Mask;

// mandelbulber2's mask, or an empty one where it wrote no image.
Mask pngAlphaMask(const std::string& path) {
    try {
        return silhouette::readPngMask(path);
    } catch (const std::runtime_error&) {
        return {};
    }
}

// A copy of a settings file for mandelbulber2 without what adds alpha where there is no surface
// or blurs it (depth of field, fog, glow, orbit-trap lights, visible light sources, transparent
// surfaces, reflections): the silhouette is the shape's alone. The list of bench/import/run.sh.
std::string peerSettings(const fs::path& file, const std::string& out) {
    const std::vector<std::pair<std::string, std::string>> keys = {{"DOF_enabled", "false"},
                                                                   {"DOF_monte_carlo", "false"},
                                                                   {"volumetric_fog_enabled", "false"},
                                                                   {"iteration_fog_enable", "false"},
                                                                   {"basic_fog_enabled", "false"},
                                                                   {"glow_enabled", "false"},
                                                                   {"fake_lights_enabled", "false"},
                                                                   {"main_light_visibility", "0"},
                                                                   {"aux_light_visibility", "0"},
                                                                   {"main_light_volumetric_enabled", "false"},
                                                                   {"mat1_transparency_of_surface", "0"},
                                                                   {"raytraced_reflections", "false"}};
    std::ifstream in(file);
    std::ofstream copy(out);
    std::string line;
    while (std::getline(in, line)) {
        bool replaced = false;
        for (const auto& [key, value] : keys) replaced = replaced || line.starts_with(key + " ");
        if (replaced) continue;
        copy << line << "\n";
        if (line == "[main_parameters]")
            for (const auto& [key, value] : keys) copy << key << " " << value << ";\n";
    }
    return out;
}

struct Expected {
    std::string file;     // under /usr/share/mandelbulber2
    std::string refuse;   // empty: imports and matches; else what the refusal names
    double minIou = 0.9;  // the silhouettes' agreement, where a file is known to differ and why
    int width = 128;      // the renders' size, width x 3/4 width
};

// The fixed set: files that import and match, each with its reason where it is there for one, and
// files refused by name.
std::vector<Expected> fixedSet() {
    const std::string km = "examples/Krzysztof Marczak collection - license Creative Commons (CC-BY 4.0)/";
    const std::string gm = "examples/Graeme McLaren  collection - license Creative Commons  (CC-BY 4.0)/";
    const std::string rp = "examples/Robert Pancoast collection - license Creative Commons (CC-BY 4.0)/";
    return {
        {"toolbar/mandelbox scale 2.fract", ""},
        {"toolbar/mandelbox scale -2.fract", ""},
        {"toolbar/menger sponge.fract", ""},
        {"toolbar/dodecahedron.fract", ""},
        {"toolbar/octahedron.fract", ""},
        {"toolbar/quaternion.fract", ""},
        // The quaternion's derivative without the 1 for c, as Mandelbulber2's (0.89 with it).
        {"examples/quaternion_001.fract", ""},
        // The power-2 sine bulb's hairs reach 1.96 in a view range of 50: the fitted bound holds
        // them (EditorFormulaFit.BoundHoldsASmallObjectInAWideSearch). Its surface is a little
        // thicker than Mandelbulber2's: the sine bulb's derivative bounds the azimuth's stretch,
        // which Mandelbulber2's r_dz leaves out (4673 hit pixels against 4335 at 128x96, 0.902).
        {"toolbar/mandelbulb_power_2.fract", ""},
        {"toolbar/icosahedron.fract", ""},
        {"examples/orbittrap002.fract", ""},
        // Kaleidoscopic IFS in Menger sponge mode (menger_scale).
        {"examples/IFS_001.fract", ""},
        // White's power-2 bulb (the sine bulb, z mirrored) in a hybrid with the Mandelbox.
        {"examples/hybrid002.fract", ""},
        {"examples/box_fold_bulb_pow2_001.fract", ""},
        // A rotation inside the formula on iterations 0-1 only (a node window).
        {gm + "pseudo kleinian maxiter10.fract", ""},
        // A hybrid sequence of 18 iterations: periodic stretches of period <= 16 with windows. It
        // and the hypercomplex view fill the image (they check that the import runs; the
        // Mb2Sequence and HypercomplexRunsItsOwnOrbit tests check the orbits themselves). Its 60
        // nodes over 250 iterations cost fraktal's render 27 s at 128x96 on two cores: 64x48.
        {km + "hybrid33.fract", "", 0.9, 64},
        // The hypercomplex orbit in its own 4D estimator.
        {km + "hypercomplex 03.fract", ""},
        // An equirectangular panorama (fraktal's equirectangular projection).
        {rp + "icoastahedron.fract", ""},
        // Aexion's 4D orbit in its own estimator.
        {"examples/aexion001.fract", ""},
        // Iteration threshold mode: hits only inside (the log estimate is small far around it).
        {"examples/hypercomplex001.fract", ""},
        // msltoe's Riemann sphere V1 (a tiled stereographic plane), delta DE: the orbit gradient.
        {"examples/riemann_sphere_msltoe_v1_001.fract", ""},
        // box_fold_bulb_pow2_v2: its fold, sphere fold, scale and power each in its own window.
        {gm + "boxFoldBulb_v2_01.fract", ""},
        // dIFS: the donut's torus measured along its orbit (the difs estimate).
        {"examples/msltoe_donut_001.fract", ""},
        // The generalized box fold on the icosahedron.
        {km + "GeneralizedFoldBox01.fract", ""},
        // A limit box around the pseudo-Kleinian DE: an object intersecting the estimate.
        {"examples/monte carlo DOF 004.fract", ""},
        // A Menger sponge with Mandelbulber2's 4D scale, its fourth coordinate 0 throughout.
        {rp + "menger-Scale4D.fract", ""},
        // A stereo pair one above the other is refused (a red-cyan anaglyph imports:
        // FractImport.RedCyanStereoIsDrawnFromBetweenTheEyes).
        {rp + "menger-4D.fract", "stereo pairs side by side or one above the other"},
        // A Menger sponge on Mandelbulber2's water (the water combine, its frame turned over).
        {km + "primitive objects - water.fract", ""},
        // Interior mode: hits only on the walls where rays come out of the set (interior walls).
        {km + "hybrid20.fract", ""},
        // Graeme McLaren's sine and cosine maximum (sin_cos_max) before the pseudo-Kleinian.
        {gm + "sinCos_pseudoKl.fract", ""},
        // A sphere fold off the origin, a scale varying with the iteration and an extra multiple of
        // c (amazing_surf_mod2 twice).
        {gm + "asurf_fakelights_backgroundl.fract", ""},
        // Mandelbulber2's dIFS cylinder formula: the shape measured along the orbit.
        {"formula/img/difs_cylinder.fract", ""},
        // abox_mod_kali_v2 with c added signed by the point (add_c_symmetric).
        {"formula/img/abox_mod_kali_v2.fract", ""},
        {"examples/aboxmod2_001.fract", "slot 1 (abox_mod2): the formula abox_mod2"},
        // Boolean mode: a kaleidoscopic IFS with a Mandelbulb carved from it and a Menger sponge
        // joined, in a limit box (each fractal placed and measured alone).
        {"examples/boolean001.fract", ""},
        // A placed, scaled and turned fractal joined to a repeated one, lit by repeated cylinders.
        {"examples/monte carlo global illumination - emmisive materials.fract", ""},
        // The 4D Sierpinski simplex's slice at initial_waxis, the whole fractal turned by
        // fractal_rotation; formula/img abox_mod11's sphere fold on the Cpara curve.
        {gm + "Sierpinski 4D.fract", ""},
        {"formula/img/abox_mod11.fract", ""},
        // Mandelbulber2's dIFS diagonal box: the box measured after the step, over its DE |s| + 1.
        {"formula/img/difs_box_diagonal_v1.fract", ""},
        // Water beside Mandelbulber2's dIFS estimate (water_combine's dIFS part).
        {"examples/difs_tree.fract", ""},
        // The Mandelbox in four dimensions, its fourth coordinate moved by the Cpara parabola
        // (abox_fold4d).
        {"formula/img/abox4d.fract", ""},
        // mancoast's modulus Mandelbulb (axis_remainder) beside the pseudo-Kleinian: a view from
        // inside, which checks that the import runs (FractImport.ModulusMandelbulbFollowsMandelbulber2sOrbits
        // checks the orbit).
        {"examples/Daniel Luchansky collection - license Creative Commons -CC-BY 4.0/pseuklein x mod mandelbulb.fract",
         ""},
        // Mandelbulber2's dIFS box (difs_box_v1), and its dIFS cylinder with the polygonal fold
        // (poly_fold).
        {"formula/img/difs_box_v1.fract", ""},
        {gm + "DIFS Cylinder complex primitive.fract", ""},
        // Views from inside, which check that the import runs (the orbit tests check the orbits:
        // FractImport.Quaternion4dFollowsMandelbulber2sOrbits, MandelbulbBermarteFollowsMandelbulber2sOrbits,
        // AboxMod11VaryingScaleFollowsMandelbulber2sOrbits): quaternion4d in 4D; visual.bermarte's bulb
        // after the inverse cylindrical transform in a hybrid with the Mandelbox; abox_mod11's scale
        // varying with the iteration (scale_vary's from_scale) beside the varying rotation.
        {"examples/quaternion4D_001.fract", ""},
        {"examples/Sebastian Jennen collection - license Creative Commons  (CC-BY 4.0)/inverse-reciprocal-iqbulb "
         "mechanical-ribs.fract",
         ""},
        {gm + "abox_mod11_rotVary.fract", ""},
        // Mandelbulber2's world-unit hit threshold (constant_DE_threshold, 1.95e-5 units) held in
        // footprints at the target: the dIFS flower's petals as thin as Mandelbulber2's.
        {gm + "DIFS BoxV1 flower.fract", ""},
        // amazing_surf_mod2 in Julia mode, its derivative's 1 added without c (a derivative_tweak).
        {gm + "asurf_julia.fract", ""},
        // Mandelbulber2's dIFS torus formula (difs_torus with the dIFS sphere's folds).
        {"formula/img/difs_torus.fract", ""},
        // transf_rotation_folding: two turns about the abs folds.
        {"formula/img/transf_rotation_folding.fract", ""},
        // Mandelbulber2's Vicsek (the Menger fold's sort, conditional_shift).
        {"formula/img/vicsek.fract", ""},
        // Camera rays end at view_distance_max (render.viewDistance): past it, 97 % of this
        // hybrid's extra hits (0.51 without it); with sin_or_cos and the spherical inversion's 1.
        // At 160x120, the bench's size (0.910; 0.899 at 128x96: its thin horns' rims).
        {gm + "Jos Leys Kleinian Hybrid inv cos.fract", "", 0.9, 160},
        // Graeme McLaren's sine or cosine (sin_or_cos) with Mandelbulber2's derivative.
        {"formula/img/transf_sin_or_cos.fract", ""},
        // The spherical inversion transform with the 1 Mandelbulber2 adds to its running
        // derivative (a derivative_tweak): 0.91 without it.
        {gm + "sphere_invert_menger_sponge.fract", ""},
        // menger_octo: the octahedral fold and its scale about a point before the Menger step.
        {"formula/img/menger_octo.fract", ""},
        // ifs_xy with its windows: the box size off from iteration 2, the pentagonal fold on the
        // first iteration only, the offset folds and the turn.
        {gm + "ifs_xy.fract", ""},
        // transf_poly_fold_sym_multi (poly_fold_sym) in the xy and zx planes before the Menger
        // sponge, on the first three iterations.
        {"formula/img/transf_poly_fold_sym_multi.fract", ""},
        // transf_spherical_fold_parab (sphere_fold_parabolic) with the sphere fold from the second
        // iteration and Mandelbulber2's offset taken back in the outer band only.
        {"formula/img/transf_spherical_fold_parab.fract", ""},
        // The quadratics of "another shot at the holy grail": Quick Dudley's with its per-term
        // multipliers (quick_dudley) in a repeated view; Buddhi's Mandelbulb 3 (mandelbulb3, its
        // derivative without the 1 for c) and Mandelbulb 4 (mandelbulb4's three turns).
        {"examples/quick-dudley_mod_001.fract", ""},
        {"examples/mandelbulb3_001.fract", ""},
        {"examples/mandelbulb4_001.fract", ""},
        // msltoe's Julia bulb mod 2 (msltoe_sym3_mod2) with c signed by the point in Julia mode.
        {"examples/msltoe_julia_bulb_mod2_001.fract", ""},
    };
}

const fs::path kMb2Share = "/usr/share/mandelbulber2";

std::string renderSize(const Expected& c) { return std::to_string(c.width) + "x" + std::to_string(c.width * 3 / 4); }

// mandelbulber2's silhouette of a file of the set, rendered now by the installed mandelbulber2.
Mask mandelbulber2Silhouette(const Expected& c, const Sandbox& box, const std::string& tag) {
    const std::string home = box.path(tag + "_home");
    fs::create_directories(home);
    const std::string peer = "HOME='" + home + "' QT_QPA_PLATFORM=offscreen mandelbulber2 -n -f png16alpha -r " +
                             renderSize(c) + " -o '" + box.path(tag + "_mb") + "' '" +
                             peerSettings(kMb2Share / c.file, box.path(tag + "_peer.fract")) +
                             "' > /dev/null 2>&1 < /dev/null";
    EXPECT_EQ(std::system(peer.c_str()), 0) << c.file;
    return pngAlphaMask(box.path(tag + "_mb.png"));
}

// mandelbulber2's silhouettes of the set are kept in tests/data/mb2_silhouettes/, one PNG per
// file (white where its alpha is over one half), named after the file's path: rendering them took
// about 4 s of CPU each at 128x96, most of this comparison's time. They are mandelbulber2's own
// (Debian 12's 2.20): `FRAKTAL_STORE_MB2_SILHOUETTES=1 fraktal_tests --gtest_filter=
// ImportVsMandelbulber2.FixedSet*` renders them again and stores them, and
// ImportVsMandelbulber2.StoredSilhouettesAreTheInstalledMandelbulber2s compares a spread of them
// with the installed program's on every run.
fs::path storedSilhouettes() { return test::sourceDir() / "tests" / "data" / "mb2_silhouettes"; }

fs::path storedSilhouettePath(const Expected& c) {
    std::string name;
    for (char ch : c.file.substr(0, c.file.rfind('.'))) name += std::isalnum((unsigned char)ch) ? ch : '_';
    return storedSilhouettes() / (name + ".png");
}

Mask readStoredSilhouette(const fs::path& path) {
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &n, 1);
    if (!pixels) return {};
    Mask m{w, h, {}};
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) m.hit.push_back(pixels[i] >= 128);
    stbi_image_free(pixels);
    return m;
}

void storeSilhouette(const fs::path& path, const Mask& m) {
    std::vector<uint8_t> rgb;
    for (bool h : m.hit) rgb.insert(rgb.end(), 3, h ? 255 : 0);
    writePngAtomic(path, m.width, m.height, rgb);
}

bool storingSilhouettes() {
    const char* store = std::getenv("FRAKTAL_STORE_MB2_SILHOUETTES");
    return store && *store && std::string(store) != "0";
}

TEST(ImportVsMandelbulber2, FixedSetMatchesOrIsRefusedForItsReason) {
    ASSERT_TRUE(fs::exists("/usr/bin/mandelbulber2"))
        << "mandelbulber2 is missing: scripts/install-deps.sh installs it";
    const std::vector<Expected> cases = fixedSet();
    // Two files at a time (each import's safe-step measurement and each render keep about one of
    // the two cores busy), each in files of its own.
    const Sandbox box;
    auto check = [&](const Expected& c, const std::string& tag) {
        SCOPED_TRACE(c.file);
        const auto started = std::chrono::steady_clock::now();
        const fs::path file = kMb2Share / c.file;
        ASSERT_TRUE(fs::exists(file));
        const std::string preset = box.path(tag + ".json"), exr = box.path(tag + ".exr");
        const auto imported = test::runCli("import '" + file.string() + "' -q -o '" + preset + "'");
        if (!c.refuse.empty()) {
            EXPECT_NE(imported.exitCode, 0);
            EXPECT_NE(imported.output.find(c.refuse), std::string::npos) << imported.output;
            return;
        }
        ASSERT_EQ(imported.exitCode, 0) << imported.output;
        const auto rendered =
            test::runCli("render '" + preset + "' --size " + renderSize(c) + " --spp 1 -q -o '" + exr + "'");
        ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
        const fs::path stored = storedSilhouettePath(c);
        if (storingSilhouettes()) storeSilhouette(stored, mandelbulber2Silhouette(c, box, tag));
        const Mask ours = silhouette::readExrMask(exr), theirs = readStoredSilhouette(stored);
        ASSERT_EQ(theirs.width, c.width) << stored << " is missing or of another size: FRAKTAL_STORE_MB2_SILHOUETTES=1 "
                                         << "stores mandelbulber2's silhouettes of the set again";
        ASSERT_EQ(ours.hit.size(), theirs.hit.size());
        long covered = 0;
        for (bool h : theirs.hit) covered += h;
        EXPECT_GT(covered, long(theirs.hit.size() / 20))
            << "Mandelbulber2 shows almost nothing: no silhouette to compare";
        const double iou = silhouette::compare(ours, theirs).iou;
        EXPECT_GE(iou, c.minIou);
        std::printf("%s: IoU %.3f (%.1f s)\n", c.file.c_str(), iou,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    };
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t k = next++; k < cases.size(); k = next++) check(cases[k], "case" + std::to_string(k));
    };
    std::thread other(worker);
    worker();
    other.join();
}

// The stored silhouettes are the installed mandelbulber2's: every file of the set that imports has
// one and every one belongs to such a file, and a spread of them (every fifth) is rendered again
// by mandelbulber2 and must be the same but for a few pixels (a new mandelbulber2 that renders
// differently shows here first).
TEST(ImportVsMandelbulber2, StoredSilhouettesAreTheInstalledMandelbulber2s) {
    ASSERT_TRUE(fs::exists("/usr/bin/mandelbulber2"))
        << "mandelbulber2 is missing: scripts/install-deps.sh installs it";
    std::vector<Expected> matched;
    for (const Expected& c : fixedSet())
        if (c.refuse.empty()) matched.push_back(c);
    std::set<fs::path> expected;
    for (const Expected& c : matched) {
        expected.insert(storedSilhouettePath(c));
        EXPECT_TRUE(fs::exists(storedSilhouettePath(c))) << c.file << " has no stored silhouette";
    }
    for (const fs::directory_entry& e : fs::directory_iterator(storedSilhouettes())) {
        if (e.path().extension() != ".png") continue;
        EXPECT_TRUE(expected.count(e.path())) << e.path() << " belongs to no file of the set that imports";
    }
    const Sandbox box;
    for (size_t k = 0; k < matched.size(); k += 5) {
        const Expected& c = matched[k];
        SCOPED_TRACE(c.file);
        const Mask now = mandelbulber2Silhouette(c, box, "live" + std::to_string(k));
        const Mask stored = readStoredSilhouette(storedSilhouettePath(c));
        ASSERT_EQ(now.width, stored.width);
        ASSERT_EQ(now.height, stored.height);
        size_t differ = 0;
        for (size_t i = 0; i < now.hit.size(); ++i) differ += now.hit[i] != stored.hit[i];
        // mandelbulber2 is not deterministic to the pixel: two runs of the same file differed in 1
        // and 5 silhouette pixels of 12288 (hybrid20, boolean001). A mandelbulber2 that renders
        // the file otherwise differs in far more.
        EXPECT_LE(differ, now.hit.size() / 200)
            << "pixels where the installed mandelbulber2's silhouette differs from the stored one";
    }
}

}  // namespace
}  // namespace fraktal
