#include "core/import/frag_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "core/custom_block.hpp"
#include "core/import/frag_builtins.hpp"
#include "core/import/frag_shading.hpp"
#include "core/whole_de.hpp"

namespace fraktal::frag {

namespace {

bool startsName(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continuesName(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Calls `visit(word, begin, end)` for each identifier of the GLSL outside comments and not after
// a '.' (a member or swizzle); numbers are skipped whole (the e of 1e5 is no name).
template <class Visit>
void forEachName(std::string_view s, Visit visit) {
    char previous = 0;
    for (size_t i = 0; i < s.size();) {
        if (s.compare(i, 2, "//") == 0) {
            const size_t end = s.find('\n', i);
            i = end == std::string_view::npos ? s.size() : end;
            continue;
        }
        if (s.compare(i, 2, "/*") == 0) {
            const size_t end = s.find("*/", i + 2);
            i = end == std::string_view::npos ? s.size() : end + 2;
            continue;
        }
        const char c = s[i];
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < s.size() && (continuesName(s[i]) || s[i] == '.' ||
                                    ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
                ++i;
            previous = '0';
            continue;
        }
        if (startsName(c)) {
            size_t j = i;
            while (j < s.size() && continuesName(s[j])) ++j;
            if (previous != '.') visit(s.substr(i, j - i), i, j);
            previous = 'a';
            i = j;
            continue;
        }
        if (!std::isspace(static_cast<unsigned char>(c))) previous = c;
        ++i;
    }
}

std::set<std::string, std::less<>> namesIn(std::string_view s) {
    std::set<std::string, std::less<>> names;
    forEachName(s, [&](std::string_view w, size_t, size_t) { names.emplace(w); });
    return names;
}

// The text with each name in `with` replaced by its value.
std::string replaceNames(std::string_view s, const std::map<std::string, std::string, std::less<>>& with) {
    std::string out;
    size_t copied = 0;
    forEachName(s, [&](std::string_view w, size_t begin, size_t end) {
        const auto it = with.find(w);
        if (it == with.end()) return;
        out.append(s.substr(copied, begin - copied));
        out += it->second;
        copied = end;
    });
    out.append(s.substr(copied));
    return out;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s = buf;
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return s;
}

// A GLSL constant of the uniform's type holding `values` (missing components 0).
std::string constantOf(const FragUniform& u, std::vector<double> values) {
    const std::string& t = u.type;
    if (t == "bool") return !values.empty() && values[0] != 0.0 ? "true" : "false";
    if (t == "int") return std::to_string(values.empty() ? 0 : int(std::lround(values[0])));
    // vecN and dvecN: N components; the scalars one.
    const int n = t.starts_with("vec") || t.starts_with("dvec") ? t.back() - '0' : 1;
    values.resize(size_t(n), 0.0);
    if (n == 1) return number(values[0]);
    std::string s = "vec" + std::to_string(n) + "(";
    for (int k = 0; k < n; ++k) s += (k ? ", " : "") + number(values[size_t(k)]);
    return s + ")";
}

// The slider as FragM's editor holds it. A vec3 or vec4 slider whose minimum equals its maximum
// (3D.frag's `Up`, slider[(0,0,0),(0,1,0),(0,0,0)]) is a direction there, each component in
// [-1, 1], not a range of one point; a component whose minimum is above its maximum holds its
// minimum (the spin box raises its maximum to the minimum). The default is held in the range as
// the spin box holds it.
FragUniform withFragMsRange(FragUniform u) {
    if (u.kind != UniformKind::Slider || u.minimum.size() != u.value.size() || u.maximum.size() != u.value.size())
        return u;
    const bool direction = (u.type.ends_with("vec3") || u.type.ends_with("vec4")) && u.minimum == u.maximum;
    for (size_t k = 0; k < u.value.size(); ++k) {
        if (direction) u.minimum[k] = -1.0, u.maximum[k] = 1.0;
        u.maximum[k] = std::max(u.maximum[k], u.minimum[k]);
        u.value[k] = std::clamp(u.value[k], u.minimum[k], u.maximum[k]);
    }
    return u;
}

// The uniform's value: the preset's line where it has one (clamped to the slider's range, as
// FragM clamps), else the declaration's default. Checkboxes give 0 or 1.
std::vector<double> valueOf(const FragUniform& u, const FragPreset* preset) {
    std::vector<double> v;
    switch (u.kind) {
        case UniformKind::Checkbox: v = {u.checked ? 1.0 : 0.0}; break;
        case UniformKind::Menu: v = {double(u.menuDefault)}; break;
        case UniformKind::FloatColor:  // (r, g, b, intensity), as FragM sets the vec4
            v = u.colour;
            if (!u.value.empty()) v.push_back(u.value[0]);
            break;
        default: v = u.value;
    }
    const PresetValue* line = preset ? preset->find(u.name) : nullptr;
    if (line) {
        if (line->boolean)
            v = {*line->boolean ? 1.0 : 0.0};
        else if (!line->numbers.empty())
            v = line->numbers;
    }
    if (u.kind == UniformKind::Slider)
        for (size_t k = 0; k < v.size() && k < u.minimum.size() && k < u.maximum.size(); ++k)
            v[k] = std::clamp(v[k], u.minimum[k], u.maximum[k]);
    return v;
}

// A preset value of a raytracer or camera setting: the chosen preset's, else the declaration's
// default where the raytracer itself was read, else `fallback`.
std::vector<double> setting(const FragFile& file, const FragPreset* preset, std::string_view key,
                            std::vector<double> fallback) {
    if (preset)
        if (const PresetValue* v = preset->find(key); v && v->numbers.size() == fallback.size()) return v->numbers;
    if (const FragUniform* u = file.findUniform(key);
        u && u->kind == UniformKind::Slider && u->value.size() == fallback.size())
        return u->value;
    return fallback;
}

const FragPreset* choosePreset(const FragFile& file, const FragImportOptions& options) {
    if (!options.presetName.empty()) {
        if (const FragPreset* p = file.findPreset(options.presetName)) return p;
        std::string names;
        for (const FragPreset& p : file.presets) names += (names.empty() ? "" : ", ") + p.name;
        throw PresetError(file.files.front().name, "",
                          "has no #preset named '" + options.presetName +
                              "' (its presets: " + (names.empty() ? "none" : names) + ")");
    }
    if (const FragPreset* p = file.defaultPreset()) return p;
    for (const FragPreset& p : file.presets)
        if (!p.keyFrame()) return &p;
    return nullptr;
}

// The byte offset in `glsl` of the start of its line `line` (0-based).
size_t lineOffset(const std::string& glsl, int line) {
    size_t at = 0;
    for (int i = 0; i < line && at != std::string::npos; ++i) at = glsl.find('\n', at) + 1;
    return std::min(at, glsl.size());
}

std::string identifierFrom(const std::string& stem) {
    std::string id = "frag_";
    for (char c : stem) id += continuesName(c) ? c : '_';
    return id.substr(0, 64);
}

}  // namespace

FragOptions importParseOptions(const std::vector<std::filesystem::path>& includeDirs) {
    FragOptions o;
    o.includeDirs = includeDirs;
    o.builtinIncludes = builtinIncludes();
    o.preferBuiltins = true;
    return o;
}

FragImport importFrag(const FragFile& file, const FragImportOptions& options) {
    const std::string fileName = file.files.front().name;
    auto refuse = [&](const std::string& reason) { throw PresetError(fileName, "", reason); };
    FragImport result;
    const FragFunction* de = file.deFunction();
    if (!de) {
        if (const FragFunction* inside = file.findFunction("inside"); inside && inside->returnType == "bool")
            refuse(
                "a Brute-Raytracer frag: `bool inside(vec3)` decides what is solid and there is no distance "
                "estimate (`float DE(vec3)`) for fraktal to march");
        refuse("has no function `float DE(vec3)`: fraktal draws a frag by its distance estimate");
    }
    const bool callsInit = file.provides.count("providesInit") > 0 && file.findFunction("init");

    // What the DE reaches: functions, globals and #define lines, by name, from DE (and init).
    struct Piece {
        size_t offset;
        std::string text;
        std::set<std::string, std::less<>> names;  // what it declares
        std::set<std::string, std::less<>> reads;  // the names in it
        bool function = false;
        bool kept = false;
    };
    std::vector<Piece> pieces;
    for (const FragFunction& f : file.functions) {
        const std::string text = file.functionSource(f);
        pieces.push_back({f.begin, text, {f.name}, namesIn(text), true});
    }
    for (const FragGlobal& g : file.globals) {
        std::string text = file.glsl.substr(g.begin, g.end - g.begin);
        if (!text.ends_with(";")) text += ';';
        const std::string_view head(g.text);
        if (head.starts_with("uniform ") || head.starts_with("varying ") || head.starts_with("in ") ||
            head.starts_with("out ") || head.starts_with("attribute ") || head.starts_with("layout"))
            continue;
        const std::vector<std::string> names = declarationNames(g.text);
        pieces.push_back({g.begin, text, {names.begin(), names.end()}, namesIn(text)});
    }
    for (const FragDefine& d : file.defines) {
        if (d.name.starts_with("provides")) continue;
        for (size_t i = 0; i < file.glslLines.size(); ++i) {
            if (file.glslLines[i].file != d.where.file || file.glslLines[i].line != d.where.line) continue;
            const size_t at = lineOffset(file.glsl, int(i));
            const size_t end = file.glsl.find('\n', at);
            const std::string text = file.glsl.substr(at, (end == std::string::npos ? file.glsl.size() : end) - at);
            pieces.push_back({at, text, {d.name}, namesIn(text.substr(text.find(d.name) + d.name.size()))});
            break;
        }
    }
    std::set<std::string, std::less<>> reached{"DE"};
    if (callsInit) reached.insert("init");
    for (bool grew = true; grew;) {
        grew = false;
        for (Piece& p : pieces) {
            if (p.kept) continue;
            const bool wanted =
                std::any_of(p.names.begin(), p.names.end(), [&](const std::string& n) { return reached.count(n); });
            if (!wanted) continue;
            p.kept = grew = true;
            reached.insert(p.reads.begin(), p.reads.end());
        }
    }

    // The uniforms the DE reads: its parameters, or what the preset cannot carry.
    const FragPreset* preset = choosePreset(file, options);
    if (preset) result.presetUsed = preset->name;
    std::map<std::string, std::string, std::less<>> rewrite;
    CustomBlock::Definition def;
    def.id = identifierFrom(std::filesystem::path(fileName).stem().string());
    def.label = std::filesystem::path(fileName).stem().string();
    def.category = Category::Estimator;
    def.wholeDE = true;
    for (const FragDirective& info : file.info)
        if (info.where.file == 0) def.help += (def.help.empty() ? "" : " ") + info.argument;
    if (def.help.empty()) def.help = "Imported from " + std::filesystem::path(fileName).filename().string();
    std::vector<vec3> values;
    // 3D.frag's camera, with its declaration's defaults where the preset has no line.
    const std::vector<double> eye = setting(file, preset, "Eye", {0.0, 0.0, -10.0});
    const std::vector<double> target = setting(file, preset, "Target", {0.0, 0.0, 0.0});
    const std::vector<double> up = setting(file, preset, "Up", {0.0, 1.0, 0.0});
    const double fov = setting(file, preset, "FOV", {0.4})[0];
    const std::map<std::string, std::vector<double>, std::less<>> camera = {
        {"Eye", eye}, {"Target", target}, {"Up", up}, {"FOV", {fov}}};
    for (const std::string& name : {std::string("texture"), std::string("texture2D"), std::string("textureLod"),
                                    std::string("texelFetch"), std::string("textureCube"), std::string("texture3D")})
        if (reached.count(name))
            refuse("a texture is sampled inside the DE (`" + name +
                   "`): fraktal's distance is a function of the point alone");
    for (const FragUniform& declared : file.uniforms) {
        if (declared.inVertex || !reached.count(declared.name)) continue;
        const FragUniform u = withFragMsRange(declared);
        if (u.kind == UniformKind::File || u.type.starts_with("sampler"))
            refuse("a texture is sampled inside the DE (`uniform " + u.type + " " + u.name +
                   "`): fraktal's distance is a function of the point alone");
        const std::vector<double> v = valueOf(u, preset);
        auto dropAsConstant = [&](const std::string& why) {
            result.unsupported.push_back({"uniform " + u.name, why});
            rewrite[u.name] = "(" + constantOf(u, v) + ")";
        };
        if (!u.arraySize.empty()) {
            dropAsConstant("an array uniform has no fraktal parameter; it keeps its first value");
            continue;
        }
        CustomBlock::Definition::Param p;
        p.name = u.name;
        p.help = u.tooltip;
        p.group = u.group;
        vec3 value(0.0);
        const bool integer = u.type == "int";
        if (u.name == "time" && u.kind == UniformKind::Plain && u.type == "float") {
            // FragM's clock, in seconds (0 on a still, as on FragM's first frame), is a parameter
            // of its own: the still is FragM's, and keying the parameter plays the frag's animation.
            p.type = ParamType::Float;
            p.min = 0.0;
            p.max = 60.0;
            p.help = "FragM's clock, in seconds: 0 is the frame FragM draws first; key it to play the frag's animation";
            result.approximated.push_back(
                {"uniform time",
                 "FragM's clock is the parameter time, 0 as on FragM's first frame; it runs only "
                 "where it is keyed"});
        } else if (u.kind == UniformKind::Slider && (u.type == "float" || u.type == "double" || integer)) {
            p.type = ParamType::Float;
            p.min = u.minimum[0];
            p.max = u.maximum[0];
            p.defaultValue = vec3(u.value[0], 0.0, 0.0);
            value.x = v[0];
            if (integer) rewrite[u.name] = "int(" + u.name + ")";
        } else if (u.kind == UniformKind::Slider && (u.type == "vec2" || u.type == "vec3")) {
            const int n = u.type == "vec2" ? 2 : 3;
            p.type = ParamType::Vec3;
            p.min = *std::min_element(u.minimum.begin(), u.minimum.end());
            p.max = *std::max_element(u.maximum.begin(), u.maximum.end());
            const double unused = std::clamp(0.0, p.min, p.max);
            for (int k = 0; k < 3; ++k) {
                p.defaultValue[k] = k < n ? u.value[size_t(k)] : unused;
                value[k] = k < n && size_t(k) < v.size() ? v[size_t(k)] : unused;
            }
            if (n == 2) rewrite[u.name] = u.name + ".xy";
            if (u.minimum != std::vector<double>(u.minimum.size(), p.min) ||
                u.maximum != std::vector<double>(u.maximum.size(), p.max))
                result.approximated.push_back(
                    {"uniform " + u.name, "its components' ranges differ; the parameter spans them all"});
        } else if (u.kind == UniformKind::Slider && (u.type == "vec4" || u.type == "dvec4") && u.value.size() == 4) {
            // A 4-vector (a quaternion's constant, a 4D offset): fraktal's parameters stop at 3
            // components, so it becomes two, its xyz and its w (NAME_w), joined again where the DE
            // reads it.
            CustomBlock::Definition::Param w = p;
            p.type = ParamType::Vec3;
            p.min = std::min({u.minimum[0], u.minimum[1], u.minimum[2]});
            p.max = std::max({u.maximum[0], u.maximum[1], u.maximum[2]});
            for (int k = 0; k < 3; ++k) {
                p.defaultValue[k] = u.value[size_t(k)];
                value[k] = size_t(k) < v.size() ? v[size_t(k)] : u.value[size_t(k)];
            }
            if (u.minimum[0] != u.minimum[1] || u.minimum[1] != u.minimum[2] || u.maximum[0] != u.maximum[1] ||
                u.maximum[1] != u.maximum[2])
                result.approximated.push_back(
                    {"uniform " + u.name, "its xyz components' ranges differ; the parameter spans them all"});
            for (int k = 0; k < 3; ++k) value[k] = std::clamp(value[k], p.min, p.max);
            def.params.push_back(std::move(p));
            values.push_back(value);
            w.name = u.name + "_w";
            w.help = "The w component of " + u.name + (u.tooltip.empty() ? "" : " (" + u.tooltip + ")");
            w.type = ParamType::Float;
            w.min = u.minimum[3];
            w.max = u.maximum[3];
            w.defaultValue = vec3(u.value[3], 0.0, 0.0);
            p = std::move(w);
            value = vec3(v.size() > 3 ? v[3] : u.value[3], 0.0, 0.0);
            rewrite[u.name] = "vec4(" + u.name + ", " + u.name + "_w)";
        } else if (u.kind == UniformKind::Checkbox && u.type == "bool") {
            p.type = ParamType::Toggle;
            p.defaultValue = vec3(u.checked ? 1.0 : 0.0, 0.0, 0.0);
            value.x = v[0] != 0.0 ? 1.0 : 0.0;
            rewrite[u.name] = "(" + u.name + " > 0.5)";
        } else if (u.kind == UniformKind::Color && u.type == "vec3") {
            p.type = ParamType::Vec3;
            p.min = 0.0;
            p.max = 1.0;
            for (int k = 0; k < 3; ++k) {
                p.defaultValue[k] = std::clamp(u.value[size_t(k)], 0.0, 1.0);
                value[k] = std::clamp(size_t(k) < v.size() ? v[size_t(k)] : 0.0, 0.0, 1.0);
            }
        } else if (u.kind == UniformKind::Menu && u.type == "int" && !u.menuItems.empty()) {
            // fraktal's parameters have no list of choices: the menu is a number whose help
            // names each choice.
            p.type = ParamType::Float;
            p.min = 0.0;
            p.max = double(u.menuItems.size() - 1);
            p.defaultValue = vec3(std::clamp(double(u.menuDefault), p.min, p.max), 0.0, 0.0);
            value.x = std::clamp(std::round(v[0]), p.min, p.max);
            std::string items;
            for (size_t k = 0; k < u.menuItems.size(); ++k)
                items += (k ? ", " : "") + std::to_string(k) + ": " + u.menuItems[k];
            p.help += (p.help.empty() ? "" : " ") + std::string("(") + items + ")";
            rewrite[u.name] = "int(" + u.name + ")";
            result.approximated.push_back({"uniform " + u.name, "a menu becomes a number (" + items + ")"});
        } else if (const auto it = camera.find(u.name); it != camera.end() && u.kind == UniformKind::Plain) {
            // The DE reads 3D.frag's camera (a 4D rotation keyed to the view, a tessellation seen
            // from the eye): it keeps the imported camera's value, so the still is FragM's; a camera
            // moved in fraktal does not move it.
            rewrite[u.name] = "(" + constantOf(u, it->second) + ")";
            result.approximated.push_back({"uniform " + u.name, "the DE reads the camera's " + u.name +
                                                                    "; it keeps the imported camera's " +
                                                                    constantOf(u, it->second) +
                                                                    ", and does not follow a camera moved in fraktal"});
            continue;
        } else if (u.kind == UniformKind::Plain) {
            dropAsConstant("set by FragM's host or raytracer, not a parameter (`" + u.type + " " + u.name +
                           "`); it keeps the value " + constantOf(u, v));
            continue;
        } else {
            dropAsConstant(std::string("a ") + uniformKindName(u.kind) + " of type " + u.type +
                           " has no fraktal parameter; it keeps the value " + constantOf(u, v));
            continue;
        }
        for (int k = 0; k < 3; ++k) value[k] = std::clamp(value[k], p.min, p.max);
        def.params.push_back(std::move(p));
        values.push_back(value);
    }

    // Passes fraktal does not run.
    for (const FragDirective& b : file.buffer) {
        const SourceFile& from = file.files[size_t(b.where.file)];
        if (from.builtin || isRaytracerInclude(from.includeName)) continue;
        result.unsupported.push_back(
            {file.where(b.where), "#buffer " + b.argument +
                                      ": a frag drawn over several passes (each reading the "
                                      "last one's image) has no fraktal equivalent; its DE is imported alone"});
    }
    for (const FragDirective& b : file.bufferShaders) {
        const SourceFile& from = file.files[size_t(b.where.file)];
        if (from.builtin || isRaytracerInclude(from.includeName)) continue;
        result.unsupported.push_back(
            {file.where(b.where), "#buffershader \"" + b.argument + "\": fraktal's own display transform replaces it"});
    }
    if (file.provides.count("providesColor"))
        result.approximated.push_back({"baseColor", "the frag's own surface colour (providesColor) is not drawn"});

    std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.offset < b.offset; });
    // In the file's order, a blank line around each function.
    std::string code;
    bool afterFunction = false;
    for (const Piece& p : pieces) {
        if (!p.kept) continue;
        if ((p.function || afterFunction) && !code.empty()) code += '\n';
        code += p.text + "\n";
        afterFunction = p.function;
    }
    def.glsl = replaceNames(code, rewrite);
    if (std::string why = CustomBlock::validate(def); !why.empty())
        refuse("its DE does not make a whole-DE estimator fraktal accepts: " + why);
    const auto block = CustomBlock::make(std::move(def));

    Preset& out = result.preset;
    Formula& f = out.formula;
    f.customBlocks = {block};
    f.nodes.clear();
    f.estimator = Node::make(block->desc());
    f.estimator.values = values;
    f.deFactor = std::clamp(setting(file, preset, "FudgeFactor", {1.0})[0], 1e-3, 2.0);

    // 3D.frag's camera: the ray through (x, y) is normalize(Dir + FOV (x Right + y Up)) with y in
    // [-1, 1], so tan(fovY / 2) = FOV.
    out.camera.position = vec3(eye[0], eye[1], eye[2]);
    out.camera.target = vec3(target[0], target[1], target[2]);
    out.camera.up = vec3(up[0], up[1], up[2]);
    if (length(out.camera.position - out.camera.target) < 1e-9) out.camera.target = out.camera.position + vec3(0, 0, 1);
    if (length(out.camera.up) < 1e-9) out.camera.up = vec3(0.0, 1.0, 0.0);
    out.camera.fovY = std::clamp(2.0 * std::atan(std::max(fov, 1e-3)) * 180.0 / M_PI, 1.0, 179.0);

    // DE-Raytracer's hit test, dist * FudgeFactor < 10^Detail * t, is a cone; fraktal hits at
    // d < pixelAngle * t * detail with pixelAngle = 2 FOV / height.
    const double detail = setting(file, preset, "Detail", {-2.3})[0];
    const double pixelAngle = 2.0 * std::max(fov, 1e-3) / double(out.render.height);
    out.render.detail = std::clamp(std::pow(10.0, detail) / pixelAngle, 1e-3, 100.0);
    out.render.maxSteps = std::clamp(int(setting(file, preset, "MaxRaySteps", {56.0})[0]), 16, 4096);
    // The bound: FragM marches to MaxDistance from the eye; fraktal needs a sphere about the
    // origin holding the object. The camera's distance to its target frames it.
    f.boundRadius = std::clamp(
        std::max(4.0, 2.0 * length(out.camera.target) + length(out.camera.position - out.camera.target)), 1.0, 1e3);
    // DE-Raytracer's floor (EnableFloor): the plane dot(normalize(FloorNormal), p) = FloorHeight,
    // which its march meets from either side. fraktal's plane object is solid below its frame's
    // z = 0, so it is turned to hold the camera on its empty side.
    const PresetValue* floorOn = preset ? preset->find("EnableFloor") : nullptr;
    const std::vector<double> floorNormal = setting(file, preset, "FloorNormal", {0.0, 0.0, 1.0});
    vec3 normal(floorNormal[0], floorNormal[1], floorNormal[2]);
    const ObjectDesc* plane = findObject("plane");
    if (floorOn && floorOn->boolean.value_or(false) && length(normal) > 1e-9 && plane) {
        normal = normalize(normal);
        double height = setting(file, preset, "FloorHeight", {0.0})[0];
        if (dot(normal, out.camera.position) < height) normal = -normal, height = -height;
        SceneObject floor = SceneObject::make(*plane);
        floor.center = normal * height;
        // The turn about z x normal that takes the frame's z to the normal.
        const vec3 axis = cross(vec3(0.0, 0.0, 1.0), normal);
        if (length(axis) > 1e-9) {
            floor.axis = normalize(axis);
            floor.angle = std::acos(std::clamp(normal.z, -1.0, 1.0)) * 180.0 / M_PI;
        } else if (normal.z < 0.0) {
            floor.axis = vec3(1.0, 0.0, 0.0);
            floor.angle = 180.0;
        }
        result.objects.push_back(floor);
        result.objectReach = setting(file, preset, "MaxDistance", {1000.0})[0];
        result.approximated.push_back(
            {"EnableFloor", "DE-Raytracer's floor is a plane object, drawn as far as the bound reaches"});
    }
    if (drawnByDERaytracer(file)) {
        // DE-Raytracer's lights, AO, fog, background and orbit-trap colours (frag_shading). Its
        // lengths are the world's; the preset holds them per bound radius, which the caller
        // rescales when it fits the bound (core/scene/scene_import.cpp).
        RaytracerLook look = raytracerLook(file, preset);
        out.shading = look.shading;
        result.aoReach = look.aoReach;
        result.fogPerUnit = look.fogPerUnit;
        holdShadingLengths(result);
        result.approximated.insert(result.approximated.end(), look.approximated.begin(), look.approximated.end());
    } else {
        for (const char* key : {"BaseColor", "OrbitStrength", "X", "Y", "Z", "R", "SpotLight", "CamLight", "AO", "Fog",
                                "Glow", "Specular", "HardShadow", "Reflection"})
            if (preset && preset->find(key) && !file.findUniform(key)) {
                result.approximated.push_back(
                    {"shading",
                     "the frag's raytracer is not DE-Raytracer: its lighting and orbit-trap palette (BaseColor, "
                     "OrbitStrength, X, Y, Z, R, lights, AO, fog) are left at fraktal's own shading"});
                break;
            }
    }
    return result;
}

void holdShadingLengths(FragImport& result) {
    const double bound = result.preset.formula.boundRadius;
    ShadingSettings& s = result.preset.shading;
    if (result.aoReach > 0.0) s.aoDistance = std::clamp(result.aoReach / bound, 1e-6, 10.0);
    if (result.fogPerUnit > 0.0) s.fogDensity = std::clamp(result.fogPerUnit * bound, 0.0, 1e3);
}

std::string importDescription(const FragFile& file, const FragImport& result) {
    std::string d = "Imported from the Fragmentarium frag " +
                    std::filesystem::path(file.files.front().name).filename().string() +
                    (result.presetUsed.empty() ? "" : ", preset " + result.presetUsed) + ".";
    if (!result.unsupported.empty()) {
        d += " Dropped:";
        for (const ImportItem& item : result.unsupported) d += " " + item.text() + ";";
    }
    if (!result.approximated.empty()) {
        d += " Approximated:";
        for (const ImportItem& item : result.approximated) d += " " + item.text() + ";";
    }
    return d;
}

}  // namespace fraktal::frag
