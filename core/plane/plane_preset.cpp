#include "core/plane/plane_preset.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace fraktal {

using nlohmann::json;

namespace {

constexpr size_t kMaxPresetBytes = 4 << 20;

std::string typeName(const json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_array()) return "an array";
    if (v.is_object()) return "an object";
    if (v.is_boolean()) return "a boolean";
    return "null";
}

std::string fmt(double d) {
    std::ostringstream s;
    s << d;
    return s.str();
}

// Reads the fields of one JSON object with its path for error messages; fields never asked
// about are rejected (a typo must not be ignored silently).
class Fields {
public:
    Fields(const std::string& file, const json& j, std::string path) : file_(file), j_(j), path_(std::move(path)) {
        if (!j_.is_object()) fail("expected an object, found " + typeName(j_));
    }
    [[noreturn]] void fail(const std::string& reason, const std::string& key = {}) const {
        throw PresetError(file_, key.empty() ? path_ : child(key), reason);
    }
    std::string child(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const { return j_.contains(key); }
    const json& at(const std::string& key) {
        seen_.insert(key);
        if (!j_.contains(key)) fail("missing required field", key);
        return j_.at(key);
    }
    double number(const std::string& key, double fallback, double lo, double hi) {
        return has(key) ? checkNumber(at(key), child(key), lo, hi) : fallback;
    }
    int integer(const std::string& key, int fallback, int lo, int hi) {
        if (!has(key)) return fallback;
        const double d = checkNumber(at(key), child(key), lo, hi);
        if (d != std::floor(d)) fail("expected a whole number, found " + fmt(d), key);
        return int(d);
    }
    bool boolean(const std::string& key, bool fallback) {
        if (!has(key)) return fallback;
        const json& v = at(key);
        if (!v.is_boolean()) fail("expected true or false, found " + typeName(v), key);
        return v.get<bool>();
    }
    std::string string(const std::string& key, const std::string& fallback, size_t maxLength = 4096) {
        if (!has(key)) return fallback;
        const json& v = at(key);
        if (!v.is_string()) fail("expected a string, found " + typeName(v), key);
        if (v.get<std::string>().size() > maxLength) fail("string longer than " + std::to_string(maxLength) + " bytes", key);
        return v.get<std::string>();
    }
    template <int N>
    glm::vec<N, double> vector(const std::string& key, const glm::vec<N, double>& fallback, double lo, double hi) {
        if (!has(key)) return fallback;
        const json& v = at(key);
        if (!v.is_array() || v.size() != N)
            fail("expected an array of " + std::to_string(N) + " numbers, found " + typeName(v), key);
        glm::vec<N, double> r;
        for (int i = 0; i < N; ++i) r[i] = checkNumber(v[i], child(key) + "[" + std::to_string(i) + "]", lo, hi);
        return r;
    }
    void rejectUnknown() const {
        for (const auto& [key, value] : j_.items())
            if (!seen_.count(key)) fail("unknown field", key);
    }
    double checkNumber(const json& v, const std::string& path, double lo, double hi) const {
        if (!v.is_number()) throw PresetError(file_, path, "expected a number, found " + typeName(v));
        const double d = v.get<double>();
        if (!std::isfinite(d)) throw PresetError(file_, path, "number is not finite");
        if (d < lo || d > hi)
            throw PresetError(file_, path, "value " + fmt(d) + " is outside the range [" + fmt(lo) + ", " + fmt(hi) + "]");
        return d;
    }

private:
    const std::string& file_;
    const json& j_;
    std::string path_;
    std::set<std::string> seen_;
};

std::string knownBlocks() {
    std::string known;
    for (const PlaneBlockDesc& b : allPlaneBlocks()) known += (known.empty() ? "" : ", ") + std::string(b.id);
    return known;
}

PlaneNode parseNode(const std::string& file, const json& j, const std::string& path) {
    Fields r(file, j, path);
    const json& id = r.at("block");
    if (!id.is_string()) r.fail("expected a block id string, found " + typeName(id), "block");
    const PlaneBlockDesc* block = findPlaneBlock(id.get<std::string>());
    if (!block) r.fail("unknown 2D block '" + id.get<std::string>() + "' (known 2D blocks: " + knownBlocks() + ")", "block");
    PlaneNode n = PlaneNode::make(*block);
    n.enabled = r.boolean("enabled", true);
    n.period = r.integer("period", 1, 1, 16);
    n.phase = r.integer("phase", 0, 0, 15);
    if (n.phase >= n.period) r.fail("phase must be smaller than period (" + std::to_string(n.period) + ")", "phase");
    if (r.has("params")) {
        Fields params(file, r.at("params"), r.child("params"));
        for (size_t i = 0; i < block->params.size(); ++i) {
            const ParamDecl& d = block->params[i];
            n.values[i].x = params.number(std::string(d.name), d.defaultValue.x, d.min, d.max);
        }
        try {
            params.rejectUnknown();
        } catch (const PresetError& e) {
            std::string known;
            for (const ParamDecl& d : block->params) known += (known.empty() ? "" : ", ") + std::string(d.name);
            throw PresetError(e.file(), e.field(),
                              "unknown parameter of 2D block '" + std::string(block->id) + "' (it has: " +
                                  (known.empty() ? "none" : known) + ")");
        }
    }
    r.rejectUnknown();
    return n;
}

std::vector<PlaneNode> parseNodeList(const std::string& file, Fields& r, const std::string& key) {
    const json& list = r.at(key);
    if (!list.is_array()) r.fail("expected an array of nodes, found " + typeName(list), key);
    if (list.size() > size_t(kMaxNodes))
        r.fail("too many nodes (" + std::to_string(list.size()) + "; at most " + std::to_string(kMaxNodes) + ")", key);
    std::vector<PlaneNode> nodes;
    for (size_t i = 0; i < list.size(); ++i)
        nodes.push_back(parseNode(file, list[i], r.child(key) + "[" + std::to_string(i) + "]"));
    return nodes;
}

PlaneFormula parseFormula(const std::string& file, const json& j) {
    Fields r(file, j, "formula");
    PlaneFormula f;
    f.iterations = r.integer("iterations", f.iterations, 0, kMaxIterations);
    f.bailout = r.number("bailout", f.bailout, 1e-3, 1e10);
    if (r.has("start")) {
        f.start = parseNodeList(file, r, "start");
        for (size_t i = 0; i < f.start.size(); ++i)
            if (f.start[i].block->isEstimator())
                throw PresetError(file, r.child("start") + "[" + std::to_string(i) + "]",
                                  "estimator '" + std::string(f.start[i].block->id) + "' may only close the node list");
    }
    std::vector<PlaneNode> nodes = parseNodeList(file, r, "nodes");
    if (nodes.empty()) r.fail("the node list is empty: a formula needs at least a closing estimator", "nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string path = r.child("nodes") + "[" + std::to_string(i) + "]";
        const bool last = i + 1 == nodes.size();
        if (nodes[i].block->isEstimator() != last)
            throw PresetError(file, path,
                              last ? "the node list must end with a 2D estimator (escape, triangle, segment), found '" +
                                         std::string(nodes[i].block->id) + "'"
                                   : "estimator '" + std::string(nodes[i].block->id) + "' may only close the node list");
        if (last && !nodes[i].enabled) throw PresetError(file, path + ".enabled", "the estimator cannot be disabled");
        if (last && nodes[i].period != 1) throw PresetError(file, path + ".period", "the estimator runs once, after the loop");
    }
    f.estimator = std::move(nodes.back());
    nodes.pop_back();
    f.nodes = std::move(nodes);
    r.rejectUnknown();
    return f;
}

PlaneViewRect parseView(const std::string& file, const json& j) {
    Fields r(file, j, "view");
    PlaneViewRect v;
    v.center = r.vector<2>("center", v.center, -1e4, 1e4);
    v.width = r.number("width", v.width, 1e-300, 1e4);
    r.rejectUnknown();
    return v;
}

RenderSettings parseRender(const std::string& file, const json& j) {
    Fields r(file, j, "render");
    RenderSettings s;
    s.width = r.integer("width", s.width, 1, kMaxImageSide);
    s.height = r.integer("height", s.height, 1, kMaxImageSide);
    s.spp = r.integer("spp", s.spp, 1, kMaxSpp);
    s.workingSpace = r.string("workingSpace", s.workingSpace, 256);
    s.display = r.string("display", s.display, 256);
    s.view = r.string("view", s.view, 256);
    s.exposure = r.number("exposure", s.exposure, -20.0, 20.0);
    r.rejectUnknown();
    return s;
}

PlaneColouring parseColouring(const std::string& file, const json& j) {
    Fields r(file, j, "colouring");
    PlaneColouring c;
    c.paletteA = r.vector<3>("paletteA", c.paletteA, -10.0, 10.0);
    c.paletteB = r.vector<3>("paletteB", c.paletteB, -10.0, 10.0);
    c.paletteC = r.vector<3>("paletteC", c.paletteC, -100.0, 100.0);
    c.paletteD = r.vector<3>("paletteD", c.paletteD, -100.0, 100.0);
    c.frequency = r.number("frequency", c.frequency, -1e3, 1e3);
    c.offset = r.number("offset", c.offset, -1e3, 1e3);
    c.interior = r.vector<3>("interior", c.interior, 0.0, 1e4);
    c.edgeWidth = r.number("edgeWidth", c.edgeWidth, 0.0, 100.0);
    r.rejectUnknown();
    return c;
}

json parseJson(std::string_view text, const std::string& file) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        std::string reason = e.what();
        if (auto p = reason.find("] "); p != std::string::npos) reason = reason.substr(p + 2);
        throw PresetError(file, "", "invalid JSON: " + reason);
    }
}

}  // namespace

bool isPlanePresetText(std::string_view text) {
    const json j = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    return j.is_object() && j.contains("dimension") && j["dimension"] == 2;
}

bool isPlanePresetFile(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > kMaxPresetBytes) return false;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return isPlanePresetText(ss.str());
}

PlanePreset parsePlanePreset(std::string_view text, const std::string& file) {
    if (text.size() > kMaxPresetBytes) throw PresetError(file, "", "file is larger than 4 MiB; not a preset");
    const json j = parseJson(text, file);
    Fields r(file, j, "");
    if (r.string("format", "") != kPresetFormat) r.fail("expected \"" + std::string(kPresetFormat) + "\"", "format");
    if (!r.has("version")) r.fail("missing required field", "version");
    r.integer("version", 0, 1, 1000000);
    if (r.integer("dimension", 3, 2, 3) != 2) r.fail("expected 2 for a 2D preset", "dimension");
    PlanePreset p;
    p.name = r.string("name", "");
    p.description = r.string("description", "", 65536);
    p.formula = parseFormula(file, r.at("formula"));
    if (r.has("view")) p.view = parseView(file, r.at("view"));
    if (r.has("render")) p.render = parseRender(file, r.at("render"));
    if (r.has("colouring")) p.colouring = parseColouring(file, r.at("colouring"));
    r.rejectUnknown();
    return p;
}

PlanePreset loadPlanePreset(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw PresetError(file, "", "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw PresetError(file, "", "is not a regular file");
    if (std::filesystem::file_size(path, ec) > kMaxPresetBytes) throw PresetError(file, "", "file is larger than 4 MiB; not a preset");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw PresetError(file, "", "cannot be opened for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    return parsePlanePreset(ss.str(), file);
}

namespace {

json nodeJson(const PlaneNode& n) {
    json j;
    j["block"] = n.block->id;
    if (!n.enabled) j["enabled"] = false;
    if (n.period != 1) j["period"] = n.period;
    if (n.phase != 0) j["phase"] = n.phase;
    json params = json::object();
    for (size_t i = 0; i < n.block->params.size(); ++i)
        if (n.values[i].x != n.block->params[i].defaultValue.x) params[std::string(n.block->params[i].name)] = n.values[i].x;
    if (!params.empty()) j["params"] = params;
    return j;
}

}  // namespace

json planePresetToJson(const PlanePreset& p) {
    const PlaneFormula formulaDefaults;
    const RenderSettings renderDefaults;
    const PlaneColouring colourDefaults;
    json j = json::object();
    j["format"] = kPresetFormat;
    j["version"] = kPresetVersion;
    j["dimension"] = 2;
    if (!p.name.empty()) j["name"] = p.name;
    if (!p.description.empty()) j["description"] = p.description;
    json f = json::object();
    if (p.formula.iterations != formulaDefaults.iterations) f["iterations"] = p.formula.iterations;
    if (p.formula.bailout != formulaDefaults.bailout) f["bailout"] = p.formula.bailout;
    if (!p.formula.start.empty()) {
        f["start"] = json::array();
        for (const PlaneNode& n : p.formula.start) f["start"].push_back(nodeJson(n));
    }
    f["nodes"] = json::array();
    for (const PlaneNode& n : p.formula.nodes) f["nodes"].push_back(nodeJson(n));
    f["nodes"].push_back(nodeJson(p.formula.estimator));
    j["formula"] = f;
    j["view"] = {{"center", {p.view.center.x, p.view.center.y}}, {"width", p.view.width}};
    json r = json::object();
    const RenderSettings& s = p.render;
    if (s.width != renderDefaults.width) r["width"] = s.width;
    if (s.height != renderDefaults.height) r["height"] = s.height;
    if (s.spp != renderDefaults.spp) r["spp"] = s.spp;
    if (s.workingSpace != renderDefaults.workingSpace) r["workingSpace"] = s.workingSpace;
    if (s.display != renderDefaults.display) r["display"] = s.display;
    if (s.view != renderDefaults.view) r["view"] = s.view;
    if (s.exposure != renderDefaults.exposure) r["exposure"] = s.exposure;
    if (!r.empty()) j["render"] = r;
    json c = json::object();
    const PlaneColouring& k = p.colouring;
    auto putVec = [&c](const char* key, const vec3& v, const vec3& d) {
        if (v != d) c[key] = {v.x, v.y, v.z};
    };
    putVec("paletteA", k.paletteA, colourDefaults.paletteA);
    putVec("paletteB", k.paletteB, colourDefaults.paletteB);
    putVec("paletteC", k.paletteC, colourDefaults.paletteC);
    putVec("paletteD", k.paletteD, colourDefaults.paletteD);
    if (k.frequency != colourDefaults.frequency) c["frequency"] = k.frequency;
    if (k.offset != colourDefaults.offset) c["offset"] = k.offset;
    putVec("interior", k.interior, colourDefaults.interior);
    if (k.edgeWidth != colourDefaults.edgeWidth) c["edgeWidth"] = k.edgeWidth;
    if (!c.empty()) j["colouring"] = c;
    return j;
}

std::string serializePlanePreset(const PlanePreset& p) { return planePresetToJson(p).dump(2) + "\n"; }

}  // namespace fraktal
