// Preset I/O: exact round trips of every shipped preset, and a clear error (file, field,
// reason), a non-zero exit and no crash for each malformed preset in tests/bad_presets/.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "test_support.hpp"

using namespace fraktal;

namespace {

void expectSameFormula(const Formula& a, const Formula& b, const std::string& what) {
    EXPECT_EQ(a.structureKey(), b.structureKey()) << what;
    EXPECT_EQ(a.iterations, b.iterations) << what;
    EXPECT_EQ(a.bailout, b.bailout) << what;
    EXPECT_EQ(a.boundRadius, b.boundRadius) << what;
    EXPECT_EQ(a.deFactor, b.deFactor) << what;
    ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
    for (size_t k = 0; k <= a.nodes.size(); ++k) {
        const Node& na = k < a.nodes.size() ? a.nodes[k] : a.estimator;
        const Node& nb = k < b.nodes.size() ? b.nodes[k] : b.estimator;
        EXPECT_EQ(na.values, nb.values) << what << " node " << k;
    }
}

}  // namespace

TEST(Preset, EveryShippedPresetRoundTripsExactly) {
    for (const auto& path : test::shippedPresets()) {
        const Preset original = loadPreset(path);
        const std::string saved = serializePreset(original);
        const Preset reloaded = parsePreset(saved, "saved " + path.filename().string());
        expectSameFormula(original.formula, reloaded.formula, path.filename().string());
        EXPECT_EQ(original.camera.position, reloaded.camera.position);
        EXPECT_EQ(original.camera.target, reloaded.camera.target);
        EXPECT_EQ(original.camera.up, reloaded.camera.up);
        EXPECT_EQ(original.camera.fovY, reloaded.camera.fovY);
        EXPECT_EQ(original.name, reloaded.name);
        EXPECT_EQ(serializePreset(reloaded), saved) << "saving is not deterministic";
    }
}

TEST(Preset, SavesOnlyWhatDiffersFromDefaults) {
    Preset p = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    const nlohmann::json j = presetToJson(p);
    const auto& nodes = j["formula"]["nodes"];
    EXPECT_FALSE(nodes[0].contains("params"));  // box_fold at its default limit 1
    EXPECT_FALSE(nodes[2].contains("params"));  // scale 2 about the origin: defaults
    p.formula.nodes[0].values[0].x = 1.25;
    EXPECT_EQ(presetToJson(p)["formula"]["nodes"][0]["params"]["limit"], 1.25);
}

TEST(Preset, UnknownTopLevelSectionsAreKept) {
    std::ifstream in(test::sourceDir() / "presets/menger.json");
    std::stringstream ss;
    ss << in.rdbuf();
    nlohmann::json j = nlohmann::json::parse(ss.str());
    j["futureSection"] = {{"answer", 42}};
    const Preset p = parsePreset(j.dump(), "future.json");
    EXPECT_EQ(presetToJson(p)["futureSection"]["answer"], 42);
}

struct BadPreset {
    const char* file;
    const char* field;   // the JSON path the message must name ("" when the file as a whole)
    const char* reason;  // part of the reason the message must give
};

const BadPreset kBadPresets[] = {
    {"unknown_block.json", "formula.nodes[0].block", "unknown block 'warp_drive'"},
    {"missing_block_field.json", "formula.nodes[0].block", "missing required field"},
    {"param_out_of_range.json", "formula.nodes[0].params.limit", "outside the range [0, 4]"},
    {"param_wrong_type.json", "formula.nodes[0].params.limit", "expected a number, found a string"},
    {"vector_wrong_length.json", "formula.nodes[0].params.offset", "expected an array of 3 numbers"},
    {"unknown_param.json", "formula.nodes[0].params.limt", "unknown parameter of block 'box_fold'"},
    {"number_overflow_inf.json", "", "invalid JSON: number overflow parsing '1e999'"},
    {"nan_literal.json", "", "invalid JSON at line 1"},
    {"empty_nodes.json", "formula.nodes", "the node list is empty"},
    {"no_estimator.json", "formula.nodes[0]", "must end with an estimator"},
    {"estimator_not_last.json", "formula.nodes[0]", "may only close the node list"},
    {"truncated.json", "", "invalid JSON"},
    {"empty_file.json", "", "file is empty"},
    {"not_an_object.json", "", "expected an object, found an array"},
    {"wrong_format.json", "format", "expected \"fraktal-preset\""},
    {"missing_version.json", "version", "missing required field"},
    {"missing_formula.json", "formula", "missing required field"},
    {"missing_camera.json", "camera", "missing required field"},
    {"iterations_fraction.json", "formula.iterations", "expected a whole number"},
    {"iterations_too_many.json", "formula.iterations", "outside the range [0, 1000]"},
    {"negative_bailout.json", "formula.bailout", "outside the range"},
    {"zero_direction.json", "formula.nodes[0].params.normal", "a direction must not be zero"},
    {"phase_not_below_period.json", "formula.nodes[0].phase", "phase must be smaller than period"},
    {"duplicate_key.json", "nodes", "duplicated key"},
    {"camera_degenerate.json", "camera", "position and target coincide"},
    {"camera_fov_absurd.json", "camera.fovY", "outside the range [1, 170]"},
    {"invalid_utf8.json", "", "invalid JSON"},
    {"deep_nesting.json", "", "nested deeper than 32 levels"},
    {"huge_string.json", "name", "string longer than 4096 bytes"},
    {"too_many_nodes.json", "formula.nodes", "too many nodes (201; at most 64)"},
    {"unknown_node_field.json", "formula.nodes[0].parms", "unknown field"},
    {"estimator_disabled.json", "formula.nodes[0].enabled", "the estimator cannot be disabled"},
    {"custom_glsl_unbounded_loop.json", "formula.customBlocks[0].glsl", "line 1: loops ('while') are not allowed"},
    {"custom_glsl_preprocessor.json", "formula.customBlocks[0].glsl", "preprocessor directives are not allowed"},
    {"custom_block_builtin_id.json", "formula.customBlocks[0].id", "'box_fold' is a built-in block"},
    {"custom_block_reserved_param.json", "formula.customBlocks[0].params[0].name", "'p' is reserved"},
    {"custom_block_defined_twice.json", "formula.customBlocks[1].id", "'spin' is defined twice"},
    {"custom_block_forbidden_word.json", "formula.customBlocks[0].glsl", "'gl_WorkGroupID' is not allowed"},
    {"custom_estimator_without_return.json", "formula.customBlocks[0].glsl", "must return the distance"},
    {"custom_block_unknown_category.json", "formula.customBlocks[0].category", "expected fold, transform"},
    {"custom_block_default_out_of_range.json", "formula.customBlocks[0].params[0].default", "outside [min, max]"},
    {"a_directory.json", "", "is a directory, not a preset file"},
};

TEST(Preset, EveryMalformedPresetGivesAClearError) {
    size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "tests/bad_presets")) {
        ++count;
        const std::string name = entry.path().filename().string();
        const BadPreset* expected = nullptr;
        for (const BadPreset& b : kBadPresets)
            if (name == b.file) expected = &b;
        ASSERT_NE(expected, nullptr) << name << " has no expected error in kBadPresets";
        try {
            loadPreset(entry.path());
            ADD_FAILURE() << name << " loaded without an error";
        } catch (const PresetError& e) {
            EXPECT_EQ(e.file(), entry.path().string()) << name;
            EXPECT_EQ(e.field(), expected->field) << name << ": " << e.what();
            EXPECT_NE(e.reason().find(expected->reason), std::string::npos) << name << ": " << e.what();
        }
    }
    EXPECT_EQ(count, std::size(kBadPresets));
}

// Every file under `dir` with its size and modification time.
std::map<std::string, std::pair<uintmax_t, std::filesystem::file_time_type>> snapshot(const std::filesystem::path& dir) {
    std::map<std::string, std::pair<uintmax_t, std::filesystem::file_time_type>> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        files[e.path().string()] = {e.is_regular_file() ? e.file_size() : 0, e.last_write_time()};
    return files;
}

TEST(Preset, CheckCommandExitsNonZeroWithTheMessage) {
    const auto corpusBefore = snapshot(test::sourceDir() / "tests/bad_presets");
    for (const BadPreset& b : kBadPresets) {
        const std::string path = (test::sourceDir() / "tests/bad_presets" / b.file).string();
        const test::CliRun r = test::runCli("check " + path);
        EXPECT_EQ(r.exitCode, 2) << b.file << ":\n" << r.output;
        EXPECT_NE(r.output.find(path + ": " + (std::string(b.field).empty() ? "" : std::string(b.field) + ": ")),
                  std::string::npos)
            << b.file << ":\n" << r.output;
    }
    const test::CliRun missing = test::runCli("check /nonexistent/preset.json");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.output.find("/nonexistent/preset.json: no such file"), std::string::npos) << missing.output;
    const test::CliRun directory = test::runCli("check " + (test::sourceDir() / "presets").string());
    EXPECT_EQ(directory.exitCode, 2);
    EXPECT_NE(directory.output.find("is a directory"), std::string::npos) << directory.output;
    EXPECT_EQ(snapshot(test::sourceDir() / "tests/bad_presets"), corpusBefore) << "checking a bad preset touched a file";
}

TEST(Preset, CheckCommandReportsASoundPreset) {
    const test::CliRun r = test::runCli("check --rays 40 " + (test::sourceDir() / "presets/menger.json").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("abs_fold"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("worst DE / true distance"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("step multiplier 1 is safe"), std::string::npos) << r.output;
}

TEST(Preset, CheckCommandFlagsAnUnsafeFormula) {
    Preset p = loadPreset(test::sourceDir() / "presets/menger.json");
    p.formula.deFactor = 1.6;
    const auto file = std::filesystem::temp_directory_path() / "fraktal_unsafe_menger.json";
    std::ofstream(file) << serializePreset(p);
    const test::CliRun r = test::runCli("check --rays 40 " + file.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("multiply formula.deFactor by"), std::string::npos) << r.output;
}
