#include "core/import/fract_import.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <set>
#include <sstream>

#include "core/import/mb2_sequence.hpp"
#include "core/json_reader.hpp"

namespace fraktal::mb2 {

namespace {

// Mandelbulber2's closing DE function of a formula (fractal_list.cpp; the reference's T5).
// LinearXy: the linear DE on the distance to the z axis (pseudo_kleinian_std_de's r).
enum class Mb2De { Linear, Log, Ifs, PseudoKleinian, JosKleinian, Difs, DeltaLinear, DeltaLog, LinearXy, None };
// Whether Mandelbulber2 adds c after the formula by default (dont_add_c_constant flips it), or
// the formula adds its own.
enum class CAdd { Yes, No, Own };

struct FormulaInfo {
    int id;
    std::string_view name;
    Mb2De de;
    double bailout;  // the formula's default bailout (use_default_bailout)
    CAdd c;
};

// Every formula the Mandelbulber2 2.20 examples run (the reference's T5), by id.
constexpr FormulaInfo kFormulas[] = {
#include "core/import/mb2_formula_list.inc"
};

// Formulas after which Mandelbulber2 adds c with x and y exchanged.
constexpr int kAboxMod1Id = 64;
constexpr int kAmazingSurfId = 73;
// Formulas whose orbit fraktal runs in an estimator of its own (4D state).
constexpr int kHypercomplexId = 4;
constexpr int kAexionId = 19;
// The formulas that carry the point's fourth coordinate through fraktal's loop (formulas/four_d.hpp).
constexpr int kSierpinski4dId = 109, kMenger4dId = 111, kAbox4dId = 116, kQuaternion4dId = 79;
constexpr int kAmazingSurfMod2Id = 132, kAboxModKaliV2Id = 135, kAboxMod11Id = 119;
// Formulas whose 4D orbit a fraktal estimator runs whole (alone in a file).
bool runsOwnOrbit(int formula) { return formula == kHypercomplexId || formula == kAexionId; }
// Formulas whose steps carry the fourth coordinate through fraktal's loop.
bool carriesFourthCoordinate(int formula) {
    return formula == kMenger4dId || formula == kSierpinski4dId || formula == kAbox4dId || formula == kQuaternion4dId;
}
// Formulas whose derivative is 2 r DE alone: Mandelbulber2 adds c without the 1 it adds to the
// derivative (every formula takes its own +1, and these take none): QuaternionIteration,
// Quaternion3dIteration, BristorbrotIteration and Quaternion4dIteration (fractal_quaternion.cpp,
// fractal_quaternion3d.cpp, fractal_bristorbrot.cpp, fractal_quaternion4d.cpp of 2.20), and
// Mandelbulb3Iteration, MsltoeSym4ModIteration, MsltoeSym3Mod2Iteration and MsltoeSym3Mod3Iteration
// (fractal_formulas.cpp).
constexpr int kQuaternionId = 5, kBristorbrotId = 21, kQuaternion3dId = 62, kMandelbulb3Id = 14;
constexpr int kMsltoeSym4ModId = 69, kMsltoeSym3Mod2Id = 80, kMsltoeSym3Mod3Id = 81;
bool derivativeTakesNoOneForC(int formula) {
    return formula == kQuaternionId || formula == kBristorbrotId || formula == kQuaternion3dId ||
           formula == kQuaternion4dId || formula == kMandelbulb3Id || formula == kMsltoeSym4ModId ||
           formula == kMsltoeSym3Mod2Id || formula == kMsltoeSym3Mod3Id;
}

const FormulaInfo* findFormula(int id) {
    for (const FormulaInfo& f : kFormulas)
        if (f.id == id) return &f;
    return nullptr;
}

std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}
std::string fmt(const vec3& v) { return fmt(v.x) + " " + fmt(v.y) + " " + fmt(v.z); }

// The 3x3 rotation Mandelbulber2 builds from Euler angles in degrees (algebra.cpp): SetRotation2
// is Rz(z) Ry(y) Rx(x), SetRotation3 Rz(x) Ry(y) Rx(z); the matrix multiplies column vectors.
glm::dmat3 rotationZYX(double z, double y, double x) {
    const auto rz = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(z), vec3(0, 0, 1)));
    const auto ry = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(y), vec3(0, 1, 0)));
    const auto rx = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(x), vec3(1, 0, 0)));
    return rz * ry * rx;
}
glm::dmat3 setRotation2(const vec3& degrees) { return rotationZYX(degrees.z, degrees.y, degrees.x); }

// A rotation matrix as one turn about one axis (degrees in (-180, 180]; the axis z for none).
struct AxisAngle {
    vec3 axis{0, 0, 1};
    double degrees = 0.0;
};
AxisAngle axisAngle(const glm::dmat3& m) {
    const glm::dquat q = glm::quat_cast(m);
    double a = glm::degrees(glm::angle(q));
    if (std::abs(a) < 1e-9) return {};
    if (a > 180.0) a -= 360.0;
    return {normalize(glm::axis(q)), a};
}
glm::dmat3 setRotation3(const vec3& degrees) { return rotationZYX(degrees.x, degrees.y, degrees.z); }

// Reads a section's values with Mandelbulber2's defaults for what the file leaves out, and
// collects what the import cannot express.
class Reader {
   public:
    Reader(const FractFile& file, std::string section, bool main, std::string where,
           std::vector<ImportItem>& unsupported)
        : file_(file), section_(std::move(section)), main_(main), where_(std::move(where)), unsupported_(unsupported) {}

    const std::string& where() const { return where_; }
    const FractFile& file() const { return file_; }
    bool given(const std::string& key) const { return file_.find(section_, key) != nullptr; }

    std::string raw(const std::string& key) const {
        if (const FractEntry* e = file_.find(section_, key)) return e->value;
        if (const char* d = defaultValue(key, main_)) return d;
        throw std::logic_error("no Mandelbulber2 default for " + key);
    }
    double number(const std::string& key) const { return read(key, parseNumber(raw(key)), "a number"); }
    int integer(const std::string& key) const { return int(std::lround(number(key))); }
    vec3 vector(const std::string& key) const { return read(key, parseVector(raw(key)), "three numbers"); }
    glm::dvec4 vector4(const std::string& key) const { return read(key, parseVector4(raw(key)), "four numbers"); }
    bool boolean(const std::string& key) const { return read(key, parseBoolean(raw(key)), "true or false"); }
    vec3 colour(const std::string& key) const { return read(key, parseColour(raw(key)), "a 16-bit hex colour"); }

    // A switch or value fraktal cannot express: unsupported unless at Mandelbulber2's default.
    void mustBeDefault(const std::string& key, const std::string& why) {
        const std::string value = raw(key);
        const char* d = defaultValue(key, main_);
        if (!d || sameValue(value, d)) return;
        unsupported(key + " " + value + ": " + why);
    }
    void unsupported(const std::string& what) { unsupported_.push_back({where_, what}); }

   private:
    template <class T>
    T read(const std::string& key, const std::optional<T>& v, const char* expected) const {
        if (v) return *v;
        const FractEntry* e = file_.find(section_, key);
        throw PresetError(file_.source,
                          "[" + section_ + "] " + key + (e ? " (line " + std::to_string(e->line) + ")" : ""),
                          std::string("expected ") + expected + ", found \"" + raw(key) + "\"");
    }
    static bool sameValue(const std::string& a, const std::string& b) {
        if (a == b) return true;
        const auto ba = parseBoolean(a), bb = parseBoolean(b);
        if (ba && bb) return *ba == *bb;
        if (const auto na = parseNumber(a), nb = parseNumber(b); na && nb) return std::abs(*na - *nb) <= 1e-12;
        const auto va = parseVector(a), vb = parseVector(b);
        return va && vb && length(*va - *vb) <= 1e-12;
    }

    const FractFile& file_;
    std::string section_;
    bool main_;
    std::string where_;
    std::vector<ImportItem>& unsupported_;
};

// Builds nodes, checking each value against its block's declared range: a value outside it is
// unsupported (fraktal's blocks would refuse it), and clamped only so that a lenient import, which
// lists it as dropped, still writes a preset fraktal reads.
class NodeBuilder {
   public:
    NodeBuilder(Reader& reader, std::vector<Node>& out, int iterations = kMaxIterations)
        : reader_(reader), out_(out), iterations_(iterations) {}

    struct Value {
        std::string_view name;
        vec3 v;
    };
    using Values = std::vector<Value>;
    void add(std::string_view blockId, std::initializer_list<Value> values) { add(blockId, Values(values)); }
    void add(std::string_view blockId, const Values& values) {
        const BlockDesc* block = findBlock(blockId);
        if (!block) throw std::logic_error("no block " + std::string(blockId));
        Node n = Node::make(*block);
        n.start = windowStart_;
        n.stop = windowStop_;
        for (const Value& v : values) {
            const int i = block->paramIndex(v.name);
            if (i < 0) throw std::logic_error("block " + std::string(blockId) + " has no " + std::string(v.name));
            const ParamDecl& d = block->params[size_t(i)];
            const int components = isScalar(d.type) ? 1 : 3;
            for (int k = 0; k < components; ++k)
                if (!(v.v[k] >= d.min - 1e-9 && v.v[k] <= d.max + 1e-9)) {
                    reader_.unsupported(std::string(blockId) + "." + std::string(v.name) + " " +
                                        (components == 1 ? fmt(v.v.x) : fmt(v.v)) + " is outside fraktal's range [" +
                                        fmt(d.min) + ", " + fmt(d.max) + "]");
                    break;
                }
            vec3 value = v.v;
            for (int k = 0; k < components; ++k)
                value[k] = std::isfinite(value[k]) ? std::clamp(value[k], d.min, d.max) : d.defaultValue[k];
            if (d.direction && length(value) < 1e-9) value = d.defaultValue;
            n.values[size_t(i)] = value;
        }
        out_.push_back(std::move(n));
    }
    static Value f(std::string_view name, double x) { return {name, vec3(x, 0.0, 0.0)}; }
    static Value v(std::string_view name, const vec3& x) { return {name, x}; }

    // One `rotate` node for a rotation matrix (any rotation is one turn about one axis).
    void rotation(const glm::dmat3& m) {
        const AxisAngle turn = axisAngle(m);
        if (std::abs(turn.degrees) < 1e-9) return;
        add("rotate", {v("axis", turn.axis), f("angle", turn.degrees)});
    }

    // The nodes `steps` adds run only on iterations [start, stop) (a formula's own window,
    // transf_start/stop_iterations), within the window already open: none when the two do not
    // meet.
    template <class Steps>
    void within(int start, int stop, Steps&& steps) {
        start = std::max(start, windowStart_);
        stop = std::min(stop, windowStop_);
        if (start >= stop) return;
        const int outerStart = windowStart_, outerStop = windowStop_;
        windowStart_ = start;
        windowStop_ = stop;
        steps();
        windowStart_ = outerStart;
        windowStop_ = outerStop;
    }

   private:
    Reader& reader_;
    std::vector<Node>& out_;
    int windowStart_ = 0, windowStop_ = kMaxIterations;
    int iterations_;

   public:
    // The iterations the open window holds that the orbit runs (the formula's N caps them).
    int firstIteration() const { return windowStart_; }
    int lastIteration() const { return std::min(windowStop_, iterations_) - 1; }
};

using N = NodeBuilder;

// transf_rotation when `enabled` is on, over the iteration window start/stop (`suffix` names it:
// "" or "_R").
void windowedRotation(Reader& r, NodeBuilder& b, const std::string& enabled, const std::string& suffix) {
    if (!r.boolean(enabled)) return;
    b.within(r.integer("transf_start_iterations" + suffix), r.integer("transf_stop_iterations" + suffix),
             [&] { b.rotation(setRotation2(r.vector("transf_rotation"))); });
}

// The axes transf_function_enabledx/y/z turn on, as 1 or 0 per axis.
vec3 enabledAxes(Reader& r) {
    return vec3(r.boolean("transf_function_enabledx"), r.boolean("transf_function_enabledy"),
                r.boolean("transf_function_enabledz"));
}

// transf_addition_constant, added after the formula's step (nothing when it is zero).
void additionConstant(Reader& r, NodeBuilder& b) {
    const vec3 add = r.vector("transf_addition_constant");
    if (length(add) > 0.0) b.add("translate", {N::v("offset", add)});
}

// The analytic DE tweak behind analyticDE_enabled_false: the running derivative times
// analyticDE_scale_1 plus `offsetKey` (analyticDE_offset_0 or _1, as the formula reads it).
void analyticTweakWhereEnabled(Reader& r, NodeBuilder& b, const char* offsetKey) {
    if (r.boolean("analyticDE_enabled_false"))
        b.add("derivative_tweak", {N::f("scale", r.number("analyticDE_scale_1")), N::f("offset", r.number(offsetKey))});
}

// A multiple of c given per axis: fraktal's add_c has one weight; its x when the three agree.
double uniformMultiplier(Reader& r, const std::string& key) {
    const vec3 m = r.vector(key);
    if (m.x != m.y || m.y != m.z) r.unsupported(key + " " + fmt(m) + ": a per-axis multiple of c");
    return m.x;
}

// The steps `steps` adds, in the formula's window transf_start_iterations_<start> ..
// transf_stop_iterations_<stop>.
template <class Steps>
void inWindow(Reader& r, NodeBuilder& b, const std::string& start, const std::string& stop, Steps&& steps) {
    b.within(r.integer("transf_start_iterations_" + start), r.integer("transf_stop_iterations_" + stop), steps);
}

// The stretches of [from, to) over which each window of `windows` (suffixes of
// transf_start/stop_iterations_) either covers all or none: steps(start, stop, covered), covered[k]
// for windows[k]. Nothing where the range is empty.
template <class Steps>
void acrossWindows(Reader& r, int from, int to, const std::vector<std::string>& windows, Steps&& steps) {
    if (from >= to) return;
    std::vector<int> cuts{from, to};
    for (const std::string& w : windows)
        for (const char* edge : {"transf_start_iterations_", "transf_stop_iterations_"})
            if (const int at = r.integer(edge + w); at > from && at < to) cuts.push_back(at);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    auto coveredAt = [&](int i) {
        std::vector<bool> covered;
        for (const std::string& w : windows)
            covered.push_back(i >= r.integer("transf_start_iterations_" + w) &&
                              i < r.integer("transf_stop_iterations_" + w));
        return covered;
    };
    for (size_t k = 0; k + 1 < cuts.size();) {
        const std::vector<bool> covered = coveredAt(cuts[k]);
        size_t end = k + 1;
        while (end + 1 < cuts.size() && coveredAt(cuts[end]) == covered) ++end;
        steps(cuts[k], cuts[end], covered);
        k = end;
    }
}

// One scale_vary step: scale, vary and the limit at `limitKey`, whether it moves the offset, and
// Mandelbulber2's option M (transf_function_enabledM_false) as its reset.
void scaleVaryNode(Reader& r, NodeBuilder& b, double scale, double vary, const std::string& limitKey, bool update) {
    b.add("scale_vary",
          {N::f("scale", scale), N::f("vary", vary), N::f("limit", r.number(limitKey)),
           N::f("update", update ? 1.0 : 0.0), N::f("reset", r.boolean("transf_function_enabledM_false") ? 1.0 : 0.0)});
}

// A scale that reads the orbit's varying offset a (Mandelbulber2's aux.actualScaleA; formulas/
// scale_vary.hpp): a + scale in window `scaleWindow`. Where the formula varies it (transf_scale_vary_0
// not 0 and `varies`), a moves by vary (|a| - limit) after the scale in window `updateWindow` (reset
// to -vary (|a| - limit) with transf_function_enabledM_false). a is 0 until a step varies it, so
// a file whose formulas never vary it draws as with a plain scale.
void varyingScale(Reader& r, NodeBuilder& b, double scale, const std::string& scaleWindow,
                  const std::string& updateWindow, bool varies, const std::string& limitKey) {
    const double vary = varies ? r.number("transf_scale_vary_0") : 0.0;
    const std::vector<std::string> windows = vary == 0.0 ? std::vector<std::string>{} : std::vector{updateWindow};
    acrossWindows(
        r, r.integer("transf_start_iterations_" + scaleWindow), r.integer("transf_stop_iterations_" + scaleWindow),
        windows, [&](int start, int stop, const std::vector<bool>& covered) {
            b.within(start, stop, [&] { scaleVaryNode(r, b, scale, vary, limitKey, !covered.empty() && covered[0]); });
        });
}

// The pseudo-Kleinian formulas' prism fold in window P .. P1.
void prismFold(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_function_enabledP_false")) return;
    b.within(r.integer("transf_start_iterations_P"), r.integer("transf_stop_iterations_P1"), [&] {
        b.add("prism_fold",
              {N::f("scale", r.number("transf_scale")), N::v("gap", r.vector("transf_constant_multiplier_000"))});
    });
}

// The first iteration's sphere inversion of the Kleinian formulas: v + offset_000 inverted in the
// sphere of squared radius maxR2, then + `add` - offset_000.
void firstIterationInversion(Reader& r, NodeBuilder& b, const std::string& add) {
    if (!r.boolean("transf_sphere_inversion_enabled_false")) return;
    b.within(0, 1, [&] {
        const vec3 offset = r.vector("transf_offset_000");
        if (length(offset) > 0.0) b.add("translate", {N::v("offset", offset)});
        b.add("sphere_invert", {N::f("radius", std::sqrt(std::max(r.number("transf_maxR2_1"), 0.0)))});
        const vec3 back = r.vector(add) - offset;
        if (length(back) > 0.0) b.add("translate", {N::v("offset", back)});
    });
}

// The pseudo-Kleinian mods' Benesi T1 (window `t1Start` .. T_1) and Benesi box fold (D .. TM_1).
void benesiFolds(Reader& r, NodeBuilder& b, const std::string& t1Start) {
    if (r.boolean("transf_benesi_T1_enabled_false"))
        b.within(r.integer(t1Start), r.integer("transf_stop_iterationsT_1"), [&] {
            b.add("benesi_t1",
                  {N::v("scale", r.vector("transf_scale3D_222")), N::v("offset", r.vector("transf_offset_200"))});
        });
    if (r.boolean("transf_function_enabledx_false"))
        b.within(r.integer("transf_start_iterations_D"), r.integer("transf_stop_iterationsTM_1"), [&] {
            b.add("benesi_box_fold", {N::v("scale", r.vector("transf_scale3D_333")),
                                      N::v("limit", r.vector("transf_addition_constant_111"))});
        });
}

// The pseudo-Kleinian mods' clamp-style fold (window C) and its conditional form (B, the same map).
void pseudoKleinianFolds(Reader& r, NodeBuilder& b) {
    auto fold = [&] {
        b.add("pseudo_kleinian", {N::v("box_size", r.vector("transf_addition_constant_0777")),
                                  N::f("size", r.number("transf_minimum_radius_05"))});
    };
    if (r.boolean("transf_function_enabledAy")) inWindow(r, b, "C", "C", fold);
    if (r.boolean("transf_function_enabledAy_false")) inWindow(r, b, "B", "B", fold);
}

// A Menger step of Mandelbulber2's formulas (abs, sort, scale transf_scale_3, x and y less twice the
// corner, transf_constant_multiplierA_111 unless named, z only above 1): menger_rotate about corner
// 2 c / (s - 1). False, with the reason named, where fraktal's step cannot hold it.
bool mengerStepWithCorner(Reader& r, double& scale, vec3& offset,
                          const std::string& cornerKey = "transf_constant_multiplierA_111") {
    scale = r.number("transf_scale_3");
    const vec3 corner = r.vector(cornerKey);
    if (std::abs(corner.z - 1.0) > 1e-9)
        r.unsupported(cornerKey + ".z " + fmt(corner.z) + ": the z shift's threshold stays at 1");
    if (std::abs(scale - 1.0) < 1e-9) {
        r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
        return false;
    }
    offset = 2.0 * corner / (scale - 1.0);
    return true;
}

// Mandelbulber2's box fold at mandelbox_folding_limit with z's limit times transf_scale_1, in
// window A (fraktal's folds reflect at the limit: a folding value other than twice it is refused).
void boxFoldScaledZ(Reader& r, NodeBuilder& b) {
    const double limit = r.number("mandelbox_folding_limit"), value = r.number("mandelbox_folding_value");
    if (std::abs(value - 2.0 * limit) > 1e-9)
        r.unsupported("mandelbox_folding_value " + fmt(value) + " with mandelbox_folding_limit " + fmt(limit) +
                      ": fraktal's box fold reflects at the limit (value = 2 x limit)");
    inWindow(r, b, "A", "A", [&] {
        b.add("box_fold_axes",
              {N::v("limit", vec3(limit, limit, limit * r.number("transf_scale_1"))), N::f("fold_z", 1.0)});
    });
}

// ---- The formulas fraktal's blocks express (reference T5 "maps", T6 for each kernel) ----

// The sphere fold's inner radius: Mandelbulber2 files use 0 on purpose (no inner scaling), below
// fraktal's range, which starts at 0.001: that draws the same (an inner ball of radius 0.001).
// `offset` is Mandelbulber2's mandelbox_offset (the scaling about -offset, the radii from the
// origin), which only the formulas that read it pass.
void sphereFold(NodeBuilder& b, double minRadius, double fixedRadius, const vec3& offset = vec3(0.0)) {
    b.add("sphere_fold",
          {N::f("min_radius", std::max(minRadius, 0.001)), N::f("fixed_radius", fixedRadius), N::v("offset", offset)});
}

// The plane fold across axis `axis`'s plane at `offset`: the coordinate reflected where it lies
// below the offset (at 0, Mandelbulber2's z.x = fabs(z.x)).
void axisMirror(NodeBuilder& b, int axis, double offset = 0.0) {
    vec3 normal(0.0);
    normal[axis] = 1.0;
    b.add("plane_fold", {N::v("normal", normal), N::f("offset", offset)});
}

// Mandelbulber2's box fold at `limit` with its folding `value` (BoxFolding, MandelboxIteration):
// the box fold where the value is twice the limit, else the fold that jumps there.
void boxFold(NodeBuilder& b, double limit, double value) {
    if (std::abs(value - 2.0 * limit) <= 1e-9)
        b.add("box_fold", {N::f("limit", limit)});
    else
        b.add("box_fold_value", {N::f("limit", limit), N::f("value", value)});
}

void mapMandelbox(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    const double limit = r.number("mandelbox_folding_limit"), value = r.number("mandelbox_folding_value");
    if (std::abs(value - 2.0 * limit) > 1e-9 && r.boolean("mandelbox_rotations_enabled"))
        r.unsupported("mandelbox_folding_value " + fmt(value) + " with mandelbox_folding_limit " + fmt(limit) +
                      " and mandelbox_rotations_enabled: the tilted fold that does not reflect at its limit");
    if (r.boolean("mandelbox_rotations_enabled")) {
        // Each axis folds in tilted frames: at +limit in the frame R0 (mandelbox_rotation_neg_N),
        // else at -limit in R1 (_pos_N). The plane x . R0^T e = limit and then x . R1^T e = -limit;
        // the pair differs from the either-or where both fire (beyond 3 x limit, as a box fold).
        for (int axis = 0; axis < 3; ++axis) {
            vec3 e(0.0);
            e[axis] = 1.0;
            const std::string n = std::to_string(axis + 1);
            const vec3 n0 = glm::transpose(setRotation2(r.vector("mandelbox_rotation_neg_" + n))) * e;
            const vec3 n1 = glm::transpose(setRotation2(r.vector("mandelbox_rotation_pos_" + n))) * e;
            b.add("plane_fold", {N::v("normal", -n0), N::f("offset", -limit)});
            b.add("plane_fold", {N::v("normal", n1), N::f("offset", -limit)});
        }
        approximated.push_back({r.where(),
                                "the tilted box fold as two plane folds per axis (the same within 3 x "
                                "the limit)"});
    } else {
        boxFold(b, limit, value);
    }
    sphereFold(b, r.number("mandelbox_folding_min_radius"), r.number("mandelbox_folding_fixed_radius"),
               r.vector("mandelbox_offset"));
    if (r.boolean("mandelbox_main_rotation_enabled")) b.rotation(setRotation2(r.vector("mandelbox_rotation_main")));
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
}

// abox_mod1: |x| and |y| (and |z|, its limit times transf_scale_1, when transf_function_enabledz)
// reflected at mandelbox_folding_value (value - ||x| - value|); the sphere fold of squared radii
// transf_minimum_radius_0 and transf_maxR2_1; the scale; the rotation (window R). c follows with
// x and y exchanged.
void mapAboxMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_addition_constant", "a shift before the fold");
    r.mustBeDefault("transf_function_enabled_false", "the sphere fold on a power of r");
    r.mustBeDefault("mandelbox_vary_scale_vary", "a scale that varies with the iteration");
    r.mustBeDefault("transf_addCpixel_enabled_false", "an extra multiple of c in a chosen axis order");
    const bool foldZ = r.boolean("transf_function_enabledz");
    for (int k = 0; k < (foldZ ? 3 : 2); ++k) {
        axisMirror(b, k);
    }
    const double value = r.number("mandelbox_folding_value");
    b.add("box_fold_axes",
          {N::v("limit", vec3(value, value, value * r.number("transf_scale_1"))), N::f("fold_z", foldZ ? 1.0 : 0.0)});
    sphereFold(b, std::sqrt(std::max(r.number("transf_minimum_radius_0"), 0.0)),
               std::sqrt(std::max(r.number("transf_maxR2_1"), 0.0)));
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
    windowedRotation(r, b, "transf_rotation_enabled", "_R");
}

// generalized_fold_box: the box fold on the polyhedron of mandelbox_generalized_fold_type at
// mandelbox_solid, then the Mandelbox's sphere fold, main rotation and scale.
void mapGeneralizedFoldBox(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("mandelbox_melt", "a melted generalized fold (the reflection eased within the melt layer)");
    const int type = r.integer("mandelbox_generalized_fold_type");
    if (type < 0 || type > 7)
        r.unsupported("mandelbox_generalized_fold_type " + std::to_string(type) + ": Mandelbulber2 has types 0 to 7");
    b.add("generalized_box_fold", {N::f("type", type), N::f("solid", r.number("mandelbox_solid"))});
    sphereFold(b, r.number("mandelbox_folding_min_radius"), r.number("mandelbox_folding_fixed_radius"),
               r.vector("mandelbox_offset"));
    if (r.boolean("mandelbox_main_rotation_enabled")) b.rotation(setRotation2(r.vector("mandelbox_rotation_main")));
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
}

void mapMengerSponge(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    // abs, sort, z *= s, x and y less 2, z less 2 above 1: menger_rotate with the corner 2 / (s - 1).
    const double s = r.number("transf_scale_3");
    if (std::abs(s - 1.0) < 1e-9) return r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
    b.add("menger_rotate", {N::f("scale", s), N::v("offset", vec3(2.0 / (s - 1.0)))});
}

int axisOrder(Reader& r, const std::string& key);

// menger_middle_mod (MengerMiddleModIteration): |v + transf_addition_constantA_000| sorted, the main
// rotation (window C), Tglad's fold with its two limits and mirror (transf_addition_constant_111,
// transf_addition_constantA_111, transf_scale3D_111: option By) and transf_scaleA_1 after it
// (window B), the Menger scale transf_scale_3 (window S), x and y less 2
// transf_constant_multiplier_111 and z less its 2 z above 1 (or everywhere with
// transf_function_enabled off), then c per axis in xyz order (transf_addCpixel_enabled_false).
// The sphere inversion before it, the box fold (Bx), the fold with an axis off (its value then
// undefined in Mandelbulber2), the varying scale and c in another order are refused.
void mapMengerMiddleMod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_sphere_inversion_enabled_false", "the sphere inversion before the Menger step");
    r.mustBeDefault("transf_function_enabledBx_false", "the box fold after the Menger fold");
    r.mustBeDefault("transf_function_enabledF_false", "the scale varied with the iteration");
    r.mustBeDefault("analyticDE_enabled_false", "a tweak of the running derivative");
    const vec3 before = r.vector("transf_addition_constantA_000");
    if (length(before) > 0.0) b.add("translate", {N::v("offset", before)});
    b.add("abs_fold", {});
    b.add("menger_fold", {});
    if (r.boolean("mandelbox_main_rotation_enabled"))
        inWindow(r, b, "C", "C", [&] { b.rotation(setRotation2(r.vector("mandelbox_rotation_main"))); });
    if (r.boolean("transf_function_enabledBy_false")) {
        for (const char* axis : {"x", "y", "z", "Ax", "Ay", "Az"})
            if (!r.boolean(std::string("transf_function_enabled") + axis))
                return r.unsupported(std::string("transf_function_enabled") + axis +
                                     " false: Tglad's fold with a term left undefined");
        b.add("box_fold_general", {N::v("low", r.vector("transf_addition_constant_111")),
                                   N::v("high", r.vector("transf_addition_constantA_111")),
                                   N::v("mirror", r.vector("transf_scale3D_111")), N::v("offset", vec3(0.0))});
        const double after = r.number("transf_scaleA_1");
        if (after != 1.0) inWindow(r, b, "B", "B", [&] { b.add("scale", {N::f("scale", after)}); });
    }
    const double s = r.number("transf_scale_3");
    const vec3 m = r.vector("transf_constant_multiplier_111");
    if (r.boolean("transf_function_enabled")) {
        // z less 2 m.z only above 1: menger_scale with the corner 2 m / (s - 1), its threshold m.z.
        r.mustBeDefault("transf_start_iterations_S", "the Menger scale in a window, its z shift above 1 in all");
        r.mustBeDefault("transf_stop_iterations_S", "the Menger scale in a window, its z shift above 1 in all");
        if (std::abs(m.z - 1.0) > 1e-9)
            return r.unsupported("transf_constant_multiplier_111.z " + fmt(m.z) +
                                 ": the z shift's threshold stays at 1");
        if (std::abs(s - 1.0) < 1e-9)
            return r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
        b.add("menger_scale", {N::f("scale", s), N::v("offset", 2.0 * m / (s - 1.0))});
    } else {
        inWindow(r, b, "S", "S", [&] { b.add("scale", {N::f("scale", s)}); });
        b.add("translate", {N::v("offset", -2.0 * m)});
    }
    if (!r.boolean("transf_addCpixel_enabled_false")) return;
    if (axisOrder(r, "mandelbulbMulti_order_of_xyz_C") != 0)
        return r.unsupported("mandelbulbMulti_order_of_xyz_C " + r.raw("mandelbulbMulti_order_of_xyz_C") +
                             ": c's axes in an order other than xyz");
    b.add("add_c_axes", {N::v("weights", r.vector("transf_constant_multiplierC_111")), N::f("julia", 0.0)});
}

void mapMengerMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const double s = r.number("transf_scale_3");
    const vec3 m = r.vector("transf_constant_multiplier_111");
    if (std::abs(m.z - 1.0) > 1e-9)
        r.unsupported("transf_constant_multiplier_111.z " + fmt(m.z) + ": the z shift's threshold stays at 1");
    r.mustBeDefault("transf_function_enabledx_false", "the sign-dependent box offset");
    r.mustBeDefault("transf_function_enabled_false", "iteration weights");
    if (std::abs(s - 1.0) < 1e-9) return r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
    b.add("menger_rotate", {N::f("scale", s), N::v("offset", 2.0 * m / (s - 1.0))});
    windowedRotation(r, b, "transf_rotation_enabled", "");
    additionConstant(r, b);
}

// menger_octo (MengerOctoIteration of 2.20): in window E the octahedral fold (x+y, x+z, x-y and
// x-z reflected where negative: Knighty's octahedral KIFS), |x| and the scale transf_scale_2 about
// transf_offset_100 (the derivative times the scale, no 1 added); the rotation (option R, window
// R); with option M, in window M, the Menger step of scale transf_scale_3 (|z| sorted, x and y less
// 2 transf_constant_multiplier_111, z less its 2 z above 1) and transf_addition_constant after it;
// the iteration weights (option "enabled_false") as their scale transf_scale_1 where they carry no
// point of a named iteration. The sign-dependent box offset (option x) and the sphere fold (option
// S, whose test reads |z| before the offset it folds about) are refused.
void mapMengerOcto(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledx_false", "the sign-dependent box offset");
    r.mustBeDefault("transf_function_enabledS_false", "the octo step's sphere fold");
    inWindow(r, b, "E", "E", [&] {
        b.add("octahedral_fold", {});
        axisMirror(b, 0);
        b.add("scale", {N::f("scale", r.number("transf_scale_2")), N::v("center", r.vector("transf_offset_100"))});
    });
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    if (r.boolean("transf_function_enabledM")) {
        const double s = r.number("transf_scale_3");
        const vec3 m = r.vector("transf_constant_multiplier_111");
        if (std::abs(m.z - 1.0) > 1e-9)
            return r.unsupported("transf_constant_multiplier_111.z " + fmt(m.z) +
                                 ": the z shift's threshold stays at 1");
        if (std::abs(s - 1.0) < 1e-9)
            return r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
        inWindow(r, b, "M", "M", [&] {
            b.add("abs_fold", {});
            b.add("menger_fold", {});
            b.add("menger_scale", {N::f("scale", s), N::v("offset", 2.0 * m / (s - 1.0))});
            additionConstant(r, b);
        });
    }
    if (!r.boolean("transf_function_enabled_false")) return;
    if (r.number("transf_offsetA_0") != 0.0 || r.number("transf_offsetB_0") != 0.0)
        return r.unsupported("iteration weights: the point of iterations transf_int_A and transf_int_B added back");
    const double weight = r.number("transf_scale_1");
    if (weight <= 0.0) return r.unsupported("transf_scale_1 " + fmt(weight) + ": a weight of the point of 0 or below");
    if (weight != 1.0) b.add("scale", {N::f("scale", weight)});
}

// ifs_xy (IfsXYIteration of 2.20), each part in its window: the point less the box size
// transf_addition_constant_0555 (option Bx, window B); |x|, |y|, |z| (options Ax, Ay, Az,
// windows X, Y, Z); the polygonal fold of transf_int_3 sides (option Cx, window J); x and y
// swapped where y > x (option By, window D); the box size taken off again (option Bx, window I);
// x and y reflected where below transf_offset_0 and transf_offset_05 (options x and y, windows A
// and C); x less transf_offset_1 (window E) and y less transf_offsetA_1 (window F); the swap again
// (option By_false, window G); the scale transf_scale_2 with 1 added to the derivative, or
// analyticDE's scale and offset_1 (window S); transf_offset_111 added (window H); the turn
// transf_rotation (window R); analyticDE's closing tweak. The varying scale is refused.
void mapIfsXy(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledF_false", "the scale varied with the iteration");
    auto translate = [&](const std::string& window, const vec3& offset) {
        if (length(offset) > 0.0) inWindow(r, b, window, window, [&] { b.add("translate", {N::v("offset", offset)}); });
    };
    // The mirror across x = y: x and y swapped where y > x.
    auto swapXy = [&](const std::string& window) {
        inWindow(r, b, window, window, [&] {
            b.add("plane_fold", {N::v("normal", vec3(1.0, -1.0, 0.0)), N::f("offset", 0.0)});
        });
    };
    const vec3 box = r.vector("transf_addition_constant_0555");
    if (r.boolean("transf_function_enabledBx_false")) translate("B", -box);
    for (int k = 0; k < 3; ++k) {
        const std::string window(1, "XYZ"[k]);
        if (r.boolean(std::string("transf_function_enabledA") + "xyz"[k] + "_false"))
            inWindow(r, b, window, window, [&] { axisMirror(b, k); });
    }
    if (r.boolean("transf_function_enabledCx_false")) {
        const int sides = r.integer("transf_int_3");
        if (sides < 1 || sides > 32)
            return r.unsupported("transf_int_3 " + std::to_string(sides) +
                                 ": a polygonal fold of other than 1 to 32 sides");
        inWindow(r, b, "J", "J", [&] { b.add("poly_fold", {N::f("order", double(sides))}); });
    }
    if (r.boolean("transf_function_enabledBy")) swapXy("D");
    if (r.boolean("transf_function_enabledBx")) translate("I", -box);
    if (r.boolean("transf_function_enabledx_false"))
        inWindow(r, b, "A", "A", [&] { axisMirror(b, 0, r.number("transf_offset_0")); });
    if (r.boolean("transf_function_enabledy"))
        inWindow(r, b, "C", "C", [&] { axisMirror(b, 1, r.number("transf_offset_05")); });
    translate("E", vec3(-r.number("transf_offset_1"), 0.0, 0.0));
    translate("F", vec3(0.0, -r.number("transf_offsetA_1"), 0.0));
    if (r.boolean("transf_function_enabledBy_false")) swapXy("G");
    const bool tweak = r.boolean("analyticDE_enabled_false");
    inWindow(r, b, "S", "S", [&] {
        b.add("scale", {N::f("scale", r.number("transf_scale_2"))});
        b.add("derivative_tweak", {N::f("scale", tweak ? r.number("analyticDE_scale_1") : 1.0),
                                   N::f("offset", tweak ? r.number("analyticDE_offset_1") : 1.0)});
    });
    translate("H", r.vector("transf_offset_111"));
    if (length(r.vector("transf_rotation")) > 0.0)
        inWindow(r, b, "R", "R", [&] { b.rotation(setRotation2(r.vector("transf_rotation"))); });
    analyticTweakWhereEnabled(r, b, "analyticDE_offset_0");
}

// transf_poly_fold_sym_multi (TransfPolyFoldSymMultiIteration of 2.20): |x|, |y|, |z| (options
// x, y, z _false), then the symmetric polygonal fold of transf_int_6 sectors in the xy plane
// (option Cx), the yz plane (Cy_false) and the zx plane (Cz_false), each over the whole turn with
// its option A*_false; transf_addition_constant; analyticDE's scale and offset_0 (analyticDE_enabled,
// on by default, the identity at its defaults). The tweak by the point's average stretch
// (analyticDE_enabled_false) is refused.
void mapTransfPolyFoldSymMulti(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    for (int k = 0; k < 3; ++k) {
        if (!r.boolean(std::string("transf_function_enabled") + "xyz"[k] + "_false")) continue;
        axisMirror(b, k);
    }
    const int order = r.integer("transf_int_6");
    if (order < 1 || order > 32)
        return r.unsupported("transf_int_6 " + std::to_string(order) + ": a fold of other than 1 to 32 sectors");
    const struct {
        const char* enabled;
        const char* fullTurn;
    } planes[] = {{"transf_function_enabledCx", "transf_function_enabledAx_false"},
                  {"transf_function_enabledCy_false", "transf_function_enabledAy_false"},
                  {"transf_function_enabledCz_false", "transf_function_enabledAz_false"}};
    for (int k = 0; k < 3; ++k)
        if (r.boolean(planes[k].enabled))
            b.add("poly_fold_sym", {N::f("order", double(order)), N::f("plane", double(k)),
                                    N::f("full_turn", r.boolean(planes[k].fullTurn) ? 1.0 : 0.0)});
    additionConstant(r, b);
    if (!r.boolean("analyticDE_enabled")) return;
    if (r.boolean("analyticDE_enabled_false"))
        return r.unsupported("analyticDE_enabled_false: the derivative times the point's average stretch");
    const double scale = r.number("analyticDE_scale_1"), offset = r.number("analyticDE_offset_0");
    if (scale != 1.0 || offset != 0.0) b.add("derivative_tweak", {N::f("scale", scale), N::f("offset", offset)});
}

// transf_spherical_fold_parab (TransfSphericalFoldParabIteration of 2.20): with option S (window
// S) Mandelbulber2's sphere fold of squared radii transf_minR2_p25 and transf_maxR2_1; in the
// formula's window the parabolic fold (sphere_fold_parabolic) of transf_scale_4 at the centre over
// the squared radius transf_scale_1, its |p|^2 moved by transf_offset_0, after the shift
// mandelbox_offset and the scale transf_scale, with Mandelbulber2's derivative (the scale's 1
// added); then the scale transf_scaleA_1 with analyticDE's scale and offset_1 on the derivative
// (its 1 by default). The options that reflect m about |p|^2 (Ax; Ay of the sphere fold) and a
// scale varied with the iteration are refused.
void mapTransfSphericalFoldParab(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledAx_false", "the parabolic fold's m reflected about |p|^2");
    if (r.boolean("transf_function_enabledS_false")) {
        r.mustBeDefault("transf_function_enabledAy_false", "the sphere fold's m reflected about |p|^2");
        inWindow(r, b, "S", "S", [&] {
            sphereFold(b, std::sqrt(std::max(r.number("transf_minR2_p25"), 0.0)),
                       std::sqrt(std::max(r.number("transf_maxR2_1"), 0.0)));
        });
    }
    const double maxR2 = r.number("transf_scale_1");
    if (maxR2 < 0.01)
        return r.unsupported("transf_scale_1 " + fmt(maxR2) + ": a parabolic fold's squared radius below 0.01");
    b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), [&] {
        b.add("sphere_fold_parabolic",
              {N::f("max_scale", r.number("transf_scale_4")), N::f("max_r2", maxR2),
               N::f("r2_offset", r.number("transf_offset_0")), N::f("scale", r.number("transf_scale")),
               N::v("offset", r.vector("mandelbox_offset")), N::f("mb2_derivative", 1.0)});
    });
    if (r.boolean("transf_function_enabledX_false") && r.number("transf_scale_vary_0") != 0.0)
        return r.unsupported("transf_scale_vary_0 " + fmt(r.number("transf_scale_vary_0")) +
                             ": the scale varied with the iteration");
    const double scale = r.number("transf_scaleA_1");
    if (scale != 1.0) b.add("scale", {N::f("scale", scale)});
    b.add("derivative_tweak",
          {N::f("scale", r.number("analyticDE_scale_1")), N::f("offset", r.number("analyticDE_offset_1"))});
}

void mapKaleidoscopicIfs(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const bool ax = r.boolean("IFS_abs_x"), ay = r.boolean("IFS_abs_y"), az = r.boolean("IFS_abs_z");
    if (ax && ay && az) {
        b.add("abs_fold", {});
    } else {
        if (ax) b.add("plane_fold", {N::v("normal", vec3(1, 0, 0)), N::f("offset", 0.0)});
        if (ay) b.add("plane_fold", {N::v("normal", vec3(0, 1, 0)), N::f("offset", 0.0)});
        if (az) b.add("plane_fold", {N::v("normal", vec3(0, 0, 1)), N::f("offset", 0.0)});
    }
    for (int i = 0; i < 9; ++i) {
        const std::string n = std::to_string(i);
        if (!r.boolean("IFS_enabled_" + n)) continue;
        // Where the point lies under a plane, the plane moves it along its normal by 2 (distance -
        // length) times its intensity (2.20's KaleidoscopicIfsIteration, fractal_formulas.cpp): 1
        // reflects it, 0 leaves it where the plane's rotation put it; a fraction between is refused.
        const double intensity = r.number("IFS_intensity_" + n);
        if (intensity != 0.0 && intensity != 1.0) {
            r.unsupported("IFS_intensity_" + n + " " + r.raw("IFS_intensity_" + n) +
                          ": a partial reflection (fraktal reflects whole or not at all)");
            continue;
        }
        b.rotation(setRotation3(r.vector("IFS_rotations_" + n)));
        if (intensity == 0.0) continue;
        const vec3 dir = r.vector("IFS_direction_" + n);
        if (length(dir) < 1e-12) {
            r.unsupported("IFS_direction_" + n + " 0 0 0: a plane without a normal");
            continue;
        }
        b.add("plane_fold", {N::v("normal", normalize(dir)), N::f("offset", r.number("IFS_distance_" + n))});
    }
    const vec3 offset = r.vector("IFS_offset");
    if (r.boolean("IFS_rotation_enabled")) {
        const glm::dmat3 m = setRotation3(r.vector("IFS_rotation"));
        if (length(offset) > 0.0) b.add("translate", {N::v("offset", -offset)});
        b.rotation(m);
        if (length(offset) > 0.0) b.add("translate", {N::v("offset", offset)});
    }
    const vec3 edge = r.vector("IFS_edge");
    for (int k = 0; k < 3; ++k)
        if (edge[k] > 0.0) {
            vec3 normal(0.0);
            normal[k] = -1.0;
            b.add("plane_fold", {N::v("normal", normal), N::f("offset", -edge[k])});
        }
    const double s = r.number("IFS_scale");
    // z = s z - offset (s - 1): a scale about the offset; in Menger sponge mode z's shift applies
    // only above the middle layer.
    if (r.boolean("IFS_menger_sponge_mode"))
        b.add("menger_scale", {N::f("scale", s), N::v("offset", offset)});
    else
        b.add("scale", {N::f("scale", s), N::v("center", offset)});
}

void mapMandelbulb(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    // Mandelbulber2's offsets are degrees, added to the angles before the power (beta on the
    // latitude, alpha on the azimuth): the sine bulb's theta_offset and phi_offset.
    b.add("mandelbulb_sine", {N::f("power", r.number("power")), N::f("theta_offset", r.number("beta_angle_offset")),
                              N::f("phi_offset", r.number("alpha_angle_offset"))});
}

// mancoast's modulus Mandelbulb (2.20's ModulusMandelbulbIteration in fractal_formulas.cpp): the
// Mandelbulb's sine bulb with its angle offsets, then y replaced by its remainder after division by
// 2 (C's fmod, keeping y's sign); Mandelbulber2's derivative is the Mandelbulb's.
void mapModulusMandelbulb(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    mapMandelbulb(r, b, approximated);
    b.add("axis_remainder", {N::v("divisor", vec3(0.0, 2.0, 0.0))});
}

// The Mandelbulb whose power varies with the iteration (mandelbulb_vary_power_v1): the sine bulb of
// Mandelbulber2's power n before transf_start_iterations_250, n + transf_offset_0 (i - start) /
// (stop - start) on iteration i of [start, stop) (stop transf_stop_iterations), n +
// transf_offset_0 from stop on; one bulb a window. A ramp over more than 16 iterations is refused.
void mapMandelbulbVaryPowerV1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const double power = r.number("power"), offset = r.number("transf_offset_0");
    const int start = r.integer("transf_start_iterations_250"), stop = r.integer("transf_stop_iterations");
    auto bulb = [&](int from, int to, double n) {
        b.within(from, to, [&] {
            b.add("mandelbulb_sine", {N::f("power", n), N::f("theta_offset", r.number("beta_angle_offset")),
                                      N::f("phi_offset", r.number("alpha_angle_offset"))});
        });
    };
    if (offset == 0.0) return bulb(0, kMaxIterations, power);
    if (stop - start > 16)
        return r.unsupported("the power varied over " + std::to_string(stop - start) + " iterations");
    bulb(0, std::min(start, stop), power);
    for (int i = std::max(start, 0); i < stop; ++i) bulb(i, i + 1, power + offset * (i - start) / (stop - start));
    bulb(std::max(stop, 0), kMaxIterations, power + offset);
}

// The rotation whose angles vary with the iteration (2.20's TransfRotationVaryV1Iteration in
// fractal_formulas.cpp): transf_rotation (degrees about x, then y, then z) before
// transf_start_iterations_250, plus transf_offset_000 (i - start) / (stop - start) on iteration i of
// [start, stop) (stop transf_stop_iterations), plus transf_offset_000 from stop on; one rotation a
// window, as the varying power above.
void mapTransfRotationVaryV1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const vec3 angles = r.vector("transf_rotation"), offset = r.vector("transf_offset_000");
    const int start = r.integer("transf_start_iterations_250"), stop = r.integer("transf_stop_iterations");
    auto turn = [&](int from, int to, const vec3& degrees) {
        b.within(from, to, [&] { b.rotation(setRotation2(degrees)); });
    };
    // Mandelbulber2 varies nothing where the range is empty (stop = start).
    if (length(offset) == 0.0 || stop == start) return turn(0, kMaxIterations, angles);
    // A stop before the start: the whole offset from the start on.
    if (stop < start) {
        turn(0, start, angles);
        return turn(start, kMaxIterations, angles + offset);
    }
    // One node an iteration of the ramp: only those on iterations this slot runs are kept, and a ramp
    // that makes more nodes than fraktal holds is refused with the sequence (importFractal).
    turn(0, start, angles);
    for (int i = std::max(start, 0); i < stop; ++i)
        turn(i, i + 1, angles + offset * double(i - start) / double(stop - start));
    turn(std::max(stop, 0), kMaxIterations, angles + offset);
}

// White's power-2 triplex, z' = -2 z sqrt(x^2 + y^2): the latitude bulb of power 2, z mirrored.
void mapMandelbulbPower2(Reader&, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("mandelbulb_sine", {N::f("power", 2.0)});
    b.add("axis_scale", {N::v("scale", vec3(1.0, 1.0, -1.0))});
}

// White's power-2 triplex with z times the box_fold_bulb_pow2 formulas' z factor: the sine bulb of
// power 2, the factor's sign folded into its z mirror.
void whitePower2TimesZFactor(Reader& r, NodeBuilder& b) {
    b.add("mandelbulb_sine", {N::f("power", 2.0)});
    b.add("axis_scale", {N::v("scale", vec3(1.0, 1.0, -r.number("boxfold_bulbpow2_z_factor")))});
}

// Box fold at the folding factor, the fixed sphere fold (min radius 0.5, fixed 1), scale 2, White's
// power 2 and z times the z factor (its sign folded into the power's mirror).
void mapBoxFoldBulbPow2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("box_fold", {N::f("limit", r.number("boxfold_bulbpow2_folding_factor"))});
    sphereFold(b, 0.5, 1.0);
    b.add("scale", {N::f("scale", 2.0)});
    whitePower2TimesZFactor(r, b);
}

void mapXenodreambuie(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("alpha_angle_offset", "phase offsets on the bulb (part 2)");
    r.mustBeDefault("beta_angle_offset", "phase offsets on the bulb (part 2)");
    // theta = acos(|z| / r): the polar bulb of the point mirrored into z >= 0.
    b.add("plane_fold", {N::v("normal", vec3(0, 0, 1)), N::f("offset", 0.0)});
    b.add("mandelbulb_cosine", {N::f("power", r.number("power"))});
}

// The pseudo-Kleinian: the first iteration's sphere inversion (v + offset inverted in the sphere of
// squared radius maxR2, then + addA - offset), the prism fold (P), Tglad's fold (E; z's with
// transf_function_enabledBy) and the box fold (A; z's limit times transf_scale_1), the clamp fold
// and inversion, the rotation (R) and the added constant.
void mapPseudoKleinian(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    firstIterationInversion(r, b, "transf_addition_constantA_000");
    prismFold(r, b);
    if (r.boolean("transf_function_enabledBy_false"))
        b.within(r.integer("transf_start_iterations_E"), r.integer("transf_stop_iterations_E"), [&] {
            b.add("box_fold_axes", {N::v("limit", r.vector("transf_addition_constant_111")),
                                    N::f("fold_z", r.boolean("transf_function_enabledBy") ? 1.0 : 0.0)});
        });
    if (r.boolean("transf_function_enabledBx_false")) boxFoldScaledZ(r, b);
    b.add("pseudo_kleinian", {N::v("box_size", r.vector("transf_addition_constant_0777")),
                              N::f("size", r.number("transf_minimum_radius_05"))});
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    additionConstant(r, b);
}

void mapBenesi(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("benesi_pow2", {}); }
void mapBenesiPineTree(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("benesi_pine_tree",
          {N::v("multiplier", r.vector("transf_constant_multiplier_100")), N::f("angle", r.number("transf_angle_0"))});
}

// benesi_t1_pine_tree (BenesiT1PineTreeIteration of 2.20): Benesi's T1 transform (option
// transf_benesi_T1_enabled, in the formula's window: benesi_t1, and the 1 Mandelbulber2's
// derivative takes with it), then the pine tree's square with c added, y and z exchanged, times
// transf_constant_multiplier_100 (option transf_addCpixel_enabled, window C), the Julia offset
// transf_offset_000 (transf_constant_julia_mode) and the second rotation
// (transf_rotation2_enabled_false). The turn inside T1, c's axes exchanged anew each iteration and
// the cosine wrap of x by y are refused.
void mapBenesiT1PineTree(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_alternate_enabled_false", "c's axes exchanged anew each iteration");
    r.mustBeDefault("transf_function_enabledBx_false", "x wrapped by the cosine and sine of y");
    if (r.boolean("transf_benesi_T1_enabled")) {
        r.mustBeDefault("transf_rotation_enabled", "a rotation inside Benesi's frame");
        b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), [&] {
            b.add("benesi_t1",
                  {N::v("scale", r.vector("transf_scale3D_222")), N::v("offset", r.vector("transf_offset_200"))});
            b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)});
        });
    }
    if (r.boolean("transf_addCpixel_enabled"))
        inWindow(r, b, "C", "C",
                 [&] { b.add("benesi_pine_tree", {N::v("multiplier", r.vector("transf_constant_multiplier_100"))}); });
    if (r.boolean("transf_constant_julia_mode")) {
        const vec3 offset = r.vector("transf_offset_000");
        if (length(offset) > 0.0) b.add("translate", {N::v("offset", offset)});
    }
    if (r.boolean("transf_rotation2_enabled_false")) b.rotation(setRotation2(r.vector("transf_rotation2")));
}

void mapQuaternion3d(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("bristorbrot", {N::f("twist", 0.0)}); }
void mapBristorbrot(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("bristorbrot", {N::f("twist", 1.0)}); }

void mapIqBulb(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_pwr_8a", "a second power on the azimuth");
    b.add("mandelbulb", {N::f("power", r.number("transf_pwr_8"))});
}

// Tglad's fold of x and y (and z when `withZ`) at per-axis limits: one box fold when the limits
// agree, else the box fold per axis.
void tgladFold(Reader&, NodeBuilder& b, const vec3& limit, bool withZ, std::vector<ImportItem>&) {
    if (withZ && limit.x == limit.y && limit.y == limit.z) return b.add("box_fold", {N::f("limit", limit.x)});
    // Without z's fold its limit is unused (kept at 1, inside the block's range).
    b.add("box_fold_axes",
          {N::v("limit", vec3(limit.x, limit.y, withZ ? limit.z : 1.0)), N::f("fold_z", withZ ? 1.0 : 0.0)});
}

void mapAmazingSurfMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    for (const char* fold : {"transf_function_enabledAy_false", "transf_function_enabledAz_false",
                             "transf_function_enabledx_false", "transf_function_enabledy_false"})
        r.mustBeDefault(fold, "a fold type other than Tglad's");
    r.mustBeDefault("transf_function_enabled_false", "the cylinder fold");
    r.mustBeDefault("transf_scale_1", "a scale blended with 1");
    r.mustBeDefault("mandelbox_vary_scale_vary", "a scale that varies with the iteration");
    const vec3 limit = r.vector("transf_addition_constant_111"), add = r.vector("transf_addition_constant");
    // Mandelbulber2 compares r^2 with sqrt(minR): fraktal's inner radius is minR^(1/4).
    const double minRadius = std::pow(std::max(r.number("transf_minimum_radius_05"), 0.0), 0.25);
    const double scale = r.number("mandelbox_scale");
    if (r.boolean("transf_function_enabledAx") && length(add) == 0.0) {
        b.add("amazing_surf",
              {N::v("fold", vec3(limit.x, limit.y, 0.0)), N::f("min_radius", minRadius), N::f("scale", scale)});
    } else {
        if (r.boolean("transf_function_enabledAx")) tgladFold(r, b, limit, false, approximated);
        if (length(add) > 0.0) b.add("translate", {N::v("offset", add)});
        sphereFold(b, minRadius, 1.0);
        b.add("scale", {N::f("scale", scale)});
    }
    b.rotation(setRotation2(r.vector("transf_rotation")));
}

// Amazing Surf (Mandelbulber2 2.20's AmazingSurfIteration in fractal_formulas.cpp;
// formula/definition/fractal_amazing_surf.cpp in later versions): Tglad's fold of x and y, the
// sphere fold's factor m = scale / clamp(r^2, sqrt(minR), 1) of which the point takes the share
// transf_scale_1 ((m - 1) share + 1), c with x and y swapped times transf_constant_multiplier_111
// (transf_addCpixel_enabled_false), then the rotation. Share 1 is the amazing_surf block. Share 0
// leaves the point to the fold and the rotation (the nodes are written) but is refused, as Mandelbulber2
// still multiplies its derivative by |m|. Another share, and the cylinder fold's radius
// (transf_function_enabled_false, r^2 less z^2) beside share 1, are refused.
void mapAmazingSurf(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("mandelbox_vary_scale_vary", "a scale that varies with the iteration");
    const double share = r.number("transf_scale_1");
    const vec3 limit = r.vector("transf_addition_constant_111");
    if (share == 1.0) {
        r.mustBeDefault("transf_function_enabled_false", "the cylinder fold");
        // Mandelbulber2 compares r^2 with sqrt(minR): fraktal's inner radius is minR^(1/4).
        const double minRadius = std::pow(std::max(r.number("transf_minimum_radius_05"), 0.0), 0.25);
        b.add("amazing_surf", {N::v("fold", vec3(limit.x, limit.y, 0.0)), N::f("min_radius", minRadius),
                               N::f("scale", r.number("mandelbox_scale"))});
    } else if (share == 0.0) {
        tgladFold(r, b, limit, false, approximated);
        // Mandelbulber2's derivative still takes |m| whole, so its linear estimate shrinks by the
        // scale each iteration while the point does not: its surface is a level set of that
        // estimate far outside the orbit's set, which fraktal's derivative (the point's) cannot draw.
        r.unsupported(
            "transf_scale_1 0: the point takes none of the sphere fold's factor, which "
            "Mandelbulber2's derivative takes whole");
    } else {
        r.unsupported("transf_scale_1 " + r.raw("transf_scale_1") + ": a sphere fold's factor blended with 1");
    }
    if (r.boolean("transf_addCpixel_enabled_false"))
        b.add("add_c_axes",
              {N::v("weights", r.vector("transf_constant_multiplier_111")), N::f("julia", 0.0), N::f("swap_xy", 1.0)});
    b.rotation(setRotation2(r.vector("transf_rotation")));
}

void mapAboxVsIcen1(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("mandelbox_vary_scale_vary", "a scale that varies with the iteration");
    const double m = uniformMultiplier(r, "transf_constant_multiplier_111");
    const vec3 juliaC = r.vector("transf_constant_julia_c");
    const bool julia = r.boolean("transf_constant_julia_mode");
    tgladFold(r, b, r.vector("transf_addition_constant_111"), true, approximated);
    if (julia) {
        b.add("add_c", {N::f("weight", m)});
    } else if (length(juliaC) > 0.0) {
        b.add("translate", {N::v("offset", juliaC)});
    }
    sphereFold(b, r.number("mandelbox_folding_min_radius"), r.number("mandelbox_folding_fixed_radius"));
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
    windowedRotation(r, b, "transf_rotation_enabled", "");
    // Julia mode: z += julia_c - m c; otherwise z += m c + julia_c.
    b.add("add_c", {N::f("weight", julia ? -m : m)});
    if (length(juliaC) > 0.0) b.add("translate", {N::v("offset", juliaC)});
}

// The sphere fold of squared radii transf_minR2_p25 (inner) and transf_maxR2_1 (fixed).
void squaredRadiiSphereFold(Reader& r, NodeBuilder& b, const vec3& offset = vec3(0.0)) {
    sphereFold(b, std::sqrt(std::max(r.number("transf_minR2_p25"), 0.0)),
               std::sqrt(std::max(r.number("transf_maxR2_1"), 0.0)), offset);
}

// Mandelbulber2's Cpara curve at iteration i, as the quadratic a + b i + c i^2 it is there
// (fractal_formulas.cpp AboxMod11Iteration, PseudoKleinianMod2Iteration; its linear part and
// "curves" read as written there, the curves' breaks at paraA and paraB included): the linear
// stretches through para00, paraA, paraB and paraC at iterations 0, iterA, iterB and iterC, the
// curves where iterB - iterA > 2 iterA, and the parabola parab_offset0 + slope i + 0.001 scale i^2.
struct Quadratic {
    double a = 0.0, b = 0.0, c = 0.0;
    bool operator==(const Quadratic&) const = default;
    Quadratic operator+(const Quadratic& o) const { return {a + o.a, b + o.b, c + o.c}; }
    // (a + b i)^2 times k: the curves' square of a linear function of i.
    static Quadratic squaredTimes(double a, double b, double k) { return {k * a * a, k * 2.0 * a * b, k * b * b}; }
};
Quadratic cparaAt(Reader& r, int i) {
    Quadratic q;
    if (r.boolean("Cpara_enabledLinear")) {
        const double p0 = r.number("Cpara_para00"), pA = r.number("Cpara_paraA"), pB = r.number("Cpara_paraB"),
                     pC = r.number("Cpara_paraC");
        const double iA = r.integer("Cpara_iterA"), iB = r.integer("Cpara_iterB"), iC = r.integer("Cpara_iterC");
        const double lengthAB = iB - iA, lengthBC = iC - iB;
        const double grade1 = (pA - p0) / iA, grade2 = (pB - pA) / lengthAB, grade3 = (pC - pB) / lengthBC;
        q = {p0, 0.0, 0.0};
        if (i < iA) q = {p0, grade1, 0.0};
        if (i < iB && i >= iA) q = {pA - iA * grade2, grade2, 0.0};
        if (i >= iB) q = {pB - iB * grade3, grade3, 0.0};
        if (r.boolean("Cpara_enabledCurves") && lengthAB > 2.0 * iA) {
            const double tempL = lengthAB - iA;
            const double curve1 = (grade2 - grade1) / (4.0 * iA), curve2 = (grade3 - grade2) / (4.0 * tempL);
            if (i < 2 * iA)  // paraIt = paraA - |paraA - i|
                q = q + (i <= pA ? Quadratic::squaredTimes(0.0, 1.0, curve1)
                                 : Quadratic::squaredTimes(2.0 * pA, -1.0, curve1));
            if (i >= 2 * iA && i < iB + tempL)  // paraIt = paraB - |paraB i|
                q = q + Quadratic::squaredTimes(pB, -std::abs(pB), curve2);
        }
    }
    if (r.boolean("Cpara_enabledParab_false"))
        q = q + Quadratic{r.number("Cpara_parab_offset0"), r.number("Cpara_parab_slope"),
                          0.001 * r.number("Cpara_parab_scale")};
    return q;
}

// The sphere fold of squared radii whose inner one follows the Cpara curve when `varies` (the
// formula's transf_function_enabledy_false): one sphere_fold per stretch of the open window's
// iterations on which the curve is one quadratic (its growth and curve parameters), the curve plus
// transf_minR2_p25 being the squared inner radius. Refused: a curve undefined on an iteration the
// orbit runs (iterA, iterB - iterA or iterC - iterB of 0 where its stretch is used), and a squared
// inner radius below 0 or above transf_maxR2_1 (where Mandelbulber2's fold shrinks the point).
void cparaSphereFold(Reader& r, NodeBuilder& b, bool varies, const vec3& offset) {
    if (!varies) return squaredRadiiSphereFold(r, b, offset);
    const double minR2 = r.number("transf_minR2_p25"), maxR2 = r.number("transf_maxR2_1");
    int from = b.firstIteration();
    Quadratic run = cparaAt(r, from);
    auto fold = [&](int to) {
        if (!std::isfinite(run.a) || !std::isfinite(run.b) || !std::isfinite(run.c))
            return r.unsupported("Cpara: a curve undefined at iteration " + std::to_string(from) +
                                 " (two of Cpara_iterA, _iterB, _iterC meet)");
        const double base = minR2 + run.a;
        // fraktal's fold keeps its inner radius within the fixed one, where Mandelbulber2's shrinks
        // a point inside it (rf^2 / rm^2 < 1); and its squared inner radius above 0, at iteration 0 too.
        for (int i = from; i < to; ++i)
            if (const double rm2 = base + (run.b + run.c * i) * i; rm2 < 0.0 || rm2 > maxR2)
                return r.unsupported("Cpara: a squared inner radius of " + fmt(rm2) + " at iteration " +
                                     std::to_string(i) + ", outside [0, transf_maxR2_1 " + fmt(maxR2) + "]");
        if (base < 0.0)
            return r.unsupported("Cpara: a squared inner radius of " + fmt(base) + " at iteration 0 of its curve, " +
                                 "below 0 (fraktal's inner radius is measured from there)");
        b.within(from, to, [&] {
            b.add("sphere_fold", {N::f("min_radius", std::sqrt(std::max(base, 1e-6))),
                                  N::f("fixed_radius", std::sqrt(std::max(maxR2, 0.0))), N::v("offset", offset),
                                  N::f("min_r2_growth", run.b), N::f("min_r2_curve", run.c)});
        });
    };
    for (int i = from + 1; i <= b.lastIteration(); ++i) {
        const Quadratic q = cparaAt(r, i);
        if (q == run) continue;
        fold(i);
        from = i;
        run = q;
    }
    if (from <= b.lastIteration()) fold(b.lastIteration() + 1);
}

// Mandelbulber2's "addCpixel" section of a formula (transf_addCpixel_enabled_false): c times
// transf_constant_multiplier_111 per axis, in the iteration window `window`, c's axes in
// mandelbulbMulti_order_of_xyz (xyz, or yxz as add_c_axes' swap_xy). Where `turnWindow` is given
// and transf_rotation_enabled is on, c is turned by transf_rotation on that window's iterations
// first (amazing_surf_mod2). Its "alternate" form, which keeps the reordered c for the next
// iteration, is refused. turnedMultipleOfC adds it on iterations [start, stop), turned in
// `turnWindow` where `turns`; extraMultipleOfC where the option says.
void turnedMultipleOfC(Reader& r, NodeBuilder& b, int start, int stop, const std::string& turnWindow, bool turns) {
    r.mustBeDefault("transf_alternate_enabled_false", "c's axes reordered anew each iteration");
    const std::string order = r.raw("mandelbulbMulti_order_of_xyz");
    const bool swapXy = order == "2" || order == "yxz";
    if (!swapXy && order != "0" && order != "xyz")
        return r.unsupported("mandelbulbMulti_order_of_xyz " + order + ": c's axes in an order other than xyz or yxz");
    const AxisAngle turn = turns ? axisAngle(setRotation2(r.vector("transf_rotation"))) : AxisAngle{};
    acrossWindows(r, start, stop, turns ? std::vector{turnWindow} : std::vector<std::string>{},
                  [&](int start, int stop, const std::vector<bool>& covered) {
                      const bool turned = !covered.empty() && covered[0];
                      b.within(start, stop, [&] {
                          b.add("add_c_axes", {N::v("weights", r.vector("transf_constant_multiplier_111")),
                                               N::f("julia", 0.0), N::f("swap_xy", swapXy ? 1.0 : 0.0),
                                               N::v("turn_axis", turned ? turn.axis : vec3(0, 0, 1)),
                                               N::f("turn_angle", turned ? turn.degrees : 0.0)});
                      });
                  });
}
void extraMultipleOfC(Reader& r, NodeBuilder& b, const std::string& window, const std::string& turnWindow = "") {
    if (!r.boolean("transf_addCpixel_enabled_false")) return;
    turnedMultipleOfC(r, b, r.integer("transf_start_iterations_" + window),
                      r.integer("transf_stop_iterations_" + window), turnWindow,
                      !turnWindow.empty() && r.boolean("transf_rotation_enabled"));
}
// transf_add_cpixel_rotated (TransfAddCpixelRotatedIteration of 2.20): c in its axis order, turned
// by transf_rotation in window G, times transf_constant_multiplier_111, on every iteration of the
// slot.
void mapTransfAddCpixelRotated(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    turnedMultipleOfC(r, b, 0, kMaxIterations, "G", true);
}

// The multiple of c signed by the point (transf_addCpixel_enabled_false: Mandelbulber2's "add
// Cpixel symmetrical"): v + sign(v) k, k = c times `weights` per axis with c's abs taken on the
// axes transf_function_enabledx/y/z name; in `window` when one is given.
void symmetricMultipleOfC(Reader& r, NodeBuilder& b, const std::string& weights, const std::string& window = "") {
    if (!r.boolean("transf_addCpixel_enabled_false")) return;
    auto add = [&] {
        b.add("add_c_symmetric", {N::v("weights", r.vector(weights)), N::v("abs_axes", enabledAxes(r))});
    };
    if (window.empty())
        add();
    else
        inWindow(r, b, window, window, add);
}

// Tom Lowe's box in DarkBeam's and mclarekin's form: each part runs in its own iteration window
// (transf_start/stop_iterations_B fold, _S sphere fold, _A scale, _R rotation, _C tweak scale).
// The fold's parabolic softening (window D .. D1) is the soft box fold where the windows meet.
void mapAboxMod11(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("transf_function_enabledSw_false", "the swap of x and z");
    const vec3 limit = r.vector("transf_addition_constant_111");
    const bool foldZ = r.boolean("transf_function_enabled");
    const int foldStart = r.integer("transf_start_iterations_B"), foldStop = r.integer("transf_stop_iterations_B");
    auto fold = [&](int from, int to) { b.within(from, to, [&] { tgladFold(r, b, limit, foldZ, approximated); }); };
    const int softStart = std::max(r.integer("transf_start_iterations_D"), 0);
    const int softStop = std::min(r.integer("transf_stop_iterations_D1"), kMaxIterations);
    if (r.boolean("transf_function_enabled_false") && softStart < softStop) {
        if (!foldZ || softStart < foldStart || softStop > foldStop)
            r.unsupported(
                "transf_function_enabled_false: the parabolic softening apart from the box fold of x, y "
                "and z (iterations " +
                std::to_string(softStart) + " to " + std::to_string(softStop) + ")");
        fold(foldStart, std::min(foldStop, softStart));
        b.within(softStart, softStop, [&] {
            b.add("box_fold_soft", {N::v("limit", limit), N::v("softness", r.vector("transf_scale3D_000"))});
        });
        fold(std::max(foldStart, softStop), foldStop);
    } else {
        fold(foldStart, foldStop);
    }
    inWindow(r, b, "S", "S",
             [&] { cparaSphereFold(r, b, r.boolean("transf_function_enabledy_false"), r.vector("mandelbox_offset")); });
    const double scale = r.number("mandelbox_scale"), vary = r.number("mandelbox_vary_scale_vary");
    if (vary == 0.0) {
        inWindow(r, b, "A", "A", [&] { b.add("scale", {N::f("scale", scale)}); });
    } else {
        // Mandelbulber2's actualScale: scale + vary (|actualScale| - 1) at the start of every
        // iteration of the formula, from the first slot's Mandelbox scale (compute_fractal.cpp), used
        // by the scale in window A. One scale_vary with from_scale over window A follows it where
        // that window holds every iteration the slot runs and the first slot's scale is this one.
        const FractEntry* first = r.file().find("fractal_1", "mandelbox_scale");
        const double firstScale =
            parseNumber(first ? first->value : std::string(defaultValue("mandelbox_scale", false))).value_or(scale);
        if (firstScale != scale)
            r.unsupported("mandelbox_vary_scale_vary " + fmt(vary) +
                          ": a varying scale that starts from another slot's Mandelbox scale");
        if (r.integer("transf_start_iterations_A") > b.firstIteration() ||
            r.integer("transf_stop_iterations_A") <= b.lastIteration())
            r.unsupported("mandelbox_vary_scale_vary " + fmt(vary) +
                          ": a varying scale whose window A leaves out iterations it varies on");
        b.add("scale_vary", {N::f("scale", scale), N::f("vary", vary), N::f("limit", 1.0), N::f("update", 1.0),
                             N::f("from_scale", 1.0)});
    }
    additionConstant(r, b);
    extraMultipleOfC(r, b, "E");
    windowedRotation(r, b, "transf_rotation_enabled", "_R");
    if (r.number("transf_scaleG_1") != 1.0)
        inWindow(r, b, "C", "C1", [&] { b.add("scale", {N::f("scale", r.number("transf_scaleG_1"))}); });
}

// box_fold_bulb_pow2_v2: Tglad's fold per axis (window B), the sphere fold of squared radii
// (window S), the scale (window C; varying, its offset moved in window X), then White's power 2
// with z times the z factor (window A).
void mapBoxFoldBulbPow2V2(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    inWindow(r, b, "B", "B", [&] { tgladFold(r, b, r.vector("transf_addition_constant_111"), true, approximated); });
    inWindow(r, b, "S", "S", [&] { squaredRadiiSphereFold(r, b, r.vector("mandelbox_offset")); });
    varyingScale(r, b, r.number("transf_scale"), "C", "X", true, "transf_scaleB_1");
    inWindow(r, b, "A", "A", [&] { whitePower2TimesZFactor(r, b); });
}

// The pseudo-Kleinian mod 2, each part in its window: the rotation (R), Benesi's T1 (T) and
// box fold (D to TM), the clamp-style pseudo-Kleinian fold (C) and its conditional form (B, the
// same map), the added constant, then the box fold at offsetA with its parabolic softening (F; the
// softening in window A only), and the multiple of c signed by the point (offsetF_000).
void mapPseudoKleinianMod2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledS_false", "the sphere fold with a radius that varies with the iteration");
    prismFold(r, b);
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    benesiFolds(r, b, "transf_start_iterations_T");
    pseudoKleinianFolds(r, b);
    additionConstant(r, b);
    if (r.boolean("transf_function_enabledF_false")) {
        const int start = r.integer("transf_start_iterations_F"), stop = r.integer("transf_stop_iterations_F");
        const vec3 limit = r.vector("transf_offsetA_000");
        auto fold = [&](int from, int to, const vec3& softness) {
            b.within(from, to, [&] { b.add("box_fold_soft", {N::v("limit", limit), N::v("softness", softness)}); });
        };
        if (r.boolean("transf_function_enabled_false")) {
            const int softStart = std::max(start, r.integer("transf_start_iterations_A"));
            const int softStop = std::min(stop, r.integer("transf_stop_iterations_A"));
            fold(start, std::min(stop, softStart), vec3(0.0));
            fold(softStart, softStop, r.vector("transf_scale3D_000"));
            fold(std::max(start, softStop), stop, vec3(0.0));
        } else {
            fold(start, stop, vec3(0.0));
        }
    }
    symmetricMultipleOfC(r, b, "transf_offsetF_000");
}

// The Mandelbox then Menger steps (Mandelbulber2's mandelbox_menger), each part in its window: the
// box fold (A; z's limit times transf_scale_1), the sphere fold (B), the main rotation (R), the
// scale (S), then transf_int_1 Menger steps (M), each with its added constant and, with the c
// option, c times the B multiplier.
void mapMandelboxMenger(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("mandelbox_rotations_enabled", "the box fold in tilted frames");
    r.mustBeDefault("transf_addCpixel_enabled_false", "an extra multiple of c, its axes reordered");
    boxFoldScaledZ(r, b);
    inWindow(r, b, "B", "B", [&] {
        sphereFold(b, r.number("mandelbox_folding_min_radius"), r.number("mandelbox_folding_fixed_radius"),
                   r.vector("mandelbox_offset"));
    });
    if (r.boolean("mandelbox_main_rotation_enabled"))
        inWindow(r, b, "R", "R", [&] { b.rotation(setRotation2(r.vector("mandelbox_rotation_main"))); });
    inWindow(r, b, "S", "S", [&] { b.add("scale", {N::f("scale", r.number("mandelbox_scale"))}); });
    double s = 0.0;
    vec3 offset(0.0);
    if (!r.boolean("transf_function_enabled") || !mengerStepWithCorner(r, s, offset)) return;
    const bool addC = r.boolean("transf_function_enabledx_false");
    if (addC) r.mustBeDefault("mandelbulbMulti_order_of_xyz_C", "c's axes reordered");
    const double weight = addC ? uniformMultiplier(r, "transf_constant_multiplierB_111") : 0.0;
    inWindow(r, b, "M", "M", [&] {
        for (int k = 0; k < std::clamp(r.integer("transf_int_1"), 0, 8); ++k) {
            b.add("menger_rotate", {N::f("scale", s), N::v("offset", offset)});
            const vec3 add = r.vector("transf_addition_constantA_000");
            if (length(add) > 0.0) b.add("translate", {N::v("offset", add)});
            if (addC) b.add("add_c", {N::f("weight", weight)});
        }
    });
    if (r.integer("transf_int_1") > 8)
        r.unsupported("transf_int_1 " + r.raw("transf_int_1") + ": more than 8 Menger steps an iteration");
}

// The pseudo-Kleinian formulas' general box fold (F): each coordinate |v + low| - |v - high| less
// v times `mirror`, then + offsetA.
void pseudoKleinianGeneralBoxFold(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_function_enabledF_false")) return;
    inWindow(r, b, "F", "F", [&] {
        b.add("box_fold_general",
              {N::v("low", r.vector("transf_offsetF_000")), N::v("high", r.vector("transf_offset_000")),
               N::v("mirror", r.vector("transf_scale3D_111")), N::v("offset", r.vector("transf_offsetA_000"))});
    });
}

// The pseudo-Kleinian formulas' Menger step (M) and the constant added after it (addA), where the
// option `enabled` is on (transf_function_enabled in the std DE, transf_function_enabledM_false in
// the mod 1).
void pseudoKleinianMengerStep(Reader& r, NodeBuilder& b, const std::string& enabled) {
    if (!r.boolean(enabled)) return;
    inWindow(r, b, "M", "M", [&] {
        double s = 0.0;
        vec3 offset(0.0);
        if (!mengerStepWithCorner(r, s, offset)) return;
        b.add("menger_rotate", {N::f("scale", s), N::v("offset", offset)});
        const vec3 add = r.vector("transf_addition_constantA_000");
        if (length(add) > 0.0) b.add("translate", {N::v("offset", add)});
    });
}

// The general box fold's axes that transf_function_enabledAx .. z switch off: refused.
void refuseGeneralBoxFoldAxesOff(Reader& r) {
    for (const char* axis : {"transf_function_enabledAx", "transf_function_enabledAy", "transf_function_enabledAz",
                             "transf_function_enabledx", "transf_function_enabledy", "transf_function_enabledz"})
        r.mustBeDefault(axis, "a box fold with one of its limits left out");
}

// The pseudo-Kleinian std DE (Knighty's, Theli-at's in Mandelbulber2), each part in its window: the
// rotation (R), Benesi's T1 (start .. T1) and box fold (D .. TM), the general box fold (F), the
// Menger step (M) and its added constant, the clamp-style pseudo-Kleinian fold (C) and its
// conditional form (B), the added constant. Its DE is the linear one on r_xy (escape_linear_xy).
void mapPseudoKleinianStdDE(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_scaleB_1", "a scale inside the pseudo-Kleinian fold");
    refuseGeneralBoxFoldAxesOff(r);
    prismFold(r, b);
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    benesiFolds(r, b, "transf_start_iterations");
    pseudoKleinianGeneralBoxFold(r, b);
    pseudoKleinianMengerStep(r, b, "transf_function_enabled");
    pseudoKleinianFolds(r, b);
    additionConstant(r, b);
}

// The pseudo-Kleinian mod 1 (Mandelbulber2 2.20's PseudoKleinianMod1Iteration in
// fractal_formulas.cpp; formula/definition/fractal_pseudo_kleinian_mod1.cpp in later versions):
// the std DE's parts in another order, each in its window: the prism fold (P), the rotation (R),
// Benesi's T1 (start .. T1) and box fold (D .. TM), the general box fold (F), the clamp-style fold
// (C; transf_function_enabledAy, which also keeps F's y limit) and its conditional form (B), the
// added constant, then the Menger step (M, option transf_function_enabledM_false) and its added
// constant. Its DE is the pseudo-Kleinian one. The scale of z inside the clamp-style fold
// (transf_scaleB_1) is refused.
void mapPseudoKleinianMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_scaleB_1", "z scaled inside the pseudo-Kleinian fold");
    if (r.boolean("transf_function_enabledF_false")) refuseGeneralBoxFoldAxesOff(r);
    prismFold(r, b);
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    benesiFolds(r, b, "transf_start_iterations");
    pseudoKleinianGeneralBoxFold(r, b);
    pseudoKleinianFolds(r, b);
    additionConstant(r, b);
    pseudoKleinianMengerStep(r, b, "transf_function_enabledM_false");
}

// box_fold_bulb_pow2_v3: V2's parts (fold B, sphere fold S, scale C), then Benesi's box fold (TM),
// the octahedral fold with |x| and the scale about offset_100 (D), the rotation (R), the Menger
// step of an offset abs (F in window M: |v + a|, then the step about transf_constant_multiplier_111,
// z shifted only above 1 unless transf_function_enabled is false), before the power (A). Its
// first-iteration sphere inversion, and the Menger step that always shifts z, are refused.
void mapBoxFoldBulbPow2V3(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("transf_sphere_inversion_enabled_false", "a first-iteration sphere inversion");
    if (r.boolean("transf_function_enabledF_false"))
        r.mustBeDefault("transf_function_enabled", "a Menger step that shifts z at every point (not only above 1)");
    inWindow(r, b, "B", "B", [&] { tgladFold(r, b, r.vector("transf_addition_constant_111"), true, approximated); });
    inWindow(r, b, "S", "S", [&] { squaredRadiiSphereFold(r, b, r.vector("mandelbox_offset")); });
    varyingScale(r, b, r.number("transf_scale"), "C", "X", true, "transf_scaleB_1");
    if (r.boolean("transf_function_enabledX_false"))
        b.within(r.integer("transf_start_iterationsTM"), r.integer("transf_stop_iterationsTM_1"), [&] {
            b.add("benesi_box_fold", {N::v("scale", r.vector("transf_scale3D_333")),
                                      N::v("limit", r.vector("transf_addition_constantA_111"))});
        });
    if (r.boolean("transf_function_enabledD_false"))
        inWindow(r, b, "D", "D", [&] {
            b.add("octahedral_fold", {});
            b.add("plane_fold", {N::v("normal", vec3(1, 0, 0)), N::f("offset", 0.0)});
            b.add("scale", {N::f("scale", r.number("transf_scaleA_2")), N::v("center", r.vector("transf_offset_100"))});
        });
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    if (r.boolean("transf_function_enabledF_false"))
        inWindow(r, b, "M", "M", [&] {
            double s = 0.0;
            vec3 offset(0.0);
            if (!mengerStepWithCorner(r, s, offset, "transf_constant_multiplier_111")) return;
            const vec3 add = r.vector("transf_addition_constantA_000");
            if (length(add) > 0.0) b.add("translate", {N::v("offset", add)});
            b.add("menger_rotate", {N::f("scale", s), N::v("offset", offset)});
        });
    inWindow(r, b, "A", "A", [&] { whitePower2TimesZFactor(r, b); });
}

// Amazing Surf mod 2 with its extra multiple of c (window H; c turned by transf_rotation in window
// G) first, its xy folds (type 1: Tglad's fold of x and y) in windows A, B and C, z's fold when
// enabled, the offset, then the sphere fold (window M) and scale (window S; varying with
// transf_function_enabledF_false, its offset moved in window Y), the main rotation (window R); +c.
void mapAmazingSurfMod2(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("transf_function_enabledCx_false", "an inverted c");
    r.mustBeDefault("transf_function_enabledCz_false", "the soft (parabolic) fold");
    r.mustBeDefault("transf_function_enabledSw_false", "the swap of x and y");
    r.mustBeDefault("transf_function_enabledBz_false", "the curved offset");
    r.mustBeDefault("transf_function_enabled_false", "the cylinder fold");
    const bool foldXy = r.boolean("transf_function_enabledAx"), foldZ = r.boolean("transf_function_enabledAx_false");
    const vec3 limit = r.vector("transf_addition_constant_111");
    const int start = r.integer("transf_start_iterations_A"), stop = r.integer("transf_stop_iterations_A");
    if (foldZ && (!foldXy || start > 0 || stop < 250))
        r.unsupported("transf_function_enabledAx_false: z's fold apart from the first xy fold's window");
    extraMultipleOfC(r, b, "H", "G");
    // Up to three xy folds, each in its window; z's fold, after them in Mandelbulber2, touches z
    // alone and goes with the first (which then runs on every iteration).
    struct XyFold {
        const char *enabled, *window, *type;
    };
    for (const XyFold& fold : {XyFold{"transf_function_enabledAx", "A", "aSurf3Folds_order_of_folds_1"},
                               XyFold{"transf_function_enabledAy_false", "B", "aSurf3Folds_order_of_folds_2"},
                               XyFold{"transf_function_enabledAz_false", "C", "aSurf3Folds_order_of_folds_3"}}) {
        if (!r.boolean(fold.enabled)) continue;
        if (const std::string type = r.raw(fold.type); type != "0" && type != "type1")
            r.unsupported(std::string(fold.type) + " " + type + ": a fold other than Tglad's");
        const bool withZ = foldZ && fold.window == std::string("A");
        inWindow(r, b, fold.window, fold.window, [&] { tgladFold(r, b, limit, withZ, approximated); });
    }
    additionConstant(r, b);
    if (r.boolean("transf_function_enabledAy")) {
        inWindow(r, b, "M", "M", [&] { squaredRadiiSphereFold(r, b, r.vector("mandelbox_offset")); });
        varyingScale(r, b, r.number("mandelbox_scale"), "S", "Y", r.boolean("transf_function_enabledF_false"),
                     "transf_scaleC_1");
    }
    if (r.boolean("mandelbox_main_rotation_enabled"))
        inWindow(r, b, "R", "R", [&] { b.rotation(setRotation2(r.vector("mandelbox_rotation_main"))); });
}

void mapKalisets1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_minimum_radius_0", "a clamped inversion radius");
    const double scale = r.number("transf_scale");
    if (!(scale > 0.0)) return r.unsupported("transf_scale " + fmt(scale) + ": an inversion needs a positive scale");
    b.add("abs_fold", {});
    b.add("sphere_invert", {N::f("radius", std::sqrt(scale))});
    if (r.boolean("transf_addCpixel_enabled_false")) {
        b.add("add_c", {N::f("weight", uniformMultiplier(r, "transf_constant_multiplier_111"))});
    }
    if (r.boolean("transf_constant_julia_mode"))
        b.add("translate", {N::v("offset", r.vector("transf_constant_julia_c"))});
    if (r.boolean("transf_rotation_enabled")) b.rotation(setRotation2(r.vector("transf_rotation")));
}

void mapAboxModKali(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledP_false", "a rotation that varies with the iteration");
    if (r.boolean("mandelbox_main_rotation_enabled")) {
        // Rotations about x, then y, then z (RotateAroundVectorByAngle, in degrees).
        const vec3 a = r.vector("mandelbox_rotation_main");
        b.rotation(rotationZYX(a.z, 0, 0) * rotationZYX(0, a.y, 0) * rotationZYX(0, 0, a.x));
    }
    // z = a - |z|, then the sphere fold's m = s / clamp(r^2, minR, 1).
    b.add("abs_fold", {});
    b.add("scale", {N::f("scale", -1.0)});
    b.add("translate", {N::v("offset", r.vector("transf_addition_constant_0555"))});
    sphereFold(b, std::sqrt(std::max(r.number("transf_minimum_radius_06"), 0.0)), 1.0);
    b.add("scale", {N::f("scale", r.number("transf_scale_015"))});
}

// Its V2: a - |v| on x and y (and z unless transf_function_enabledM is off), the sphere fold of
// squared radii minR2 and maxR2 times scale_015, then the added constant on both sides of the
// rotation (window start .. stop), as Mandelbulber2 adds it twice, and the multiple of c signed by
// the point (window C).
void mapAboxModKaliV2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledS_false", "signs restored from the point before the fold");
    const vec3 a = r.vector("transf_addition_constant_0555");
    if (r.boolean("transf_function_enabledM")) {
        b.add("abs_fold", {});
        b.add("scale", {N::f("scale", -1.0)});
        b.add("translate", {N::v("offset", a)});
    } else {
        b.add("plane_fold", {N::v("normal", vec3(1, 0, 0)), N::f("offset", 0.0)});
        b.add("plane_fold", {N::v("normal", vec3(0, 1, 0)), N::f("offset", 0.0)});
        b.add("axis_scale", {N::v("scale", vec3(-1.0, -1.0, 1.0))});
        b.add("translate", {N::v("offset", vec3(a.x, a.y, 0.0))});
    }
    squaredRadiiSphereFold(r, b);
    b.add("scale", {N::f("scale", r.number("transf_scale_015"))});
    additionConstant(r, b);
    if (r.boolean("transf_rotation_enabled"))
        b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"),
                 [&] { b.rotation(setRotation2(r.vector("transf_rotation"))); });
    additionConstant(r, b);
    symmetricMultipleOfC(r, b, "transf_constant_multiplier_000", "C");
}

// msltoe's Riemann spheres: the rotation before the step (the first and V2), V1's inside it.
void mapRiemannSphere(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_rotation_enabled")) b.rotation(setRotation2(r.vector("transf_rotation")));
    b.add("riemann_sphere", {N::f("scale", r.number("transf_scale")), N::f("s_phase", r.number("transf_offsetA_0")),
                             N::f("t_phase", r.number("transf_offsetB_0"))});
    additionConstant(r, b);
}
void mapRiemannSphereV1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_rotation_enabled", "a rotation of the projected plane inside the step");
    b.add("riemann_sphere_v1",
          {N::f("scale", r.number("transf_scale")), N::v("multiplier", r.vector("transf_constant_multiplier_441"))});
    additionConstant(r, b);
}
void mapRiemannSphereV2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_rotation_enabled")) b.rotation(setRotation2(r.vector("transf_rotation")));
    b.add("riemann_sphere_v2",
          {N::f("scale", r.number("transf_scale_08")), N::f("theta_scale", r.number("transf_scaleA_1")),
           N::f("phi_scale", r.number("transf_scaleB_1")), N::v("offset", r.vector("transf_offset_010"))});
}

// Jos Leys' Kleinian (Mandelbulber2's form), after its optional sphere inversion on the first
// iteration: z + offset inverted in the sphere of squared radius maxR2, then + add - offset.
void mapJosKleinian(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    firstIterationInversion(r, b, "transf_addition_constant");
    b.add("jos_kleinian",
          {N::f("klein_r", r.number("transf_folding_value")), N::f("klein_i", r.number("transf_offset")),
           N::v("box_size", r.vector("transf_offset_111"))});
}

// x's multiplier is transf_scale3D_000's x, y's and z's transf_offset_000's (as Mandelbulber2
// reads them).
// Mandelbulber2's transforms multiply its running derivative by analyticDE_scale_1 (and some add
// analyticDE_offset_1): a "DE tweak" with no map behind it, which sets how thick the surface is
// at the hit threshold. fraktal's derivative_tweak does the same after the step; below 1 its
// estimate is no bound, and the import's measured step factor keeps the march safe.
void derivativeTweak(Reader& r, NodeBuilder& b, bool withOffset = false) {
    const double scale = r.number("analyticDE_scale_1"), offset = withOffset ? r.number("analyticDE_offset_1") : 0.0;
    if (scale != 1.0 || offset != 0.0) b.add("derivative_tweak", {N::f("scale", scale), N::f("offset", offset)});
}
void mapTransfAbsAddConditional(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const vec3 axes = enabledAxes(r);
    const vec3 offset = r.vector("transf_offset_000");
    b.add("abs_add_conditional", {N::v("axes", axes), N::v("offset", r.vector("transf_offset_111")),
                                  N::v("multiplier", vec3(r.vector("transf_scale3D_000").x, offset.y, offset.z))});
    derivativeTweak(r, b);
}

void mapMandelbulb2(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("mandelbulb2", {}); }
void mapLkmitch(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("lkmitch", {}); }

// The quadratics of "another shot at the holy grail" (QuickDudleyIteration, QuickDudleyModIteration,
// Makin3d2Iteration of 2.20) take their derivative as 2 r DE analyticDE_scale_1 +
// analyticDE_offset_1 whatever the analytic DE switch says: 2 r DE + 1 at the defaults, which the
// block's 2 r and add_c's 1 give. Elsewhere a derivative_tweak after the block carries the rest.
void quadraticDerivativeTweak(Reader& r, NodeBuilder& b) {
    const double scale = r.number("analyticDE_scale_1"), offset = r.number("analyticDE_offset_1");
    if (scale != 1.0 || offset != 1.0) b.add("derivative_tweak", {N::f("scale", scale), N::f("offset", offset - 1.0)});
}
void mapQuickDudley(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("quick_dudley", {});
    quadraticDerivativeTweak(r, b);
}
// quick_dudley_mod: the squares times transf_constant_multiplier_111, the products times _222.
void mapQuickDudleyMod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("quick_dudley", {N::v("squares", r.vector("transf_constant_multiplier_111")),
                           N::v("products", r.vector("transf_constant_multiplier_222"))});
    quadraticDerivativeTweak(r, b);
}
void mapMakin3d2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("makin3d2", {});
    quadraticDerivativeTweak(r, b);
}
// Ide's formulas (IdesIteration, Ides2Iteration of 2.20): the multipliers
// transf_constant_multiplier_121 and the subtracted transf_addition_constant_0555; ides damps x and
// z first, ides2 keeps the point. Mandelbulber2 measures their distance by differences (the
// gradient estimator here).
void ides(Reader& r, NodeBuilder& b, bool damp) {
    b.add("ides", {N::v("multiplier", r.vector("transf_constant_multiplier_121")),
                   N::v("subtract", r.vector("transf_addition_constant_0555")), N::f("damp", damp ? 1.0 : 0.0),
                   N::f("keep", damp ? 0.0 : 1.0)});
}
void mapIdes(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { ides(r, b, true); }
void mapIdes2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { ides(r, b, false); }
// aexion_octopus_mod (AexionOctopusModIteration): the octopus with transf_scale3D_111's x and y
// (its z is unused) and the abs of the axes transf_function_enabledAx/Ay/Az, the rotation
// (transf_rotation_enabled), transf_addition_constant, then the signed multiple of c. Mandelbulber2
// adds no other c.
void mapAexionOctopusMod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const vec3 scale = r.vector("transf_scale3D_111");
    b.add("aexion_octopus",
          {N::f("x_scale", scale.x), N::f("y_scale", scale.y),
           N::v("abs_axes", vec3(r.boolean("transf_function_enabledAx"), r.boolean("transf_function_enabledAy"),
                                 r.boolean("transf_function_enabledAz")))});
    if (r.boolean("transf_rotation_enabled")) b.rotation(setRotation2(r.vector("transf_rotation")));
    additionConstant(r, b);
    symmetricMultipleOfC(r, b, "transf_constant_multiplier_000");
}
// msltoe_toroidal (MsltoeToroidalIteration of 2.20): the scale per axis transf_scale3D_111 (option
// "enabled_false", window D to D1), the toroidal bulb of ring radius transf_minimum_radius_05,
// powers transf_pwr_4 (radial), transf_pwr_8 (latitude) and power (azimuth), with its spherical
// offset transf_offset and scale transf_scale (option Ax_false, which adds its own 1 to the
// derivative). Its DE tweak (analyticDE_enabled_false: rp DE (pwr4 + offset_2) scale_1 + offset_1
// in place of rp DE (pwr4 + 1) + 1) is the derivative_tweak that turns the one into the other.
void mapMsltoeToroidal(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_function_enabled_false")) {
        const vec3 stretch = r.vector("transf_scale3D_111");
        b.within(r.integer("transf_start_iterations_D"), r.integer("transf_stop_iterations_D1"), [&] {
            if (stretch != vec3(1.0)) b.add("axis_scale", {N::v("scale", stretch)});
        });
    }
    const bool pulled = r.boolean("transf_function_enabledAx_false");
    const double power = r.number("transf_pwr_4");
    b.add("msltoe_toroidal",
          {N::f("ring_radius", r.number("transf_minimum_radius_05")), N::f("radial_power", power),
           N::f("latitude_power", r.number("transf_pwr_8")), N::f("azimuth_power", r.number("power")),
           N::f("offset", pulled ? r.number("transf_offset") : 0.0),
           N::f("scale", pulled ? r.number("transf_scale") : 1.0)});
    if (r.boolean("analyticDE_enabled_false")) {
        const double scale = (power + r.number("analyticDE_offset_2")) * r.number("analyticDE_scale_1") / (power + 1.0);
        b.add("derivative_tweak", {N::f("scale", scale), N::f("offset", r.number("analyticDE_offset_1") - 1.0)});
    }
    if (pulled) b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)});
}
// riemann_bulb_msltoe_mod2 (RiemannBulbMsltoeMod2Iteration of 2.20): the Riemann bulb with its
// parameters as the formula names them. Mandelbulber2 adds no c and measures the distance by
// differences (the gradient estimator here).
void mapRiemannBulbMsltoeMod2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("riemann_bulb",
          {N::f("radius", r.number("transf_minimum_radius_05")),
           N::f("smooth_inside", r.boolean("transf_function_enabled") ? 1.0 : 0.0),
           N::f("inside_scale", r.number("transf_scaleA_1")),
           N::v("inside_multiplier", r.vector("transf_constant_multiplier_111")),
           N::v("multiplier", r.vector("transf_constant_multiplier_222")), N::f("shift", r.number("transf_offset_1")),
           N::f("scale", r.number("transf_scale_3")), N::f("y_offset", r.number("transf_offset_105")),
           N::f("tile", r.boolean("transf_function_enabledx") ? 1.0 : 0.0),
           N::f("sine", r.boolean("transf_function_enabledx_false") ? 1.0 : 0.0),
           N::f("sine_scale", r.number("transf_scale_1"))});
}
// collatz and collatz_mod (CollatzIteration, CollatzModIteration of 2.20): the Collatz block with
// Mandelbulber2's derivative, DE 4 analyticDE_scale_1 (collatz_mod's; collatz's 1) + 1, the 1 a
// derivative_tweak (Mandelbulber2 adds no c). collatz_mod's values are its offset
// transf_constant_multiplierB_111, transf_scale_4, its axis transf_constant_multiplier_111,
// transf_scale_2, its angle transf_scale_1 (times pi) and transf_scale_025; its multiple of c with
// the axes reversed (transf_addCpixel_enabled_false) is refused.
void mapCollatz(Reader&, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("collatz", {N::f("mb2_derivative", 1.0)});
    b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)});
}
void mapCollatzMod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_addCpixel_enabled_false", "a multiple of c with its axes reversed (zyx)");
    b.add("collatz",
          {N::v("offset", r.vector("transf_constant_multiplierB_111")), N::f("linear", r.number("transf_scale_4")),
           N::v("axis", r.vector("transf_constant_multiplier_111")), N::f("quadratic", r.number("transf_scale_2")),
           N::f("angle", r.number("transf_scale_1")), N::f("scale", r.number("transf_scale_025")),
           N::f("mb2_derivative", 1.0)});
    b.add("derivative_tweak", {N::f("scale", r.number("analyticDE_scale_1")), N::f("offset", 1.0)});
}
// Mandelbulb3Iteration takes 2 r DE and no 1 for c (derivativeTakesNoOneForC).
void mapMandelbulb3(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("mandelbulb3", {}); }
// Mandelbulb4Iteration: its turns' offsets are alpha_angle_offset (about z), beta_angle_offset
// (about y) and gamma_angle_offset (about x), degrees in the file.
void mapMandelbulb4(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("mandelbulb4", {N::f("power", r.number("power")), N::f("alpha", r.number("alpha_angle_offset")),
                          N::f("beta", r.number("beta_angle_offset")), N::f("gamma", r.number("gamma_angle_offset"))});
}

// The buffalo bulb: White's power-2 triplex (the sine bulb of power 2, z mirrored unless
// buffalo_pos_z) between |axis| folds chosen per axis (plane folds through the origin).
void mapBuffalo(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    auto absFolds = [&](const std::string& prefix) {
        for (int k = 0; k < 3; ++k)
            if (r.boolean(prefix + "xyz"[k])) {
                axisMirror(b, k);
            }
    };
    absFolds("buffalo_preabs_");
    b.add("mandelbulb_sine", {N::f("power", 2.0)});
    if (!r.boolean("buffalo_pos_z")) b.add("axis_scale", {N::v("scale", vec3(1.0, 1.0, -1.0))});
    absFolds("buffalo_abs_");
}

// mandelbulb_abs_power2: the buffalo step between a rotation (window R) and an offset (window D)
// before it and an offset (window M) and the main rotation (window S) after it, then the final
// abs of the chosen axes (window H).
void mapMandelbulbAbsPower2(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    r.mustBeDefault("transf_addCpixel_enabled_false", "an extra multiple of c in a chosen axis order");
    windowedRotation(r, b, "transf_rotation_enabled", "_R");
    auto offset = [&](const std::string& enabled, const std::string& window, const std::string& key) {
        const vec3 v = r.vector(key);
        if (r.boolean(enabled) && length(v) > 0.0)
            inWindow(r, b, window, window, [&] { b.add("translate", {N::v("offset", v)}); });
    };
    offset("transf_function_enabledD_false", "D", "transf_offsetA_000");
    mapBuffalo(r, b, approximated);
    offset("transf_function_enabledM", "M", "transf_offset_000");
    if (r.boolean("transf_function_enabled"))
        inWindow(r, b, "S", "S", [&] { b.rotation(setRotation2(r.vector("mandelbox_rotation_main"))); });
    if (r.boolean("transf_function_enabledP_false"))
        inWindow(r, b, "H", "H", [&] {
            for (int k = 0; k < 3; ++k)
                if (r.boolean(std::string("transf_function_enabledC") + "xyz"[k] + "_false")) {
                    axisMirror(b, k);
                }
        });
    if (r.boolean("analyticDE_enabled_false"))
        approximated.push_back({r.where(),
                                "analyticDE_enabled_false: the derivative's scale and offset are left as "
                                "they are (the log estimate's own)"});
}

void mapCoastalbrot(Reader&, NodeBuilder& b, std::vector<ImportItem>&) { b.add("coastalbrot", {}); }

void mapMandelbulbEye(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    auto axes = [&](const char* prefix) {
        const std::string k = std::string("buffalo_") + prefix;
        return vec3(r.boolean(k + "x"), r.boolean(k + "y"), r.boolean(k + "z"));
    };
    b.add("mandelbulb_eye",
          {N::v("abs_before", axes("preabs_")), N::f("theta_scale", r.number("transf_scaleB_1")),
           N::f("theta2_scale", r.number("transf_scaleC_1")), N::f("phi_scale", r.number("transf_scale_1")),
           N::f("phi_mirror", r.boolean("transf_function_enabled_false")), N::v("abs_after", axes("abs_")),
           N::v("offset", r.vector("transf_addition_constantA_000"))});
}

void mapMsltoeDonut(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("msltoe_donut",
          {N::f("ring_radius", r.number("donut_ring_radius")), N::f("thickness", r.number("donut_ring_thickness")),
           N::f("sections", r.number("donut_number")), N::f("factor", r.number("donut_factor"))});
}

// ---- Mandelbulber2's 4D transforms on an orbit whose fourth coordinate stays 0 ----
// The importer takes initial_waxis 0 (the hypercomplex orbit apart), and Mandelbulber2's 3D
// formulas leave the fourth coordinate w of their CVector4 at 0 (c's is 0). These transforms map
// w = 0 to 0 when their own w parts do, so on such an orbit they are the 3D steps below; a part
// that would move w off 0 is refused.

void mapTransfScale4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledF_false", "a scale that varies with the iteration");
    b.add("scale", {N::f("scale", r.number("transf_scale"))});
}
void mapTransfSphericalFold4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const auto offset = r.vector4("transf_offset_0000");
    if (offset.w != 0.0) r.unsupported("transf_offset_0000's w " + fmt(offset.w) + ": a fold that moves w off 0");
    squaredRadiiSphereFold(r, b, vec3(offset));
}
// transf_rotation4d (TransfRotation4dIteration of 2.20): turns in the xy, yz and xz planes
// (transf_rotation44a, degrees), then in xw, yw and zw (transf_rotation44b), as rotate4d turns.
// Nothing when every angle is 0 (Mandelbulber2's default); a turn with w is refused: it would move
// w off 0.
void mapTransfRotation4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const vec3 turns = r.vector("transf_rotation44a"), turnsW = r.vector("transf_rotation44b");
    if (length(turnsW) != 0.0)
        return r.unsupported("transf_rotation44b " + fmt(turnsW) + ": a turn in a plane with w moves w off 0");
    if (length(turns) != 0.0) b.add("rotate4d", {N::v("angles", turns), N::v("angles_w", vec3(0.0))});
}
// z times transf_scale, plus z times transf_offset on iteration transf_int_A and times
// transf_offset_0 on transf_int_B: the scale, and on those iterations a scale by the ratio.
void mapTransfIterationWeight4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const double s = r.number("transf_scale");
    const int a = r.integer("transf_int_A"), c = r.integer("transf_int_B");
    const double onA = r.number("transf_offset"), onB = r.number("transf_offset_0");
    if (s == 0.0) return r.unsupported("transf_scale 0: a weight that collapses the orbit");
    if (s != 1.0) b.add("scale", {N::f("scale", s)});
    auto on = [&](int i) {
        const double weight = s + (i == a ? onA : 0.0) + (i == c ? onB : 0.0);
        if (weight != s) b.within(i, i + 1, [&] { b.add("scale", {N::f("scale", weight / s)}); });
    };
    on(a);
    if (c != a) on(c);
}
// Tglad's fold of each enabled axis at transf_addition_constant_0000 (a limit may be negative),
// in its window (A, B, C): one general box fold when the three agree, else one per axis (the
// others left as they are: low = high = 0 with mirror -1).
void mapTransfAbsAddTgladFold4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const glm::dvec4 limit = r.vector4("transf_addition_constant_0000");
    const char* enabled[3] = {"transf_function_enabledAx", "transf_function_enabledAy", "transf_function_enabledAz"};
    const char* window[3] = {"A", "B", "C"};
    auto fold = [&](const vec3& axes) {
        const vec3 l = vec3(limit) * axes;
        b.add("box_fold_general", {N::v("low", l), N::v("high", l), N::v("mirror", 2.0 * axes - vec3(1.0))});
    };
    bool same = true;
    for (int k = 0; k < 3; ++k)
        same =
            same && r.boolean(enabled[k]) &&
            r.integer(std::string("transf_start_iterations_") + window[k]) == r.integer("transf_start_iterations_A") &&
            r.integer(std::string("transf_stop_iterations_") + window[k]) == r.integer("transf_stop_iterations_A");
    if (same) return inWindow(r, b, "A", "A", [&] { fold(vec3(1.0)); });
    for (int k = 0; k < 3; ++k) {
        if (!r.boolean(enabled[k])) continue;
        vec3 axis(0.0);
        axis[k] = 1.0;
        inWindow(r, b, window[k], window[k], [&] { fold(axis); });
    }
}
void mapTransfAbsAddConditional4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const vec3 axes = enabledAxes(r);
    b.add("abs_add_conditional", {N::v("axes", axes), N::v("offset", vec3(r.vector4("transf_offset_1111"))),
                                  N::v("multiplier", vec3(r.vector4("transf_scale_0000")))});
    derivativeTweak(r, b);
}

// ---- Mandelbulber2's 4D formulas: the orbit carries the point's fourth coordinate
// (formulas/four_d.hpp), from initial_waxis (a start_w node, importFractal) ----

// menger4d (Menger4dIteration): the 4D offset transf_addition_constant_0000 before it (window C),
// the fold and sort, the turn in 4D's six planes (option R), the scale transf_scale_3 about
// transf_addition_constant_111d5, a 4D sphere fold (S) and an iteration weight (option F); then
// the derivative times analyticDE_scale_1. The turn and the sphere fold are refused.
void mapMenger4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const glm::dvec4 before = r.vector4("transf_addition_constant_0000");
    if (before != glm::dvec4(0.0))
        inWindow(r, b, "C", "C", [&] {
            b.add("translate", {N::v("offset", vec3(before)), N::f("offset_w", before.w)});
        });
    r.mustBeDefault("transf_function_enabledR_false", "a turn in the six planes of 4D");
    r.mustBeDefault("transf_function_enabledS_false", "a 4D sphere fold after the Menger 4D step");
    const glm::dvec4 offset = r.vector4("transf_addition_constant_111d5");
    b.add("menger4d",
          {N::f("scale", r.number("transf_scale_3")), N::v("offset", vec3(offset)), N::f("offset_w", offset.w)});
    // Option F: z times transf_scale (plus z times transf_offset on iteration transf_int_A and
    // times transf_offset_0 on transf_int_B, refused), the derivative times transf_scale_1.
    double derivative = r.number("analyticDE_scale_1");
    if (r.boolean("transf_function_enabled_false")) {
        r.mustBeDefault("transf_offset", "a 4D iteration weight of its own on iteration transf_int_A");
        r.mustBeDefault("transf_offset_0", "a 4D iteration weight of its own on iteration transf_int_B");
        const double weight = r.number("transf_scale");
        if (weight == 0.0) return r.unsupported("transf_scale 0: a weight that collapses the orbit");
        if (weight != 1.0) b.add("scale", {N::f("scale", weight)});
        derivative *= r.number("transf_scale_1") / std::abs(weight);
    }
    if (derivative != 1.0) b.add("derivative_tweak", {N::f("scale", derivative), N::f("offset", 0.0)});
}

// abox4d (2.20's Abox4dIteration in fractal_formulas.cpp), the Mandelbox in 4D: w moved by the
// Cpara parabola of the iteration (option Cpara_enabledParab_false), Tglad's fold of each
// coordinate at transf_offset_1111, the sphere fold of squared radii transf_minR2_p25 and
// transf_maxR2_1 measured on |v|^(2 mandelbox_vary_rpower) and scaling about -transf_offset_0000
// (abox_fold4d), the scale, the turns in the six planes of transf_rotation44a and _44b (option R,
// window R: rotate4d), then transf_addition_constant_0000; c follows. Refused: the scale that
// varies with the iteration, and an inner radius above the fixed one (where Mandelbulber2's fold
// jumps).
void mapAbox4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("mandelbox_vary_scale_vary", "a scale that varies with the iteration");
    const double minR2 = r.number("transf_minR2_p25"), maxR2 = r.number("transf_maxR2_1");
    if (minR2 > maxR2)
        r.unsupported("transf_minR2_p25 " + fmt(minR2) + " above transf_maxR2_1 " + fmt(maxR2) +
                      ": a sphere fold that jumps at its inner radius");
    const glm::dvec4 limit = r.vector4("transf_offset_1111"), offset = r.vector4("transf_offset_0000"),
                     add = r.vector4("transf_addition_constant_0000");
    const vec3 parabola =
        r.boolean("Cpara_enabledParab_false")
            ? vec3(r.number("Cpara_parab_offset0"), r.number("Cpara_parab_slope"), r.number("Cpara_parab_scale"))
            : vec3(0.0);
    b.add("abox_fold4d", {N::v("limit", vec3(limit)), N::f("limit_w", limit.w), N::f("min_r2", minR2),
                          N::f("max_r2", maxR2), N::f("power", r.number("mandelbox_vary_rpower")),
                          N::v("offset", vec3(offset)), N::f("offset_w", offset.w), N::v("w_parabola", parabola)});
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
    const vec3 turns = r.vector("transf_rotation44a"), turnsW = r.vector("transf_rotation44b");
    if (r.boolean("transf_function_enabledR_false") && length(turns) + length(turnsW) > 0.0)
        inWindow(r, b, "R", "R", [&] { b.add("rotate4d", {N::v("angles", turns), N::v("angles_w", turnsW)}); });
    if (glm::length(add) > 0.0) b.add("translate", {N::v("offset", vec3(add)), N::f("offset_w", add.w)});
}

// quaternion4d (Quaternion4dIteration in fractal_formulas.cpp of 2.20): (x^2 - y^2 - z^2 - w^2, x y,
// x z, w) times transf_constant_multiplier_1220, plus transf_addition_constant_0000, on the 4D
// point; then, with option R, the turn in 4D's six planes (transf_rotation44a and 44b, window R),
// in the order and sense of abox4d's.
void mapQuaternion4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const glm::dvec4 multiplier = r.vector4("transf_constant_multiplier_1220"),
                     add = r.vector4("transf_addition_constant_0000");
    b.add("quaternion4d", {N::v("multiplier", vec3(multiplier)), N::f("multiplier_w", multiplier.w),
                           N::v("offset", vec3(add)), N::f("offset_w", add.w)});
    const vec3 turns = r.vector("transf_rotation44a"), turnsW = r.vector("transf_rotation44b");
    if (r.boolean("transf_function_enabledR_false") && length(turns) + length(turnsW) > 0.0)
        inWindow(r, b, "R", "R", [&] { b.add("rotate4d", {N::v("angles", turns), N::v("angles_w", turnsW)}); });
}

// sierpinski4d (Sierpinski4dIteration): the six mirrors, the scale transf_scaleA_2, minus
// transf_offset_1111 in window C; then, with analyticDE_enabled_false, the derivative times
// analyticDE_scale_1 plus analyticDE_offset_0. Its turn in 4D's six planes (option R) is refused.
void mapSierpinski4d(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledR_false", "a turn in the six planes of 4D");
    const double scale = r.number("transf_scaleA_2");
    auto step = [&](const glm::dvec4& offset) {
        b.add("sierpinski4d", {N::f("scale", scale), N::v("offset", vec3(offset)), N::f("offset_w", offset.w)});
    };
    const int start = r.integer("transf_start_iterations_C"), stop = r.integer("transf_stop_iterations_C");
    b.within(0, start, [&] { step(glm::dvec4(0.0)); });
    b.within(start, stop, [&] { step(r.vector4("transf_offset_1111")); });
    b.within(std::max(start, stop), kMaxIterations, [&] { step(glm::dvec4(0.0)); });
    if (r.boolean("analyticDE_enabled_false")) {
        const double tweak = r.number("analyticDE_scale_1"), offset = r.number("analyticDE_offset_0");
        if (tweak != 1.0 || offset != 0.0) b.add("derivative_tweak", {N::f("scale", tweak), N::f("offset", offset)});
    }
}

// Mandelbulber2's Vicsek (VicsekIteration in fractal_formulas.cpp of 2.20), each part in its
// window: the sphere fold (option S: radii from transf_minR2_p25 and transf_maxR2_1, then
// transf_scale_08), the Vicsek step (option M, on by default: |v| sorted, scaled by transf_scale_3,
// x shifted back by limit.x transf_scaleA_1 above limit.x / 2, y by limit.y above limit.y / 2, z by
// 2 limit.z above limit.z, limit transf_offset_111, then x plus transf_offset_0), the turn of 45
// degrees about z (option X) and the analytic DE tweak. The octahedral fold before them (option
// x) and iteration weights other than none are refused.
void mapVicsek(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledx_false", "the octahedral fold before the Vicsek step");
    if (r.boolean("transf_function_enabled_false") &&
        (r.number("transf_scale_1") != 1.0 || r.number("transf_offsetA_0") != 0.0 ||
         r.number("transf_offsetB_0") != 0.0))
        r.unsupported("transf_function_enabled_false true: iteration weights");
    if (r.boolean("transf_function_enabledS_false"))
        inWindow(r, b, "S", "S", [&] {
            sphereFold(b, std::sqrt(r.number("transf_minR2_p25")), std::sqrt(r.number("transf_maxR2_1")));
            b.add("scale", {N::f("scale", r.number("transf_scale_08"))});
        });
    if (r.boolean("transf_function_enabledM"))
        inWindow(r, b, "M", "M", [&] {
            const vec3 limit = r.vector("transf_offset_111");
            b.add("abs_fold", {});
            b.add("menger_fold", {});
            b.add("scale", {N::f("scale", r.number("transf_scale_3"))});
            b.add("conditional_shift",
                  {N::v("threshold", vec3(limit.x * 0.5, limit.y * 0.5, limit.z)),
                   N::v("shift", vec3(limit.x * r.number("transf_scaleA_1"), limit.y, 2.0 * limit.z))});
            const double offset = r.number("transf_offset_0");
            if (offset != 0.0) b.add("translate", {N::v("offset", vec3(offset, 0.0, 0.0))});
        });
    if (r.boolean("transf_function_enabledX_false"))
        b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"),
                 [&] { b.rotation(setRotation2(vec3(0.0, 0.0, 45.0))); });
    analyticTweakWhereEnabled(r, b, "analyticDE_offset_0");
}

// transf_rotation_folding (TransfRotationFoldingIteration in fractal_formulas.cpp of 2.20): the turn
// transf_rotation, then (option on by default) |v + o| - o on the axes transf_function_enabledx/y/z
// say (a plane fold at -o each, o transf_offset_000), Tglad's fold |v + l| - |v - l| - v at
// l transf_offset_111 on the axes transf_function_enabledA{x,y,z} say (option Ay), Mandelbulber2's
// box fold at mandelbox_folding_limit and _value (option Az), and the turn transf_rotation2. The box
// fold on some axes only, or with z's limit scaled, is refused.
void mapTransfRotationFolding(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.rotation(setRotation2(r.vector("transf_rotation")));
    if (r.boolean("transf_function_enabled")) {
        const vec3 o = r.vector("transf_offset_000"), axes = enabledAxes(r);
        for (int k = 0; k < 3; ++k) {
            if (axes[k] == 0.0) continue;
            axisMirror(b, k, -o[k]);
        }
    }
    if (r.boolean("transf_function_enabledAy_false")) {
        const vec3 l = r.vector("transf_offset_111");
        const vec3 on(r.boolean("transf_function_enabledAx"), r.boolean("transf_function_enabledAy"),
                      r.boolean("transf_function_enabledAz"));
        // An axis left out keeps v: |v| - |v| + v, the mirror -1.
        b.add("box_fold_general",
              {N::v("low", l * on), N::v("high", l * on), N::v("mirror", 2.0 * on - 1.0), N::v("offset", vec3(0.0))});
    }
    if (r.boolean("transf_function_enabledAz_false")) {
        for (const char* axis : {"transf_function_enabledBx", "transf_function_enabledBy", "transf_function_enabledBz"})
            r.mustBeDefault(axis, "the box fold with an axis left out");
        r.mustBeDefault("transf_scale_1", "the box fold's z limit scaled");
        boxFold(b, r.number("mandelbox_folding_limit"), r.number("mandelbox_folding_value"));
    }
    b.rotation(setRotation2(r.vector("transf_rotation2")));
}

// ---- dIFS: shape steps whose least distance along the orbit is the estimate (formulas/difs.hpp) ----

// difs_msltoe_donut: the distance to the donut's torus at the point before the step, over the
// derivative after it (DE times the factor, plus 1), then msltoe's donut.
void mapDifsMsltoeDonut(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const double radius = r.number("donut_ring_radius"), thickness = r.number("donut_ring_thickness");
    const double factor = r.number("donut_factor");
    b.add("difs_torus", {N::f("ring_radius", radius), N::f("thickness", thickness), N::f("w_scale", std::abs(factor)),
                         N::f("w_offset", 1.0)});
    b.add("msltoe_donut", {N::f("ring_radius", radius), N::f("thickness", thickness),
                           N::f("sections", r.number("donut_number")), N::f("factor", factor)});
}

// The transf_difs shapes divide by DE + 1 and leave the point as it is.
void mapTransfDifsBox(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("difs_box", {N::v("size", r.vector("transf_addition_constant_111")), N::f("w_offset", 1.0)});
}
void mapTransfDifsEllipsoid(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("difs_ellipsoid", {N::v("radii", r.vector("transf_addition_constant_111")), N::f("w_offset", 1.0)});
}
// The grids: measured in the frame of transf_rotation when it is on (a turn there and back).
// Mandelbulber2 divides the square grid's z by transf_scaleF_1 before the turn and the hexagonal
// one's after it; fraktal's grids divide in their own frame, so the square grid with both is refused.
void difsGrid(Reader& r, NodeBuilder& b, std::string_view block, bool zScaledFirst) {
    const bool turned = r.boolean("transf_rotation_enabled");
    const double zScale = r.number("transf_scaleF_1");
    if (turned && zScaledFirst && zScale != 1.0)
        r.unsupported("transf_scaleF_1 " + fmt(zScale) + " with transf_rotation_enabled: z scaled before the turn");
    const glm::dmat3 turn = setRotation2(r.vector("transf_rotation"));
    if (turned) b.rotation(turn);
    b.add(block, {N::f("cell", r.number("transf_scale_1")), N::f("thickness", r.number("transf_offset_0005")),
                  N::f("z_scale", zScale), N::f("square_bars", r.boolean("transf_function_enabledJ_false") ? 1.0 : 0.0),
                  N::f("w_offset", 1.0)});
    if (turned) b.rotation(glm::transpose(turn));
}
void mapTransfDifsGrid(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { difsGrid(r, b, "difs_grid", true); }
void mapTransfDifsHextgrid2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    difsGrid(r, b, "difs_hex_grid", false);
}

// ---- Mandelbulber2's dIFS formulas (difs_cylinder, difs_sphere: DIFSCylinderIteration and
// DIFSSphereIteration in fractal_formulas.cpp). Each iteration measures its shape at the point it
// starts from, over the derivative after its scale (DE |s| + 1; fraktal's running derivative
// carries the product of the scales without the added ones), then folds |x|, |y| (|z|) and, with
// transf_function_enabled_false, shifts by box offsets and folds across diagonals and offset
// planes; then scales about the "reverse offsets" (x by offsetE, y by offsetF) in window S, the
// scale varying with option K; adds offset_001 and turns (option R). Every part has its window. ----

// Whether the dIFS formula's scale varies (option K with a vary other than 0).
bool difsScaleVaries(Reader& r) {
    return r.boolean("transf_function_enabledK_false") && r.number("transf_scale_vary_0") != 0.0;
}

// A shape step (`block`, its own parameters `shape`) in the window of `suffix` (transf_start/
// stop_iterations + suffix), split by window S (whether its scale, and so DE |s| + 1, counts) and
// by the windows of its options (`options`: each a toggle of the block, its flag and window).
struct DifsOption {
    const char* param;
    const char* flag;
    const char* window;
    double on = 1.0;  // the parameter's value where the option is on (a toggle's 1, or a number)
};
void difsShape(Reader& r, NodeBuilder& b, std::string_view block, const NodeBuilder::Values& shape,
               const std::vector<DifsOption>& options, const std::string& suffix = "") {
    const double scale = r.number("transf_scale_2");
    if (scale < 0.01) return r.unsupported("transf_scale_2 " + fmt(scale) + ": a dIFS scale below 0.01");
    std::vector<std::string> windows{"S"};
    for (const DifsOption& o : options) windows.push_back(o.window);
    const bool varies = difsScaleVaries(r);
    acrossWindows(
        r, r.integer("transf_start_iterations" + suffix), r.integer("transf_stop_iterations" + suffix), windows,
        [&](int start, int stop, const std::vector<bool>& covered) {
            b.within(start, stop, [&] {
                NodeBuilder::Values values(shape.begin(), shape.end());
                values.push_back(N::f("w_scale", covered[0] ? scale : 1.0));
                values.push_back(N::f("w_offset", covered[0] ? 1.0 : 0.0));
                values.push_back(N::f("w_vary", covered[0] && varies ? 1.0 : 0.0));
                for (size_t k = 0; k < options.size(); ++k)
                    values.push_back(
                        N::f(options[k].param, r.boolean(options[k].flag) && covered[k + 1] ? options[k].on : 0.0));
                b.add(block, values);
            });
        });
}

// The dIFS formulas' polygonal fold (option P, window P): transf_int_6 sides.
void polyFold(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_function_enabledP_false")) return;
    const int sides = r.integer("transf_int_6");
    if (sides < 1 || sides > 32)
        return r.unsupported("transf_int_6 " + std::to_string(sides) +
                             ": a polygonal fold of other than 1 to 32 sides");
    inWindow(r, b, "P", "P", [&] { b.add("poly_fold", {N::f("order", double(sides))}); });
}

// The folds before the scale. The sphere's box offsets are transf_addition_constantA_111 under
// options A and B, its second diagonal fold swaps x and y again after the offset folds; the
// cylinder's are transf_addition_constant_111 under Bx and By, its second diagonal fold swaps x
// and z before them.
void difsFolds(Reader& r, NodeBuilder& b, bool sphere) {
    auto fold = [&](const char* flag, const std::string& window, const vec3& normal, double offset) {
        if (!r.boolean(flag)) return;
        inWindow(r, b, window, window, [&] { b.add("plane_fold", {N::v("normal", normal), N::f("offset", offset)}); });
    };
    fold("transf_function_enabledAx", "X", vec3(1.0, 0.0, 0.0), 0.0);
    fold("transf_function_enabledAy", "Y", vec3(0.0, 1.0, 0.0), 0.0);
    fold("transf_function_enabledAz_false", "Z", vec3(0.0, 0.0, 1.0), 0.0);
    if (!r.boolean("transf_function_enabled_false")) return;
    const vec3 box = r.vector(sphere ? "transf_addition_constantA_111" : "transf_addition_constant_111");
    auto shift = [&](const char* flag, const std::string& window, const vec3& by) {
        if (r.boolean(flag)) inWindow(r, b, window, window, [&] { b.add("translate", {N::v("offset", -by)}); });
    };
    shift(sphere ? "transf_function_enabledA_false" : "transf_function_enabledBx_false", "A", vec3(box.x, box.y, 0.0));
    shift(sphere ? "transf_function_enabledB_false" : "transf_function_enabledBy_false", "B", box);
    polyFold(r, b);
    fold("transf_function_enabledCx_false", "Cx", vec3(-1.0, 1.0, 0.0), 0.0);
    if (!sphere) fold("transf_function_enabledCy_false", "Cy", vec3(-1.0, 0.0, 1.0), 0.0);
    fold("transf_function_enabledC_false", "C", vec3(1.0, 0.0, 0.0), r.number("transf_offsetC_0"));
    fold("transf_function_enabledD_false", "D", vec3(0.0, 1.0, 0.0), r.number("transf_offsetD_0"));
    if (sphere) fold("transf_function_enabledCy_false", "Cy", vec3(-1.0, 1.0, 0.0), 0.0);
}

// The scale about the reverse offsets (window S; x's offset in window E, y's in F: transf_offsetE_2
// and _F_2, or with `reverse0` transf_offsetE_0 and _F_0), varying in window K with option K; then
// offset_001 (in window H with `offsetInH`) and the turn. With `exactDerivative` the running
// derivative follows Mandelbulber2's DE |s| + 1 itself (a derivative_tweak adding the 1 after
// the scale), so that a shape measured after the step divides by it alone.
void difsScaleAndTurn(Reader& r, NodeBuilder& b, bool reverse0 = false, bool offsetInH = false,
                      bool exactDerivative = false) {
    const bool varies = difsScaleVaries(r);
    const double e = r.number(reverse0 ? "transf_offsetE_0" : "transf_offsetE_2");
    const double f = r.number(reverse0 ? "transf_offsetF_0" : "transf_offsetF_2");
    acrossWindows(r, r.integer("transf_start_iterations_S"), r.integer("transf_stop_iterations_S"), {"E", "F", "K"},
                  [&](int start, int stop, const std::vector<bool>& covered) {
                      b.within(start, stop, [&] {
                          b.add("scale_vary", {N::f("scale", r.number("transf_scale_2")),
                                               N::f("vary", varies ? r.number("transf_scale_vary_0") : 0.0),
                                               N::f("limit", r.number("transf_scaleC_1")),
                                               N::f("update", varies && covered[2] ? 1.0 : 0.0),
                                               N::v("center", vec3(covered[0] ? e : 0.0, covered[1] ? f : 0.0, 0.0))});
                          if (exactDerivative) b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)});
                      });
                  });
    const vec3 offset = r.vector("transf_offset_001");
    if (length(offset) > 0.0) {
        if (offsetInH)
            inWindow(r, b, "H", "H", [&] { b.add("translate", {N::v("offset", offset)}); });
        else
            b.add("translate", {N::v("offset", offset)});
    }
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
}

// The cylinder and, with option I, the torus beside it (in window I; its axes exchanged with
// option J, refused).
void mapDifsCylinder(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_function_enabledI_false")) {
        r.mustBeDefault("transf_function_enabledJ_false", "the torus about x");
        difsShape(r, b, "difs_torus",
                  {N::f("ring_radius", r.number("transf_offsetT_1")), N::f("thickness", r.number("transf_offset_05"))},
                  {}, "_I");
    }
    difsShape(r, b, "difs_cylinder",
              {N::f("radius", r.number("transf_radius_1")), N::f("height", r.number("transf_offsetA_1")),
               N::f("cone", r.number("transf_scale_0")), N::f("round", r.number("transf_offsetR_0")),
               N::f("swap_xz", r.boolean("transf_function_enabledSw_false") ? 1.0 : 0.0)},
              {{"signed_z", "transf_function_enabledM_false", "M"},
               {"squared_z", "transf_function_enabledT_false", "T"},
               {"flat_tops", "transf_function_enabledN_false", "N"},
               {"rings", "transf_function_enabledO_false", "O"}});
    difsFolds(r, b, false);
    difsScaleAndTurn(r, b);
}

void mapDifsSphere(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabled4d_false", "the sphere measured in 4D");
    r.mustBeDefault("transf_function_enabledT_false", "the torus beside the sphere");
    const double radius = r.number("transf_offsetR_1");
    difsShape(r, b, "difs_ellipsoid", {N::v("radii", vec3(radius))}, {});
    difsFolds(r, b, true);
    difsScaleAndTurn(r, b);
}

// difs_torus (DIFSTorusIteration in fractal_formulas.cpp of 2.20): the torus about z (ring radius
// transf_offsetT_1, tube transf_offset_05) in its window, measured as the sphere is, then the
// sphere's folds, scale and turn. The torus about x (option Sw) and the stretched torus (option
// M) are refused, and so is a torus switched off (nothing left to measure).
void mapDifsTorus(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledM", "the torus switched off");
    r.mustBeDefault("transf_function_enabledSw_false", "the torus about x");
    r.mustBeDefault("transf_function_enabledM_false", "the stretched torus");
    difsShape(r, b, "difs_torus",
              {N::f("ring_radius", r.number("transf_offsetT_1")), N::f("thickness", r.number("transf_offset_05"))}, {});
    difsFolds(r, b, true);
    difsScaleAndTurn(r, b);
}

// Mandelbulber2's dIFS diagonal boxes (difs_box_diagonal_v1, _v3: DIFSBoxDiagonalV1Iteration and
// V3 in formula/opencl of 2.20): folds, the scale about the reverse offsets (transf_offsetE_0,
// _F_0) and the turn of the dIFS formulas above, the running derivative carried as Mandelbulber2's
// DE |s| + 1, then the box of half-sizes transf_addition_constant_111 measured at the point the
// iteration ends on, over that derivative; with option Y at the point it started from, over the
// derivative after the scale, as the cylinder. V1 swaps x and y where x > y (window Cx), takes |x|, |y| (windows
// X, Y) and subtracts transf_addition_constantA_111's x and y (window A) whatever its options say;
// V3 subtracts surfBox_offset1A_111 (option A), takes the abs of its options Ax, Ay, Az, swaps
// where y > x (Cx), subtracts transf_addition_constantA_111 (B) and folds Tglad's way at
// transf_offsetA_000 (I). The box's curved and pyramid sides and V3's polygonal fold are refused.
void mapDifsBoxDiagonal(Reader& r, NodeBuilder& b, bool v3) {
    r.mustBeDefault("transf_function_enabledT_false", "the box's sides curved by z^2");
    r.mustBeDefault("transf_function_enabledM_false", "the box narrowed along z (a pyramid)");
    if (v3) r.mustBeDefault("transf_function_enabledP_false", "the polygonal fold");
    const vec3 size = r.vector("transf_addition_constant_111");
    const bool atStart = r.boolean("transf_function_enabledY_false");
    if (atStart) difsShape(r, b, "difs_box", {N::v("size", size)}, {});
    auto fold = [&](bool on, const std::string& window, const vec3& normal, double offset) {
        if (on)
            inWindow(r, b, window, window, [&] {
                b.add("plane_fold", {N::v("normal", normal), N::f("offset", offset)});
            });
    };
    auto shift = [&](bool on, const std::string& window, const vec3& by) {
        if (on) inWindow(r, b, window, window, [&] { b.add("translate", {N::v("offset", -by)}); });
    };
    const vec3 boxFold = r.vector("transf_addition_constantA_111");
    if (v3) {
        shift(r.boolean("transf_function_enabledA_false"), "A", r.vector("surfBox_offset1A_111"));
        fold(r.boolean("transf_function_enabledAx"), "X", vec3(1.0, 0.0, 0.0), 0.0);
        fold(r.boolean("transf_function_enabledAy"), "Y", vec3(0.0, 1.0, 0.0), 0.0);
        fold(r.boolean("transf_function_enabledAz_false"), "Z", vec3(0.0, 0.0, 1.0), 0.0);
        fold(r.boolean("transf_function_enabledCx_false"), "Cx", vec3(1.0, -1.0, 0.0), 0.0);
        shift(r.boolean("transf_function_enabledB_false"), "B", boxFold);
        if (r.boolean("transf_function_enabledI_false"))
            inWindow(r, b, "I", "I", [&] {
                const vec3 limit = r.vector("transf_offsetA_000");
                b.add("box_fold_general",
                      {N::v("low", limit), N::v("high", limit), N::v("mirror", vec3(1.0)), N::v("offset", vec3(0.0))});
            });
    } else {
        fold(true, "Cx", vec3(-1.0, 1.0, 0.0), 0.0);
        fold(true, "X", vec3(1.0, 0.0, 0.0), 0.0);
        fold(true, "Y", vec3(0.0, 1.0, 0.0), 0.0);
        shift(true, "A", vec3(boxFold.x, boxFold.y, 0.0));
    }
    fold(r.boolean("transf_function_enabledC_false"), "C", vec3(1.0, 0.0, 0.0), r.number("transf_offsetC_0"));
    fold(r.boolean("transf_function_enabledD_false"), "D", vec3(0.0, 1.0, 0.0), r.number("transf_offsetD_0"));
    if (v3) fold(r.boolean("transf_function_enabledCy_false"), "Cy", vec3(1.0, -1.0, 0.0), 0.0);
    difsScaleAndTurn(r, b, true, v3, true);
    if (atStart) return;
    b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), [&] {
        b.add("difs_box", {N::v("size", size), N::f("w_scale", 1.0), N::f("w_offset", 0.0), N::f("w_vary", 0.0)});
    });
}
void mapDifsBoxDiagonalV1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { mapDifsBoxDiagonal(r, b, false); }

// Mandelbulber2's dIFS box (difs_box_v1: DIFSBoxV1Iteration in fractal_formulas.cpp of 2.20), the
// diagonal box's sibling: |x|, |y|, |z| (options Ax, Ay, Az, windows X, Y, Z), Tglad's fold of x
// and y at transf_addition_constantA_111 (option Cx, on by default; window A), that constant taken
// off x, y and z (B), the polygonal fold (P), x and y swapped where x > y (Cx_false), the offset
// folds (C, D), the swap again (Cy); then the scale about the reverse offsets, offset_001 and the
// turn as the diagonal box, and the box of half-sizes transf_addition_constant_111 at the point
// the iteration ends on (with option Y where it starts), its x and y sides curved by scale_0 z^2
// (option T, window T) and narrowed by scaleA_0 z (M, window M). Option E takes offsetB_0 off the
// least distance so far on every iteration, which is refused.
void mapDifsBoxV1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_function_enabledE_false"))
        r.mustBeDefault("transf_offsetB_0", "the least dIFS distance less an offset every iteration");
    const vec3 size = r.vector("transf_addition_constant_111");
    const std::vector<DifsOption> sides{
        {"curve", "transf_function_enabledT_false", "T", r.number("transf_scale_0")},
        {"pyramid", "transf_function_enabledM_false", "M", r.number("transf_scaleA_0")}};
    const bool atStart = r.boolean("transf_function_enabledY_false");
    if (atStart) difsShape(r, b, "difs_box", {N::v("size", size)}, sides);
    auto fold = [&](bool on, const std::string& window, const vec3& normal, double offset) {
        if (on)
            inWindow(r, b, window, window, [&] {
                b.add("plane_fold", {N::v("normal", normal), N::f("offset", offset)});
            });
    };
    fold(r.boolean("transf_function_enabledAx_false"), "X", vec3(1.0, 0.0, 0.0), 0.0);
    fold(r.boolean("transf_function_enabledAy_false"), "Y", vec3(0.0, 1.0, 0.0), 0.0);
    fold(r.boolean("transf_function_enabledAz_false"), "Z", vec3(0.0, 0.0, 1.0), 0.0);
    const vec3 boxFold = r.vector("transf_addition_constantA_111");
    if (r.boolean("transf_function_enabledCx"))
        inWindow(r, b, "A", "A", [&] { b.add("box_fold_axes", {N::v("limit", boxFold), N::f("fold_z", 0.0)}); });
    if (r.boolean("transf_function_enabledB_false"))
        inWindow(r, b, "B", "B", [&] { b.add("translate", {N::v("offset", -boxFold)}); });
    polyFold(r, b);
    fold(r.boolean("transf_function_enabledCx_false"), "Cx", vec3(-1.0, 1.0, 0.0), 0.0);
    fold(r.boolean("transf_function_enabledC_false"), "C", vec3(1.0, 0.0, 0.0), r.number("transf_offsetC_0"));
    fold(r.boolean("transf_function_enabledD_false"), "D", vec3(0.0, 1.0, 0.0), r.number("transf_offsetD_0"));
    fold(r.boolean("transf_function_enabledCy_false"), "Cy", vec3(-1.0, 1.0, 0.0), 0.0);
    difsScaleAndTurn(r, b, true, false, true);
    if (atStart) return;
    acrossWindows(
        r, r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), {"T", "M"},
        [&](int start, int stop, const std::vector<bool>& covered) {
            b.within(start, stop, [&] {
                NodeBuilder::Values values{N::v("size", size), N::f("w_scale", 1.0), N::f("w_offset", 0.0),
                                           N::f("w_vary", 0.0)};
                for (size_t k = 0; k < sides.size(); ++k)
                    values.push_back(N::f(sides[k].param, r.boolean(sides[k].flag) && covered[k] ? sides[k].on : 0.0));
                b.add("difs_box", values);
            });
        });
}
void mapDifsBoxDiagonalV3(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { mapDifsBoxDiagonal(r, b, true); }

// msltoe's sym2 mod and eiffie's variant share their parameters.
void msltoeTriplex(Reader& r, NodeBuilder& b, std::string_view block) {
    r.mustBeDefault("transf_addCpixel_enabled_false", "an extra multiple of c, signed by the point");
    b.add(block, {N::f("y_scale", r.number("transf_scale")), N::v("add", r.vector("transf_addition_constant")),
                  N::f("offset", r.number("transf_offset")), N::f("scale", r.number("transf_scale_1"))});
}
void mapMsltoeSym2Mod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { msltoeTriplex(r, b, "msltoe_sym2_mod"); }
void mapEiffieMsltoe(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { msltoeTriplex(r, b, "eiffie_msltoe"); }

// The sym3 family's signed multiple of c (transf_addCpixel_enabled_false) comes after `add` and
// before the pull and the scale: a step of its own after the block where those two leave the point
// as it is, else refused.
void msltoeSymmetricMultipleOfC(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_addCpixel_enabled_false")) return;
    if (r.number("transf_offset") != 0.0 || r.number("transf_scale_1") != 1.0)
        return r.unsupported(
            "transf_addCpixel_enabled_false: a multiple of c signed by the point before the pull "
            "towards the origin (transf_offset) and the scale (transf_scale_1)");
    symmetricMultipleOfC(r, b, "transf_constant_multiplier_000");
}
// The quaternion fold of sym3 mod and mod3 (option "enabled_false", window A): the point becomes
// (x^2 - y^2 - z^2, 2 x y, 2 x z), the twist-free Bristorbrot, whose derivative 2 r is
// Mandelbulber2's. Its other derivative (analyticDE_enabled_false: times the average stretch of
// the (1, 2, 2) factor) is refused.
void msltoeQuaternionFold(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_function_enabled_false")) return;
    r.mustBeDefault("analyticDE_enabled_false", "the quaternion fold's derivative times its average stretch");
    inWindow(r, b, "A", "A", [&] { b.add("bristorbrot", {N::f("twist", 0.0)}); });
}
// msltoe_sym3_mod and msltoe_sym3_mod3 (MsltoeSym3ModIteration, MsltoeSym3Mod3Iteration of 2.20):
// the block's octant swap or sector turn, the triplex with the stretch transf_scale_0, then the
// signed multiple of c and the quaternion fold. mod3's derivative takes no 1 for c
// (derivativeTakesNoOneForC).
void msltoeSym3(Reader& r, NodeBuilder& b, bool sector) {
    b.add("msltoe_sym3_mod",
          {N::f("y_scale", r.number("transf_scale")), N::v("add", r.vector("transf_addition_constant")),
           N::f("offset", r.number("transf_offset")), N::f("scale", r.number("transf_scale_1")),
           N::f("stretch", r.number("transf_scale_0")), N::f("sector", sector ? 1.0 : 0.0)});
    msltoeSymmetricMultipleOfC(r, b);
    msltoeQuaternionFold(r, b);
}
void mapMsltoeSym3Mod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { msltoeSym3(r, b, false); }
void mapMsltoeSym3Mod3(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) { msltoeSym3(r, b, true); }
// msltoe_sym3_mod2 (MsltoeSym3Mod2Iteration): the block with the stretch transf_scale_0, then the
// signed multiple of c; its derivative takes no 1 for c (derivativeTakesNoOneForC).
void mapMsltoeSym3Mod2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("msltoe_sym3_mod2",
          {N::f("stretch", r.number("transf_scale_0")), N::v("add", r.vector("transf_addition_constant")),
           N::f("offset", r.number("transf_offset")), N::f("scale", r.number("transf_scale_1"))});
    msltoeSymmetricMultipleOfC(r, b);
}
// msltoe_sym4_mod (MsltoeSym4ModIteration): the fold weighted by transf_constant_multiplier_111,
// the scale per axis transf_scale3D_111, the quaternion square (the twist-free Bristorbrot),
// transf_addition_constant, the rotation (transf_rotation_enabled), then the signed multiple of c.
// The pull towards the origin and the scale after the rotation are refused where set; its
// derivative takes no 1 for c (derivativeTakesNoOneForC).
void mapMsltoeSym4Mod(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_offset", "the pull towards the origin after the rotation");
    r.mustBeDefault("transf_scale_1", "the scale after the rotation");
    b.add("msltoe_sym4_fold", {N::v("weights", r.vector("transf_constant_multiplier_111"))});
    const vec3 stretch = r.vector("transf_scale3D_111");
    if (stretch != vec3(1.0)) b.add("axis_scale", {N::v("scale", stretch)});
    b.add("bristorbrot", {N::f("twist", 0.0)});
    additionConstant(r, b);
    if (r.boolean("transf_rotation_enabled")) b.rotation(setRotation2(r.vector("transf_rotation")));
    symmetricMultipleOfC(r, b, "transf_constant_multiplier_000");
}

// The platonic solid transform: v times A theta(F v) + rhoMul rho (platonic_solid). Its first
// mode takes rho = sqrt(r); its second (transf_function_enabled_false) sums sqrt(r), r and r^2 as
// options x, y and z say, or blends the first two (Ax) or the last two (Ay) by transf_scale_1, and
// takes the wave's abs with Az. Its derivative's own factor (analyticDE_scale_1) is listed.
void mapTransfPlatonicSolid(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const double mul = r.number("platonic_solid_rhoMul");
    vec3 weights(1.0, 0.0, 0.0);  // of sqrt(r), r, r^2
    bool absWave = false;
    if (r.boolean("transf_function_enabled_false")) {
        const vec3 on(r.boolean("transf_function_enabledx"), r.boolean("transf_function_enabledy_false"),
                      r.boolean("transf_function_enabledz_false"));
        const double blend = r.number("transf_scale_1");
        if (r.boolean("transf_function_enabledAx_false"))
            weights = vec3(on.x * (1.0 - blend), on.y * blend, 0.0);
        else if (r.boolean("transf_function_enabledAy_false"))
            weights = vec3(0.0, on.y * (1.0 - blend), on.z * blend);
        else
            weights = on;
        absWave = r.boolean("transf_function_enabledAz_false");
    }
    b.add("platonic_solid",
          {N::f("frequency", r.number("platonic_solid_frequency")),
           N::f("amplitude", r.number("platonic_solid_amplitude")), N::f("abs_wave", absWave ? 1.0 : 0.0),
           N::f("root", mul * weights.x), N::f("linear", mul * weights.y), N::f("square", mul * weights.z)});
    // Its derivative times analyticDE_scale_1 plus _offset_1, where the analytic DE is on.
    if (r.boolean("analyticDE_enabled")) derivativeTweak(r, b, true);
}

// The fold box mod 1 (FoldBoxMod1Iteration), each part in its window: the general box fold
// |v + a| - |v - b| - m v per axis (transf_start/stop_iterations), the box fold with z's limit
// times transf_scale_1 (option A), the Mandelbox sphere fold (B), the scale (varying in window D
// with option X, plain elsewhere) and the main rotation (C). A box fold with one of its limits
// left out is refused.
void mapFoldBoxMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    for (const char* axis : {"transf_function_enabledx", "transf_function_enabledy", "transf_function_enabledz",
                             "transf_function_enabledAx", "transf_function_enabledAy", "transf_function_enabledAz"})
        if (!r.boolean(axis)) r.unsupported(std::string(axis) + " false: a box fold with one of its limits left out");
    b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), [&] {
        b.add("box_fold_general", {N::v("low", r.vector("transf_addition_constant_111")),
                                   N::v("high", r.vector("transf_addition_constantA_111")),
                                   N::v("mirror", r.vector("transf_scale3D_111"))});
    });
    if (r.boolean("transf_function_enabled_false")) boxFoldScaledZ(r, b);
    inWindow(r, b, "B", "B", [&] {
        sphereFold(b, r.number("mandelbox_folding_min_radius"), r.number("mandelbox_folding_fixed_radius"));
    });
    const double scale = r.number("mandelbox_scale");
    const bool varies = r.boolean("transf_function_enabledX_false");
    acrossWindows(r, 0, kMaxIterations, varies ? std::vector<std::string>{"D"} : std::vector<std::string>{},
                  [&](int start, int stop, const std::vector<bool>& covered) {
                      b.within(start, stop, [&] {
                          if (covered.empty() || !covered[0]) return b.add("scale", {N::f("scale", scale)});
                          scaleVaryNode(r, b, scale, r.number("transf_scale_vary_0"), "transf_scaleB_1", true);
                      });
                  });
    if (r.boolean("mandelbox_main_rotation_enabled"))
        inWindow(r, b, "C", "C", [&] { b.rotation(setRotation2(r.vector("mandelbox_rotation_main"))); });
}

// The Sierpinski tetrahedron of Mandelbulber2 (Sierpinski3dIteration): the full tetra fold (the
// sort x >= y >= z, then the mirrors across x + y = 0, x + z = 0 and y + z = 0; with
// transf_function_enabled_false the reversed one after it, mirrors first), the scale
// transf_scaleA_2, less offset_111 in window C, the rotation in window R. Each mirror and swap is
// a plane fold. With analyticDE_enabled_false the derivative's own factor and offset are listed.
void mapSierpinski3d(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    auto mirrors = [&](const std::vector<vec3>& normals) {
        for (const vec3& n : normals) b.add("plane_fold", {N::v("normal", n), N::f("offset", 0.0)});
    };
    const std::vector<vec3> sort{vec3(1, -1, 0), vec3(1, 0, -1), vec3(0, 1, -1)};
    const std::vector<vec3> sums{vec3(1, 1, 0), vec3(1, 0, 1), vec3(0, 1, 1)};
    if (r.boolean("transf_function_enabled")) {
        mirrors(sort);
        mirrors(sums);
    }
    if (r.boolean("transf_function_enabled_false")) {
        mirrors(sums);
        mirrors(sort);
    }
    b.add("scale", {N::f("scale", r.number("transf_scaleA_2"))});
    inWindow(r, b, "C", "C", [&] { b.add("translate", {N::v("offset", -r.vector("transf_offset_111"))}); });
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
    if (r.boolean("analyticDE_enabled_false") &&
        (r.number("analyticDE_scale_1") != 1.0 || r.number("analyticDE_offset_0") != 0.0))
        approximated.push_back({r.where(), "analyticDE: the derivative's own factor and offset are left out"});
}

// Knighty's cross Menger KIFS (MengerCrossKIFSIteration) in window A: |y| and |z| (|x| with
// transf_function_enabledz_false), the mirror across the plane at 30 degrees to x, |y| again, y
// and z sorted, y mirrored about 1/2, with option x the point mirrored through the edge offset_222,
// then the scale transf_scale_3 about (sqrt(3)/2, 3/2, 3/2), the offset, option P's x abs with
// offsets, and the rotation transf_rotation2 in window R. Each mirror is a plane fold; the step
// before it (transf_function_enabled_false) is refused.
void mapMengerCrossKifs(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabled_false", "the cross step before the cross Menger step");
    if (!r.boolean("transf_function_enabled")) return;
    inWindow(r, b, "A", "A", [&] {
        auto mirror = [&](const vec3& normal, double offset) {
            b.add("plane_fold", {N::v("normal", normal), N::f("offset", offset)});
        };
        mirror(vec3(0, 1, 0), 0.0);
        mirror(vec3(0, 0, 1), 0.0);
        if (r.boolean("transf_function_enabledz_false")) mirror(vec3(1, 0, 0), 0.0);
        mirror(vec3(std::sqrt(3.0) / 2.0, -0.5, 0.0), 0.0);
        mirror(vec3(0, 1, 0), 0.0);
        mirror(vec3(0, -1, 1), 0.0);
        mirror(vec3(0, 1, 0), 0.5);
        if (r.boolean("transf_function_enabledx_false")) {
            b.add("scale", {N::f("scale", -1.0)});
            b.add("translate", {N::v("offset", r.vector("transf_offset_222"))});
        }
        b.add("scale",
              {N::f("scale", r.number("transf_scale_3")), N::v("center", vec3(std::sqrt(3.0) / 2.0, 1.5, 1.5))});
        const vec3 offset = r.vector("transf_offset_000");
        if (length(offset) > 0.0) b.add("translate", {N::v("offset", offset)});
        if (r.boolean("transf_function_enabledP_false")) {
            b.add("translate", {N::v("offset", vec3(r.number("transf_offset"), 0.0, 0.0))});
            mirror(vec3(1, 0, 0), 0.0);
            b.add("translate", {N::v("offset", vec3(r.number("transf_offset_0"), 0.0, 0.0))});
        }
        if (r.boolean("transf_function_enabledR_false"))
            inWindow(r, b, "R", "R", [&] { b.rotation(setRotation2(r.vector("transf_rotation2"))); });
    });
}

// The smooth Menger sponge, its rotation in window R.
void mapMengerSmooth(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledz_false", "iteration weights");
    const double k = r.number("transf_offset_0005");
    b.add("menger_smooth", {N::f("scale", r.number("transf_scale_3")), N::v("offset", r.vector("transf_offset_1105")),
                            N::f("abs_smoothness", k), N::v("sort_smoothness", vec3(k)), N::f("fold_smoothness", k)});
    windowedRotation(r, b, "transf_rotation_enabled", "_R");
}

// Its mod 1: the abs rounded by its own amount, each sort by its own, weighted; the corner given
// as (o.x (s - 1), o.y (s - 1)) and z's fold centre as o.z / 3; then the rotation (window R) and
// the box offset sign(v) a + v (window A: abs_add_conditional with multiplier 2). Option F adds
// an offset after an abs: after the rounded abs, whose values are positive, the abs is the same;
// without the rounded abs it is the plain one.
void mapMengerSmoothMod1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledz_false", "iteration weights");
    const bool roundedAbs = r.boolean("transf_function_enabled"),
               offsetAbs = r.boolean("transf_function_enabledF_false");
    if (!roundedAbs && !offsetAbs)
        r.unsupported(
            "transf_function_enabled and transf_function_enabledF_false false: a Menger step without its abs");
    const double s = r.number("transf_scale_3"), k = r.number("transf_offset_0005");
    if (std::abs(s - 1.0) < 1e-9) return r.unsupported("transf_scale_3 1: a Menger step with scale 1 does not shrink");
    const vec3 corner = r.vector("transf_constant_multiplier_221");
    b.add("menger_smooth",
          {N::f("scale", s),
           N::v("offset", vec3(corner.x / (s - 1.0), corner.y / (s - 1.0), corner.z * s / (3.0 * (s - 1.0)))),
           N::f("abs_smoothness", roundedAbs ? r.number("transf_offset_0") : 0.0),
           N::f("abs_offset", offsetAbs ? r.number("transf_offset") : 0.0),
           N::v("sort_smoothness", k * r.vector("transf_constant_multiplier_111")), N::f("fold_smoothness", k),
           N::f("sort_weight", r.number("transf_scale_05"))});
    windowedRotation(r, b, "transf_rotation_enabled", "_R");
    if (r.boolean("transf_function_enabledx_false"))
        inWindow(r, b, "A", "A", [&] {
            b.add("abs_add_conditional",
                  {N::v("axes", vec3(1.0)), N::v("offset", r.vector("transf_addition_constantA_000")),
                   N::v("multiplier", vec3(2.0))});
        });
}

// The smooth folds, the main rotation, the scale (a uniform scale commutes with the rotation).
void mapMandelboxSmooth(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("mandelbox_smooth_fold",
          {N::f("limit", r.number("mandelbox_folding_limit")), N::f("value", r.number("mandelbox_folding_value")),
           N::f("min_radius", std::max(r.number("mandelbox_folding_min_radius"), 0.001)),
           N::f("fixed_radius", r.number("mandelbox_folding_fixed_radius")),
           N::f("sharpness", r.number("mandelbox_sharpness"))});
    if (r.boolean("mandelbox_main_rotation_enabled")) b.rotation(setRotation2(r.vector("mandelbox_rotation_main")));
    b.add("scale", {N::f("scale", r.number("mandelbox_scale"))});
}

// transf_abs_add_multi: |v + a| - |v - o| - m v + add per axis, the general box fold.
void mapTransfAbsAddMulti(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    for (const char* axis : {"transf_function_enabledAx", "transf_function_enabledAy", "transf_function_enabledAz",
                             "transf_function_enabledx", "transf_function_enabledy", "transf_function_enabledz"})
        r.mustBeDefault(axis, "a box fold with one of its limits left out");
    b.add("box_fold_general",
          {N::v("low", r.vector("transf_addition_constant")), N::v("high", r.vector("transf_offset_000")),
           N::v("mirror", r.vector("transf_scale3D_111")), N::v("offset", r.vector("transf_offsetA_000"))});
}

// transf_sin_and_cos_max: each chosen axis the largest of its two waves and their product
// (sin_cos_max), v added or multiplied back in as combo4 says when enabledM is on. Its analytic DE
// tweak is Mandelbulber2's own estimate of the stretch; fraktal's derivative bounds it.
void mapTransfSinAndCosMax(Reader& r, NodeBuilder& b, std::vector<ImportItem>& approximated) {
    const std::string combo = r.raw("combo4");
    int keep = 0;
    if (r.boolean("transf_function_enabledM_false")) {
        keep = combo == "0" || combo == "type1" ? 1
               : combo == "type2"               ? 2
               : combo == "type3"               ? 3
               : combo == "type4"               ? 4
                                                : 0;
        if (keep == 0) r.unsupported("combo4 " + combo + ": a way of keeping v that Mandelbulber2 2.20 does not have");
    }
    if (r.boolean("analyticDE_enabled_false"))
        approximated.push_back({r.where(),
                                "analyticDE: the derivative's own factor and offset are left out (fraktal's "
                                "derivative bounds the waves' slope)"});
    auto on = [&](const char* key) { return r.boolean(key) ? 1.0 : 0.0; };
    b.add("sin_cos_max",
          {N::f("x", on("transf_function_enabledAx")), N::f("y", on("transf_function_enabledAy_false")),
           N::f("z", on("transf_function_enabledAz_false")),
           N::v("sin_period", r.vector("transf_constant_multiplierA_111")),
           N::v("cos_period", r.vector("transf_constant_multiplierB_111")),
           N::f("sin_scale", r.number("transf_scaleA_1")), N::f("cos_scale", r.number("transf_scaleB_1")),
           N::f("product_scale", r.number("transf_scaleC_1")), N::f("divide", on("transf_function_enabled_false")),
           N::f("scale", r.number("transf_scale")), N::f("keep", keep)});
}

// transf_sin_or_cos (TransfSinOrCosIteration in fractal_formulas.cpp of 2.20): each axis where
// transf_function_enabledA{x,y,z} say becomes transf_scale sin(m v), cos where
// transf_function_enabledA{x,y,z}_false say, m transf_constant_multiplierC_111; the others 0. With
// transf_function_enabled_false each axis is scaled again and divided by |v| + 1. The running
// derivative is Mandelbulber2's (|transf_scale|, the block's mb2_derivative) plus 1, or times
// analyticDE_scale_1 plus analyticDE_offset_1 with analyticDE_enabled_false: a derivative_tweak.
void mapTransfSinOrCos(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    auto on = [&](const char* key) { return r.boolean(key) ? 1.0 : 0.0; };
    b.add("sin_or_cos",
          {N::f("x", on("transf_function_enabledAx")), N::f("y", on("transf_function_enabledAy")),
           N::f("z", on("transf_function_enabledAz")), N::f("cos_x", on("transf_function_enabledAx_false")),
           N::f("cos_y", on("transf_function_enabledAy_false")), N::f("cos_z", on("transf_function_enabledAz_false")),
           N::v("multiplier", r.vector("transf_constant_multiplierC_111")), N::f("scale", r.number("transf_scale")),
           N::f("divide", on("transf_function_enabled_false")), N::f("mb2_derivative", 1.0)});
    const bool tweak = r.boolean("analyticDE_enabled_false");
    b.add("derivative_tweak", {N::f("scale", tweak ? r.number("analyticDE_scale_1") : 1.0),
                               N::f("offset", tweak ? r.number("analyticDE_offset_1") : 1.0)});
}

// transf_spherical_inv: v + offset scaled, inverted in the unit sphere, less offset and the added
// constant. Its conditional mode (inversion within a radius) is refused.
void mapTransfSphericalInv(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledz_false", "the conditional inversion (within the fixed radius)");
    const vec3 offset = r.vector("mandelbox_offset");
    if (length(offset) > 0.0) b.add("translate", {N::v("offset", offset)});
    b.add("scale", {N::f("scale", r.number("transf_scale"))});
    // TransfSphericalInvIteration (fractal_formulas.cpp of 2.20) adds 1 to the running derivative
    // with the scale, and its analytic tweak (scale_1, offset_0) after the inversion.
    b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)});
    b.add("sphere_invert", {N::f("radius", 1.0)});
    const vec3 back = offset + r.vector("transf_addition_constant");
    if (length(back) > 0.0) b.add("translate", {N::v("offset", -back)});
    analyticTweakWhereEnabled(r, b, "analyticDE_offset_0");
}

// transf_benesi_t1: |v| scaled per axis in Benesi's frame, less offset_200 (its rotation inside the
// frame refused).
void mapTransfBenesiT1(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_rotation_enabled", "a rotation inside Benesi's frame");
    b.add("benesi_t1", {N::v("scale", r.vector("transf_scale3D_222")), N::v("offset", r.vector("transf_offset_200"))});
}

// transf_diagonal_fold: x and y swapped where x > y, y and z where y > z, z and x where z > x (each a
// plane fold through the diagonal plane), each on all iterations or in its own window (A, B, C).
void mapTransfDiagonalFold(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const bool windowed = r.boolean("transf_function_enabledAx_false");
    auto swapFold = [&](const char* enabled, const char* window, const vec3& normal) {
        if (!r.boolean(enabled)) return;
        const int start = windowed ? r.integer(std::string("transf_start_iterations_") + window) : 0;
        const int stop = windowed ? r.integer(std::string("transf_stop_iterations_") + window) : kMaxIterations;
        b.within(start, stop, [&] { b.add("plane_fold", {N::v("normal", normal), N::f("offset", 0.0)}); });
    };
    swapFold("transf_function_enabledAx", "A", vec3(-1.0, 1.0, 0.0));
    swapFold("transf_function_enabledAy_false", "B", vec3(0.0, -1.0, 1.0));
    swapFold("transf_function_enabledAz_false", "C", vec3(1.0, 0.0, -1.0));
}

void mapTransfAddConstant(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("translate",
          {N::v("offset", r.vector("transf_addition_constant") + r.vector("transf_addition_constantA_000"))});
}
void mapTransfScale(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.add("scale", {N::f("scale", r.number("transf_scale"))});
}
void mapTransfRotation(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    b.rotation(setRotation2(r.vector("transf_rotation")));
}

// One of Mandelbulber2's six axis orders (mandelbulbMulti_order_of_xyz and its kin), written as its
// number or its name: 0 xyz, 1 xzy, 2 yxz, 3 yzx, 4 zxy, 5 zyx; -1 for anything else.
int axisOrder(Reader& r, const std::string& key) {
    static constexpr std::array<std::string_view, 6> kNames{"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};
    const std::string v = r.raw(key);
    for (int k = 0; k < 6; ++k)
        if (v == kNames[size_t(k)] || v == std::to_string(k)) return k;
    r.unsupported(key + " " + v + ": not an axis order");
    return -1;
}
// A two-way choice written as its number or its name (mandelbulbMulti_acos_or_asin: acos or asin;
// _atan_or_atan2: atan or atan2): whether it is the second.
bool secondChoice(Reader& r, const std::string& key, const std::string& second) {
    const std::string v = r.raw(key);
    return v == "1" || v == second;
}

// The Kali bulbs' abs of the axes transf_function_enabledAx/Ay/Az_false choose, with the option
// transf_function_enabled_false: plane folds through the origin.
void absOfChosenAxes(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_function_enabled_false")) return;
    for (int k = 0; k < 3; ++k)
        if (r.boolean(std::string("transf_function_enabledA") + "xyz"[k] + "_false")) {
            axisMirror(b, k);
        }
}

void multiBulbMultipleOfC(Reader& r, NodeBuilder& b);

// Kali's multi Mandelbulb: the axes made positive first where transf_function_enabled_false and
// enabledA{x,y,z}_false say (each a plane fold), the bulb of both measurements, then the formula's
// own multiple of c in mandelbulbMulti_order_of_xyz_C (xyz, or yxz as add_c_axes' swap_xy).
void mapMandelbulbKaliMulti(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("analyticDE_enabled_false", "a tweak of the bulb's running derivative");
    absOfChosenAxes(r, b);
    const int order = axisOrder(r, "mandelbulbMulti_order_of_xyz");
    const bool own = r.boolean("transf_function_enabledx_false");  // the second measurement's own choices
    const int second = own ? axisOrder(r, "mandelbulbMulti_order_of_xyz_2") : order;
    const std::string suffix = own ? "_A" : "";
    b.add("mandelbulb_kali_multi",
          {N::f("power", r.number("transf_pwr_8")), N::f("order", std::max(order, 0)),
           N::f("order_second", std::max(second, 0)),
           N::f("theta_asin", secondChoice(r, "mandelbulbMulti_acos_or_asin", "asin")),
           N::f("theta_asin_second", secondChoice(r, "mandelbulbMulti_acos_or_asin" + suffix, "asin")),
           N::f("phi_atan", !secondChoice(r, "mandelbulbMulti_atan_or_atan2", "atan2")),
           N::f("phi_atan_second", !secondChoice(r, "mandelbulbMulti_atan_or_atan2" + suffix, "atan2")),
           N::f("sine_first", r.boolean("transf_function_enabledBx_false")),
           N::f("sine_second", r.boolean("transf_function_enabledz_false")),
           N::f("theta_scale", r.number("transf_scaleA_1")), N::f("phi_scale", r.number("transf_scaleB_1")),
           N::f("theta_offset", r.number("beta_angle_offset")), N::f("phi_offset", r.number("alpha_angle_offset")),
           N::f("theta_offset_second", r.number("transf_beta_angle_offset"))});
    multiBulbMultipleOfC(r, b);
}

// The multi bulbs' own multiple of c (transf_addCpixel_enabled_false): c times
// transf_constant_multiplierC_111 in mandelbulbMulti_order_of_xyz_C (xyz, or yxz as add_c_axes'
// swap_xy).
void multiBulbMultipleOfC(Reader& r, NodeBuilder& b) {
    if (!r.boolean("transf_addCpixel_enabled_false")) return;
    r.mustBeDefault("transf_alternate_enabled_false", "c's axes reordered anew each iteration");
    const int orderC = axisOrder(r, "mandelbulbMulti_order_of_xyz_C");
    if (orderC != 0 && orderC != 2)
        return r.unsupported("mandelbulbMulti_order_of_xyz_C " + r.raw("mandelbulbMulti_order_of_xyz_C") +
                             ": c's axes in an order other than xyz or yxz");
    b.add("add_c_axes", {N::v("weights", r.vector("transf_constant_multiplierC_111")), N::f("julia", 0.0),
                         N::f("swap_xy", orderC == 2 ? 1.0 : 0.0)});
}

// The multi bulb's sine or cosine form and its horizontal factor's theta (before the power with
// option y_false in the cosine form, z_false in the sine form), with the angle options given.
void multiBulb(Reader& r, NodeBuilder& b, int order, bool thetaAsin, bool phiAtan) {
    const bool cosine = r.boolean("transf_function_enabledx_false");
    b.add("mandelbulb_multi",
          {N::f("power", r.number("power")), N::f("order", std::max(order, 0)), N::f("theta_asin", thetaAsin),
           N::f("phi_atan", phiAtan), N::f("cosine", cosine),
           N::f("latitude_unscaled",
                r.boolean(cosine ? "transf_function_enabledy_false" : "transf_function_enabledz_false")),
           N::f("theta_scale", r.number("transf_scaleA_1")), N::f("phi_scale", r.number("transf_scaleB_1")),
           N::f("theta_offset", r.number("beta_angle_offset")), N::f("phi_offset", r.number("alpha_angle_offset"))});
}

// mandelbulb_multi (MandelbulbMultiIteration of 2.20): the abs of the chosen axes, the bulb measured
// in mandelbulbMulti_order_of_xyz with its acos or asin and atan or atan2, then its own multiple of c.
void mapMandelbulbMulti(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    absOfChosenAxes(r, b);
    multiBulb(r, b, axisOrder(r, "mandelbulbMulti_order_of_xyz"),
              secondChoice(r, "mandelbulbMulti_acos_or_asin", "asin"),
              !secondChoice(r, "mandelbulbMulti_atan_or_atan2", "atan2"));
    multiBulbMultipleOfC(r, b);
}

// An orthogonal map: a rotation, or a rotation and the mirror through the origin where it
// reverses handedness.
void orthogonalMap(NodeBuilder& b, const glm::dmat3& m) {
    if (glm::determinant(m) > 0.0) return b.rotation(m);
    b.rotation(-m);
    b.add("axis_scale", {N::v("scale", vec3(-1.0))});
}

// mandelbulb_multi2 (MandelbulbMulti2Iteration of 2.20): with option "enabled_false" the abs of x,
// y and z each in its window (X, Y, Z) where options Ax, Ay, Az_false say; the bulb measured in
// sinTan2Trig_order_of_zyx (Mandelbulber2 numbers it zyx, zxy, yzx, yxz, xzy, xyz) with asin or
// acos and atan2 or atan; with option K_false x and y exchanged (option D_false, window D), x and z
// (E_false, window E) and the axes Bx, By, Bz_false negated; then transf_addition_constant, the
// multiple of c and the rotation (option R_false, window R).
void mapMandelbulbMulti2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("transf_function_enabled_false"))
        for (int k = 0; k < 3; ++k) {
            const std::string axis(1, "xyz"[k]), upper(1, "XYZ"[k]);
            if (r.boolean("transf_function_enabledA" + axis + "_false"))
                inWindow(r, b, upper, upper, [&] { axisMirror(b, k); });
        }
    const std::string zyx = r.raw("sinTan2Trig_order_of_zyx");
    int order = -1;
    for (int k = 0; k < 6; ++k)
        if (zyx == std::to_string(k)) order = 5 - k;
    if (order < 0) order = axisOrder(r, "sinTan2Trig_order_of_zyx");
    multiBulb(r, b, order, !secondChoice(r, "sinTan2Trig_asin_or_acos", "acos"),
              secondChoice(r, "sinTan2Trig_atan2_or_atan", "atan"));
    if (r.boolean("transf_function_enabledK_false")) {
        auto exchange = [&](const char* option, const std::string& window, int a, int c) {
            if (!r.boolean(option)) return;
            glm::dmat3 m(1.0);
            m[a][a] = m[c][c] = 0.0;
            m[a][c] = m[c][a] = 1.0;
            inWindow(r, b, window, window, [&] { orthogonalMap(b, m); });
        };
        exchange("transf_function_enabledD_false", "D", 0, 1);
        exchange("transf_function_enabledE_false", "E", 0, 2);
        const vec3 negate(r.boolean("transf_function_enabledBx_false") ? -1.0 : 1.0,
                          r.boolean("transf_function_enabledBy_false") ? -1.0 : 1.0,
                          r.boolean("transf_function_enabledBz_false") ? -1.0 : 1.0);
        if (negate != vec3(1.0)) b.add("axis_scale", {N::v("scale", negate)});
    }
    additionConstant(r, b);
    multiBulbMultipleOfC(r, b);
    windowedRotation(r, b, "transf_function_enabledR_false", "_R");
}

// Kali's Mandelbulb (2.20's MandelbulbKaliIteration in fractal_formulas.cpp) is the multi bulb's
// first case: the latitude acos(z / r) and the azimuth atan(y / x) (axis order zyx, the quotient's
// atan both times), theta times n transf_scaleA_1, the unit point of those angles, then its
// latitude plus transf_beta_angle_offset and its azimuth times n transf_scaleB_1, r^n times the
// point. Kali measures the second azimuth afresh where the multi bulb adds it to the first and
// halves the sum; the two agree where the first lies in (-90, 90) degrees, which atan's quotient
// keeps it in without an azimuth offset: alpha_angle_offset is refused. The abs of chosen axes
// before it, as the multi bulb's; its DE tweak is refused.
void mapMandelbulbKali(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("analyticDE_enabled_false", "a tweak of the bulb's running derivative");
    r.mustBeDefault("alpha_angle_offset", "an azimuth offset, which Kali's second measurement wraps back");
    absOfChosenAxes(r, b);
    constexpr double kZyx = 5.0;
    b.add("mandelbulb_kali_multi",
          {N::f("power", r.number("transf_pwr_8")), N::f("order", kZyx), N::f("order_second", kZyx),
           N::f("phi_atan", 1.0), N::f("phi_atan_second", 1.0), N::f("theta_scale", r.number("transf_scaleA_1")),
           N::f("phi_scale", r.number("transf_scaleB_1")), N::f("theta_offset", r.number("beta_angle_offset")),
           N::f("theta_offset_second", r.number("transf_beta_angle_offset"))});
}

// Luca GN's inverse cylindrical coordinates (transf_inv_cylindrical: TransfInvCylindricalIteration
// in fractal_formulas.cpp of 2.20): (x cos(s y), x sin(s y), z transf_scaleC_1) times
// transf_scaleA_1, s transf_scale_1, the running derivative Mandelbulber2's (|transf_scaleA_1|, the
// block's mb2_derivative), times transf_scaleB_1 plus transf_offset_1 (1 by default) every
// iteration, as a derivative_tweak. Its forms with x cos(y) or
// x sin(y) in place of x and y (options _false and x_false) are refused.
void mapTransfInvCylindrical(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabled_false", "x cos(y) in place of the radius");
    r.mustBeDefault("transf_function_enabledx_false", "x sin(y) in place of the angle");
    b.add("inv_cylindrical",
          {N::f("angle_scale", r.number("transf_scale_1")), N::f("z_scale", r.number("transf_scaleC_1")),
           N::f("scale_all", r.number("transf_scaleA_1")), N::f("mb2_derivative", 1.0)});
    const double tweak = r.number("transf_scaleB_1"), offset = r.number("transf_offset_1");
    if (tweak != 1.0 || offset != 0.0) b.add("derivative_tweak", {N::f("scale", tweak), N::f("offset", offset)});
}

// visual.bermarte's Mandelbulb (mandelbulb_bermarte: MandelbulbBermarteIteration in
// fractal_formulas.cpp of 2.20): |x|, |y|, |z| first where transf_function_enabledA{x,y,z}_false say
// (plane folds), the bulb of both measurements (the first by acos with transf_function_enabled_false,
// the second with transf_function_enabledx_false; the axes made absolute between them where
// transf_function_enabledA{x,y,z} say, on by default), then |x| and |y| where
// transf_function_enabledB{x,y}_false say. The DE tweak (analyticDE_enabled_false) with values off
// those that give the default derivative is refused.
void mapMandelbulbBermarte(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    if (r.boolean("analyticDE_enabled_false") &&
        (r.number("analyticDE_scale_1") != 1.0 || r.number("analyticDE_offset_1") != 1.0 ||
         r.number("analyticDE_offset_2") != 1.0))
        r.unsupported("analyticDE_enabled_false true: a tweak of the bulb's running derivative");
    auto absOf = [&](const std::string& flag, int axis) {
        if (!r.boolean(flag)) return;
        axisMirror(b, axis);
    };
    for (int k = 0; k < 3; ++k) absOf(std::string("transf_function_enabledA") + "xyz"[k] + "_false", k);
    vec3 between(0.0);
    for (int k = 0; k < 3; ++k) between[k] = r.boolean(std::string("transf_function_enabledA") + "xyz"[k]) ? 1.0 : 0.0;
    b.add("mandelbulb_bermarte",
          {N::f("power", r.number("transf_pwr_8")), N::f("theta_scale", r.number("transf_scaleA_1")),
           N::f("phi_scale", r.number("transf_scaleB_1")), N::f("theta_offset", r.number("beta_angle_offset")),
           N::f("phi_offset", r.number("alpha_angle_offset")),
           N::f("theta_offset_second", r.number("transf_beta_angle_offset")),
           N::f("acos_first", r.boolean("transf_function_enabled_false") ? 1.0 : 0.0),
           N::f("acos_second", r.boolean("transf_function_enabledx_false") ? 1.0 : 0.0), N::v("abs_between", between)});
    for (int k = 0; k < 2; ++k) absOf(std::string("transf_function_enabledB") + "xy"[k] + "_false", k);
}

// Benesi's power-2 Mandelbulb (benesi_pwr2_mandelbulb): Benesi's T1 on its window, his power 2 with
// c times transf_constant_multiplierA_100 per axis on window F (x alone by default), Julia mode's
// offset on window E. Its prism fold, pine-tree step, cosine wrap, second rotation and DE tweak
// are refused.
void mapBenesiPwr2Mandelbulb(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("transf_function_enabledP_false", "the prism fold before Benesi's T1");
    r.mustBeDefault("transf_addCpixel_enabled_false", "Benesi's pine-tree power inside the formula");
    r.mustBeDefault("transf_function_enabledBx_false", "x wrapped by the cosine and sine of y");
    r.mustBeDefault("transf_rotation2_enabled_false", "a rotation after the formula");
    r.mustBeDefault("analyticDE_enabled_false", "a tweak of the running derivative");
    if (r.boolean("transf_benesi_T1_enabled"))
        b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"), [&] {
            r.mustBeDefault("transf_rotation_enabled", "a rotation inside Benesi's frame");
            b.add("benesi_t1",
                  {N::v("scale", r.vector("transf_scale3D_222")), N::v("offset", r.vector("transf_offset_200"))});
        });
    if (r.boolean("transf_addCpixel_enabled"))
        b.within(r.integer("transf_start_iterations_F"), r.integer("transf_stop_iterations_F"), [&] {
            b.add("benesi_pow2", {});
            const vec3 weights = r.vector("transf_constant_multiplierA_100");
            if (weights == vec3(1.0))
                b.add("add_c", {});
            else if (weights != vec3(0.0))
                b.add("add_c_axes", {N::v("weights", weights), N::f("julia", 0.0)});
        });
    if (r.boolean("transf_constant_julia_mode"))
        b.within(r.integer("transf_start_iterations_E"), r.integer("transf_stop_iterations_E"),
                 [&] { b.add("translate", {N::v("offset", r.vector("transf_offset_000"))}); });
}

// transf_zvector_axis_swap: the axes in mandelbulbMulti_order_of_xyz, those that
// transf_function_enabled{x,y,z}_false name negated, then (transf_function_enabled_false, on its
// window) x and y turned 45 degrees about z. The reordering is one orthogonal map: a rotation, or
// a rotation and the mirror through the origin where it reverses handedness.
void mapTransfZvectorAxisSwap(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    const int order = axisOrder(r, "mandelbulbMulti_order_of_xyz");
    if (order < 0) return;
    static constexpr int kSource[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    glm::dmat3 m(0.0);  // column-major: m[column][row]; row k reads axis kSource[order][k]
    for (int k = 0; k < 3; ++k)
        m[kSource[order][k]][k] = r.boolean(std::string("transf_function_enabled") + "xyz"[k] + "_false") ? -1.0 : 1.0;
    orthogonalMap(b, m);
    if (r.boolean("transf_function_enabled_false"))
        b.within(r.integer("transf_start_iterations"), r.integer("transf_stop_iterations"),
                 [&] { b.rotation(rotationZYX(45.0, 0.0, 0.0)); });
}

// The scator square (scator_power2): its real or imaginary form and multiplier, the formula's own
// multiple of c on window E, and its running derivative, 2 r (or the larger of that and the
// stretch of |v| with analyticDE_enabled_false) times analyticDE_scale_1 plus analyticDE_offset_1.
// Mandelbulber2's bailout and log estimate of a scator orbit read its scator magnitude, fraktal's
// |v|: the silhouettes differ (IoU 0.28 to 0.78 on the three files that use it), so the formula is
// refused by that reason; the nodes are still written for a lenient import.
void mapScatorPower2(Reader& r, NodeBuilder& b, std::vector<ImportItem>&) {
    r.mustBeDefault("analyticDE_enabled", "the running derivative left as it is");
    r.unsupported(
        "the scator magnitude (|v|^2 + y^2 z^2 / x^2)^(1/2) as the orbit's r (Mandelbulber2's bailout and "
        "log estimate of a scator orbit; fraktal's measure |v|)");
    const bool ratio = r.boolean("analyticDE_enabled_false");
    if (ratio && r.boolean("transf_addCpixel_enabled_false"))
        r.unsupported("analyticDE_enabled_false with transf_addCpixel_enabled_false: the stretch measured after c");
    b.add("scator_power2", {N::f("imaginary", r.boolean("transf_function_enabled_false")),
                            N::v("multiplier", r.vector("transf_constant_multiplier_122")), N::f("ratio", ratio),
                            N::f("ratio_scale", r.number("transf_scaleA_1"))});
    const double scale = r.number("analyticDE_scale_1"), offset = r.number("analyticDE_offset_1");
    if (scale != 1.0 || offset != 0.0) b.add("derivative_tweak", {N::f("scale", scale), N::f("offset", offset)});
    extraMultipleOfC(r, b, "E");
}

using MapFn = void (*)(Reader&, NodeBuilder&, std::vector<ImportItem>& approximated);
struct Mapping {
    int id;
    MapFn map;
};
constexpr Mapping kMappings[] = {
    {2, mapMandelbulb},
    {3, mapMandelbulbPower2},
    {16, mapBoxFoldBulbPow2},
    {kQuaternionId, mapQuaternion3d},
    {7, mapMengerSponge},
    {8, mapMandelbox},
    {37, mapGeneralizedFoldBox},
    {10, mapKaleidoscopicIfs},
    {11, mapXenodreambuie},
    {kBristorbrotId, mapBristorbrot},
    {61, mapMengerMod1},
    {kQuaternion3dId, mapQuaternion3d},
    {83, mapIqBulb},
    {103, mapPseudoKleinian},
    {104, mapPseudoKleinianMod1},
    {1001, mapTransfAddConstant},
    {1002, mapTransfRotation},
    {1003, mapTransfScale},
    {60, mapAboxModKali},
    {74, mapKalisets1},
    {76, mapAboxVsIcen1},
    {73, mapAmazingSurf},
    {77, mapAmazingSurfMod1},
    {119, mapAboxMod11},
    {132, mapAmazingSurfMod2},
    {20, mapBenesi},
    {66, mapBenesiPineTree},
    {125, mapBoxFoldBulbPow2V2},
    {71, mapRiemannSphereV1},
    {72, mapRiemannSphere},
    {139, mapRiemannSphereV2},
    {129, mapCoastalbrot},
    {800, mapMandelbulbEye},
    {82, mapMsltoeDonut},
    {51, mapMsltoeSym2Mod},
    {17, mapMandelboxSmooth},
    {122, mapJosKleinian},
    {1065, mapTransfAbsAddConditional},
    {70, mapEiffieMsltoe},
    {113, mapMengerSmooth},
    {114, mapMengerSmoothMod1},
    {117, mapPseudoKleinianMod2},
    {98, mapMengerCrossKifs},
    {110, mapSierpinski3d},
    {kSierpinski4dId, mapSierpinski4d},
    {kMenger4dId, mapMenger4d},
    {59, mapFoldBoxMod1},
    {56, mapTransfPlatonicSolid},
    {101, mapPseudoKleinianStdDE},
    {91, mapMandelboxMenger},
    {135, mapAboxModKaliV2},
    {13, mapMandelbulb2},
    {49, mapLkmitch},
    {41, mapBuffalo},
    {1029, mapTransfAbsAddMulti},
    {1055, mapTransfSphericalInv},
    {126, mapBoxFoldBulbPow2V3},
    {1009, mapTransfBenesiT1},
    {1098, mapTransfDiagonalFold},
    {137, mapMandelbulbAbsPower2},
    {64, mapAboxMod1},
    {1043, mapTransfScale4d},
    {1042, mapTransfSphericalFold4d},
    {1041, mapTransfIterationWeight4d},
    {1045, mapTransfAbsAddTgladFold4d},
    {1067, mapTransfAbsAddConditional4d},
    {610, mapDifsMsltoeDonut},
    {1600, mapTransfDifsBox},
    {1602, mapTransfDifsEllipsoid},
    {1603, mapTransfDifsHextgrid2},
    {1613, mapTransfDifsGrid},
    {603, mapDifsCylinder},
    {604, mapDifsSphere},
    {606, mapDifsTorus},
    {142, mapVicsek},
    {1064, mapTransfRotationFolding},
    {1069, mapTransfRotation4d},
    {600, mapDifsBoxDiagonalV1},
    {601, mapDifsBoxV1},
    {kQuaternion4dId, mapQuaternion4d},
    {78, mapMandelbulbVaryPowerV1},
    {131, mapModulusMandelbulb},
    {116, mapAbox4d},
    {1036, mapTransfRotationVaryV1},
    {92, mapMandelbulbKali},
    {94, mapMandelbulbBermarte},
    {1053, mapTransfInvCylindrical},
    {95, mapMengerMiddleMod},
    {115, mapMengerOcto},
    {150, mapIfsXy},
    {1081, mapTransfPolyFoldSymMulti},
    {1073, mapTransfSphericalFoldParab},
    {602, mapDifsBoxDiagonalV3},
    {1084, mapTransfSinAndCosMax},
    {1082, mapTransfSinOrCos},
    {93, mapMandelbulbKaliMulti},
    {105, mapBenesiPwr2Mandelbulb},
    {1022, mapTransfZvectorAxisSwap},
    {173, mapScatorPower2},
    {48, mapQuickDudley},
    {84, mapQuickDudleyMod},
    {50, mapMakin3d2},
    {kMandelbulb3Id, mapMandelbulb3},
    {15, mapMandelbulb4},
    {68, mapMsltoeSym3Mod},
    {kMsltoeSym3Mod2Id, mapMsltoeSym3Mod2},
    {kMsltoeSym3Mod3Id, mapMsltoeSym3Mod3},
    {kMsltoeSym4ModId, mapMsltoeSym4Mod},
    {39, mapIdes},
    {40, mapIdes2},
    {63, mapAexionOctopusMod},
    {67, mapBenesiT1PineTree},
    {86, mapMsltoeToroidal},
    {85, mapRiemannBulbMsltoeMod2},
    {65, mapMandelbulbMulti},
    {118, mapMandelbulbMulti2},
    {1078, mapTransfAddCpixelRotated},
    {88, mapCollatz},
    {89, mapCollatzMod},
};

MapFn findMapping(int id) {
    for (const Mapping& m : kMappings)
        if (m.id == id) return m.map;
    return nullptr;
}

// Mandelbulber2's closing DE function as fraktal's estimator.
struct EstimatorChoice {
    Mb2De de = Mb2De::Linear;
    bool delta = false;
};

// What the closing DE functions read from a formula's own settings (Mandelbulber2 reads the
// first formula's in a hybrid).
struct EstimatorValues {
    double pkThickness = 1.0;  // the pseudo-Kleinian's analyticDE_scale_1
    // The Jos-Kleinian's strip height (transf_folding_value), the caps of its distance
    // (analyticDE_tweak_005) and of the least derivative (analyticDE_offset_1), and whether the
    // strip's far plane counts (transf_spheres_enabled).
    double josHeight = 2.0, josClampY = 0.05, josClampDf = 1.0;
    bool josSpheres = true;
    bool josRead = false;
};

void addEstimator(Formula& f, const EstimatorChoice& choice, Reader& main, const EstimatorValues& values,
                  std::vector<ImportItem>& approximated) {
    auto set = [&](std::string_view id, std::initializer_list<std::pair<std::string_view, double>> values) {
        f.estimator = Node::make(*findBlock(id));
        for (const auto& [name, v] : values) f.estimator.values[size_t(f.estimator.block->paramIndex(name))].x = v;
    };
    const double offset = main.number("linear_DE_offset");
    switch (choice.de) {
        case Mb2De::Linear:
        case Mb2De::DeltaLinear: {
            const bool delta = choice.delta || choice.de == Mb2De::DeltaLinear;
            set(delta ? "escape_linear_gradient" : "escape_linear", {{"offset", std::clamp(offset, 0.0, 10.0)}});
            return;
        }
        case Mb2De::Ifs: set("escape_linear", {{"offset", 2.0}}); return;
        case Mb2De::LinearXy: set("escape_linear_xy", {{"offset", std::clamp(offset, 0.0, 10.0)}}); return;
        case Mb2De::Log:
        case Mb2De::DeltaLog:
            set(choice.delta || choice.de == Mb2De::DeltaLog ? "escape_gradient" : "escape_log", {});
            return;
        case Mb2De::PseudoKleinian:
            set("pseudo_kleinian_de", {{"thickness", std::clamp(values.pkThickness, 0.0, 1.0)}, {"offset", 0.0}});
            return;
        case Mb2De::JosKleinian: {
            // min(y, a - y) capped, over the derivative held above its least: kleinian_de.
            if (!values.josSpheres) {
                main.unsupported("transf_spheres_enabled false: the Jos-Kleinian DE without the strip's far plane");
                break;
            }
            const BlockDesc& de = *findBlock("kleinian_de");
            const double v[] = {values.josHeight, values.josClampY, values.josClampDf};
            bool inRange = true;
            for (size_t i = 0; i < 3; ++i)
                if (!(v[i] >= de.params[i].min && v[i] <= de.params[i].max)) {
                    main.unsupported("kleinian_de." + std::string(de.params[i].name) + " " + fmt(v[i]) +
                                     " is outside fraktal's range [" + fmt(de.params[i].min) + ", " +
                                     fmt(de.params[i].max) + "]");
                    inRange = false;
                }
            if (!inRange) break;
            set("kleinian_de", {{"klein_r", v[0]}, {"clamp_y", v[1]}, {"clamp_df", v[2]}});
            return;
        }
        case Mb2De::Difs:
            // Mandelbulber2's delta DE method takes |z| itself as the distance of a dIFS formula
            // (calculate_distance.cpp: "Can we calculate dIFS in deltaDE mode?").
            if (choice.delta) {
                main.unsupported(
                    "the dIFS DE function with the delta DE method (Mandelbulber2 then draws |z| as the "
                    "distance)");
                break;
            }
            set("difs", {});
            return;
        case Mb2De::None: break;  // no mapped formula: each is named already
    }
    set("escape_linear", {});
}

Mb2De functionFromSetting(int function, Mb2De preferred) {
    switch (function) {
        case 1: return Mb2De::Linear;
        case 2: return Mb2De::Log;
        case 3: return Mb2De::PseudoKleinian;
        case 4: return Mb2De::JosKleinian;
        case 5: return Mb2De::Difs;
        default: return preferred;
    }
}

bool isDelta(Mb2De de) { return de == Mb2De::DeltaLinear || de == Mb2De::DeltaLog; }
Mb2De analyticOf(Mb2De de) {
    return de == Mb2De::DeltaLinear ? Mb2De::Linear : de == Mb2De::DeltaLog ? Mb2De::Log : de;
}

// A colour as Mandelbulber2 shows it (display sRGB, 16 bits) in fraktal's scene-linear Rec.709.
vec3 linearFromDisplay(const vec3& c) {
    auto lin = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return {lin(c.x), lin(c.y), lin(c.z)};
}

void importCamera(Reader& main, FractImport& out) {
    Camera& c = out.preset.camera;
    c.position = main.vector("camera");
    c.target = main.vector("target");
    c.up = main.vector("camera_top");
    if (length(c.target - c.position) < 1e-9 * std::max(1.0, length(c.position))) {
        // A free-flying camera whose target sits on it (camera_distance_to_target near 0): the
        // view direction is camera_rotation's, yaw about z then pitch about x of the camera's
        // forward y axis (camera_target.cpp); the target goes one unit ahead.
        const vec3 angles = glm::radians(main.vector("camera_rotation"));
        const vec3 forward(-std::sin(angles.x) * std::cos(angles.y), std::cos(angles.x) * std::cos(angles.y),
                           std::sin(angles.y));
        c.target = c.position + forward;
    }
    if (length(glm::cross(normalize(c.target - c.position), c.up)) < 1e-9)
        c.up = std::abs(normalize(c.target - c.position).z) < 0.9 ? vec3(0, 0, 1) : vec3(0, 1, 0);
    const double fov = main.number("fov");
    const FractFile& file = main.file();
    // Three-point perspective: ray = normalize(u fov, 1, v fov) with v in [-1/2, 1/2] over the
    // image height, so tan(fovY / 2) = fov / 2; files from 2.21 store the angle in degrees.
    c.fovY = file.versionNumber >= 2.21 - 1e-9 ? fov : glm::degrees(2.0 * std::atan(fov / 2.0));
    // The wide projections (projection_3d.cpp, CalculateViewVector) turn by fov x pi/2 from the
    // centre to the top edge, with that same internal fov (2 tan of half the angle from 2.21 on):
    // fraktal's fovY is 180 fov degrees. Both programs' equirectangular image spans 2 fovY across
    // whatever its aspect (render_worker.cpp takes it as 2:1; shaders/camera.glsl).
    const std::string perspective = main.raw("perspective_type");
    const bool fishEye = perspective == "1" || perspective == "fish_eye";
    const bool equirectangular = perspective == "2" || perspective == "equirectangular";
    if (fishEye || equirectangular) {
        const double internal = file.versionNumber >= 2.21 - 1e-9 ? 2.0 * std::tan(glm::radians(fov) * 0.5) : fov;
        c.projection = fishEye ? Projection::FishEye : Projection::Equirectangular;
        c.fovY = 180.0 * internal;
    } else if (perspective != "0" && perspective != "three_point") {
        main.unsupported("perspective_type " + perspective +
                         ": fraktal's cameras are perspective, fish eye and equirectangular");
    }
    const double widest = c.projection == Projection::Perspective ? 170.0 : 360.0;
    if (!(c.fovY >= 1.0 && c.fovY <= widest)) {
        main.unsupported("fov " + fmt(fov) + ": a field of view of " + fmt(c.fovY) + " degrees (fraktal: 1 to " +
                         fmt(widest) + ")");
        c.fovY = std::clamp(c.fovY, 1.0, widest);
    }
    main.mustBeDefault("sweet_spot_horizontal_angle", "a view turned after the frame");
    main.mustBeDefault("sweet_spot_vertical_angle", "a view turned after the frame");
    // Red-cyan anaglyphs (stereo_mode 2) are drawn as the view from between the eyes; pairs side by
    // side or one above the other are other pictures and are refused.
    if (main.boolean("stereo_enabled")) {
        const std::string mode = main.raw("stereo_mode");
        if (mode == "2" || mode == "red_cyan")
            out.approximated.push_back({"camera", "stereo_mode red-cyan: one view from between the eyes (" +
                                                      fmt(main.number("stereo_eye_distance")) +
                                                      " apart), no anaglyph"});
        else
            main.unsupported("stereo_enabled true: stereo pairs side by side or one above the other (stereo_mode " +
                             mode + ")");
    }
    // The v1.x picture: the top image row at v = -1/2 (render_job.cpp), a mirror of the standard
    // one.
    c.flipVertical = main.boolean("legacy_coordinate_system");
}

void importLook(const FractFile& file, Reader& main, FractImport& out) {
    ShadingSettings& s = out.preset.shading;
    const CameraBasis basis = out.preset.camera.basis();
    // The main light: (cos(a - 90) cos b, sin(a - 90) cos b, sin b) toward the light, in the
    // camera's frame (x right, y forward, z up) when its position is relative (render_worker.cpp).
    const double a = glm::radians(main.number("main_light_alpha") - 90.0),
                 b = glm::radians(main.number("main_light_beta"));
    const vec3 d(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
    s.lightDirection = main.boolean("main_light_position_relative")
                           ? normalize(basis.right * d.x + basis.forward * d.y + basis.up * d.z)
                           : normalize(d);
    const double intensity =
        main.boolean("main_light_enable") ? std::max(main.number("main_light_intensity"), 0.0) : 0.0;
    s.lightColor = linearFromDisplay(main.colour("main_light_colour")) * (1.6 * intensity);
    s.shadowSteps = main.boolean("shadows_enabled") ? s.shadowSteps : 0;
    // Background: three stops top to bottom (two without background_3_colors_enable).
    s.backgroundTop = linearFromDisplay(main.colour("background_color_1"));
    s.backgroundBottom = linearFromDisplay(
        main.colour(main.boolean("background_3_colors_enable") ? "background_color_3" : "background_color_2"));
    if (main.boolean("background_3_colors_enable"))
        out.approximated.push_back({"background", "the middle stop of the three-colour gradient is left out"});
    if (main.boolean("basic_fog_enabled")) {
        s.fogColor = linearFromDisplay(main.colour("basic_fog_color"));
        // Mandelbulber2's visibility is a distance; fraktal's density is per bound radius.
        s.fogDensity =
            std::clamp(out.preset.formula.boundRadius / std::max(main.number("basic_fog_visibility"), 1e-3), 0.0, 10.0);
        out.approximated.push_back({"fog", "the basic fog's visibility distance as a density per bound radius"});
    }
    if (main.boolean("ambient_occlusion_enabled")) {
        s.aoStrength = std::clamp(main.number("ambient_occlusion"), 0.0, 1.0);
    } else {
        s.aoSteps = 0;
    }
    // Mandelbulber2 traces a reflected ray only where the material reflects: RayRecursion pushes a
    // reflection only `if (reflect > 0.0f)`, reflect being the material's reflectance
    // (render_worker.cpp). raytraced_reflections at reflectance 0, as all nine toolbar files set
    // it, traces none; a reflected march there cost fraktal a second march a hit for nothing
    // (bench/import/README.md, "The speed table in one command"). The reflectance is the share of
    // the mirror image: fraktal's Fresnel F0.
    const double reflectance = main.number("mat1_reflectance");
    s.reflection = main.boolean("raytraced_reflections") && reflectance > 0.0 ? std::min(reflectance, 1.0) : 0.0;
    if (main.boolean("DOF_enabled")) {
        ThinLens& lens = out.preset.lighting.lens;
        lens.focusDistance = std::max(main.number("DOF_focus"), 1e-3);
        // Mandelbulber2's blur radius is in its own units: 0.0015 x radius x focus in the world.
        lens.apertureRadius = 0.0015 * main.number("DOF_radius") * lens.focusDistance;
        out.approximated.push_back({"depth of field", "DOF_radius as a thin lens (path-traced mode)"});
    }
    // Colour: Mandelbulber2 runs its own colour index through the material's gradient; fraktal's
    // orbit-trap cosine palette gets the gradient's mean colour and spread.
    const std::string gradientKey =
        file.find("main_parameters", "mat1_surface_color_gradient") || file.versionNumber >= 2.19
            ? "mat1_surface_color_gradient"
            : "";
    if (!gradientKey.empty()) {
        std::istringstream in(main.raw(gradientKey));
        std::string position, colour;
        vec3 sum(0.0), lo(1e9), hi(-1e9);
        int count = 0;
        while (in >> position >> colour) {
            unsigned rgb = 0;
            const auto [end, ec] = std::from_chars(colour.data(), colour.data() + colour.size(), rgb, 16);
            if (ec != std::errc() || end != colour.data() + colour.size() || colour.size() > 6) break;
            const vec3 c = linearFromDisplay(vec3((rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255) / 255.0);
            sum += c, lo = glm::min(lo, c), hi = glm::max(hi, c), ++count;
        }
        if (count > 0) {
            s.paletteA = sum / double(count);
            s.paletteB = (hi - lo) * 0.5;
        }
    }
    out.approximated.push_back({"colour",
                                "Mandelbulber2's colour index through its gradient becomes fraktal's "
                                "orbit-trap palette with the gradient's mean colour and spread"});
    for (int i = 1; i <= 4; ++i)
        if (main.boolean("aux_light_enabled_" + std::to_string(i)))
            out.approximated.push_back(
                {"lights", "aux_light_" + std::to_string(i) + " (a point light) is not imported"});
    for (const char* key : {"volumetric_fog_enabled", "iteration_fog_enable", "glow_enabled", "fake_lights_enabled",
                            "textured_background", "env_mapping_enable"})
        if (main.boolean(key) && (std::string(key) != "glow_enabled" || main.given(key)))
            out.approximated.push_back({"look", std::string(key) + ": not imported"});
    for (const auto& [section, rows] : file.animationRows)
        out.approximated.push_back({"animation", "[" + section + "] (" + std::to_string(std::max(rows, 0)) +
                                                     " rows): the animation is not imported, the still is"});
}

// The primitives a file switches on ("box", 1), in file order.
std::vector<std::pair<std::string, std::string>> enabledPrimitives(const FractFile& file) {
    std::vector<std::pair<std::string, std::string>> out;
    const auto it = file.sections.find("main_parameters");
    if (it == file.sections.end()) return out;
    for (const auto& [key, entry] : it->second) {
        if (!key.starts_with("primitive_") || !key.ends_with("_enabled") || parseBoolean(entry.value) != true) continue;
        const std::string rest = key.substr(10, key.size() - 10 - 8);  // "box_1"
        const size_t underscore = rest.rfind('_');
        if (underscore != std::string::npos) out.emplace_back(rest.substr(0, underscore), rest.substr(underscore + 1));
    }
    return out;
}

// Mandelbulber2's boolean operators (fractparams.hpp enumBooleanOperator: AND, OR, SUB), for the
// objects and the fractals of a boolean combination.
constexpr ObjectOperation kBooleanOperations[] = {ObjectOperation::Intersect, ObjectOperation::Join,
                                                  ObjectOperation::Carve};
constexpr const char* kCarvedExactly = "carved exactly (Mandelbulber2 carves within 1.5 hit thresholds)";

// Mandelbulber2 measures a placed shape at M (p - position), M = SetRotation2(rotation in
// degrees): the shape is turned by M's inverse.
void placeByMandelbulber2(Placement& place, const vec3& position, const vec3& rotation) {
    place.center = position;
    const AxisAngle turn = axisAngle(glm::transpose(setRotation2(rotation)));
    place.axis = turn.axis;
    place.angle = turn.degrees;
}

// A cut by a box (limits_enabled) and objects beside the fractal (primitives). One box, sphere or
// plane, unrotated, or the limit box alone, beside a linear or log estimate keep to fraktal's
// combine estimators (the fractal's linear estimate |v| - offset over |dr|, Mandelbulber2's linear
// and IFS DE functions, or its log estimate, log_part); one water surface is the water combine.
// Everything else becomes the formula's objects (Formula::objects), in file order, joined,
// intersected or carved as each primitive's boolean operator says, then the limit box
// intersecting them all (calculate_distance.cpp: the limit applies after the primitives).
void importObjects(const FractFile& file, Reader& main, FractImport& out) {
    Formula& f = out.preset.formula;
    const auto primitives = enabledPrimitives(file);
    const bool limits = main.boolean("limits_enabled");
    if (!limits && primitives.empty()) return;
    const std::string_view estimator = f.estimator.block ? f.estimator.block->id : "";
    const bool linear = estimator == "escape_linear";
    const bool logPart = estimator == "escape_log" || estimator == "escape_gradient" || estimator == "escape_potential";
    const bool difs = estimator == "difs";
    // Interior mode changes the fractal's estimate alone, before the cut and the primitives: the
    // objects come after it (evaluate()), where a combine estimator would mix them into it. A
    // combine estimator is evaluated in the fractal's placed frame, where Mandelbulber2 places the
    // primitives and the limit box in the world's (fractal_position and fractal_rotation move the
    // fractal alone): beside a placement they are objects (ides1_001's plane, turned 135 degrees
    // with the fractal, put the camera inside it: IoU 0.86, the view filled).
    const bool combines = (linear || logPart) && f.hitRule != HitRule::InteriorWalls && f.placement.identity();
    const double offset = linear ? f.estimator.values[0].x : 0.0;
    auto combine = [&](std::string_view id, std::initializer_list<NodeBuilder::Value> values) {
        std::vector<Node> nodes;
        NodeBuilder b(main, nodes);
        b.add(id, values);
        if (estimator != "escape_log" && logPart)
            out.approximated.push_back(
                {"DE", "the cut or object joins the analytic log estimate (" + std::string(estimator) + " before)"});
        f.estimator = std::move(nodes.front());
        f.estimator.values[size_t(f.estimator.block->paramIndex("offset"))].x = offset;
        f.estimator.values[size_t(f.estimator.block->paramIndex("log_part"))].x = logPart ? 1.0 : 0.0;
        if (const int i = f.estimator.block->paramIndex("difs_part"); i >= 0) f.estimator.values[size_t(i)].x = difs;
    };
    const vec3 limitLow = main.vector("limit_min"), limitHigh = main.vector("limit_max");
    if (limits && primitives.empty() && combines) {
        combine("box_combine", {N::f("intersect", 1.0), N::v("center", (limitLow + limitHigh) * 0.5),
                                N::v("size", glm::abs(limitHigh - limitLow) * 0.5)});
        return;
    }
    main.mustBeDefault("all_primitives_position", "the primitives moved together");
    main.mustBeDefault("all_primitives_rotation", "the primitives turned together");
    const bool one = primitives.size() == 1 && !limits && combines;
    int waters = 0;
    for (const auto& [type, index] : primitives) waters += type == "water";
    for (const auto& [type, index] : primitives) {
        const std::string key = "primitive_" + type + "_" + index + "_";
        const std::string where = "primitive " + type + " " + index;
        auto value = [&](const std::string& name, const char* fallback) {
            const FractEntry* e = file.find("main_parameters", key + name);
            return std::string(e ? e->value : fallback);
        };
        auto vectorOf = [&](const std::string& name, const char* fallback) {
            const std::optional<vec3> v = parseVector(value(name, fallback));
            if (!v) throw PresetError(file.source, "[main_parameters] " + key + name, "expected three numbers");
            return *v;
        };
        auto numberOf = [&](const std::string& name, const char* fallback) {
            const std::optional<double> v = parseNumber(value(name, fallback));
            if (!v) throw PresetError(file.source, "[main_parameters] " + key + name, "expected a number");
            return *v;
        };
        auto flag = [&](const std::string& name, bool fallback) {
            return parseBoolean(value(name, fallback ? "true" : "false")) == true;
        };
        const bool water = type == "water";
        const vec3 position = vectorOf("position", "0 0 0");
        const vec3 rotation = vectorOf("rotation", "0 0 0");
        if (flag("wave_from_objects_enable", false)) {
            main.unsupported(where + ": waves from the objects");
            continue;
        }
        if (water) {
            // The water combine: the estimator itself, so one water surface beside a linear or log
            // estimate, whatever else is there.
            if (waters > 1 || !(linear || logPart || difs)) {
                main.unsupported(where +
                                 ": water beside a DE function other than linear, log or dIFS, or a second water "
                                 "surface");
                continue;
            }
            // primitives.cpp and settings.cpp: files before 2.13 name the height `amplitude`, and
            // those up to 2.12 give it in world units (divided by the length on load).
            const double waveLength = numberOf("length", "0.1");
            double amplitude = numberOf("relative_amplitude", "0.2");
            if (file.versionNumber < 2.13 - 1e-9 && file.find("main_parameters", key + "amplitude"))
                amplitude = numberOf("amplitude", "0.2");
            if (file.versionNumber <= 2.12 + 1e-9) amplitude /= waveLength;
            const AxisAngle turn = axisAngle(setRotation2(rotation));
            const double frame = main.given("frame_no") ? main.number("frame_no") : 0.0;
            combine("water_combine", {N::v("center", position), N::v("axis", turn.axis), N::f("angle", turn.degrees),
                                      N::f("wave_length", waveLength), N::f("amplitude", amplitude),
                                      N::f("iterations", numberOf("iterations", "5")),
                                      N::f("phase", -numberOf("anim_speed", "1") * frame * 0.1)});
            continue;
        }
        const bool empty = flag("empty", false);
        const int booleanOperator = int(std::lround(numberOf("boolean_operator", "1")));
        if (one && length(rotation) == 0.0 && !empty && booleanOperator == 1 &&
            length(vectorOf("repeat", "0 0 0")) == 0.0 && !file.find("main_parameters", key + "normal") &&
            (type == "box" || type == "sphere" || type == "plane")) {
            if (type == "sphere") {
                combine("sphere_combine", {N::v("center", position), N::f("radius", numberOf("radius", "1"))});
            } else if (type == "plane") {
                // Solid below the plane through `position` with the normal (0, 0, 1) (unrotated).
                combine("plane_combine", {N::v("normal", vec3(0, 0, 1)), N::f("height", position.z)});
            } else {
                // Mandelbulber2's box size is its full extent.
                combine("box_combine", {N::v("center", position), N::v("size", vectorOf("size", "1 1 1") * 0.5)});
                if (numberOf("rounding", "0") > 1e-9)
                    out.approximated.push_back({where, "rounded edges are drawn sharp"});
            }
            continue;
        }
        // An object of the formula's own.
        const ObjectDesc* kind = findObject(type);
        if (!kind || type == "cone") {
            main.unsupported(where + ": a " + type +
                             " beside the fractal (fraktal's objects: plane, box, sphere, "
                             "cylinder, torus)");
            continue;
        }
        if (file.find("main_parameters", key + "normal")) {
            main.unsupported(where + ": a plane given by its normal (files before 2.10)");
            continue;
        }
        if (booleanOperator < 0 || booleanOperator > 2) {
            main.unsupported(where + ": boolean operator " + std::to_string(booleanOperator) +
                             " (the fractal carved from the object)");
            continue;
        }
        if (int(f.objects.size()) >= kMaxObjects) {
            main.unsupported(where + ": more than " + std::to_string(kMaxObjects) + " objects");
            continue;
        }
        SceneObject o = SceneObject::make(*kind);
        o.operation = kBooleanOperations[booleanOperator];
        o.hollow = empty;
        o.center = position;
        // Mandelbulber2 measures at M (p - position), M = SetRotation2(rotation): the object is
        // turned by M's inverse.
        placeByMandelbulber2(o, position, rotation);
        o.repeat = glm::max(vectorOf("repeat", "0 0 0"), vec3(0.0));
        auto set = [&](std::string_view name, const vec3& v) {
            o.values[size_t(std::find_if(kind->params.begin(), kind->params.end(),
                                         [&](const ParamDecl& d) { return d.name == name; }) -
                            kind->params.begin())] = v;
        };
        if (type == "box") {
            set("size", vectorOf("size", "1 1 1") * 0.5);
            set("rounding", vec3(numberOf("rounding", "0")));
            if (empty && numberOf("rounding", "0") > 1e-9)
                out.approximated.push_back({where, "a hollow box's rounding is left out"});
        } else if (type == "sphere") {
            set("radius", vec3(numberOf("radius", "1")));
        } else if (type == "cylinder") {
            set("radius", vec3(numberOf("radius", "1")));
            set("height", vec3(numberOf("height", "1")));
            set("caps", vec3(flag("caps", true) ? 1.0 : 0.0));
        } else if (type == "torus") {
            if (numberOf("radius_lpow", "1") != 1.0 || numberOf("tube_radius_lpow", "1") != 1.0) {
                main.unsupported(where + ": a torus measured in another norm (radius_lpow, tube_radius_lpow)");
                continue;
            }
            set("radius", vec3(numberOf("radius", "1")));
            set("tube", vec3(numberOf("tube_radius", "0.2")));
        }
        if (booleanOperator == 2) out.approximated.push_back({where, kCarvedExactly});
        // The primitive's colour is its material's (material_id, 1 unless given): the material's
        // surface colour where the material does not take its colours from the palette; a
        // palette-coloured material (Mandelbulber2's default) leaves the object its own grey.
        const std::string material = "mat" + value("material_id", "1") + "_";
        const FractEntry* surface = file.find("main_parameters", material + "surface_color");
        const FractEntry* fromPalette = file.find("main_parameters", material + "use_colors_from_palette");
        if (surface && fromPalette && parseBoolean(fromPalette->value) == false) {
            const std::optional<vec3> colour = parseColour(surface->value);
            if (!colour)
                throw PresetError(file.source, "[main_parameters] " + material + "surface_color",
                                  "expected a 16-bit hex colour");
            o.color = clamp(linearFromDisplay(*colour), 0.0, 1.0);
        } else {
            out.approximated.push_back({where, "coloured by its material's palette in Mandelbulber2, grey here"});
        }
        f.objects.push_back(std::move(o));
    }
    if (limits) {
        SceneObject box = SceneObject::make(*findObject("box"));
        box.operation = ObjectOperation::Intersect;
        box.center = (limitLow + limitHigh) * 0.5;
        box.values[0] = glm::abs(limitHigh - limitLow) * 0.5;
        f.objects.push_back(std::move(box));
    }
}

// One fractal from the slots in `slots` that run on the iterations of `sequence` (the 0-based
// slot of each): its nodes, estimator, iterations, bailout and factor. `own` is the suffix of the
// keys each fractal of a boolean combination has of its own ("_2" for slot 2; "" otherwise):
// julia_mode, julia_c, fractal_constant_factor and initial_waxis (nine_fractals.cpp).
Formula importFractal(const FractFile& file, Reader& main, const std::vector<int>& slots,
                      const std::vector<int>& sequence, int N, const std::string& own, FractImport& out) {
    Formula f;
    // The fourth coordinate the orbit starts from: the hypercomplex orbit reads it itself, and the
    // 4D steps carry it from a start_w node (below). Other formulas leave w aside where
    // Mandelbulber2 measures r in 4D, so they are refused with it.
    auto formulaOf = [&](int k) { return main.integer("formula_" + std::to_string(k + 1)); };
    const bool carriesW = !slots.empty() && std::all_of(slots.begin(), slots.end(),
                                                        [&](int k) { return carriesFourthCoordinate(formulaOf(k)); });
    const bool hypercomplex =
        std::any_of(slots.begin(), slots.end(), [&](int k) { return formulaOf(k) == kHypercomplexId; });
    if (!hypercomplex && !carriesW)
        main.mustBeDefault("initial_waxis" + own,
                           "a fourth coordinate beside formulas that do not carry it (fraktal's 4D formulas are "
                           "menger4d, sierpinski4d, abox4d and quaternion4d)");

    // ---- Each slot's nodes ----
    // Files up to 2.04 store the factor as one number (MB2's Compatibility() makes it a vector).
    const std::optional<double> uniformFactor = parseNumber(main.raw("fractal_constant_factor" + own));
    const vec3 factor = uniformFactor ? vec3(*uniformFactor) : main.vector("fractal_constant_factor" + own);
    const bool julia = main.boolean("julia_mode" + own);
    const vec3 juliaC = main.vector("julia_c" + own);
    const bool perAxisFactor = std::abs(factor.x - factor.y) > 1e-12 || std::abs(factor.x - factor.z) > 1e-12;
    const bool boxFolding = main.boolean("box_folding"), sphericalFolding = main.boolean("spherical_folding");
    std::map<Mb2De, int> deVotes;
    double bailout = 0.0;
    EstimatorValues estimatorValues;
    bool delta = false;
    std::array<std::vector<Node>, kSlots> groups;
    int ownOrbitSlot = -1;
    for (const int k : slots) {
        const std::string n = std::to_string(k + 1);
        const int formula = main.integer("formula_" + n);
        const int runs = int(std::count(sequence.begin(), sequence.end(), k));
        if (runs == 0) continue;  // outside its window on every iteration
        // A hybrid's slot of weight 0 is an identity: Mandelbulber2 calls no formula for it and
        // blends the point back to where the iteration started, c and all (compute_fractal.cpp: z =
        // tempZ + (z - tempZ) weight), its derivative untouched. The slot keeps its iterations in
        // the sequence and has no nodes.
        if (main.boolean("hybrid_fractal_enable") && !main.boolean("boolean_operators") &&
            main.number("formula_weight_" + n) == 0.0)
            continue;
        const FormulaInfo* info = findFormula(formula);
        Reader r(file, "fractal_" + n, false, "slot " + n + " (" + formulaName(formula) + ")", out.unsupported);
        std::vector<Node>& group = groups[size_t(k)];
        NodeBuilder b(r, group, N);
        if (runsOwnOrbit(formula) && info) {
            // A 4D orbit: fraktal's hypercomplex Mandelbrot or Aexion estimator runs it (below),
            // alone. Refused (and, leniently, dropped) beside other slots or with options it lacks.
            const size_t named = out.unsupported.size();
            if (slots.size() > 1) r.unsupported("a 4D orbit beside other slots (its estimator runs it alone)");
            if (boxFolding || sphericalFolding) r.unsupported("global folds before a 4D orbit");
            if (julia && formula != kHypercomplexId)
                r.unsupported("julia_mode: a " + std::string(info->name) + " Julia set");
            // Aexion adds its own folded c (cpixelAlreadyHas): dont_add_c changes nothing there.
            if (formula == kHypercomplexId && main.boolean("dont_add_c_constant_" + n))
                r.unsupported("dont_add_c_constant: the orbit without c");
            if (formula == kAexionId && !r.boolean("analyticDE_enabled"))
                r.unsupported("analyticDE_enabled false: a derivative that stays 1");
            if (out.unsupported.size() > named) continue;
            out.formulas.push_back(std::string(info->name));
            ownOrbitSlot = k;
            deVotes[Mb2De::Log] += runs;
            bailout = std::max(bailout, info->bailout);
            continue;
        }
        if (boxFolding) boxFold(b, main.number("box_folding_limit"), main.number("box_folding_value"));
        if (sphericalFolding)
            sphereFold(b, main.number("spherical_folding_inner"), main.number("spherical_folding_outer"));
        const MapFn map = findMapping(formula);
        if (!map || !info) {
            r.unsupported("the formula " + formulaName(formula) + " (id " + std::to_string(formula) +
                          ") has no fraktal blocks yet");
            continue;
        }
        out.formulas.push_back(std::string(info->name));
        map(r, b, out.approximated);
        const bool dontAddC = main.boolean("dont_add_c_constant_" + n);
        const bool addC = info->c == CAdd::Yes ? !dontAddC : info->c == CAdd::No ? dontAddC : false;
        // Mandelbulber2's c is (point, initial_waxis) (compute_fractal.cpp); fraktal's add_c adds
        // its xyz alone, so a 4D orbit that adds c must start from w = 0.
        if (addC && !julia && carriesFourthCoordinate(formula) && main.number("initial_waxis" + own) != 0.0)
            r.unsupported("initial_waxis " + fmt(main.number("initial_waxis" + own)) +
                          " with c added: c's fourth coordinate, which fraktal's add_c leaves out");
        // aboxMod1 and amazing surf add c with x and y exchanged (compute_fractal.cpp).
        const bool swapC = formula == kAboxMod1Id || formula == kAmazingSurfId;
        if (addC && (perAxisFactor || swapC)) {
            b.add("add_c_axes", {N::v("weights", factor), N::f("julia", julia ? 1.0 : 0.0),
                                 N::v("julia_c", juliaC * factor), N::f("swap_xy", swapC ? 1.0 : 0.0)});
        } else if (addC) {
            b.add("add_c",
                  {N::f("weight", factor.x), N::f("julia", julia ? 1.0 : 0.0), N::v("julia_c", juliaC * factor.x)});
            // The quaternions' and the Bristorbrot's derivative takes no 1 for c in Mandelbulber2
            // (derivativeTakesNoOneForC), so the derivative_tweak takes back the 1 add_c adds. Its
            // estimate is then Mandelbulber2's, no bound, and the step factor is measured
            // (quaternion4D_001 pulled back to see the whole object: IoU 0.81 with the 1, 0.95
            // without; the toolbar's quaternion: bench/import/README.md).
            if (derivativeTakesNoOneForC(formula) && !julia && factor.x != 0.0)
                b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", -std::abs(factor.x))});
        }
        // AmazingSurfMod2Iteration, AboxMod11Iteration and AboxModKaliV2Iteration add their 1 to
        // the derivative themselves (aux.DE = aux.DE |scale| + 1: Amazing Surf mod 2's in its
        // scale's window S, abox_mod11's in its window A, unless their DE tweak replaces it),
        // whether c is added or not; fraktal's add_c adds it only where it adds c, so a slot in
        // Julia mode or without c takes it from a derivative_tweak. abox_mod11's tweak scale
        // (window C) multiplies that 1 after it, and the derivative_tweak comes at the slot's end:
        // only where that scale is 1.
        if (!addC || julia) {
            auto addOne = [&] { b.add("derivative_tweak", {N::f("scale", 1.0), N::f("offset", 1.0)}); };
            const bool ownTweak = r.boolean("analyticDE_enabled_false");
            if (formula == kAboxModKaliV2Id) addOne();
            if (formula == kAmazingSurfMod2Id && r.boolean("transf_function_enabledAy") && !ownTweak)
                inWindow(r, b, "S", "S", addOne);
            if (formula == kAboxMod11Id && r.number("transf_scaleG_1") == 1.0 && !ownTweak)
                inWindow(r, b, "A", "A", addOne);
        }
        if (info->de != Mb2De::None) deVotes[analyticOf(info->de)] += runs;
        delta = delta || isDelta(info->de);
        bailout = std::max(bailout, info->bailout);
        if (info->de == Mb2De::PseudoKleinian) estimatorValues.pkThickness = r.number("analyticDE_scale_1");
        if (info->de == Mb2De::JosKleinian && !estimatorValues.josRead) {
            estimatorValues.josHeight = r.number("transf_folding_value");
            estimatorValues.josClampY = r.number("analyticDE_tweak_005");
            estimatorValues.josClampDf = r.number("analyticDE_offset_1");
            estimatorValues.josSpheres = r.boolean("transf_spheres_enabled");
            estimatorValues.josRead = true;
        }
    }

    // ---- The node list: each stretch of the sequence as schedules (period, phase, window) ----
    // A node's own window (a rotation on some iterations) meets its stretch's; the last stretch
    // runs on past N, so that more iterations go on with the same cycle.
    const int iterationsRun = int(sequence.size());
    for (const PeriodicStretch& stretch : periodicStretches(sequence, kMaxPeriod)) {
        const int period = int(stretch.pattern.size());
        for (int k = 0; k < period; ++k) {
            if (stretch.pattern[size_t(k)] < 0) continue;
            for (Node node : groups[size_t(stretch.pattern[size_t(k)])]) {
                node.period = period;
                node.phase = (stretch.start + k) % period;
                node.start = std::max(node.start, stretch.start);
                if (stretch.stop < iterationsRun) node.stop = std::min(node.stop, stretch.stop);
                if (node.start >= node.stop || node.iterationsRunBefore(iterationsRun) == 0) continue;
                if (f.nodes.size() <= size_t(kMaxNodes)) f.nodes.push_back(std::move(node));
            }
        }
    }
    if (const double w = main.number("initial_waxis" + own); carriesW && w != 0.0) {
        std::vector<Node> start;
        NodeBuilder(main, start).add("start_w", {N::f("w", w)});
        f.nodes.insert(f.nodes.begin(), start.begin(), start.end());
    }
    if (f.nodes.size() > size_t(kMaxNodes))
        main.unsupported("a sequence of more than " + std::to_string(kMaxNodes) + " nodes (fraktal holds at most " +
                         std::to_string(kMaxNodes) + ")");

    // ---- Closing estimator: the DE function (delta_DE_method, delta_DE_function) ----
    int method = main.integer("delta_DE_method"), function = main.integer("delta_DE_function");
    if (file.versionNumber < 2.09 - 1e-9 && (function == 0 || function == 2)) function = 2 - function;
    if (file.versionNumber < 2.20 - 1e-9 && method == 0) function = 0;
    Mb2De preferred = Mb2De::None;
    if (deVotes.empty() && !out.formulas.empty())
        main.unsupported("no formula with a DE function runs (transforms alone)");
    if (deVotes.count(Mb2De::Difs)) {
        preferred = Mb2De::Difs;
    } else {
        int best = 0;
        for (const auto& [de, votes] : deVotes)
            if (votes > best) best = votes, preferred = de;
    }
    EstimatorChoice choice{functionFromSetting(function, preferred), delta || method == 1};
    if (choice.delta && choice.de == Mb2De::Linear) choice.de = Mb2De::DeltaLinear;
    if (choice.delta && choice.de == Mb2De::Log) choice.de = Mb2De::DeltaLog;
    if (!f.nodes.empty() || !out.unsupported.empty()) addEstimator(f, choice, main, estimatorValues, out.approximated);

    // ---- Iterations, bailout, step ----
    f.iterations = std::clamp(N, 1, kMaxIterations);
    if (N > kMaxIterations) main.unsupported("N " + std::to_string(N) + " (fraktal runs at most 1000 iterations)");
    f.bailout = main.boolean("use_default_bailout") ? (bailout > 0.0 ? bailout : 100.0) : main.number("bailout");
    f.bailout = std::clamp(f.bailout, 1e-3, 1e10);
    f.deFactor = std::clamp(main.number("DE_factor"), 1e-3, 2.0);
    if (ownOrbitSlot >= 0) {
        // The whole orbit in the estimator: N iterations, escaping at the bailout. Hypercomplex
        // from c = (point, initial_waxis); Aexion from the folded point, with its analytic
        // derivative (scale and offset), which the delta DE method replaces by differences.
        const std::string n = std::to_string(ownOrbitSlot + 1);
        const int formula = main.integer("formula_" + n);
        std::vector<Node> nodes;
        NodeBuilder b(main, nodes);
        if (formula == kHypercomplexId && julia) {
            // Julia mode adds julia_c times the constant factor in place of c, its fourth coordinate 0.
            b.add("hypercomplex_julia", {N::v("constant", juliaC * factor), N::f("constant_w", 0.0),
                                         N::f("slice", main.number("initial_waxis" + own)), N::f("orbit", N),
                                         N::f("escape", std::max(f.bailout, 2.0))});
        } else if (formula == kHypercomplexId) {
            b.add("hypercomplex_mandelbrot", {N::f("slice", main.number("initial_waxis" + own)), N::f("orbit", N),
                                              N::f("escape", std::max(f.bailout, 2.0))});
        } else {
            Reader r(file, "fractal_" + n, false, "slot " + n + " (aexion)", out.unsupported);
            b.add("aexion",
                  {N::f("cadd", r.number("cadd")), N::f("orbit", N), N::f("escape", std::max(f.bailout, 2.0)),
                   N::f("scale", r.number("analyticDE_scale_1")), N::f("offset", r.number("analyticDE_offset_1"))});
            if (choice.delta)
                out.approximated.push_back(
                    {"DE", "delta_DE_method: Aexion's estimate from its analytic derivative, not differences"});
        }
        f.nodes.clear();
        f.estimator = nodes.front();
        f.iterations = 1;
    }
    return f;
}

// Mandelbulber2's boolean mode (calculate_distance.cpp): each enabled slot is a fractal of its
// own, run alone for N iterations, placed by formula_position, _rotation, _repeat and _scale of
// its slot (the point moved, repeated, turned and divided by the scale; the estimate multiplied
// by it), and combined with what the slots before it made by boolean_operator of the slot before
// (AND intersects, OR joins, SUB carves).
void importBooleanFractals(const FractFile& file, Reader& main, const std::vector<int>& slots, int N,
                           FractImport& out) {
    Formula& f = out.preset.formula;
    const std::vector<int> sequence(size_t(std::clamp(N, 1, kMaxIterations)), 0);
    for (const int k : slots) {
        const std::string n = std::to_string(k + 1);
        std::vector<int> alone = sequence;
        std::fill(alone.begin(), alone.end(), k);
        Formula fractal = importFractal(file, main, {k}, alone, N, "_" + n, out);
        placeByMandelbulber2(fractal.placement, main.vector("formula_position_" + n),
                             main.vector("formula_rotation_" + n));
        fractal.placement.repeat = glm::max(main.vector("formula_repeat_" + n), vec3(0.0));
        const double scale = main.number("formula_scale_" + n);
        if (scale <= 0.0) main.unsupported("formula_scale_" + n + ": a scale that is not positive");
        fractal.placement.scale = 1.0 / std::max(scale, 1e-4);
        if (k == slots.front()) {
            f = std::move(fractal);
            continue;
        }
        const int op = main.integer("boolean_operator_" + std::to_string(k));
        if (op < 0 || op > 2) {
            main.unsupported("boolean_operator_" + std::to_string(k) + " " + std::to_string(op));
            continue;
        }
        if (int(f.fractals.size()) >= kMaxCombinedFractals) {
            main.unsupported("slot " + n + ": more than " + std::to_string(kMaxCombinedFractals + 1) + " fractals");
            continue;
        }
        if (op == 2) out.approximated.push_back({"slot " + n, kCarvedExactly});
        f.fractals.push_back({std::move(fractal), kBooleanOperations[op], true});
    }
}

// Mandelbulber2's hit threshold in fraktal's unit, pixel footprints (2.20's
// cRenderWorker::CalcDistThresh in render_worker.cpp): a footprint at the point over detail_level,
// or with constant_DE_threshold DE_thresh in world units wherever the point is. fraktal's threshold
// is per footprint, so the world one is taken at the target's distance from the camera in an image
// of the file's own size, and kept only where it is the finer of the two: at that size it is
// Mandelbulber2's at the target, and in a smaller image (whose footprints are larger) it stays
// finer than the per-footprint one there. A camera without a target keeps the per-footprint one.
// Measured against Mandelbulber2 at 160x120 (bench/import/README.md): the world threshold lifts the
// dIFS files that set it far under a footprint (DIFS BoxV1 flower 0.80 to 0.94: 1.95e-5 units,
// 0.009 footprints at the target), and where it was the coarser it drew surfaces too thick
// (TransfDIFSEllipsoid asurf 0.97 to 0.86, menger addConstCond 0.94 to 0.89).
double mandelbulber2HitThreshold(Reader& main, const Camera& camera, const RenderSettings& render,
                                 std::vector<ImportItem>& approximated) {
    const double perFootprint = 1.0 / std::max(main.number("detail_level"), 1e-6);
    if (!main.boolean("constant_DE_threshold")) return perFootprint;
    // A free-flying camera's target sits on it (importCamera): no distance to take it at.
    const vec3 camera3 = main.vector("camera");
    const double targetDistance = length(main.vector("target") - camera3);
    if (targetDistance < 1e-9 * std::max(1.0, length(camera3))) {
        approximated.push_back({"detail",
                                "constant_DE_threshold: a hit threshold in world units, with no target to "
                                "hold it at; fraktal's is a footprint over detail_level"});
        return perFootprint;
    }
    const double atTarget =
        main.number("DE_thresh") / (targetDistance * camera.pixelAngle(render.height, render.width));
    approximated.push_back({"detail", "constant_DE_threshold: the hit threshold of " + fmt(main.number("DE_thresh")) +
                                          " world units held in pixel footprints as at the target, " +
                                          fmt(targetDistance) + " from the camera (" + fmt(atTarget) +
                                          "), where finer than a footprint over detail_level"});
    return std::min(atTarget, perFootprint);
}

}  // namespace

FractImport importFract(const FractFile& file) {
    FractImport out;
    Preset& p = out.preset;
    p.name = "";
    Reader main(file, "main_parameters", true, "main", out.unsupported);

    // ---- Which slot runs on each iteration (nine_fractals.cpp; reference Notes 2) ----
    const bool boolean = main.boolean("boolean_operators");
    const bool hybrid = !boolean && main.boolean("hybrid_fractal_enable");
    const int N = main.integer("N");
    SlotSequencing sequencing;
    sequencing.hybrid = hybrid;
    sequencing.repeatFrom = hybrid ? main.integer("repeat_from") : 1;
    std::vector<int> slots;  // 0-based, in slot order
    for (int k = 0; k < (hybrid || boolean ? kSlots : 1); ++k) {
        const std::string n = std::to_string(k + 1);
        const int formula = main.integer("formula_" + n);
        if (formula == 0 || !main.boolean("fractal_enable_" + n)) continue;
        sequencing.runs[size_t(k)] = true;
        sequencing.count[size_t(k)] = main.integer("formula_iterations_" + n);
        sequencing.first[size_t(k)] = main.integer("formula_start_iteration_" + n);
        sequencing.last[size_t(k)] = main.integer("formula_stop_iteration_" + n);
        Reader slotMain(file, "main_parameters", true, "slot " + n + " (" + formulaName(formula) + ")",
                        out.unsupported);
        // A weight of 0 makes the slot an identity (importFractal); one between takes a blend.
        if (const double weight = slotMain.number("formula_weight_" + n); hybrid && weight != 0.0 && weight != 1.0)
            slotMain.unsupported("formula_weight_" + n + " " + slotMain.raw("formula_weight_" + n) +
                                 ": a blend of the point before and after the slot");
        // Mandelbulber2 skips the bailout test after such a slot's iterations (a pre-transform, or a
        // box whose linear estimate r / dr settles whatever the radius it stops at); fraktal tests
        // after every iteration, which ends some orbits an iteration sooner.
        if (hybrid && !main.boolean("check_for_bailout_" + n))
            out.approximated.push_back({"slot " + n,
                                        "check_for_bailout off: fraktal tests the bailout after every "
                                        "iteration"});
        slots.push_back(k);
    }
    if (slots.empty()) main.unsupported("no formula slot runs");
    // Mandelbulber2 moves, repeats and turns the point before every formula (compute_fractal.cpp:
    // (point - fractal_position) mod repeat, turned by fractal_rotation's matrix): the first
    // fractal's placement. In boolean mode each slot's own placement comes first, and the two do not
    // make one placement.
    const char* placementKeys[] = {"fractal_position", "fractal_rotation", "repeat"};
    if (boolean) {
        for (const char* key : placementKeys)
            main.mustBeDefault(key, "the whole scene's placement inside each boolean slot's own");
        importBooleanFractals(file, main, slots, N, out);
    } else {
        p.formula = importFractal(file, main, slots, slotOfEachIteration(sequencing, std::clamp(N, 1, kMaxIterations)),
                                  N, "", out);
        placeByMandelbulber2(p.formula.placement, main.vector("fractal_position"), main.vector("fractal_rotation"));
        p.formula.placement.repeat = glm::max(main.vector("repeat"), vec3(0.0));
    }
    p.formula.boundRadius = std::clamp(main.number("view_distance_max"), 1e-3, 1e4);
    // Mandelbulber2's camera rays end at view_distance_max from the camera (the scene import
    // fits the bound sphere to the object, which may reach past it).
    p.render.viewDistance = std::clamp(main.number("view_distance_max"), 1e-3, 1e6);
    // iteration_threshold_mode: Mandelbulber2 stops only where the orbit stays bounded for N
    // iterations, fraktal's hits only inside, the estimate sizing the steps. interior_mode: it stops
    // only in a band just outside the set and crawls through the set, fraktal's interior walls.
    const bool iterationThreshold = main.boolean("iteration_threshold_mode");
    if (main.boolean("interior_mode")) {
        if (iterationThreshold)
            main.unsupported(
                "interior_mode with iteration_threshold_mode: a ray that never stops (each mode "
                "moves the other's hits away)");
        p.formula.hitRule = HitRule::InteriorWalls;
        // A ray crosses the set a fifth of a hit threshold a step: Mandelbulber2's own limit.
        p.render.maxSteps = kMaxMarchSteps;
    } else if (iterationThreshold) {
        p.formula.hitRule = HitRule::InsideOnly;
    }
    importObjects(file, main, out);

    // ---- Image, camera, look ----
    p.render.width = std::clamp(main.integer("image_width"), 16, 16384);
    p.render.height = std::clamp(main.integer("image_height"), 16, 16384);
    // Mandelbulber2 makes a pixel of its own rays alone: one through its centre, or with
    // antialiasing a grid of them inside it, averaged (a box). fraktal's default reconstruction
    // (Blackman-Harris, radius 2) spreads each sample over five pixels, the softer image of a print;
    // the import keeps Mandelbulber2's footprint with the filter's narrowest radius, so its image is
    // as sharp as Mandelbulber2's, and one sample per pixel reaches the coverage error Mandelbulber2
    // reaches with one (bench/import/README.md, "Speed on imported scenes").
    p.render.filterRadius = 0.5;
    // Mandelbulber2 stops a ray where its estimate falls under one pixel's footprint over
    // detail_level (the same footprint as fraktal's unit), and only then scales the step by
    // DE_factor; fraktal's threshold applies to the scaled estimate, so it scales by the factor too.
    // For the spherical powers fraktal's running derivative bounds the stretch from above (their
    // phi stretch, up to the power, formulas/mandelbulb.hpp and mandelbulb_variants.hpp) where
    // Mandelbulber2 carries n r^(n-1) alone, and for the Bristorbrot its Jacobian's largest
    // singular value where Mandelbulber2 carries 2 r: its log estimate is the smaller near the
    // surface, and the threshold divided by the largest such power puts the surface where
    // Mandelbulber2 draws it (bench/import/README.md: the toolbar's power-9 bulb IoU 0.77
    // undivided, 0.94 divided). The quaternion's derivative is Mandelbulber2's own (2 r, and no 1
    // for c: derivativeTakesNoOneForC), so its threshold is not divided (quaternion_001 0.89
    // divided with the 1, 0.98 undivided without it; the toolbar's quaternion 0.96 and 0.97).
    // Powers whose derivative is Mandelbulber2's own keep the threshold (formula/img
    // riemann_sphere_msltoe_v2 0.79 divided by its 4, 0.97 not).
    constexpr std::string_view kBoundingPowers[] = {"mandelbulb", "mandelbulb_phase", "mandelbulb_sine",
                                                    "mandelbulb_cosine", "bristorbrot"};
    double degree = 1.0;
    for (const Node& n : p.formula.nodes) {
        if (std::find(std::begin(kBoundingPowers), std::end(kBoundingPowers), n.block->id) == std::end(kBoundingPowers))
            continue;
        // Without its cross terms (twist 0: the quaternion square on a 3D slice) the Jacobian's
        // largest singular value is 2 r, Mandelbulber2's own derivative: nothing to divide.
        if (n.block->id == "bristorbrot" && n.args().f(0) == 0.0) continue;
        degree = std::max(degree, n.block->degreeAt(n.args()));
    }
    const bool logType = p.formula.estimator.block && p.formula.estimator.block->id != "escape_linear" &&
                         p.formula.estimator.block->membership == Membership::EscapeTime;
    importCamera(main, out);
    // In iteration_threshold_mode the threshold is one footprint whatever detail_level and
    // constant_DE_threshold say, and a step outside is at least (1.01 - 0.5) of it times DE_factor
    // (CalcDistThresh, RayMarching): fraktal's step floor and bisection tolerance, 1.01 hit
    // thresholds, is the same length.
    if (p.formula.hitRule == HitRule::InsideOnly)
        p.render.detail = std::clamp(0.5 * p.formula.deFactor, 1e-3, 100.0);
    else
        p.render.detail =
            std::clamp(p.formula.deFactor * mandelbulber2HitThreshold(main, p.camera, p.render, out.approximated) /
                           (logType ? degree : 1.0),
                       1e-3, 100.0);
    importLook(file, main, out);
    return out;
}

std::string importDescription(const FractFile& file, const FractImport& result) {
    std::ostringstream s;
    s << "Imported from the Mandelbulber2 settings file " << std::filesystem::path(file.source).filename().string();
    if (!file.version.empty()) s << " (version " << file.version << ")";
    s << ": ";
    for (size_t i = 0; i < result.formulas.size(); ++i) s << (i ? " + " : "") << result.formulas[i];
    s << ".";
    if (!result.unsupported.empty()) {
        s << " Dropped (fraktal cannot express):";
        for (const ImportItem& item : result.unsupported) s << " " << item.text() << ";";
    }
    if (!result.approximated.empty()) {
        s << " Approximated:";
        for (const ImportItem& item : result.approximated) s << " " << item.text() << ";";
    }
    return s.str();
}

std::string formulaName(int id) {
    if (const FormulaInfo* f = findFormula(id)) return std::string(f->name);
    return "formula " + std::to_string(id);
}

}  // namespace fraktal::mb2
