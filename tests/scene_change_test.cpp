// Every edit shows at once. The preset readers note every field they ask about (FieldLog in
// core/json_reader.hpp), present or absent, with what it accepts; these tests walk that list for
// every shipped 3D preset, so a field added to the format is covered without anyone adding it
// here. Each field is changed to another valid value and:
//   - the scene revision (core/scene/scene_revision.hpp), the one owner of "what changed", must
//     say so: a restart for what the image is rendered from, a reprojection for the camera's
//     pose, a redisplay for the display transform, nothing for what no render reads
//     (fieldsNoRenderReads, each with its reason);
//   - the editor's viewport, settled on the preset, must start again and settle to the image a
//     fresh open of the changed preset settles to (the fast mode, and the path tracer at rest for
//     the lights, environment, lens and path-tracing fields, which only it reads).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "app/editor/viewport/viewport_adapter.hpp"
#include "core/scene/scene_revision.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

using nlohmann::json;

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// "formula.nodes[2].params.scale" -> "formula.nodes[].params.*": one kind of field (every
// block parameter of a list reaches the renderer the same way).
std::string kindOf(const std::string& path) {
    const std::string unnumbered = std::regex_replace(path, std::regex(R"(\[\d+\])"), "[]");
    return std::regex_replace(unnumbered, std::regex(R"(\.params\.\w+$)"), ".params.*");
}

bool parses(const json& document, Preset* out = nullptr, FieldLog* log = nullptr) {
    try {
        Preset p = parsePreset(document.dump(), "changed", log);
        if (out) *out = std::move(p);
        return true;
    } catch (const PresetError&) {
        return false;
    }
}

// The preset's document with every optional object the readers asked about and that may be
// empty ({}: all its fields at their defaults) written out, until no new one appears, so that
// the fields inside sections and placements the file leaves out are asked about too. The
// preset it describes is the file's own.
json withOptionalSectionsSpelledOut(json document) {
    for (int round = 0; round < 8; ++round) {
        FieldLog log;
        if (!parses(document, nullptr, &log)) break;
        bool added = false;
        for (const FieldAsked& f : log) {
            if (f.kind != FieldAsked::Kind::Optional) continue;
            const json::json_pointer at(pointerFromPath(f.path));
            if (document.contains(at)) continue;
            json tried = document;
            tried[at] = json::object();
            if (parses(tried)) {
                document = std::move(tried);
                added = true;
            }
        }
        if (!added) break;
    }
    return document;
}

// The fields of a document, as its readers ask about them (the optional ones spelled out).
struct PresetFields {
    json document;
    std::vector<FieldAsked> fields;  // every leaf: not the optional objects
};

PresetFields fieldsOf(const std::filesystem::path& path) {
    PresetFields out;
    out.document = withOptionalSectionsSpelledOut(json::parse(readText(path)));
    FieldLog log;
    EXPECT_TRUE(parses(out.document, nullptr, &log)) << path;
    std::set<std::string> seen;
    for (FieldAsked& f : log)
        if (f.kind != FieldAsked::Kind::Optional && seen.insert(f.path).second) out.fields.push_back(std::move(f));
    return out;
}

// Other valid-looking values of a field, nearest first.
std::vector<json> otherValues(const FieldAsked& f) {
    std::vector<json> out;
    auto numbers = [&](double c, bool whole) {
        std::vector<double> tries =
            whole ? std::vector<double>{c + 1, c - 1, c + 2, c - 2, f.lo, f.hi}
                  : std::vector<double>{c * 1.1, c * 0.9, c + 0.1, c - 0.1, c + 1, c - 1, 0.5 * (f.lo + f.hi),
                                        f.lo,    f.hi};
        std::vector<double> kept;
        for (double v : tries)
            if (std::isfinite(v) && v >= f.lo && v <= f.hi && v != c) kept.push_back(v);
        return kept;
    };
    switch (f.kind) {
        case FieldAsked::Kind::Number:
        case FieldAsked::Kind::Integer:
            for (double v : numbers(f.value.get<double>(), f.kind == FieldAsked::Kind::Integer))
                out.push_back(f.kind == FieldAsked::Kind::Integer ? json(int(v)) : json(v));
            break;
        case FieldAsked::Kind::Boolean: out.push_back(!f.value.get<bool>()); break;
        case FieldAsked::Kind::Choice:
            for (const std::string& c : f.choices)
                if (c != f.value.get<std::string>()) out.push_back(c);
            break;
        case FieldAsked::Kind::String:
            // The same file by another path, or another string.
            out.push_back("./" + f.value.get<std::string>());
            out.push_back(f.value.get<std::string>() + " ");
            break;
        case FieldAsked::Kind::Vector:
            for (int i = 0; i < f.size; ++i)
                for (double v : numbers(f.value[size_t(i)].get<double>(), false)) {
                    json changed = f.value;
                    changed[size_t(i)] = v;
                    out.push_back(changed);
                }
            break;
        case FieldAsked::Kind::Optional: break;
    }
    return out;
}

// The document with the field changed to the first other value that still reads, and the
// preset it reads as; nullopt when none does.
struct Changed {
    json document;
    Preset preset;
    json value;
};
std::optional<Changed> change(const json& document, const FieldAsked& f, const Preset& original) {
    const json::json_pointer at(pointerFromPath(f.path));
    for (const json& v : otherValues(f)) {
        Changed c{document, {}, v};
        c.document[at] = v;
        if (!parses(c.document, &c.preset)) continue;
        // A value that reads back as the same preset (a direction scaled, say) is no change.
        if (serializePreset(c.preset) == serializePreset(original)) continue;
        return c;
    }
    return std::nullopt;
}

bool matches(const std::string& path, const std::string& prefix) {
    return path == prefix || path.rfind(prefix + ".", 0) == 0 || path.rfind(prefix + "[", 0) == 0;
}

enum class Expected { Nothing, Display, Camera, Restart };

Expected expectedFor(const std::string& path) {
    for (const scene::IgnoredField& f : scene::fieldsNoRenderReads())
        if (matches(path, f.path)) return Expected::Nothing;
    for (const char* p : {"colorManagement.display", "colorManagement.view", "colorManagement.exposure"})
        if (path == p) return Expected::Display;
    for (const char* p :
         {"camera.position", "camera.target", "camera.up", "camera.fovY", "camera.projection", "camera.flipVertical"})
        if (path == p) return Expected::Camera;
    return Expected::Restart;
}

// Only the path tracer at rest reads these: the viewport is tested on them in that mode.
bool pathTracerField(const std::string& path) {
    return matches(path, "lights") || matches(path, "environment") || matches(path, "pathTrace") ||
           matches(path, "camera.aperture") || matches(path, "camera.focusDistance") || matches(path, "camera.blades");
}

std::vector<std::filesystem::path> shipped3dPresets() { return test::shippedPresets(); }

TEST(SceneChange, TheRevisionSeesEveryFieldOfEveryShippedPreset) {
    std::map<std::string, int> kinds;  // kind of field -> fields changed
    int total = 0;
    for (const auto& path : shipped3dPresets()) {
        SCOPED_TRACE(path.filename().string());
        const PresetFields p = fieldsOf(path);
        Preset original;
        ASSERT_TRUE(parses(p.document, &original));
        // Spelling the optional sections out changes nothing.
        EXPECT_EQ(serializePreset(original), serializePreset(loadPreset(path)));
        const scene::SceneRevision before = scene::sceneRevision(original);
        int changed = 0, unchangeable = 0;
        for (const FieldAsked& f : p.fields) {
            SCOPED_TRACE(f.path);
            const std::optional<Changed> c = change(p.document, f, original);
            if (!c) {
                // Only a field whose every other value is refused by a rule across fields
                // (a direction that must not be zero is not one: other vectors are tried).
                ++unchangeable;
                std::printf("  %s: %s has no other value that reads\n", path.filename().c_str(), f.path.c_str());
                continue;
            }
            ++changed;
            ++kinds[kindOf(f.path)];
            const scene::SceneChange what = scene::sceneChange(&before, scene::sceneRevision(c->preset));
            switch (expectedFor(f.path)) {
                case Expected::Nothing: EXPECT_FALSE(what.any()) << "to " << c->value; break;
                case Expected::Display:
                    EXPECT_TRUE(what.display) << "to " << c->value;
                    EXPECT_FALSE(what.restarts() || what.camera) << "to " << c->value;
                    break;
                case Expected::Camera:
                    EXPECT_TRUE(what.camera) << "to " << c->value;
                    EXPECT_FALSE(what.restarts()) << "to " << c->value;
                    break;
                case Expected::Restart: EXPECT_TRUE(what.restarts()) << "to " << c->value; break;
            }
        }
        // Fields another field pins (the estimator's schedule, a phase under period 1, the focus
        // of a closed lens) have no other value that reads: a few per preset.
        EXPECT_LE(unchangeable * 4, changed) << "most fields have another value";
        std::printf("%s: %d fields changed (%d without another value that reads)\n", path.filename().c_str(), changed,
                    unchangeable);
        total += changed;
    }
    std::printf("%d fields of %zu kinds changed over %zu presets\n", total, kinds.size(), shipped3dPresets().size());
    // The kinds the format has beyond the shipped files' own: sections they leave out were asked about.
    EXPECT_TRUE(kinds.count("render.maxSteps") && kinds.count("shading.aoSteps") && kinds.count("camera.projection"));
}

// The editor's viewport on a preset and on a change of one field of it, at a size llvmpipe
// settles quickly.
struct ViewportRun {
    static constexpr int kW = 40, kH = 24;
    const ColorPipeline& color;
    editor::ViewSettings settings;

    ViewportRun(const ColorPipeline& c, bool pathTraced) : color(c) {
        settings.aaCap = 2;
        settings.stepsPerFrame = 400;
        settings.frameTimeTargetMs = 0.0;  // always full size: frames are what a still view shows
        settings.pathTraceAtRest = pathTraced;
        settings.pathSppCap = 1;
    }
    // Frames until the view settles (-1: it did not in 200).
    int settle(editor::ViewportView& v, const Preset& p) const {
        for (int frame = 1; frame <= 200; ++frame) {
            v.render(p, settings, kW, kH);
            if (v.stats().settled && !v.stats().compiling) return frame;
            if (!v.compileError().empty()) return -1;
        }
        return -1;
    }
    std::vector<uint8_t> shown(const editor::ViewportView& v) const {
        std::vector<uint8_t> pixels(size_t(kW) * kH * 4);
        glGetTextureImage(v.displayTexture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
        return pixels;
    }
};

double psnr8(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    if (sum == 0.0) return 99.0;
    return 10.0 * std::log10(255.0 * 255.0 / (sum / double(a.size())));
}

// One field of each kind (the first preset that has it): changed while the viewport rests, the
// viewport starts again (the frame after the change is not a continued one) and settles to the
// image a fresh open of the changed preset settles to.
TEST(SceneChange, TheSettledViewportStartsAgainAndShowsTheChangedPresetForEveryKindOfField) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    std::set<std::string> done;
    int fields = 0, compared = 0;
    for (const auto& path : shipped3dPresets()) {
        const PresetFields p = fieldsOf(path);
        Preset original;
        ASSERT_TRUE(parses(p.document, &original));
        std::vector<std::pair<FieldAsked, Changed>> todo;
        for (const FieldAsked& f : p.fields) {
            if (expectedFor(f.path) == Expected::Nothing || done.count(kindOf(f.path))) continue;
            std::optional<Changed> c = change(p.document, f, original);
            if (!c) continue;
            done.insert(kindOf(f.path));
            todo.emplace_back(f, std::move(*c));
        }
        if (todo.empty()) continue;
        for (bool pathTraced : {false, true}) {
            const ViewportRun run(color, pathTraced);
            std::unique_ptr<editor::ViewportView> view = editor::makeViewportView(color);
            view->setPresetFile(path.string());
            ASSERT_GT(run.settle(*view, original), 0) << path << " does not settle: " << view->compileError();
            for (const auto& [f, c] : todo) {
                if (pathTracerField(f.path) != pathTraced) continue;
                SCOPED_TRACE(path.filename().string() + ": " + f.path + " to " + c.value.dump());
                ++fields;
                // The changed preset, opened afresh.
                std::unique_ptr<editor::ViewportView> fresh = editor::makeViewportView(color);
                fresh->setPresetFile(path.string());
                const int freshFrames = run.settle(*fresh, c.preset);
                // The edit at rest.
                view->render(c.preset, run.settings, run.kW, run.kH);
                const editor::ViewportStats& after = view->stats();
                const Expected expected = expectedFor(f.path);
                const bool refused = !fresh->displayError().empty() || !fresh->compileError().empty();
                if (refused) {
                    // Checked below, after the edited view has had its frames.
                } else if (expected == Expected::Display) {
                    EXPECT_EQ(after.deEvaluationsPerPixel, 0.0) << "a display change renders nothing again";
                } else {
                    EXPECT_FALSE(std::string(after.action) == "continue" && after.settled && !after.pathTracing)
                        << "the settled viewport kept its image";
                    EXPECT_FALSE(after.pathTracing && after.pathSamples >= run.settings.pathSppCap && after.settled)
                        << "the path-traced image at rest was kept";
                }
                const int frames = run.settle(*view, c.preset);
                if (!fresh->displayError().empty() || !fresh->compileError().empty()) {
                    // A value the renderer refuses (an unknown colour space, say): the edited
                    // view says so too.
                    EXPECT_FALSE(view->displayError().empty() && view->compileError().empty())
                        << "a fresh open reports \"" << fresh->displayError() << fresh->compileError()
                        << "\"; the edited view reports nothing";
                } else if (freshFrames > 0) {
                    ASSERT_GT(frames, 0) << "the edited view does not settle: " << view->compileError();
                    const double db = psnr8(run.shown(*view), run.shown(*fresh));
                    EXPECT_GE(db, 40.0) << "the settled edit differs from a fresh open";
                    ++compared;
                } else {
                    ADD_FAILURE() << "a fresh open of the changed preset does not settle";
                }
                // Back to the preset, settled, for the next field.
                ASSERT_GT(run.settle(*view, original), 0);
            }
        }
    }
    std::printf("%d kinds of field changed at rest, %d compared with a fresh open\n", fields, compared);
    EXPECT_GT(compared, 50);
}

}  // namespace
}  // namespace fraktal
