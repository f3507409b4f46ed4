#include "core/preset.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/atomic_file.hpp"

namespace fraktal {

using nlohmann::json;

PresetDocument readPresetDocument(std::string_view text, const std::string& file) {
    PresetDocument doc;
    doc.json = parseGuardedJson(text, file);
    const ReadContext context{file, &doc.json, nullptr};
    FieldReader r(context, doc.json, "");
    if (r.string("format", "") != kPresetFormat) r.fail("expected \"" + std::string(kPresetFormat) + "\"", "format");
    if (!r.has("version")) r.fail("missing required field", "version");
    doc.fileVersion = r.integer("version", 0, 1, 1000000);
    if (doc.fileVersion < kPresetVersion)
        doc.migration = migratePreset(doc.json, doc.fileVersion, kPresetVersion, presetMigrations());
    return doc;
}

PresetError errorAsInFile(const PresetError& e, const PresetDocument& document) {
    return PresetError(e.file(), document.migration.fieldInFile(e.field()), e.reason());
}

namespace {

// Custom blocks first (a preset may not redefine a built-in id; CustomBlock::validate refuses).
const BlockDesc* lookUpBlock(const std::string& id, const CustomBlocks& custom) {
    for (const auto& b : custom)
        if (b->desc().id == id) return &b->desc();
    return findBlock(id);
}

// An escape-time estimate needs orbits that leave: some enabled power, fold or scale must push
// points outside the set away. A stack of translations and rotations alone keeps every orbit
// bounded (or none), so the estimate bounds no object.
void checkEscapeIsBounded(const std::vector<Node>& nodes, const Node& estimator, size_t listNumber,
                          const std::string& file, const std::string& path) {
    if (estimator.block->membership != Membership::EscapeTime || estimator.block->custom) return;
    if (canBoundEscape(nodes)) return;
    throw PresetError(file, path,
                      "block " + std::to_string(listNumber) + " '" + std::string(estimator.block->id) +
                          "': an escape-time estimator needs an enabled power, fold or scale block before it; "
                          "nothing here bounds the object");
}

Node parseNode(const ReadContext& context, const json& j, const std::string& path, const CustomBlocks& custom,
               size_t listNumber) {
    FieldReader r(context, j, path);
    const json& id = r.at("block");
    if (!id.is_string()) r.fail("expected a block id string, found " + FieldReader::typeName(id), "block");
    if (context.log) {
        std::vector<std::string> ids;
        for (const BlockDesc& b : allBlocks()) ids.emplace_back(b.id);
        for (const auto& b : custom) ids.emplace_back(b->desc().id);
        r.noteChoice("block", id.get<std::string>(), std::move(ids));
    }
    const BlockDesc* block = lookUpBlock(id.get<std::string>(), custom);
    if (!block) {
        std::string known;
        for (const BlockDesc& b : allBlocks()) known += (known.empty() ? "" : ", ") + std::string(b.id);
        for (const auto& b : custom) known += ", " + std::string(b->desc().id);
        r.fail("block " + std::to_string(listNumber) + ": unknown block '" + id.get<std::string>() +
                   "' (known blocks: " + known + ")",
               "block");
    }
    Node n = Node::make(*block);
    readNodeSchedule(r, n);
    readNodeParams(r, n, listNumber, "block");
    r.finish();
    return n;
}

// A custom block, parsed by core/custom_block.cpp, which refuses unknown fields. In a file of a
// newer version, a field it refuses as unknown is taken out, kept, and the block parsed again
// (each round removes one field, so this ends).
std::shared_ptr<const CustomBlock> parseCustomBlockKeepingUnknown(const ReadContext& context, const json& j,
                                                                  const std::string& path) {
    if (!context.keepUnknown) return parseCustomBlock(j, context.file, path);
    json block = j;
    for (;;) {
        try {
            return parseCustomBlock(block, context.file, path);
        } catch (const PresetError& e) {
            const std::string& field = e.field();
            const size_t dot = field.rfind('.');
            if (e.reason() != "unknown field" || field.compare(0, path.size() + 1, path + ".") != 0 ||
                dot == std::string::npos || dot < path.size())
                throw;
            const std::string holderPath = field.substr(0, dot), key = field.substr(dot + 1);
            const json::json_pointer holder(pointerFromPath(holderPath).substr(pointerFromPath(path).size()));
            if (!block.contains(holder) || !block.at(holder).is_object() || !block.at(holder).contains(key)) throw;
            context.keepUnknown->keep(*context.document, holderPath, key, block.at(holder).at(key));
            block.at(holder).erase(key);
        }
    }
}

// An object beside the fractal: {"object": kind, "operation": "join" | "intersect" | "carve",
// "hollow", "enabled", "center", "axis", "angle", "repeat", "color", "params"}. Errors name it as "object N 'kind'".
SceneObject parseObject(const ReadContext& context, const json& j, const std::string& path, size_t listNumber) {
    FieldReader r(context, j, path);
    const json& id = r.at("object");
    if (!id.is_string()) r.fail("expected an object kind string, found " + FieldReader::typeName(id), "object");
    if (context.log) {
        std::vector<std::string> ids;
        for (const ObjectDesc& o : allObjects()) ids.emplace_back(o.id);
        r.noteChoice("object", id.get<std::string>(), std::move(ids));
    }
    const ObjectDesc* kind = findObject(id.get<std::string>());
    if (!kind) {
        std::string known;
        for (const ObjectDesc& o : allObjects()) known += (known.empty() ? "" : ", ") + std::string(o.id);
        r.fail("object " + std::to_string(listNumber) + ": unknown kind '" + id.get<std::string>() +
                   "' (known kinds: " + known + ")",
               "object");
    }
    SceneObject o = SceneObject::make(*kind);
    o.operation = ObjectOperation(
        r.choice("operation", kObjectOperationNames, 0, "operation", "object " + std::to_string(listNumber) + ": "));
    o.hollow = r.boolean("hollow", false);
    o.enabled = r.boolean("enabled", true);
    o.center = r.vector<3>("center", o.center, -1e4, 1e4);
    o.axis = r.vector<3>("axis", o.axis, -1.0, 1.0);
    if (length(o.axis) < 1e-9) r.fail("object " + std::to_string(listNumber) + ": the axis must not be zero", "axis");
    o.angle = r.number("angle", 0.0, -360.0, 360.0);
    o.repeat = r.vector<3>("repeat", o.repeat, 0.0, 1e4);
    // A reflectance: above 1 a surface would give back more light than it receives.
    o.color = r.vector<3>("color", o.color, 0.0, 1.0);
    readNodeParams(r, o, listNumber, "object", "object");
    r.finish();
    return o;
}

// A placement {"center", "axis", "angle", "scale", "repeat"} (FractalPlacement), each optional.
FractalPlacement parsePlacement(const ReadContext& context, const json& j, const std::string& path) {
    FieldReader r(context, j, path);
    FractalPlacement place;
    place.center = r.vector<3>("center", place.center, -1e4, 1e4);
    place.axis = r.vector<3>("axis", place.axis, -1.0, 1.0);
    if (length(place.axis) < 1e-9) r.fail("the axis must not be zero", "axis");
    place.angle = r.number("angle", 0.0, -360.0, 360.0);
    place.scale = r.number("scale", 1.0, 1e-4, 1e4);
    place.repeat = r.vector<3>("repeat", place.repeat, 0.0, 1e4);
    r.finish();
    return place;
}

// What each fractal of a formula has: iterations, bailout, DE factor, the node list closed by
// its estimator, and the placement. Blocks are looked up among `custom` (the formula's).
void parseFractal(FieldReader& r, const CustomBlocks& custom, Formula& f) {
    const ReadContext& context = r.context();
    f.iterations = r.integer("iterations", f.iterations, 0, kMaxIterations);
    f.bailout = r.number("bailout", f.bailout, 1e-3, 1e10);
    f.deFactor = r.number("deFactor", f.deFactor, 1e-3, 2.0);
    f.deFactorMeasuredFor = r.string("deFactorMeasuredFor", "", 64);
    const json& nodes = r.at("nodes");
    const std::string path = r.child("nodes");
    if (!nodes.is_array()) r.fail("expected an array of nodes, found " + FieldReader::typeName(nodes), "nodes");
    if (nodes.empty()) r.fail("the node list is empty: a formula needs at least a closing estimator", "nodes");
    if (nodes.size() > size_t(kMaxNodes))
        r.fail("too many nodes (" + std::to_string(nodes.size()) + "; at most " + std::to_string(kMaxNodes) + ")",
               "nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string nodePath = path + "[" + std::to_string(i) + "]";
        Node n = parseNode(context, nodes[i], nodePath, custom, i + 1);
        const bool last = i + 1 == nodes.size();
        if (n.block->isEstimator() && !last)
            throw PresetError(context.file, nodePath,
                              "estimator '" + std::string(n.block->id) + "' may only close the node list");
        if (!n.block->isEstimator() && last)
            throw PresetError(context.file, nodePath,
                              "the node list must end with an estimator (box, sphere, tetrahedron, escape_log, "
                              "escape_potential, escape_linear), found '" +
                                  std::string(n.block->id) + "'");
        if (last) {
            checkEstimatorSchedule(n, context.file, nodePath);
            checkEscapeIsBounded(f.nodes, n, i + 1, context.file, nodePath);
            f.estimator = std::move(n);
        } else {
            f.nodes.push_back(std::move(n));
        }
    }
    if (f.estimator.block && f.estimator.block->wholeDE && !f.nodes.empty())
        throw PresetError(context.file, path + "[0]",
                          "estimator '" + std::string(f.estimator.block->id) +
                              "' is a whole DE: it computes the whole distance, so it must be the only node (found " +
                              std::to_string(f.nodes.size()) + " before it)");
    if (r.has("placement")) f.placement = parsePlacement(context, r.at("placement"), r.child("placement"));
}

// A fractal combined with the first: {"operation", "enabled"} and the fields parseFractal reads.
CombinedFractal parseCombinedFractal(const ReadContext& context, const json& j, const std::string& path,
                                     const CustomBlocks& custom, size_t listNumber) {
    FieldReader r(context, j, path);
    CombinedFractal c;
    c.operation = ObjectOperation(r.choice("operation", kObjectOperationNames, 0, "operation",
                                           "fractal " + std::to_string(listNumber + 1) + ": "));
    c.enabled = r.boolean("enabled", true);
    parseFractal(r, custom, c.formula);
    r.finish();
    return c;
}

// Reads an optional array field of at most `most` entries with `parse(element, path, number)`.
template <class Parse>
void readList(FieldReader& r, const std::string& key, std::string_view what, size_t most, Parse parse) {
    if (!r.has(key)) return;
    const json& list = r.at(key);
    if (!list.is_array())
        r.fail("expected an array of " + std::string(what) + ", found " + FieldReader::typeName(list), key);
    if (list.size() > most)
        r.fail("too many " + std::string(what) + " (" + std::to_string(list.size()) + "; at most " +
                   std::to_string(most) + ")",
               key);
    for (size_t i = 0; i < list.size(); ++i) parse(list[i], r.child(key) + "[" + std::to_string(i) + "]", i + 1);
}

Formula parseFormula(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "formula");
    Formula f;
    f.boundRadius = r.number("boundRadius", f.boundRadius, 1e-3, 1e4);
    if (r.has("hitInsideOnly")) {  // the older field, read as the rule it named
        if (r.has("hitRule")) r.fail("give hitRule alone (hitInsideOnly is its older form)", "hitInsideOnly");
        if (r.boolean("hitInsideOnly", false)) f.hitRule = HitRule::InsideOnly;
    }
    f.hitRule = HitRule(r.choice("hitRule", kHitRuleNames, int(f.hitRule), "hit rule"));
    if (r.has("customBlocks")) {
        const json& blocks = r.at("customBlocks");
        if (!blocks.is_array()) r.fail("expected an array of custom blocks", "customBlocks");
        if (blocks.size() > size_t(kMaxCustomBlocks))
            r.fail("more than " + std::to_string(kMaxCustomBlocks) + " custom blocks", "customBlocks");
        for (size_t i = 0; i < blocks.size(); ++i) {
            const std::string where = r.child("customBlocks") + "[" + std::to_string(i) + "]";
            auto block = parseCustomBlockKeepingUnknown(context, blocks[i], where);
            if (lookUpBlock(block->definition().id, f.customBlocks))
                throw PresetError(context.file, where + ".id", "'" + block->definition().id + "' is defined twice");
            f.customBlocks.push_back(std::move(block));
        }
    }
    parseFractal(r, f.customBlocks, f);
    readList(r, "fractals", "combined fractals", size_t(kMaxCombinedFractals),
             [&](const json& e, const std::string& path, size_t number) {
                 f.fractals.push_back(parseCombinedFractal(context, e, path, f.customBlocks, number));
             });
    readList(r, "objects", "objects", size_t(kMaxObjects), [&](const json& e, const std::string& path, size_t number) {
        f.objects.push_back(parseObject(context, e, path, number));
    });
    r.finish();
    return f;
}

Camera parseCamera(const ReadContext& context, const json& j, ThinLens& lens) {
    FieldReader r(context, j, "camera");
    Camera c;
    c.position = r.requiredVector<3>("position", -1e4, 1e4);
    c.target = r.requiredVector<3>("target", -1e4, 1e4);
    c.up = r.vector<3>("up", c.up, -1e4, 1e4);
    c.projection = Projection(r.choice("projection", kProjectionNames, 0, "projection"));
    // A pinhole sees less than half the sphere; the wide projections up to all of it.
    c.fovY = r.number("fovY", c.fovY, 1.0, c.projection == Projection::Perspective ? 170.0 : 360.0);
    c.flipVertical = r.boolean("flipVertical", c.flipVertical);
    if (length(c.target - c.position) < 1e-9) r.fail("position and target coincide");
    if (length(glm::cross(normalize(c.target - c.position), c.up)) < 1e-6)
        r.fail("up is zero or parallel to the viewing direction", "up");
    readLens(r, c, lens);
    r.finish();
    return c;
}

void parseRender(const ReadContext& context, const json& j, RenderSettings& s) {
    FieldReader r(context, j, "render");
    readImageSize(r, s);
    s.maxSteps = r.integer("maxSteps", s.maxSteps, 1, kMaxMarchSteps);
    s.detail = r.number("detail", s.detail, 1e-3, 100.0);
    s.overRelaxation = r.number("overRelaxation", s.overRelaxation, 1.0, 1.95);
    s.maxStepGrowth = r.number("maxStepGrowth", s.maxStepGrowth, 1.0, kMaxStepGrowth);
    s.filterRadius = r.number("filterRadius", s.filterRadius, 0.5, 4.0);
    s.viewDistance = r.number("viewDistance", s.viewDistance, 0.0, 1e6);
    s.transparentBackground = r.boolean("transparentBackground", s.transparentBackground);
    r.finish();
}

ShadingSettings parseShading(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "shading");
    ShadingSettings s;
    s.lightDirection = r.vector<3>("lightDirection", s.lightDirection, -1e3, 1e3);
    if (length(s.lightDirection) < 1e-9) r.fail("a direction must not be zero", "lightDirection");
    s.lightColor = r.vector<3>("lightColor", s.lightColor, 0.0, 1e4);
    s.fillColor = r.vector<3>("fillColor", s.fillColor, 0.0, 1e4);
    s.specular = r.number("specular", s.specular, 0.0, 100.0);
    s.shininess = r.number("shininess", s.shininess, 1.0, 10000.0);
    s.shadowSteps = r.integer("shadowSteps", s.shadowSteps, 0, kMaxMarchSteps);
    s.shadowSoftness = r.number("shadowSoftness", s.shadowSoftness, 0.1, 1000.0);
    s.aoSteps = r.integer("aoSteps", s.aoSteps, 0, 64);
    s.aoDistance = r.number("aoDistance", s.aoDistance, 1e-6, 10.0);
    s.aoStrength = r.number("aoStrength", s.aoStrength, 0.0, 1.0);
    s.trapWeights = r.vector<4>("trapWeights", s.trapWeights, -1e3, 1e3);
    s.trapScale = r.number("trapScale", s.trapScale, -1e4, 1e4);
    s.trapOffset = r.number("trapOffset", s.trapOffset, -1e4, 1e4);
    s.paletteA = r.vector<3>("paletteA", s.paletteA, -10.0, 10.0);
    s.paletteB = r.vector<3>("paletteB", s.paletteB, -10.0, 10.0);
    s.paletteC = r.vector<3>("paletteC", s.paletteC, -100.0, 100.0);
    s.paletteD = r.vector<3>("paletteD", s.paletteD, -100.0, 100.0);
    s.fogColor = r.vector<3>("fogColor", s.fogColor, 0.0, 1e4);
    s.fogDensity = r.number("fogDensity", s.fogDensity, 0.0, 1e3);
    s.reflection = r.number("reflection", s.reflection, 0.0, 1.0);
    s.reflectionSteps = r.integer("reflectionSteps", s.reflectionSteps, 1, kMaxMarchSteps);
    s.backgroundTop = r.vector<3>("backgroundTop", s.backgroundTop, 0.0, 1e4);
    s.backgroundBottom = r.vector<3>("backgroundBottom", s.backgroundBottom, 0.0, 1e4);
    r.finish();
    return s;
}

const char* const kKnownSections[] = {"format",      "version",         "dimension", "name",
                                      "description", "formula",         "camera",    "render",
                                      "shading",     "colorManagement", "animation"};

Preset readPreset(const PresetDocument& doc, const std::string& file, FieldLog* log) {
    Preset p;
    const ReadContext context{file, &doc.json, doc.newer() ? &p.unknownFields : nullptr, log};
    FieldReader r(context, doc.json, "");
    if (r.has("dimension") && doc.json["dimension"] != 3)
        r.fail(
            "a 2D preset (\"dimension\": 2) where a 3D one is expected; 2D presets are rendered by `fraktal "
            "render`",
            "dimension");
    if (doc.newer()) p.formatVersion = doc.fileVersion;
    p.migrationNotes = doc.migration.notes;
    p.name = r.string("name", "");
    p.description = r.string("description", "", 65536);
    p.formula = parseFormula(context, r.at("formula"));
    p.camera = parseCamera(context, r.at("camera"), p.lighting.lens);
    if (r.has("lights")) p.lighting.lights = parseLights(context, r.at("lights"));
    if (r.has("environment")) p.lighting.environment = parseEnvironment(context, r.at("environment"));
    if (r.has("pathTrace")) p.lighting.pathTrace = parsePathTrace(context, r.at("pathTrace"));
    if (r.has("render")) parseRender(context, r.at("render"), p.render);
    if (r.has("colorManagement")) parseColorManagement(context, r.at("colorManagement"), p.render);
    if (r.has("shading")) p.shading = parseShading(context, r.at("shading"));
    if (r.has("animation")) p.animation = parseAnimation(context, r.at("animation"), p);
    for (const auto& [key, value] : doc.json.items())
        if (std::find(std::begin(kKnownSections), std::end(kKnownSections), key) == std::end(kKnownSections) &&
            !isLightingSection(key))
            p.extra[key] = value;
    return p;
}

}  // namespace

void readImageSize(FieldReader& r, RenderSettings& s) {
    s.width = r.integer("width", s.width, 1, kMaxImageSide);
    s.height = r.integer("height", s.height, 1, kMaxImageSide);
    s.spp = r.integer("spp", s.spp, 1, kMaxSpp);
}

void writeImageSize(const RenderSettings& s, json& j) {
    const RenderSettings d;
    if (s.width != d.width) j["width"] = s.width;
    if (s.height != d.height) j["height"] = s.height;
    if (s.spp != d.spp) j["spp"] = s.spp;
}

void parseColorManagement(const ReadContext& context, const json& j, RenderSettings& s) {
    FieldReader r(context, j, "colorManagement");
    s.workingSpace = r.string("workingSpace", s.workingSpace, 256);
    s.display = r.string("display", s.display, 256);
    s.view = r.string("view", s.view, 256);
    s.exposure = r.number("exposure", s.exposure, -20.0, 20.0);
    r.finish();
}

json colorManagementJson(const RenderSettings& s) {
    const RenderSettings d;
    json j = json::object();
    if (s.workingSpace != d.workingSpace) j["workingSpace"] = s.workingSpace;
    if (s.display != d.display) j["display"] = s.display;
    if (s.view != d.view) j["view"] = s.view;
    if (s.exposure != d.exposure) j["exposure"] = s.exposure;
    return j;
}

Preset parsePreset(std::string_view text, const std::string& file, FieldLog* log) {
    const PresetDocument doc = readPresetDocument(text, file);
    try {
        return readPreset(doc, file, log);
    } catch (const PresetError& e) {
        throw errorAsInFile(e, doc);
    }
}

Preset loadPreset(const std::filesystem::path& path) { return parsePreset(readGuardedFile(path), path.string()); }

namespace {

// Only the fields that differ from the defaults.
json renderJson(const RenderSettings& s) {
    const RenderSettings d;
    json j = json::object();
    auto put = [&](const char* key, const auto& value, const auto& fallback) {
        if (value != fallback) j[key] = value;
    };
    writeImageSize(s, j);
    put("maxSteps", s.maxSteps, d.maxSteps);
    put("detail", s.detail, d.detail);
    put("overRelaxation", s.overRelaxation, d.overRelaxation);
    put("maxStepGrowth", s.maxStepGrowth, d.maxStepGrowth);
    put("filterRadius", s.filterRadius, d.filterRadius);
    put("viewDistance", s.viewDistance, d.viewDistance);
    put("transparentBackground", s.transparentBackground, d.transparentBackground);
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

}  // namespace

namespace {
// A Placement's fields that differ from their defaults (objects and fractals write them alike).
void writePlacement(const Placement& place, json& j) {
    if (place.center != vec3(0.0)) j["center"] = vecJson(place.center);
    if (place.axis != vec3(0.0, 0.0, 1.0)) j["axis"] = vecJson(place.axis);
    if (place.angle != 0.0) j["angle"] = place.angle;
}
}  // namespace

// An object beside the fractal: its kind, what differs from the defaults, its parameters.
json objectToJson(const SceneObject& o) {
    json j = paramsOnlyJson(o);
    j["object"] = o.block->id;
    if (o.operation != ObjectOperation::Join) j["operation"] = kObjectOperationNames[int(o.operation)];
    if (o.hollow) j["hollow"] = true;
    if (!o.enabled) j["enabled"] = false;
    writePlacement(o, j);
    if (o.repeat != vec3(0.0)) j["repeat"] = vecJson(o.repeat);
    if (o.color != vec3(kDefaultObjectColor)) j["color"] = vecJson(o.color);
    return j;
}

namespace {

// A placement's fields that differ from the identity; empty at the identity.
json placementToJson(const FractalPlacement& place) {
    json j = json::object();
    writePlacement(place, j);
    if (place.scale != 1.0) j["scale"] = place.scale;
    if (place.repeat != vec3(0.0)) j["repeat"] = vecJson(place.repeat);
    return j;
}

// What parseFractal reads: the fields that differ from the defaults, the nodes, the placement.
void writeFractal(const Formula& fractal, json& f) {
    const Formula defaults;
    if (fractal.iterations != defaults.iterations) f["iterations"] = fractal.iterations;
    if (fractal.bailout != defaults.bailout) f["bailout"] = fractal.bailout;
    if (fractal.deFactor != defaults.deFactor) f["deFactor"] = fractal.deFactor;
    if (!fractal.deFactorMeasuredFor.empty()) f["deFactorMeasuredFor"] = fractal.deFactorMeasuredFor;
    json nodes = json::array();
    for (const Node& n : fractal.nodes) nodes.push_back(nodeToJson(n));
    if (fractal.estimator.block) nodes.push_back(nodeToJson(fractal.estimator));  // none: a formula being built
    f["nodes"] = nodes;
    if (json place = placementToJson(fractal.placement); !place.empty()) f["placement"] = place;
}

}  // namespace

json formulaToJson(const Formula& formula) {
    const Formula defaults;
    json f = json::object();
    if (formula.boundRadius != defaults.boundRadius) f["boundRadius"] = formula.boundRadius;
    if (formula.hitRule != defaults.hitRule) f["hitRule"] = kHitRuleNames[int(formula.hitRule)];
    if (!formula.customBlocks.empty()) {
        f["customBlocks"] = json::array();
        for (const auto& b : formula.customBlocks) f["customBlocks"].push_back(customBlockToJson(*b));
    }
    writeFractal(formula, f);
    if (!formula.fractals.empty()) {
        json fractals = json::array();
        for (const CombinedFractal& c : formula.fractals) {
            json e = json::object();
            if (c.operation != ObjectOperation::Join) e["operation"] = kObjectOperationNames[int(c.operation)];
            if (!c.enabled) e["enabled"] = false;
            writeFractal(c.formula, e);
            fractals.push_back(e);
        }
        f["fractals"] = fractals;
    }
    if (!formula.objects.empty()) {
        json objects = json::array();
        for (const SceneObject& o : formula.objects) objects.push_back(objectToJson(o));
        f["objects"] = objects;
    }
    return f;
}

json presetToJson(const Preset& p) {
    const Camera camDefaults;
    json j = json::object();
    j["format"] = kPresetFormat;
    j["version"] = std::max(kPresetVersion, p.formatVersion);
    if (!p.name.empty()) j["name"] = p.name;
    if (!p.description.empty()) j["description"] = p.description;
    j["formula"] = formulaToJson(p.formula);
    json c = json::object();
    c["position"] = vecJson(p.camera.position);
    c["target"] = vecJson(p.camera.target);
    if (p.camera.up != camDefaults.up) c["up"] = vecJson(p.camera.up);
    if (p.camera.fovY != camDefaults.fovY) c["fovY"] = p.camera.fovY;
    if (p.camera.flipVertical) c["flipVertical"] = true;
    if (p.camera.projection != Projection::Perspective) c["projection"] = kProjectionNames[int(p.camera.projection)];
    j["camera"] = c;
    if (json r = renderJson(p.render); !r.empty()) j["render"] = r;
    if (json c = colorManagementJson(p.render); !c.empty()) j["colorManagement"] = c;
    if (json s = shadingJson(p.shading); !s.empty()) j["shading"] = s;
    // Without keys too: frames per second and the frame range an artist set on the timeline are
    // the document's, and a save must not drop them.
    if (p.animation != Animation{}) j["animation"] = animationJson(p.animation);
    writeLighting(p.lighting, j);
    p.unknownFields.writeBack(j);
    for (const auto& [key, value] : p.extra.items())
        if (!j.contains(key)) j[key] = value;
    return j;
}

std::string serializePreset(const Preset& p) { return presetToJson(p).dump(2) + "\n"; }

void savePresetFile(const std::filesystem::path& path, const Preset& preset) {
    writeFileAtomically(path, serializePreset(preset), /*keepBackup=*/true);
}

std::string describeFormula(const Formula& f) {
    std::ostringstream s;
    auto describePlacement = [&](const FractalPlacement& place) {
        if (place.identity()) return;
        s << "  placed at (" << place.center.x << ", " << place.center.y << ", " << place.center.z << ")";
        if (place.turned())
            s << ", turned " << place.angle << " degrees about (" << place.axis.x << ", " << place.axis.y << ", "
              << place.axis.z << ")";
        if (place.scale != 1.0) s << ", scaled " << place.scale;
        if (place.repeat != vec3(0.0))
            s << ", repeated every (" << place.repeat.x << ", " << place.repeat.y << ", " << place.repeat.z << ")";
        s << "\n";
    };
    auto describeNode = [&](const Node& n, const std::string& prefix) {
        s << prefix << n.block->id << " [" << categoryName(n.block->category) << "]";
        if (!n.enabled) s << " (disabled)";
        if (!n.always()) s << " (" << n.describe() << ")";
        for (size_t i = 0; i < n.values.size(); ++i) {
            const ParamDecl& d = n.block->params[i];
            s << (i == 0 ? ": " : ", ") << d.name << " = ";
            if (d.type == ParamType::Toggle)
                s << (n.values[i].x > 0.5 ? "on" : "off");
            else if (d.type == ParamType::Float)
                s << n.values[i].x;
            else
                s << "(" << n.values[i].x << ", " << n.values[i].y << ", " << n.values[i].z << ")";
        }
        s << "\n";
    };
    // Numbered from 1 with the estimator last, as the editor's list and the preset errors number them.
    auto describeNodes = [&](const Formula& fractal) {
        for (size_t k = 0; k < fractal.nodes.size(); ++k)
            describeNode(fractal.nodes[k], "  " + std::to_string(k + 1) + ". ");
        describeNode(fractal.estimator, "  " + std::to_string(fractal.nodes.size() + 1) + ". ");
    };
    s << "iterations " << f.iterations << ", bailout " << f.bailout << ", bound radius " << f.boundRadius
      << ", DE factor " << f.deFactor
      << (f.hitRule == HitRule::InsideOnly      ? ", hits only inside"
          : f.hitRule == HitRule::InteriorWalls ? ", hits the interior walls"
                                                : "")
      << "\n";
    describePlacement(f.placement);
    describeNodes(f);
    for (size_t j = 0; j < f.fractals.size(); ++j) {
        const CombinedFractal& c = f.fractals[j];
        s << "fractal " << j + 2 << " (" << kObjectOperationNames[int(c.operation)] << (c.enabled ? "" : ", off")
          << "): iterations " << c.formula.iterations << ", bailout " << c.formula.bailout << ", DE factor "
          << c.formula.deFactor << "\n";
        describePlacement(c.formula.placement);
        describeNodes(c.formula);
    }
    for (size_t k = 0; k < f.objects.size(); ++k) {
        const SceneObject& o = f.objects[k];
        s << "  object " << k + 1 << ". " << o.block->id << " (" << kObjectOperationNames[int(o.operation)]
          << (o.hollow ? ", hollow" : "") << (o.enabled ? "" : ", off") << ") at (" << o.center.x << ", " << o.center.y
          << ", " << o.center.z << ")";
        if (o.angle != 0.0)
            s << ", turned " << o.angle << " degrees about (" << o.axis.x << ", " << o.axis.y << ", " << o.axis.z
              << ")";
        if (o.repeat != vec3(0.0))
            s << ", repeated every (" << o.repeat.x << ", " << o.repeat.y << ", " << o.repeat.z << ")";
        for (size_t i = 0; i < o.values.size(); ++i) {
            const ParamDecl& d = o.block->params[i];
            s << (i == 0 ? ": " : ", ") << d.name << " = ";
            if (d.type == ParamType::Vec3)
                s << "(" << o.values[i].x << ", " << o.values[i].y << ", " << o.values[i].z << ")";
            else
                s << o.values[i].x;
        }
        s << "\n";
    }
    return s.str();
}

}  // namespace fraktal
