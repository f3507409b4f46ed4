// What a renderer reads from a document, and what a change of it costs: the one place that says
// what changed between two frames. Every consumer (the viewport, the path tracer at rest, the
// resolution controller) compares revisions instead of keeping keys of its own, so a field added
// to the preset is seen by all of them at once (tests/scene_change_test.cpp walks every leaf of
// every shipped preset to keep it so).
//
// The revision is built from the preset's own serialization (presetToJson): whatever the format
// can hold is in it, and a field the writer knows cannot be forgotten here. It is split by cost:
//   structure  recompiles the formula's programs (Formula::structureKey);
//   values     restarts accumulation: parameter values, objects, combined fractals, placement,
//              custom blocks, shading, quality settings, lens, lights, environment, path tracing
//              and the working space;
//   camera     the pose and projection: the viewport reprojects;
//   display    display, view and exposure: applied at display only (like tev, the data stays
//              linear), nothing is rendered again.
// What no render reads is left out: the name and description, the animation's keys (renderers
// are given the document as evaluated at a frame), the editor's own section, and the export's
// image size and samples (the viewport has its own size and sample cap).
#pragma once

#include <string>

#include "core/camera.hpp"
#include "core/preset.hpp"

namespace fraktal::scene {

struct SceneRevision {
    std::string structure;
    std::string values;
    Camera camera;
    std::string display;
};

// What differs between two revisions. A structure change is also a values change (a recompiled
// formula restarts); every flag is set independently otherwise.
struct SceneChange {
    bool structure = false;  // recompile
    bool values = false;     // restart accumulation
    bool camera = false;     // reproject
    bool display = false;    // redisplay only
    bool any() const { return structure || values || camera || display; }
    bool restarts() const { return structure || values; }
};

SceneRevision sceneRevision(const Preset& preset);
// The same, with the formula's structure already computed this frame (the editor computes it once,
// after the panels that edit the node list, for the step factor and the viewport alike).
// `structure` must be preset.formula.structureKey() (checked where assertions are on).
SceneRevision sceneRevision(const Preset& preset, std::string structure);
// `before` null: everything changed (a first frame).
SceneChange sceneChange(const SceneRevision* before, const SceneRevision& after);

// The top-level preset sections and camera fields sceneRevision leaves out of `values` (and
// `display`), each with the reason: the leaf test lists them as the fields the viewport ignores on
// purpose.
struct IgnoredField {
    const char* path;  // a JSON pointer-like path: "render.width", "animation", ...
    const char* reason;
};
const std::vector<IgnoredField>& fieldsNoRenderReads();

}  // namespace fraktal::scene
