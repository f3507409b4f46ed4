// `fraktal check --apply`: the measured step factor written into the preset with the rest of the
// file byte for byte as it was, atomically; and the in-place edit it rests on
// (core/preset_text_edit.hpp). `fraktal check --fit`: the estimator, bailout and bound fitted to
// the blocks first (with --apply, written too); a useless estimate fails the check, which names
// the estimator the fit would choose.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/preset.hpp"
#include "core/preset_text_edit.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

std::string fileText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(PresetTextEdit, ReplacesOnlyTheNumber) {
    const std::string text =
        "{\n  \"name\": \"x\",\n  \"formula\": {\"iterations\": 6,   \"deFactor\": 1.0e0, \"nodes\": []},\n"
        "  \"animation\": {\"tracks\": [{\"target\": \"formula.deFactor\"}]}\n}\n";
    const std::string edited = withNumberInPlace(text, "formula", "deFactor", 0.703, "p.json");
    EXPECT_EQ(edited, std::regex_replace(text, std::regex("1\\.0e0"), "0.703"));
}

TEST(PresetTextEdit, InsertsAMissingKeyAsTheFirstMemberInTheFilesOwnLayout) {
    const std::string lines = "{\n  \"formula\": {\n    \"iterations\": 6,\n    \"nodes\": []\n  }\n}\n";
    EXPECT_EQ(withNumberInPlace(lines, "formula", "deFactor", 0.5, "p.json"),
              "{\n  \"formula\": {\n    \"deFactor\": 0.5,\n    \"iterations\": 6,\n    \"nodes\": []\n  }\n}\n");
    const std::string oneLine = R"({"formula": {"iterations": 6}, "camera": {}})";
    EXPECT_EQ(withNumberInPlace(oneLine, "formula", "deFactor", 0.25, "p.json"),
              R"({"formula": {"deFactor": 0.25, "iterations": 6}, "camera": {}})");
    EXPECT_EQ(withNumberInPlace(R"({"formula": {}})", "formula", "deFactor", 2, "p.json"),
              R"({"formula": {"deFactor": 2}})");
}

TEST(PresetTextEdit, KeysInsideStringsAndOtherSectionsAreLeftAlone) {
    const std::string text = R"({"editor": {"deFactor": 9}, "formula": {"name": "\"deFactor\": 3", "deFactor": 0.9}})";
    EXPECT_EQ(withNumberInPlace(text, "formula", "deFactor", 0.8, "p.json"),
              R"({"editor": {"deFactor": 9}, "formula": {"name": "\"deFactor\": 3", "deFactor": 0.8}})");
}

TEST(PresetTextEdit, BadFilesAreClearErrors) {
    const auto message = [](const std::string& text) {
        try {
            withNumberInPlace(text, "formula", "deFactor", 0.5, "p.json");
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("{\"formula\": ").find("p.json: not valid JSON"), std::string::npos);
    EXPECT_NE(message("{\"camera\": {}}").find("has no formula object"), std::string::npos);
    EXPECT_NE(message("[1, 2]").find("has no formula object"), std::string::npos);
    EXPECT_NE(message(R"({"formula": {"deFactor": "fast"}})").find("holds string, not a number"), std::string::npos);
}

TEST(PresetTextEdit, ReplacesTheLastElementOfAnArray) {
    const std::string text =
        "{\n  \"formula\": {\n    \"nodes\": [\n      {\"block\": \"abs_fold\", \"name\": \"]\"},\n"
        "      {\"block\": \"escape_linear\"}\n    ]\n  },\n  \"camera\": {\"nodes\": [1]}\n}\n";
    const nlohmann::json box = {{"block", "box"}, {"params", {{"size", {1.0, 2.0, 1.0}}}}};
    EXPECT_EQ(withLastElementInPlace(text, "formula", "nodes", box, "p.json"),
              "{\n  \"formula\": {\n    \"nodes\": [\n      {\"block\": \"abs_fold\", \"name\": \"]\"},\n"
              "      {\"block\": \"box\", \"params\": {\"size\": [1.0, 2.0, 1.0]}}\n    ]\n  },\n"
              "  \"camera\": {\"nodes\": [1]}\n}\n");
    const auto message = [&](const std::string& bad) {
        try {
            withLastElementInPlace(bad, "formula", "nodes", box, "p.json");
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"formula": {"nodes": []}})").find("p.json: the last element of formula.nodes"),
              std::string::npos);
    EXPECT_NE(message(R"({"formula": {"nodes": 3}})").find("no such array"), std::string::npos);
    EXPECT_NE(message(R"({"formula": )").find("not valid JSON"), std::string::npos);
}

// An overshooting factor: the check fails without --apply; with it the measured factor is written
// into the file, every other byte unchanged, and the check of the written file passes.
TEST(CheckApply, WritesTheMeasuredFactorAndKeepsTheRestOfTheFile) {
    const test::Sandbox dir("fraktal_check_apply");
    const std::filesystem::path preset = dir.path("menger.json");
    std::string text = fileText(test::sourceDir() / "presets/menger.json");
    text = withNumberInPlace(text, "formula", "deFactor", 2.0, "menger.json");  // overshoots
    std::ofstream(preset, std::ios::binary) << text;

    const test::CliRun plain = test::runCli("check " + preset.string());
    EXPECT_EQ(plain.exitCode, 1) << plain.output;
    EXPECT_EQ(fileText(preset), text);

    const test::CliRun apply = test::runCli("check --apply " + preset.string());
    ASSERT_EQ(apply.exitCode, 0) << apply.output;
    EXPECT_NE(apply.output.find("applied: formula.deFactor"), std::string::npos) << apply.output;
    const std::string written = fileText(preset);
    const double factor = loadPreset(preset).formula.deFactor;
    EXPECT_LT(factor, 1.01);
    EXPECT_GT(factor, 0.5);
    EXPECT_EQ(written, withNumberInPlace(text, "formula", "deFactor", factor, "menger.json"));
    // No temporary file is left beside it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.dir), std::filesystem::directory_iterator{}), 1);
    const test::CliRun again = test::runCli("check " + preset.string());
    EXPECT_EQ(again.exitCode, 0) << again.output;
}

TEST(CheckApply, RefusesWhatItCannotWrite) {
    const test::Sandbox dir("fraktal_check_apply_bad");
    const std::filesystem::path fractFile = dir.path("x.fract");
    std::ofstream(fractFile) << "# Mandelbulber settings file\n";
    const test::CliRun fract = test::runCli("check --apply " + fractFile.string());
    EXPECT_NE(fract.exitCode, 0);
    EXPECT_NE(fract.output.find("import the Mandelbulber2 file first"), std::string::npos) << fract.output;
    const test::CliRun plane =
        test::runCli("check --apply " + (test::sourceDir() / "presets/2d/mandelbrot.json").string());
    EXPECT_NE(plane.exitCode, 0);
    EXPECT_NE(plane.output.find("2D preset has no step factor"), std::string::npos) << plane.output;
    const test::CliRun frame =
        test::runCli("check --apply --frame 3 " + (test::sourceDir() / "presets/mandelbox_flythrough.json").string());
    EXPECT_NE(frame.exitCode, 0);
}

// A new user's stack (tests/slow_presets/twisted_kifs.json): a twist, an octahedral KIFS and the
// linear escape-time estimate an artist might pick, at bailout 1000. The twist's stretch bound grows with the orbit's
// radius and the running derivative multiplies it every iteration, so the estimate is under 2e-4 everywhere in the
// bound: every ray would stop at once.
std::string twistedKifs() {
    return fileText(std::filesystem::path(FRAKTAL_TEST_DIR) / "slow_presets/twisted_kifs.json");
}

// The check fails the useless estimate, leaves the file alone, and names the fit's estimator
// (a box at the smallest bailout that keeps the object) and the command that writes it.
TEST(CheckFit, AUselessEstimateFailsAndNamesTheEstimatorTheFitChooses) {
    const test::Sandbox dir("fraktal_check_useless");
    const std::filesystem::path preset = dir.path("twisted.json");
    std::ofstream(preset, std::ios::binary) << twistedKifs();
    const test::CliRun check = test::runCli("check " + preset.string());
    EXPECT_EQ(check.exitCode, 1) << check.output;
    EXPECT_NE(check.output.find("PROBLEM: the estimate is useless"), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("Estimator box at bailout"), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("fraktal check --fit --apply"), std::string::npos) << check.output;
    EXPECT_EQ(fileText(preset), twistedKifs());
}

// --fit --apply writes the fitted estimator, bailout, bound and the factor measured for them, and
// nothing else; the written preset passes the check and marches at a useful speed.
TEST(CheckFit, FitApplyWritesTheFittedFormulaAndKeepsTheRestOfTheFile) {
    const test::Sandbox dir("fraktal_check_fit");
    const std::filesystem::path preset = dir.path("twisted.json");
    std::ofstream(preset, std::ios::binary) << twistedKifs();
    const test::CliRun fit = test::runCli("check --fit --apply " + preset.string());
    ASSERT_EQ(fit.exitCode, 0) << fit.output;
    EXPECT_NE(fit.output.find("fit: estimator escape_linear -> box"), std::string::npos) << fit.output;

    const Preset written = loadPreset(preset);
    EXPECT_EQ(written.formula.estimator.block->id, "box");
    EXPECT_LT(written.formula.bailout, 1000.0);
    std::string expected = withLastElementInPlace(twistedKifs(), "formula", "nodes",
                                                  nodeToJson(written.formula.estimator), "twisted.json");
    expected = withNumberInPlace(expected, "formula", "bailout", written.formula.bailout, "twisted.json");
    expected = withNumberInPlace(expected, "formula", "boundRadius", written.formula.boundRadius, "twisted.json");
    expected = withNumberInPlace(expected, "formula", "deFactor", written.formula.deFactor, "twisted.json");
    EXPECT_EQ(fileText(preset), expected);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.dir), std::filesystem::directory_iterator{}), 1);

    const test::CliRun again = test::runCli("check " + preset.string());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    const std::smatch speed = [&] {
        std::smatch m;
        std::regex_search(again.output, m, std::regex("speed ([0-9.]+) \\(factor x median"));
        return m;
    }();
    ASSERT_EQ(speed.size(), 2u) << again.output;
    EXPECT_GT(std::stod(speed[1].str()), 0.1) << again.output;
}

}  // namespace
}  // namespace fraktal
