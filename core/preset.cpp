#include "core/preset.hpp"

#include "core/image/atomic_file.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace fraktal {

using nlohmann::json;

PresetError::PresetError(std::string file, std::string field, std::string reason)
    : std::runtime_error(file + ": " + (field.empty() ? "" : field + ": ") + reason),
      file_(std::move(file)),
      field_(std::move(field)),
      reason_(std::move(reason)) {}

namespace {

constexpr size_t kMaxPresetBytes = 4 << 20;
constexpr int kMaxJsonDepth = 32;

// Reads fields of one JSON object, with the path for error messages, and rejects fields it was
// not asked about (a typo must not be silently ignored).
class Reader {
public:
    Reader(const std::string& file, const json& j, std::string path) : file_(file), j_(j), path_(std::move(path)) {
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

    double number(const std::string& key, double fallback, double lo, double hi, bool required = false) {
        if (!has(key)) {
            if (required) fail("missing required field", key);
            return fallback;
        }
        return checkNumber(at(key), child(key), lo, hi);
    }
    int integer(const std::string& key, int fallback, int lo, int hi) {
        if (!has(key)) return fallback;
        const json& v = at(key);
        const double d = checkNumber(v, child(key), lo, hi);
        if (d != std::floor(d)) fail("expected a whole number, found " + v.dump(), key);
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
        std::string s = v.get<std::string>();
        if (s.size() > maxLength) fail("string longer than " + std::to_string(maxLength) + " bytes", key);
        return s;
    }
    vec3 vector3(const std::string& key, const vec3& fallback, double lo, double hi, bool required = false) {
        if (!has(key)) {
            if (required) fail("missing required field", key);
            return fallback;
        }
        return checkVec3(at(key), child(key), lo, hi);
    }

    // Fields present but never read.
    void rejectUnknown(const std::set<std::string>& alsoAllowed = {}) const {
        for (const auto& [key, value] : j_.items())
            if (!seen_.count(key) && !alsoAllowed.count(key)) fail("unknown field", key);
    }

    double checkNumber(const json& v, const std::string& path, double lo, double hi) const {
        if (!v.is_number()) throw PresetError(file_, path, "expected a number, found " + typeName(v));
        const double d = v.get<double>();
        if (!std::isfinite(d)) throw PresetError(file_, path, "number is not finite");
        if (d < lo || d > hi)
            throw PresetError(file_, path, "value " + v.dump() + " is outside the range [" + fmt(lo) + ", " + fmt(hi) + "]");
        return d;
    }
    vec3 checkVec3(const json& v, const std::string& path, double lo, double hi) const {
        if (!v.is_array() || v.size() != 3)
            throw PresetError(file_, path, "expected an array of 3 numbers, found " + typeName(v) +
                                               (v.is_array() ? " of " + std::to_string(v.size()) : ""));
        vec3 r;
        for (int i = 0; i < 3; ++i) r[i] = checkNumber(v[i], path + "[" + std::to_string(i) + "]", lo, hi);
        return r;
    }

    static std::string typeName(const json& v) {
        if (v.is_number()) return "a number";
        if (v.is_string()) return "a string";
        if (v.is_array()) return "an array";
        if (v.is_object()) return "an object";
        if (v.is_boolean()) return "a boolean";
        if (v.is_null()) return "null";
        return v.type_name();
    }
    static std::string fmt(double d) {
        std::ostringstream s;
        s << d;
        return s.str();
    }

private:
    const std::string& file_;
    const json& j_;
    std::string path_;
    std::set<std::string> seen_;
};

// Custom blocks first (a preset may not redefine a built-in id; CustomBlock::validate refuses).
const BlockDesc* lookUpBlock(const std::string& id, const CustomBlocks& custom) {
    for (const auto& b : custom)
        if (b->desc().id == id) return &b->desc();
    return findBlock(id);
}

Node parseNode(const std::string& file, const json& j, const std::string& path, const CustomBlocks& custom) {
    Reader r(file, j, path);
    const json& id = r.at("block");
    if (!id.is_string()) r.fail("expected a block id string, found " + Reader::typeName(id), "block");
    const BlockDesc* block = lookUpBlock(id.get<std::string>(), custom);
    if (!block) {
        std::string known;
        for (const BlockDesc& b : allBlocks()) known += (known.empty() ? "" : ", ") + std::string(b.id);
        for (const auto& b : custom) known += ", " + std::string(b->desc().id);
        r.fail("unknown block '" + id.get<std::string>() + "' (known blocks: " + known + ")", "block");
    }
    Node n = Node::make(*block);
    n.enabled = r.boolean("enabled", true);
    n.period = r.integer("period", 1, 1, 16);
    n.phase = r.integer("phase", 0, 0, 15);
    if (n.phase >= n.period) r.fail("phase must be smaller than period (" + std::to_string(n.period) + ")", "phase");
    if (r.has("params")) {
        Reader params(file, r.at("params"), r.child("params"));
        for (size_t i = 0; i < block->params.size(); ++i) {
            const ParamDecl& d = block->params[i];
            const std::string key(d.name);
            if (d.type == ParamType::Float) n.values[i].x = params.number(key, d.defaultValue.x, d.min, d.max);
            else n.values[i] = params.vector3(key, d.defaultValue, d.min, d.max);
            if (d.direction && length(n.values[i]) < 1e-9) params.fail("a direction must not be zero", key);
        }
        try {
            params.rejectUnknown();
        } catch (const PresetError& e) {
            std::string known;
            for (const ParamDecl& d : block->params) known += (known.empty() ? "" : ", ") + std::string(d.name);
            throw PresetError(e.file(), e.field(),
                              "unknown parameter of block '" + std::string(block->id) + "' (it has: " +
                                  (known.empty() ? "none" : known) + ")");
        }
    }
    r.rejectUnknown();
    return n;
}

Formula parseFormula(const std::string& file, const json& j) {
    Reader r(file, j, "formula");
    Formula f;
    f.iterations = r.integer("iterations", f.iterations, 0, kMaxIterations);
    f.bailout = r.number("bailout", f.bailout, 1e-3, 1e10);
    f.boundRadius = r.number("boundRadius", f.boundRadius, 1e-3, 1e4);
    f.deFactor = r.number("deFactor", f.deFactor, 1e-3, 2.0);
    if (r.has("customBlocks")) {
        const json& blocks = r.at("customBlocks");
        if (!blocks.is_array()) r.fail("expected an array of custom blocks", "customBlocks");
        if (blocks.size() > size_t(kMaxCustomBlocks))
            r.fail("more than " + std::to_string(kMaxCustomBlocks) + " custom blocks", "customBlocks");
        for (size_t i = 0; i < blocks.size(); ++i) {
            const std::string where = r.child("customBlocks") + "[" + std::to_string(i) + "]";
            auto block = parseCustomBlock(blocks[i], file, where);
            if (lookUpBlock(block->definition().id, f.customBlocks))
                throw PresetError(file, where + ".id", "'" + block->definition().id + "' is defined twice");
            f.customBlocks.push_back(std::move(block));
        }
    }
    const json& nodes = r.at("nodes");
    const std::string path = r.child("nodes");
    if (!nodes.is_array()) r.fail("expected an array of nodes, found " + Reader::typeName(nodes), "nodes");
    if (nodes.empty()) r.fail("the node list is empty: a formula needs at least a closing estimator", "nodes");
    if (nodes.size() > size_t(kMaxNodes))
        r.fail("too many nodes (" + std::to_string(nodes.size()) + "; at most " + std::to_string(kMaxNodes) + ")", "nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string nodePath = path + "[" + std::to_string(i) + "]";
        Node n = parseNode(file, nodes[i], nodePath, f.customBlocks);
        const bool last = i + 1 == nodes.size();
        if (n.block->isEstimator() && !last)
            throw PresetError(file, nodePath, "estimator '" + std::string(n.block->id) + "' may only close the node list");
        if (!n.block->isEstimator() && last)
            throw PresetError(file, nodePath, "the node list must end with an estimator (box, sphere, tetrahedron, escape_log, escape_linear), found '" +
                                                  std::string(n.block->id) + "'");
        if (last) {
            if (!n.enabled) throw PresetError(file, nodePath + ".enabled", "the estimator cannot be disabled");
            if (n.period != 1) throw PresetError(file, nodePath + ".period", "the estimator runs once, after the loop");
            f.estimator = std::move(n);
        } else {
            f.nodes.push_back(std::move(n));
        }
    }
    r.rejectUnknown();
    return f;
}

Camera parseCamera(const std::string& file, const json& j) {
    Reader r(file, j, "camera");
    Camera c;
    c.position = r.vector3("position", c.position, -1e4, 1e4, true);
    c.target = r.vector3("target", c.target, -1e4, 1e4, true);
    c.up = r.vector3("up", c.up, -1e4, 1e4);
    c.fovY = r.number("fovY", c.fovY, 1.0, 170.0);
    if (length(c.target - c.position) < 1e-9) r.fail("position and target coincide");
    if (length(glm::cross(normalize(c.target - c.position), c.up)) < 1e-6)
        r.fail("up is zero or parallel to the viewing direction", "up");
    r.rejectUnknown();
    return c;
}

RenderSettings parseRender(const std::string& file, const json& j) {
    Reader r(file, j, "render");
    RenderSettings s;
    s.width = r.integer("width", s.width, 1, kMaxImageSide);
    s.height = r.integer("height", s.height, 1, kMaxImageSide);
    s.spp = r.integer("spp", s.spp, 1, kMaxSpp);
    s.maxSteps = r.integer("maxSteps", s.maxSteps, 1, kMaxMarchSteps);
    s.detail = r.number("detail", s.detail, 1e-3, 100.0);
    s.overRelaxation = r.number("overRelaxation", s.overRelaxation, 1.0, 1.95);
    s.filterRadius = r.number("filterRadius", s.filterRadius, 0.5, 4.0);
    s.transparentBackground = r.boolean("transparentBackground", s.transparentBackground);
    s.workingSpace = r.string("workingSpace", s.workingSpace, 256);
    s.display = r.string("display", s.display, 256);
    s.view = r.string("view", s.view, 256);
    s.exposure = r.number("exposure", s.exposure, -20.0, 20.0);
    r.rejectUnknown();
    return s;
}

vec4 readVec4(Reader& r, const std::string& key, const vec4& fallback, double lo, double hi) {
    if (!r.has(key)) return fallback;
    const json& v = r.at(key);
    if (!v.is_array() || v.size() != 4) r.fail("expected an array of 4 numbers, found " + Reader::typeName(v), key);
    vec4 out;
    for (int i = 0; i < 4; ++i) out[i] = r.checkNumber(v[i], r.child(key) + "[" + std::to_string(i) + "]", lo, hi);
    return out;
}

ShadingSettings parseShading(const std::string& file, const json& j) {
    Reader r(file, j, "shading");
    ShadingSettings s;
    s.lightDirection = r.vector3("lightDirection", s.lightDirection, -1e3, 1e3);
    if (length(s.lightDirection) < 1e-9) r.fail("a direction must not be zero", "lightDirection");
    s.lightColor = r.vector3("lightColor", s.lightColor, 0.0, 1e4);
    s.fillColor = r.vector3("fillColor", s.fillColor, 0.0, 1e4);
    s.specular = r.number("specular", s.specular, 0.0, 100.0);
    s.shininess = r.number("shininess", s.shininess, 1.0, 10000.0);
    s.shadowSteps = r.integer("shadowSteps", s.shadowSteps, 0, kMaxMarchSteps);
    s.shadowSoftness = r.number("shadowSoftness", s.shadowSoftness, 0.1, 1000.0);
    s.aoSteps = r.integer("aoSteps", s.aoSteps, 0, 64);
    s.aoDistance = r.number("aoDistance", s.aoDistance, 1e-6, 10.0);
    s.aoStrength = r.number("aoStrength", s.aoStrength, 0.0, 1.0);
    s.trapWeights = readVec4(r, "trapWeights", s.trapWeights, -1e3, 1e3);
    s.trapScale = r.number("trapScale", s.trapScale, -1e4, 1e4);
    s.trapOffset = r.number("trapOffset", s.trapOffset, -1e4, 1e4);
    s.paletteA = r.vector3("paletteA", s.paletteA, -10.0, 10.0);
    s.paletteB = r.vector3("paletteB", s.paletteB, -10.0, 10.0);
    s.paletteC = r.vector3("paletteC", s.paletteC, -100.0, 100.0);
    s.paletteD = r.vector3("paletteD", s.paletteD, -100.0, 100.0);
    s.fogColor = r.vector3("fogColor", s.fogColor, 0.0, 1e4);
    s.fogDensity = r.number("fogDensity", s.fogDensity, 0.0, 1e3);
    s.reflection = r.number("reflection", s.reflection, 0.0, 1.0);
    s.reflectionSteps = r.integer("reflectionSteps", s.reflectionSteps, 1, kMaxMarchSteps);
    s.backgroundTop = r.vector3("backgroundTop", s.backgroundTop, 0.0, 1e4);
    s.backgroundBottom = r.vector3("backgroundBottom", s.backgroundBottom, 0.0, 1e4);
    r.rejectUnknown();
    return s;
}

// Parses JSON, rejecting duplicate keys and nesting deeper than kMaxJsonDepth (nlohmann keeps
// the last duplicate silently; a preset with two values for one field is ambiguous).
json parseJson(std::string_view text, const std::string& file) {
    std::vector<std::set<std::string>> keys;
    std::string duplicate, tooDeep;
    auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
        if (depth > kMaxJsonDepth && tooDeep.empty()) tooDeep = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
        switch (event) {
            case json::parse_event_t::object_start: keys.emplace_back(); break;
            case json::parse_event_t::object_end:
                if (!keys.empty()) keys.pop_back();
                break;
            case json::parse_event_t::key:
                if (!keys.empty() && !keys.back().insert(parsed.get<std::string>()).second && duplicate.empty())
                    duplicate = parsed.get<std::string>();
                break;
            default: break;
        }
        return tooDeep.empty();
    };
    json j;
    try {
        j = json::parse(text.begin(), text.end(), callback);
    } catch (const json::parse_error& e) {
        // Byte offset to line:column.
        const size_t at = std::min(e.byte, text.size());
        const size_t line = 1 + std::count(text.begin(), text.begin() + long(at ? at - 1 : 0), '\n');
        std::string reason = e.what();
        if (auto p = reason.find("parse error"); p != std::string::npos) reason = reason.substr(p);
        if (!tooDeep.empty()) reason = tooDeep;
        throw PresetError(file, "", "invalid JSON at line " + std::to_string(line) + ": " + reason);
    } catch (const json::exception& e) {  // e.g. out_of_range 406: a number too large for a double
        std::string reason = e.what();
        if (auto p = reason.find("] "); p != std::string::npos) reason = reason.substr(p + 2);
        throw PresetError(file, "", "invalid JSON: " + reason);
    }
    if (!tooDeep.empty()) throw PresetError(file, "", "invalid preset: " + tooDeep);
    if (!duplicate.empty()) throw PresetError(file, duplicate, "duplicated key");
    return j;
}

}  // namespace

Preset parsePreset(std::string_view text, const std::string& file) {
    if (text.size() > kMaxPresetBytes)
        throw PresetError(file, "", "file is larger than " + std::to_string(kMaxPresetBytes >> 20) + " MiB; not a preset");
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw PresetError(file, "", "file is empty");
    const json j = parseJson(text, file);
    Reader r(file, j, "");
    const std::string format = r.string("format", "");
    if (format != kPresetFormat) r.fail("expected \"" + std::string(kPresetFormat) + "\"", "format");
    const int version = r.integer("version", 0, 1, 1000000);
    if (!r.has("version")) r.fail("missing required field", "version");
    if (version > kPresetVersion) {
        // A newer file: read what we understand; unknown sections are kept.
    }
    Preset p;
    p.name = r.string("name", "");
    p.description = r.string("description", "", 65536);
    p.formula = parseFormula(file, r.at("formula"));
    p.camera = parseCamera(file, r.at("camera"));
    if (r.has("render")) p.render = parseRender(file, r.at("render"));
    if (r.has("shading")) p.shading = parseShading(file, r.at("shading"));
    for (const auto& [key, value] : j.items())
        if (key != "format" && key != "version" && key != "name" && key != "description" && key != "formula" &&
            key != "camera" && key != "render" && key != "shading")
            p.extra[key] = value;
    return p;
}

Preset loadPreset(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw PresetError(file, "", "no such file");
    if (std::filesystem::is_directory(status)) throw PresetError(file, "", "is a directory, not a preset file");
    if (!std::filesystem::is_regular_file(status)) throw PresetError(file, "", "is not a regular file");
    if (std::filesystem::file_size(path, ec) > kMaxPresetBytes)
        throw PresetError(file, "", "file is larger than " + std::to_string(kMaxPresetBytes >> 20) + " MiB; not a preset");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw PresetError(file, "", "cannot be opened for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    return parsePreset(ss.str(), file);
}

namespace {

json vecJson(const vec3& v) { return json::array({v.x, v.y, v.z}); }

// Only the fields that differ from the defaults.
json renderJson(const RenderSettings& s) {
    const RenderSettings d;
    json j = json::object();
    auto put = [&](const char* key, const auto& value, const auto& fallback) {
        if (value != fallback) j[key] = value;
    };
    put("width", s.width, d.width);
    put("height", s.height, d.height);
    put("spp", s.spp, d.spp);
    put("maxSteps", s.maxSteps, d.maxSteps);
    put("detail", s.detail, d.detail);
    put("overRelaxation", s.overRelaxation, d.overRelaxation);
    put("filterRadius", s.filterRadius, d.filterRadius);
    put("transparentBackground", s.transparentBackground, d.transparentBackground);
    put("workingSpace", s.workingSpace, d.workingSpace);
    put("display", s.display, d.display);
    put("view", s.view, d.view);
    put("exposure", s.exposure, d.exposure);
    return j;
}

json shadingJson(const ShadingSettings& s) {
    const ShadingSettings d;
    json j = json::object();
    auto put = [&](const char* key, const auto& value, const auto& fallback) {
        if (value != fallback) j[key] = value;
    };
    auto putVec = [&](const char* key, const vec3& value, const vec3& fallback) {
        if (value != fallback) j[key] = vecJson(value);
    };
    putVec("lightDirection", s.lightDirection, d.lightDirection);
    putVec("lightColor", s.lightColor, d.lightColor);
    putVec("fillColor", s.fillColor, d.fillColor);
    put("specular", s.specular, d.specular);
    put("shininess", s.shininess, d.shininess);
    put("shadowSteps", s.shadowSteps, d.shadowSteps);
    put("shadowSoftness", s.shadowSoftness, d.shadowSoftness);
    put("aoSteps", s.aoSteps, d.aoSteps);
    put("aoDistance", s.aoDistance, d.aoDistance);
    put("aoStrength", s.aoStrength, d.aoStrength);
    if (s.trapWeights != d.trapWeights)
        j["trapWeights"] = json::array({s.trapWeights.x, s.trapWeights.y, s.trapWeights.z, s.trapWeights.w});
    put("trapScale", s.trapScale, d.trapScale);
    put("trapOffset", s.trapOffset, d.trapOffset);
    putVec("paletteA", s.paletteA, d.paletteA);
    putVec("paletteB", s.paletteB, d.paletteB);
    putVec("paletteC", s.paletteC, d.paletteC);
    putVec("paletteD", s.paletteD, d.paletteD);
    putVec("fogColor", s.fogColor, d.fogColor);
    put("fogDensity", s.fogDensity, d.fogDensity);
    put("reflection", s.reflection, d.reflection);
    put("reflectionSteps", s.reflectionSteps, d.reflectionSteps);
    putVec("backgroundTop", s.backgroundTop, d.backgroundTop);
    putVec("backgroundBottom", s.backgroundBottom, d.backgroundBottom);
    return j;
}

json nodeJson(const Node& n) {
    json j;
    j["block"] = n.block->id;
    if (!n.enabled) j["enabled"] = false;
    if (n.period != 1) j["period"] = n.period;
    if (n.phase != 0) j["phase"] = n.phase;
    json params = json::object();
    for (size_t i = 0; i < n.block->params.size(); ++i) {
        const ParamDecl& d = n.block->params[i];
        if (d.type == ParamType::Float) {
            if (n.values[i].x != d.defaultValue.x) params[std::string(d.name)] = n.values[i].x;
        } else if (n.values[i] != d.defaultValue) {
            params[std::string(d.name)] = vecJson(n.values[i]);
        }
    }
    if (!params.empty()) j["params"] = params;
    return j;
}

}  // namespace

json presetToJson(const Preset& p) {
    const Formula defaults;
    const Camera camDefaults;
    json j = json::object();
    j["format"] = kPresetFormat;
    j["version"] = kPresetVersion;
    if (!p.name.empty()) j["name"] = p.name;
    if (!p.description.empty()) j["description"] = p.description;
    json f = json::object();
    if (p.formula.iterations != defaults.iterations) f["iterations"] = p.formula.iterations;
    if (p.formula.bailout != defaults.bailout) f["bailout"] = p.formula.bailout;
    if (p.formula.boundRadius != defaults.boundRadius) f["boundRadius"] = p.formula.boundRadius;
    if (p.formula.deFactor != defaults.deFactor) f["deFactor"] = p.formula.deFactor;
    if (!p.formula.customBlocks.empty()) {
        f["customBlocks"] = json::array();
        for (const auto& b : p.formula.customBlocks) f["customBlocks"].push_back(customBlockToJson(*b));
    }
    json nodes = json::array();
    for (const Node& n : p.formula.nodes) nodes.push_back(nodeJson(n));
    nodes.push_back(nodeJson(p.formula.estimator));
    f["nodes"] = nodes;
    j["formula"] = f;
    json c = json::object();
    c["position"] = vecJson(p.camera.position);
    c["target"] = vecJson(p.camera.target);
    if (p.camera.up != camDefaults.up) c["up"] = vecJson(p.camera.up);
    if (p.camera.fovY != camDefaults.fovY) c["fovY"] = p.camera.fovY;
    j["camera"] = c;
    if (json r = renderJson(p.render); !r.empty()) j["render"] = r;
    if (json s = shadingJson(p.shading); !s.empty()) j["shading"] = s;
    for (const auto& [key, value] : p.extra.items()) j[key] = value;
    return j;
}

std::string serializePreset(const Preset& p) { return presetToJson(p).dump(2) + "\n"; }

void savePresetFile(const std::filesystem::path& path, const Preset& preset) {
    writeFileAtomically(path, serializePreset(preset), /*keepBackup=*/true);
}

std::string describeFormula(const Formula& f) {
    std::ostringstream s;
    s << "iterations " << f.iterations << ", bailout " << f.bailout << ", bound radius " << f.boundRadius
      << ", DE factor " << f.deFactor << "\n";
    auto describeNode = [&](const Node& n, const std::string& prefix) {
        s << prefix << n.block->id << " [" << categoryName(n.block->category) << "]";
        if (!n.enabled) s << " (disabled)";
        if (n.period > 1) s << " (iterations i % " << n.period << " == " << n.phase << ")";
        for (size_t i = 0; i < n.values.size(); ++i) {
            const ParamDecl& d = n.block->params[i];
            s << (i == 0 ? ": " : ", ") << d.name << " = ";
            if (d.type == ParamType::Float) s << n.values[i].x;
            else s << "(" << n.values[i].x << ", " << n.values[i].y << ", " << n.values[i].z << ")";
        }
        s << "\n";
    };
    for (size_t k = 0; k < f.nodes.size(); ++k) describeNode(f.nodes[k], "  " + std::to_string(k) + ". ");
    describeNode(f.estimator, "  => ");
    return s.str();
}

}  // namespace fraktal
