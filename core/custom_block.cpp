#include "core/custom_block.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/preset.hpp"
#include "core/whole_de.hpp"

namespace fraktal {

namespace {

const std::regex kIdentifier("[A-Za-z][A-Za-z0-9_]*");

// Words a snippet may not use. Loops: the formula's own loop is the only one, and it is
// bounded (kMaxIterations), so no preset can hang the GPU. The rest would reach outside the
// block's function or break the generated shader's structure.
const std::set<std::string> kForbiddenWords{"for",    "while",  "do",      "uniform",   "buffer",
                                            "layout", "shared", "discard", "struct",    "in",
                                            "out",    "inout",  "main",    "formulaDE", "DE"};

std::string findForbidden(const std::string& glsl) {
    int line = 1;
    int depth = 0;
    for (size_t i = 0; i < glsl.size();) {
        const char ch = glsl[i];
        if (ch == '\n') ++line;
        if (ch == '#') return "line " + std::to_string(line) + ": preprocessor directives are not allowed";
        if (ch == '{') ++depth;
        if (ch == '}' && --depth < 0) return "line " + std::to_string(line) + ": unbalanced '}'";
        if (std::isalpha(static_cast<unsigned char>(ch)) || ch == '_') {
            size_t j = i;
            while (j < glsl.size() && (std::isalnum(static_cast<unsigned char>(glsl[j])) || glsl[j] == '_')) ++j;
            const std::string word = glsl.substr(i, j - i);
            if (word == "for" || word == "while" || word == "do")
                return "line " + std::to_string(line) + ": loops ('" + word +
                       "') are not allowed in custom blocks: the formula's iteration loop is the only loop, so "
                       "that no preset can hang the GPU";
            if (kForbiddenWords.count(word) || word.rfind("gl_", 0) == 0 || word.rfind("fraktal", 0) == 0 ||
                word.rfind("u_", 0) == 0)
                return "line " + std::to_string(line) + ": '" + word + "' is not allowed in a custom block";
            i = j;
            continue;
        }
        ++i;
    }
    if (depth != 0) return "unbalanced '{'";
    return {};
}

Category categoryFromName(const std::string& s, bool& ok) {
    ok = true;
    for (Category c : {Category::Fold, Category::Transform, Category::Power, Category::Estimator})
        if (categoryName(c) == s) return c;
    ok = false;
    return Category::Transform;
}

}  // namespace

std::string CustomBlock::validate(const Definition& d) {
    if (!std::regex_match(d.id, kIdentifier) || d.id.size() > 64)
        return "id: '" + d.id + "' is not a name (a letter, then letters, digits or _; at most 64)";
    if (findBlock(d.id)) return "id: '" + d.id + "' is a built-in block";
    if (d.wholeDE && d.category != Category::Estimator)
        return "wholeDE: a whole DE computes the distance, so its category is estimator";
    const int maxParams = d.wholeDE ? kMaxWholeDEParams : kMaxCustomParams;
    if (d.params.size() > size_t(maxParams)) return "params: more than " + std::to_string(maxParams) + " parameters";
    std::set<std::string> names;
    for (size_t i = 0; i < d.params.size(); ++i) {
        const auto& p = d.params[i];
        const std::string where = "params[" + std::to_string(i) + "]";
        if (!std::regex_match(p.name, kIdentifier) || p.name.size() > 64)
            return where + ".name: '" + p.name + "' is not a GLSL name";
        if (p.name == "p" || p.name == "c" || p.name == "degree" || p.name == "surfaceLogR" ||
            p.name == "orbitGradient" || kForbiddenWords.count(p.name) || p.name.rfind("gl_", 0) == 0)
            return where + ".name: '" + p.name + "' is reserved";
        if (!names.insert(p.name).second) return where + ".name: '" + p.name + "' is declared twice";
        if (!(p.min <= p.max)) return where + ": min is above max";
        if (p.type == ParamType::Toggle &&
            (p.min != 0.0 || p.max != 1.0 || (p.defaultValue.x != 0.0 && p.defaultValue.x != 1.0)))
            return where + ": a toggle is 0 or 1 (range 0 to 1)";
        for (int k = 0; k < (isScalar(p.type) ? 1 : 3); ++k)
            if (p.defaultValue[k] < p.min || p.defaultValue[k] > p.max) return where + ".default: outside [min, max]";
    }
    if (d.glsl.empty()) return "glsl: empty";
    const size_t maxBytes = d.wholeDE ? kMaxWholeDEGlslBytes : kMaxCustomGlslBytes;
    if (d.glsl.size() > maxBytes) return "glsl: longer than " + std::to_string(maxBytes) + " bytes";
    if (d.wholeDE) {
        if (std::count(d.glsl.begin(), d.glsl.end(), '\n') >= kMaxWholeDELines)
            return "glsl: more than " + std::to_string(kMaxWholeDELines) + " lines";
        std::vector<std::string> params;
        for (const auto& p : d.params) params.push_back(p.name);
        if (std::string why = wholeDEProblem(d.glsl, params); !why.empty()) return "glsl: " + why;
        return {};
    }
    if (std::string why = findForbidden(d.glsl); !why.empty()) return "glsl: " + why;
    if (d.category == Category::Estimator && d.glsl.find("return") == std::string::npos)
        return "glsl: an estimator must return the distance";
    return {};
}

CustomBlock::CustomBlock(Definition d) : def_(std::move(d)) {
    for (const auto& p : def_.params) decls_.push_back(ParamDecl{p.name, p.type, p.defaultValue, p.min, p.max, p.help});
    desc_ = BlockDesc{.id = def_.id,
                      .label = def_.label.empty() ? def_.id : def_.label,
                      .help = def_.help,
                      .category = def_.category,
                      .params = decls_,
                      .glsl = def_.glsl};
    desc_.membership = def_.membership;
    desc_.custom = true;
    desc_.wholeDE = def_.wholeDE;
    // Unknown GLSL bounds nothing (DerivativeBound::None): the check's note says so in these words.
    desc_.jump = "a GLSL block declares no bound, so its map may jump anywhere";
}

std::shared_ptr<const CustomBlock> CustomBlock::make(Definition d) {
    return std::shared_ptr<const CustomBlock>(new CustomBlock(std::move(d)));
}

std::shared_ptr<const CustomBlock> parseCustomBlock(const nlohmann::json& j, const std::string& file,
                                                    const std::string& path) {
    auto fail = [&](const std::string& field, const std::string& reason) -> void {
        throw PresetError(file, field.empty() ? path : path + "." + field, reason);
    };
    if (!j.is_object()) fail("", "expected an object describing a custom block");
    static const std::set<std::string> known{"id",         "label",  "help", "category",
                                             "membership", "params", "glsl", "wholeDE"};
    for (const auto& [key, value] : j.items())
        if (!known.count(key)) fail(key, "unknown field");
    auto text = [&](const char* key, bool required, size_t maxLength) {
        if (!j.contains(key)) {
            if (required) fail(key, "missing required field");
            return std::string();
        }
        if (!j[key].is_string()) fail(key, "expected a string");
        std::string s = j[key].get<std::string>();
        if (s.size() > maxLength) fail(key, "longer than " + std::to_string(maxLength) + " bytes");
        return s;
    };
    CustomBlock::Definition d;
    d.id = text("id", true, 64);
    d.label = text("label", false, 256);
    d.help = text("help", false, 4096);
    bool ok = true;
    d.category = categoryFromName(text("category", true, 32), ok);
    if (!ok) fail("category", "expected fold, transform, power or estimator");
    const std::string membership = text("membership", false, 32);
    if (membership == "escape")
        d.membership = Membership::EscapeTime;
    else if (!membership.empty() && membership != "distance")
        fail("membership", "expected distance or escape");
    if (j.contains("wholeDE")) {
        if (!j["wholeDE"].is_boolean()) fail("wholeDE", "expected true or false");
        d.wholeDE = j["wholeDE"].get<bool>();
    }
    d.glsl = text("glsl", true, d.wholeDE ? kMaxWholeDEGlslBytes : kMaxCustomGlslBytes);
    if (j.contains("params")) {
        const auto& params = j["params"];
        if (!params.is_array()) fail("params", "expected an array");
        const int maxParams = d.wholeDE ? kMaxWholeDEParams : kMaxCustomParams;
        if (params.size() > size_t(maxParams)) fail("params", "more than " + std::to_string(maxParams) + " parameters");
        for (size_t i = 0; i < params.size(); ++i) {
            const std::string where = "params[" + std::to_string(i) + "]";
            const auto& pj = params[i];
            if (!pj.is_object()) fail(where, "expected an object");
            CustomBlock::Definition::Param p;
            auto num = [&](const char* key, double fallback) {
                if (!pj.contains(key)) return fallback;
                if (!pj[key].is_number()) fail(where + "." + key, "expected a number");
                const double v = pj[key].get<double>();
                if (!std::isfinite(v) || std::abs(v) > 1e6)
                    fail(where + "." + key, "expected a finite number within 1e6");
                return v;
            };
            for (const auto& [key, value] : pj.items())
                if (key != "name" && key != "type" && key != "default" && key != "min" && key != "max" &&
                    key != "help" && key != "group")
                    fail(where + "." + key, "unknown field");
            if (!pj.contains("name") || !pj["name"].is_string()) fail(where + ".name", "expected a string");
            p.name = pj["name"].get<std::string>();
            const std::string type = pj.value("type", std::string("float"));
            if (type == "vec3")
                p.type = ParamType::Vec3;
            else if (type == "toggle")
                p.type = ParamType::Toggle;
            else if (type != "float")
                fail(where + ".type", "expected float, vec3 or toggle");
            p.min = num("min", 0.0);
            p.max = num("max", 1.0);
            if (pj.contains("default")) {
                const auto& dv = pj["default"];
                if (p.type == ParamType::Toggle && dv.is_boolean()) {
                    p.defaultValue = vec3(dv.get<bool>() ? 1.0 : 0.0, 0.0, 0.0);
                } else if (isScalar(p.type)) {
                    p.defaultValue = vec3(num("default", 0.0), 0.0, 0.0);
                } else {
                    if (!dv.is_array() || dv.size() != 3) fail(where + ".default", "expected an array of 3 numbers");
                    for (int k = 0; k < 3; ++k) {
                        if (!dv[k].is_number() || !std::isfinite(dv[k].get<double>()))
                            fail(where + ".default", "expected finite numbers");
                        p.defaultValue[k] = dv[k].get<double>();
                    }
                }
            } else {
                p.defaultValue = vec3(std::clamp(0.0, p.min, p.max));
                if (isScalar(p.type)) p.defaultValue.y = p.defaultValue.z = 0.0;
            }
            if (pj.contains("help")) {
                if (!pj["help"].is_string()) fail(where + ".help", "expected a string");
                p.help = pj["help"].get<std::string>();
            }
            if (pj.contains("group")) {
                if (!pj["group"].is_string() || pj["group"].get<std::string>().size() > 256)
                    fail(where + ".group", "expected a string of at most 256 bytes");
                p.group = pj["group"].get<std::string>();
            }
            d.params.push_back(std::move(p));
        }
    }
    if (std::string why = CustomBlock::validate(d); !why.empty()) {
        const size_t colon = why.find(": ");
        fail(why.substr(0, colon), why.substr(colon + 2));
    }
    return CustomBlock::make(std::move(d));
}

nlohmann::json customBlockToJson(const CustomBlock& block) {
    const auto& d = block.definition();
    nlohmann::json j;
    j["id"] = d.id;
    if (!d.label.empty()) j["label"] = d.label;
    if (!d.help.empty()) j["help"] = d.help;
    j["category"] = categoryName(d.category);
    if (d.category == Category::Estimator && d.membership == Membership::EscapeTime) j["membership"] = "escape";
    nlohmann::json params = nlohmann::json::array();
    for (const auto& p : d.params) {
        nlohmann::json pj{{"name", p.name}, {"min", p.min}, {"max", p.max}};
        if (p.type == ParamType::Vec3) {
            pj["type"] = "vec3";
            pj["default"] = {p.defaultValue.x, p.defaultValue.y, p.defaultValue.z};
        } else if (p.type == ParamType::Toggle) {
            pj["type"] = "toggle";
            pj["default"] = p.defaultValue.x > 0.5;
        } else {
            pj["default"] = p.defaultValue.x;
        }
        if (!p.help.empty()) pj["help"] = p.help;
        if (!p.group.empty()) pj["group"] = p.group;
        params.push_back(pj);
    }
    if (!params.empty()) j["params"] = params;
    if (d.wholeDE) j["wholeDE"] = true;
    j["glsl"] = d.glsl;
    return j;
}

CustomBlocks loadBlockLibrary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw PresetError(path, "", "cannot be opened for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(ss.str());
    } catch (const nlohmann::json::exception& e) {
        throw PresetError(path, "", std::string("invalid JSON: ") + e.what());
    }
    if (!j.is_object() || j.value("format", "") != "fraktal-blocks")
        throw PresetError(path, "format", "expected \"fraktal-blocks\"");
    if (!j.contains("customBlocks") || !j["customBlocks"].is_array())
        throw PresetError(path, "customBlocks", "expected an array of blocks");
    CustomBlocks blocks;
    for (size_t i = 0; i < j["customBlocks"].size(); ++i)
        blocks.push_back(parseCustomBlock(j["customBlocks"][i], path, "customBlocks[" + std::to_string(i) + "]"));
    return blocks;
}

std::string serializeBlockLibrary(const CustomBlocks& blocks) {
    nlohmann::json j{{"format", "fraktal-blocks"}, {"version", 1}, {"customBlocks", nlohmann::json::array()}};
    for (const auto& b : blocks) j["customBlocks"].push_back(customBlockToJson(*b));
    return j.dump(2) + "\n";
}

}  // namespace fraktal
