#include "app/editor/document/formula_edits.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <regex>

#include "core/animation.hpp"
#include "core/safe_step.hpp"

namespace fraktal::editor {

std::vector<const BlockDesc*> blocksIn(Category category) {
    std::vector<const BlockDesc*> out;
    for (const BlockDesc& b : allBlocks())
        if (b.category == category) out.push_back(&b);
    return out;
}

bool addObject(Formula& f, const ObjectDesc& kind) {
    if (int(f.objects.size()) >= kMaxObjects) return false;
    f.objects.push_back(SceneObject::make(kind));
    return true;
}

std::optional<double> lowestPointAlong(const Formula& f, const vec3& up) {
    if (!f.cpuEvaluable()) return std::nullopt;
    Formula solid = f;
    std::erase_if(solid.objects, [](const SceneObject& o) { return o.block && o.block->id == "plane"; });
    const vec3 u = normalize(up);
    const vec3 across = normalize(glm::cross(u, std::abs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    const vec3 along = glm::cross(u, across);
    const double radius = f.boundRadius, hit = 1e-3 * radius;
    std::optional<double> lowest;
    vec2 lowestColumn(0.0);
    // The column through (a, b) of the bound's disc across `up` (in bound radii), marched up from
    // the sphere's lower side. It gives up once it climbs above the lowest point found.
    const auto column = [&](double a, double b) {
        if (a * a + b * b >= 1.0) return;
        const double half = radius * std::sqrt(1.0 - a * a - b * b);
        const vec3 start = radius * (a * across + b * along) - half * u;
        double t = 0.0;
        for (int step = 0; step < 256 && t <= 2.0 * half; ++step) {
            const vec3 at = start + t * u;
            if (lowest && dot(at, u) >= *lowest) return;
            const double d = distanceEstimate(solid, at);
            if (d < hit) {
                lowest = dot(at, u);
                lowestColumn = vec2(a, b);
                return;
            }
            t += d;
        }
    };
    // 24 x 24 columns across the disc, then as many again across the cell of the lowest one
    // and its neighbours, twice, each time a twelfth as far apart: an edge or a tip pointing down
    // is found to a thousandth of the bound, not to the first grid's spacing.
    constexpr int kColumns = 24;
    double spacing = 2.0 / kColumns;
    for (int i = 0; i < kColumns; ++i)
        for (int j = 0; j < kColumns; ++j) column((i + 0.5) * spacing - 1.0, (j + 0.5) * spacing - 1.0);
    for (int round = 0; round < 2 && lowest; ++round) {
        const vec2 centre = lowestColumn;
        spacing *= 2.0 / kColumns;
        for (int i = -kColumns / 2; i < kColumns / 2; ++i)
            for (int j = -kColumns / 2; j < kColumns / 2; ++j)
                column(centre.x + (i + 0.5) * spacing, centre.y + (j + 0.5) * spacing);
    }
    return lowest;
}

SceneObject floorPlane(const Formula& f, const vec3& up) {
    SceneObject floor = SceneObject::make(*findObject("plane"));
    const vec3 u = length(up) > 0.0 ? normalize(up) : vec3(0.0, 1.0, 0.0);
    // The plane's normal is its frame's z: turn z onto `up` (about any axis across z when up is -z).
    const vec3 z(0.0, 0.0, 1.0);
    const vec3 axis = glm::cross(z, u);
    if (length(axis) > 1e-9) {
        floor.axis = normalize(axis);
        floor.angle = glm::degrees(std::acos(std::clamp(dot(z, u), -1.0, 1.0)));
    } else if (dot(z, u) < 0.0) {
        floor.axis = vec3(1.0, 0.0, 0.0);
        floor.angle = 180.0;
    }
    // A thousandth of the bound under the lowest point found (which is itself up to that much
    // above the surface): the fractal stands on the floor rather than sinking into it.
    const std::optional<double> lowest = lowestPointAlong(f, u);
    const double height = lowest ? *lowest - 2e-3 * f.boundRadius : -f.boundRadius;
    floor.center = height * u;
    return floor;
}

void growBoundForFloor(Preset& p, const SceneObject& floor) {
    Formula& f = p.formula;
    const double depth = std::abs(floor.distanceAt(vec3(0.0)));
    const double reach = kFloorReach * std::max(length(p.camera.position), f.boundRadius);
    // The Formula panel's bound slider ends at 100: stay within what it can show.
    const double wanted = std::min(std::sqrt(reach * reach + depth * depth), 100.0);
    if (wanted <= f.boundRadius) return;
    // Two significant digits up: the panel shows a round number.
    const double digits = std::pow(10.0, std::floor(std::log10(wanted)) - 1.0);
    const double bound = std::min(std::ceil(wanted / digits) * digits, 100.0);
    const double grow = bound / f.boundRadius;
    f.boundRadius = bound;
    p.shading.aoDistance = std::max(p.shading.aoDistance / grow, 1e-6);
    p.shading.fogDensity = std::min(p.shading.fogDensity * grow, 1e3);
}

bool addObject(Preset& p, const ObjectDesc& kind) {
    if (kind.id != "plane") return addObject(p.formula, kind);
    if (int(p.formula.objects.size()) >= kMaxObjects) return false;
    const SceneObject floor = floorPlane(p.formula, p.camera.up);
    p.formula.objects.push_back(floor);
    growBoundForFloor(p, floor);
    return true;
}

bool removeObject(Formula& f, int index) {
    if (index < 0 || index >= int(f.objects.size())) return false;
    f.objects.erase(f.objects.begin() + index);
    return true;
}

bool combinable(const Formula& source) {
    auto builtIn = [](const Node& n) { return n.block && !n.block->custom; };
    return source.customBlocks.empty() && builtIn(source.estimator) &&
           std::all_of(source.nodes.begin(), source.nodes.end(), builtIn);
}

bool addFractal(Formula& f, const Formula& source) {
    if (int(f.fractals.size()) >= kMaxCombinedFractals || !combinable(source)) return false;
    CombinedFractal c;
    c.formula.nodes = source.nodes;
    c.formula.estimator = source.estimator;
    c.formula.iterations = source.iterations;
    c.formula.bailout = source.bailout;
    c.formula.deFactor = source.deFactor;
    c.formula.placement = source.placement;
    f.fractals.push_back(std::move(c));
    return true;
}

bool removeFractal(Formula& f, int index) {
    if (index < 0 || index >= int(f.fractals.size())) return false;
    f.fractals.erase(f.fractals.begin() + index);
    return true;
}

std::vector<FractalChoice> combinableFractals(const std::vector<std::filesystem::path>& folders) {
    std::vector<FractalChoice> out;
    for (const std::filesystem::path& folder : folders) {
        std::error_code ec;
        std::vector<std::filesystem::path> files;
        for (const auto& e : std::filesystem::directory_iterator(folder, ec))
            if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const std::filesystem::path& file : files) {
            try {
                Preset p = loadPreset(file);  // throws for a 2D preset and a broken file
                if (combinable(p.formula)) out.push_back({file.stem().string(), std::move(p.formula)});
            } catch (const std::exception&) {
            }
        }
    }
    return out;
}

std::vector<const BlockDesc*> customBlocksIn(const Formula& f, Category category) {
    std::vector<const BlockDesc*> out;
    for (const auto& b : f.customBlocks)
        if (b->desc().category == category) out.push_back(&b->desc());
    return out;
}

const CustomBlock* findCustomBlock(const Formula& f, std::string_view id) {
    for (const auto& b : f.customBlocks)
        if (b->definition().id == id) return b.get();
    return nullptr;
}

namespace {

// The node for `block` with the values of `old` where a parameter of the same name and type
// survives, clamped to the new range.
Node rebind(const Node& old, const BlockDesc& block) {
    Node n = Node::make(block);
    n.enabled = old.enabled;
    n.schedule() = old.schedule();
    for (size_t i = 0; i < block.params.size(); ++i) {
        const int j = old.block->paramIndex(block.params[i].name);
        if (j < 0 || old.block->params[size_t(j)].type != block.params[i].type) continue;
        n.values[i] = glm::clamp(old.values[size_t(j)], vec3(block.params[i].min), vec3(block.params[i].max));
    }
    return n;
}

}  // namespace

std::string upsertCustomBlock(Formula& f, CustomBlock::Definition definition) {
    if (std::string why = CustomBlock::validate(definition); !why.empty()) return why;
    const CustomBlock* existing = findCustomBlock(f, definition.id);
    if (!existing && int(f.customBlocks.size()) >= kMaxCustomBlocks)
        return "more than " + std::to_string(kMaxCustomBlocks) + " custom blocks";
    const BlockDesc* oldDesc = existing ? &existing->desc() : nullptr;
    auto usedBy = [&](const Node& n) { return oldDesc && n.block == oldDesc; };
    const bool wasEstimator = oldDesc && oldDesc->isEstimator();
    const bool isEstimator = definition.category == Category::Estimator;
    if (oldDesc && wasEstimator != isEstimator &&
        (usedBy(f.estimator) || std::any_of(f.nodes.begin(), f.nodes.end(), usedBy)))
        return "category: the block is in use as " + std::string(wasEstimator ? "the estimator" : "a node") +
               "; remove it there first";
    std::shared_ptr<const CustomBlock> block = CustomBlock::make(std::move(definition));
    for (Node& n : f.nodes)
        if (usedBy(n)) n = rebind(n, block->desc());
    if (usedBy(f.estimator)) f.estimator = rebind(f.estimator, block->desc());
    if (existing) {
        for (auto& b : f.customBlocks)
            if (b.get() == existing) b = block;  // the old definition dies here, after the rebind
    } else {
        f.customBlocks.push_back(std::move(block));
    }
    return {};
}

namespace {
bool validIndex(const Formula& f, int i) { return i >= 0 && i < int(f.nodes.size()); }

Node* nodeAt(Formula& f, int index) {
    if (index == int(f.nodes.size())) return &f.estimator;
    return validIndex(f, index) ? &f.nodes[size_t(index)] : nullptr;
}
}  // namespace

bool addNode(Formula& f, const BlockDesc& block, int insertAt) {
    if (block.isEstimator()) return setEstimator(f, block);
    // A whole DE (an imported frag) is the whole formula: a step before it would never run, and
    // a preset holding one is refused.
    if (wholeDEFormula(f) || int(f.nodes.size()) >= kMaxNodes) return false;
    if (insertAt < 0 || insertAt > int(f.nodes.size())) insertAt = int(f.nodes.size());
    f.nodes.insert(f.nodes.begin() + insertAt, Node::make(block));
    return true;
}

bool removeNode(Formula& f, int index) {
    if (!validIndex(f, index)) return false;
    f.nodes.erase(f.nodes.begin() + index);
    return true;
}

bool duplicateNode(Formula& f, int index) {
    if (!validIndex(f, index) || int(f.nodes.size()) >= kMaxNodes) return false;
    const Node copy = f.nodes[size_t(index)];
    f.nodes.insert(f.nodes.begin() + index + 1, copy);
    return true;
}

bool moveNode(Formula& f, int from, int to) {
    if (!validIndex(f, from) || !validIndex(f, to) || from == to) return false;
    Node n = std::move(f.nodes[size_t(from)]);
    f.nodes.erase(f.nodes.begin() + from);
    f.nodes.insert(f.nodes.begin() + to, std::move(n));
    return true;
}

bool setNodeEnabled(Formula& f, int index, bool enabled) {
    if (!validIndex(f, index) || f.nodes[size_t(index)].enabled == enabled) return false;
    f.nodes[size_t(index)].enabled = enabled;
    return true;
}

bool wholeDEFormula(const Formula& f) { return f.estimator.block && f.estimator.block->wholeDE; }

bool setEstimator(Formula& f, const BlockDesc& estimator) {
    if (!estimator.isEstimator() || (estimator.wholeDE && !f.nodes.empty())) return false;
    f.estimator = Node::make(estimator);
    return true;
}

namespace {

// Old node i is at newIndexOf(i) after the edit (-1: removed).
template <typename Where>
void followNodes(Preset& p, size_t oldCount, Where newIndexOf) {
    std::vector<int> to(oldCount);
    for (size_t i = 0; i < oldCount; ++i) to[i] = newIndexOf(int(i));
    remapNodeTracks(p.animation, to, p.formula.nodes.size());
}

}  // namespace

bool addNode(Preset& p, const BlockDesc& block, int insertAt) {
    if (block.isEstimator()) return setEstimator(p, block);
    const size_t count = p.formula.nodes.size();
    if (insertAt < 0 || insertAt > int(count)) insertAt = int(count);
    if (!addNode(p.formula, block, insertAt)) return false;
    followNodes(p, count, [&](int i) { return i < insertAt ? i : i + 1; });
    return true;
}

bool removeNode(Preset& p, int index) {
    const size_t count = p.formula.nodes.size();
    if (!removeNode(p.formula, index)) return false;
    followNodes(p, count, [&](int i) { return i == index ? -1 : i < index ? i : i - 1; });
    return true;
}

bool duplicateNode(Preset& p, int index) {
    const size_t count = p.formula.nodes.size();
    if (!duplicateNode(p.formula, index)) return false;
    followNodes(p, count, [&](int i) { return i <= index ? i : i + 1; });
    return true;
}

bool moveNode(Preset& p, int from, int to) {
    const size_t count = p.formula.nodes.size();
    if (!moveNode(p.formula, from, to)) return false;
    followNodes(p, count, [&](int i) {
        if (i == from) return to;
        if (from < to && i > from && i <= to) return i - 1;
        if (to < from && i >= to && i < from) return i + 1;
        return i;
    });
    return true;
}

bool setEstimator(Preset& p, const BlockDesc& estimator) {
    if (!setEstimator(p.formula, estimator)) return false;
    dropEstimatorTracks(p.animation, p.formula.nodes.size());
    return true;
}

bool setParam(Formula& f, int index, int param, const ParamValue& value) {
    Node* n = nodeAt(f, index);
    if (!n || !n->block || param < 0 || param >= int(n->block->params.size())) return false;
    const ParamDecl& d = n->block->params[size_t(param)];
    ParamValue v = glm::clamp(value, vec3(d.min), vec3(d.max));
    if (isScalar(d.type)) v.y = v.z = 0.0;
    if (d.type == ParamType::Toggle) v.x = v.x > 0.5 ? 1.0 : 0.0;
    // A direction must not collapse to zero (the preset reader refuses that too).
    if (d.direction && glm::length(v) == 0.0) return false;
    n->values[size_t(param)] = v;
    return true;
}

void resetParam(Formula& f, int index, int param) {
    Node* n = nodeAt(f, index);
    if (!n || !n->block || param < 0 || param >= int(n->block->params.size())) return;
    n->values[size_t(param)] = n->block->params[size_t(param)].defaultValue;
}

int nodeNamedInLog(const std::string& log, int nodeCount) {
    // The first node or estimator the log names; one of a combined fractal carries its number.
    const std::regex named(R"((fractal \d+: )?(node (\d+) "|estimator "))");
    std::smatch m;
    if (!std::regex_search(log, m, named) || m[1].matched) return -1;
    if (m[3].matched) return std::stoi(m[3]) - 1;  // numbered from 1, as listed
    return nodeCount;
}

// On Linux a thread's nice value is its own (setpriority(2), NOTES).
void yieldToRendering() { setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10); }

void AutoStepFactor::apply(const EstimatorMeasurement& m, Formula& f) {
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - measuringSince).count();
    rays = m.report.rays;
    noHits = m.report.samples == 0;
    noSafeFactor = !hasSafeStepFactor(m);
    worst = m.report.worstRatio;
    speed = noHits || noSafeFactor ? 0.0 : m.speed();
    measured = noHits ? 0.0 : m.factor;
    if (!overridden && !noHits) {
        f.deFactor = measured;
        f.deFactorMeasuredFor = stepFactorTag(f);
    }
}

AutoStepFactor AutoStepFactor::adopting(const Formula& f) {
    AutoStepFactor a;
    // A factor never measured for this structure (a file written by hand or by another tool, or
    // edited in a text editor since) is measured as after a structure change: update() finds no
    // measured key and starts.
    if (!stepFactorMeasured(f)) return a;
    a.measuredKey = f.structureKey();
    a.remember(true);
    return a;
}

void AutoStepFactor::remember(bool complete) {
    if (known.size() >= kKnownStructures && !known.count(measuredKey))
        known.erase(std::min_element(known.begin(), known.end(),
                                     [](const auto& x, const auto& y) { return x.second.order < y.second.order; }));
    known[measuredKey] = {measured, seconds, worst, speed, rays, noHits, noSafeFactor, complete, ++knownOrder};
}

void AutoStepFactor::restore(const Formula& f) {
    std::string key = f.structureKey();
    if (key == measuredKey) return;  // the same structure: its measurement, ended or running, stands
    stopMeasuring();                 // the rounds measuring the structure left
    measuredKey = std::move(key);
    const auto it = known.find(measuredKey);
    if (it == known.end() || !it->second.complete) {
        measuredKey.clear();  // measured again by update()
        return;
    }
    const Measured& m = it->second;
    measured = m.measured, seconds = m.seconds, worst = m.worst, speed = m.speed;
    rays = m.rays, noHits = m.noHits, noSafeFactor = m.noSafeFactor;
}

void AutoStepFactor::stopMeasuring() {
    if (furtherWorker.joinable()) {
        furtherWorker.request_stop();
        stopped.push_back({std::move(furtherWorker), std::move(workerEnded)});
    }
    first = {};
    further = {};
}

void AutoStepFactor::reapStopped() {
    std::erase_if(stopped, [](const StoppedWorker& w) { return w.ended->load(); });  // joins at once
}

void AutoStepFactor::measureOnWorker(const Formula& f, const Camera& camera, SafeStepOptions options, bool yield,
                                     std::future<EstimatorMeasurement>& into) {
    stopMeasuring();  // a worker still running (none when the settled rounds have ended)
    std::promise<EstimatorMeasurement> result;
    into = result.get_future();
    workerEnded = std::make_shared<std::atomic<bool>>(false);
    furtherWorker = std::jthread(
        [f, camera, options, yield, ended = workerEnded, result = std::move(result)](std::stop_token stop) mutable {
            if (yield) yieldToRendering();
            SafeStepOptions stoppable = options;
            stoppable.stop = stop;
            try {
                result.set_value(measureSafeStep(f, camera, stoppable));
            } catch (...) {
                result.set_exception(std::current_exception());
            }
            *ended = true;
        });
}

namespace {
bool ended(const std::future<EstimatorMeasurement>& f) {
    return f.valid() && f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}
}  // namespace

bool AutoStepFactor::update(Formula& f, const Camera& camera, const std::string& structure) {
    reapStopped();
    if (structure == measuredKey) {
        if (ended(first)) {
            std::future<EstimatorMeasurement> settledRounds = std::move(first);
            furtherWorker = {};  // ended: joins at once
            EstimatorMeasurement m;
            try {
                m = settledRounds.get();
            } catch (const std::exception&) {
                remember(true);
                return false;  // the factor stays as it was
            }
            apply(m, f);
            const SafeStepOptions check = checkOptions();
            const bool settled = noHits || noSafeFactor || check.tailCovered(m.report, *f.estimator.block, f.nodes);
            remember(settled);
            // The check's rounds from the first: the sampling is seeded, so the factor is the one
            // `fraktal check` reports for this formula and camera. They give way to the rendering.
            if (!settled) measureOnWorker(f, camera, check, true, further);
            return true;
        }
        if (!ended(further)) return false;
        std::future<EstimatorMeasurement> furtherRounds = std::move(further);
        furtherWorker = {};  // ended: joins at once
        try {
            apply(furtherRounds.get(), f);
        } catch (const std::exception&) {
            remember(true);
            return false;  // the settled rounds' factor stays
        }
        remember(true);
        return true;
    }
    stopMeasuring();  // the rounds of the previous structure
    measuredKey = structure;
    if (!f.cpuEvaluable() || !f.estimator.block) return false;
    measuringSince = std::chrono::steady_clock::now();
    // At the editor's own priority: the view waits for this factor.
    measureOnWorker(f, camera, options(), false, first);
    return false;
}

}  // namespace fraktal::editor
