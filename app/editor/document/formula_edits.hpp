// Edits of a formula's node list, as the formula panel performs them. Pure functions on the
// data, so the panel stays thin and the rules are unit-tested. Which edits need a recompile is
// decided by Formula::structureKey() alone, through the frame's scene::SceneRevision.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/preset.hpp"
#include "core/safe_step.hpp"

namespace fraktal::editor {

// All block ids of one category, in registry order (for the categorised "Add block" menu).
std::vector<const BlockDesc*> blocksIn(Category category);

// Each returns false (and leaves the formula alone) when the edit is not possible, e.g. an
// index out of range or kMaxNodes reached.
bool addNode(Formula& f, const BlockDesc& block, int insertAt = -1);  // -1: at the end
bool removeNode(Formula& f, int index);
bool duplicateNode(Formula& f, int index);    // the copy goes right after the original
bool moveNode(Formula& f, int from, int to);  // `to` is the index the node ends at
bool setNodeEnabled(Formula& f, int index, bool enabled);
// keeps nothing of the old one; a whole DE (BlockDesc::wholeDE) only closes an empty node list
bool setEstimator(Formula& f, const BlockDesc& estimator);
// Whether the formula's estimator is a whole DE (an imported frag): it takes no steps before it.
bool wholeDEFormula(const Formula& f);
// The same edits on a document's formula, keeping its animation's parameter tracks on the nodes
// they key (a removed or replaced node's tracks go with it).
bool addNode(Preset& p, const BlockDesc& block, int insertAt = -1);
bool removeNode(Preset& p, int index);
bool duplicateNode(Preset& p, int index);
bool moveNode(Preset& p, int from, int to);
bool setEstimator(Preset& p, const BlockDesc& estimator);
// Objects beside the fractal: one of `kind` at the end of the list (false at kMaxObjects), or
// object `index` removed (false out of range). They carry no animation tracks.
bool addObject(Formula& f, const ObjectDesc& kind);
bool removeObject(Formula& f, int index);
// What the "Add object" menu adds: a plane is a floor (floorPlane, with the bound grown by
// growBoundForFloor), every other kind is addObject's default object.
bool addObject(Preset& p, const ObjectDesc& kind);
// A plane under the fractal: its normal the camera's `up` (the up the editor shows), its surface
// just below the lowest point of what `f` already holds (lowestPointAlong), or at the bottom of
// the bound where that cannot be probed.
SceneObject floorPlane(const Formula& f, const vec3& up);
// The lowest point of the formula's surface along `up` (the smallest dot(point, up)), marched up
// in columns across the bound sphere with the CPU estimate; none when the formula has GLSL blocks
// the CPU cannot run or no column meets the surface. Planes already in `f` are left out: they fill
// the space below them.
std::optional<double> lowestPointAlong(const Formula& f, const vec3& up);
// Every marcher stops at the bound sphere, which cuts a plane down to a disc of the bound's size:
// under a fractal that fills the view, a coaster rather than a floor. The bound grows until the
// floor reaches kFloorReach times the camera's distance from the origin (and at least that many
// bound radii) out from the centre. The AO distance and fog density, measured in bound radii,
// are scaled back so that the fractal is shaded as before.
inline constexpr double kFloorReach = 3.0;
void growBoundForFloor(Preset& p, const SceneObject& floor);
// Whole fractals combined with the first (Formula::fractals). addFractal appends `source`'s own
// fractal, joined: its nodes, estimator, iterations, bailout, DE factor and placement; not its
// objects, the fractals combined with it, its bound or hit rule (the holding formula's apply).
// False at kMaxCombinedFractals or when `source` is not combinable(). removeFractal takes
// combined fractal `index` (0: the first combined one, the formula's fractal 2) out; false out of
// range.
bool addFractal(Formula& f, const Formula& source);
bool removeFractal(Formula& f, int index);
// Whether a formula's fractal can be combined into another formula: built-in blocks only, since
// custom GLSL blocks belong to the formula that defines them and would not resolve in another.
bool combinable(const Formula& source);
// The presets the "Add fractal" menu offers: each .json file of `folders` (in that order, sorted
// by name within each) that loads as a 3D preset with a combinable formula. Others (2D presets,
// broken files, custom blocks) are skipped.
struct FractalChoice {
    std::string name;  // the file's stem
    Formula formula;
};
std::vector<FractalChoice> combinableFractals(const std::vector<std::filesystem::path>& folders);
// Sets parameter `param` of node `index` (nodes.size() means the estimator), clamped to the
// declared range.
bool setParam(Formula& f, int index, int param, const ParamValue& value);
void resetParam(Formula& f, int index, int param);

// The formula's own GLSL blocks of one category (the "Add block" menu lists them after the
// built-in ones).
std::vector<const BlockDesc*> customBlocksIn(const Formula& f, Category category);
// The formula's custom block with this id, or null.
const CustomBlock* findCustomBlock(const Formula& f, std::string_view id);

// Adds a user's GLSL block to the formula, or replaces the one with the same id: every node
// that uses it is rebound to the new definition, keeping the values of parameters that still
// exist (clamped to their new range) and taking defaults for new ones. Returns the reason when
// the definition is not sound (CustomBlock::validate, or a category change of a block in use),
// leaving the formula alone; empty on success. A GLSL compile error shows later, at the node.
std::string upsertCustomBlock(Formula& f, CustomBlock::Definition definition);

// The step factor `fraktal check` measures (core/safe_step.hpp), applied after every change of
// structure so that a new stack never shows overshoot specks; a factor set by hand is kept
// (`overridden`) until the user hands it back to the check. An opened document keeps its own.
//
// It is measured in two parts, both on a worker thread. The settled rounds (options()) took 30-380
// ms over the shipped presets (two cores): on the main thread that froze the window at every
// structure edit, so the editor now holds the last image while they run (`measuring()`; the new
// structure's programs compile meanwhile) and applies their factor when they end. Where the rays'
// tail is heavy, the check goes on sampling up to 2048 rays (SafeStepOptions::tailRounds), which
// takes seconds: those further rounds follow on the worker (`refining()`), at a lower priority,
// and their factor, the one `fraktal check` reports, replaces the first when they end. A new
// structure, or the editor closing, stops either within a round.
// A worker thread's measurement gives way to the viewport's rendering, whose threads (llvmpipe's)
// share the cores: the calling thread's nice value is raised (Linux: it is per thread).
void yieldToRendering();

struct AutoStepFactor {
    std::string measuredKey;  // the structure the current factor belongs to
    bool overridden = false;
    double measured = 0.0;  // the last measured factor (0: none this session)
    double seconds = 0.0;   // how long measuring it took (wall time, the further rounds included)
    int rays = 0;           // how many rays it rests on
    // The last measurement met nothing to compare with: none of the check's rays reached the
    // object from outside it (sheets with no inside, a camera looking away). The factor is kept
    // rather than set to the 1 an empty sample would allow.
    bool noHits = false;
    // The last measurement found the estimate overshooting by more than the smallest factor a
    // preset may hold makes up for (dust, jumps): the smallest factor is applied and the panel
    // says the structure has no safe one. `worst` is the DE / true distance it saw at factor 1.
    bool noSafeFactor = false;
    double worst = 0.0;
    // The measured factor times the median DE / true distance per orbit (EstimatorMeasurement::
    // speed): the share of the gap a typical step covers (0: not measured).
    double speed = 0.0;
    // What was measured for each structure this session (at most kKnownStructures, the latest):
    // undo and redo bring a structure back with the factor measured for it then (restore()).
    struct Measured {
        double measured = 0.0, seconds = 0.0, worst = 0.0, speed = 0.0;
        int rays = 0;
        bool noHits = false, noSafeFactor = false;
        bool complete = false;  // no further rounds left (ended, or not called for)
        unsigned long order = 0;
    };
    static constexpr size_t kKnownStructures = 64;
    std::map<std::string, Measured> known;
    unsigned long knownOrder = 0;
    // The settled rounds for measuredKey, then its further rounds, while they run.
    std::future<EstimatorMeasurement> first{};
    std::future<EstimatorMeasurement> further{};
    std::chrono::steady_clock::time_point measuringSince{};
    // Workers of structures left behind, asked to stop: each ends within a round (up to about a
    // third of a second on two cores), and is joined once it has (reapStopped), so that an edit
    // never waits for the measurement it made obsolete. Each writes only to its own promise.
    struct StoppedWorker {
        std::jthread thread;
        std::shared_ptr<std::atomic<bool>> ended;
    };
    std::vector<StoppedWorker> stopped{};
    std::shared_ptr<std::atomic<bool>> workerEnded{};  // furtherWorker's
    std::jthread furtherWorker{};                      // last: destroyed (stopped and joined) before what it writes to

    // The settled rounds alone: the factor applied first.
    static SafeStepOptions options() {
        SafeStepOptions quick;
        quick.tailRounds = 0;
        return quick;
    }
    // `fraktal check`'s: its further rounds, on its finer baseline march.
    static SafeStepOptions checkOptions() {
        SafeStepOptions check;
        check.rays.stepsAcrossBound = ConservativenessOptions{}.stepsAcrossBound;
        return check;
    }
    // Takes f's factor as the one for its structure (an opened document).
    static AutoStepFactor adopting(const Formula& f);
    // Undo or redo brought back f, with the factor its state held (measured for its structure,
    // or the preset's own): when this session measured that structure to the end (or adopted it),
    // its figures are shown again and nothing is measured; otherwise (its further rounds were cut
    // short by the next edit) update() measures it again, and the caller folds the result into
    // the restored state (UndoHistory::amendPresent), recording no step. Stops the further
    // rounds of the structure left; those of the same structure (an undone value edit) go on.
    void restore(const Formula& f);
    // When f's structure differs from measuredKey: starts measuring its estimator from `camera`
    // on the worker (CPU; formulas with custom GLSL blocks keep their factor). When the settled
    // rounds have ended: unless overridden, sets f.deFactor to their factor (not when noHits) and
    // starts the further rounds where the tail calls for them. When the further rounds have
    // ended: applies their factor the same way. True when it applied a measurement. `structure`
    // is f.structureKey(), computed once a frame by the editor (the two-argument form computes it).
    bool update(Formula& f, const Camera& camera, const std::string& structure);
    bool update(Formula& f, const Camera& camera) { return update(f, camera, f.structureKey()); }
    // The settled rounds run: f.deFactor is still the previous structure's.
    bool measuring() const { return first.valid(); }
    // Any rounds run: the factor shown may still change.
    bool refining() const { return first.valid() || further.valid(); }
    // Workers of structures left, stopping: each is joined by the first update() after it ends.
    size_t stoppingWorkers() const { return stopped.size(); }

   private:
    void apply(const EstimatorMeasurement& m, Formula& f);
    void remember(bool complete);
    // Measures f from `camera` with `options` on furtherWorker, into `into`; lowered in priority
    // first when `yield`.
    void measureOnWorker(const Formula& f, const Camera& camera, SafeStepOptions options, bool yield,
                         std::future<EstimatorMeasurement>& into);
    void stopMeasuring();
    void reapStopped();
};

// The node index a compile-error log talks about (`node 3 "Box fold" (box_fold)...`, numbered
// from 1 as ShaderSource::explainLog writes it), or -1 when it names none. The estimator is index nodes.size().
// A log that first names a combined fractal's node (`fractal 2: node 3 "..."`) names none of the
// first fractal's: -1.
int nodeNamedInLog(const std::string& log, int nodeCount);

}  // namespace fraktal::editor
