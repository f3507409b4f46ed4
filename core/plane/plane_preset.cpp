#include "core/plane/plane_preset.hpp"

#include <algorithm>
#include <sstream>

namespace fraktal {

using nlohmann::json;

namespace {

std::string knownBlocks() {
    std::string known;
    for (const PlaneBlockDesc& b : allPlaneBlocks()) known += (known.empty() ? "" : ", ") + std::string(b.id);
    return known;
}

// `listNumber`: the node's 1-based place in its list (start or loop), as the editor lists it.
PlaneNode parseNode(const ReadContext& context, const json& j, const std::string& path, size_t listNumber) {
    FieldReader r(context, j, path);
    const json& id = r.at("block");
    if (!id.is_string()) r.fail("expected a block id string, found " + FieldReader::typeName(id), "block");
    const PlaneBlockDesc* block = findPlaneBlock(id.get<std::string>());
    if (!block)
        r.fail("unknown 2D block '" + id.get<std::string>() + "' (known 2D blocks: " + knownBlocks() + ")", "block");
    PlaneNode n = PlaneNode::make(*block);
    readNodeSchedule(r, n);
    readNodeParams(r, n, listNumber, "2D block");
    r.finish();
    return n;
}

std::vector<PlaneNode> parseNodeList(const ReadContext& context, FieldReader& r, const std::string& key) {
    const json& list = r.at(key);
    if (!list.is_array()) r.fail("expected an array of nodes, found " + FieldReader::typeName(list), key);
    if (list.size() > size_t(kMaxNodes))
        r.fail("too many nodes (" + std::to_string(list.size()) + "; at most " + std::to_string(kMaxNodes) + ")", key);
    std::vector<PlaneNode> nodes;
    for (size_t i = 0; i < list.size(); ++i)
        nodes.push_back(parseNode(context, list[i], r.child(key) + "[" + std::to_string(i) + "]", i + 1));
    return nodes;
}

PlaneFormula parsePlaneFormula(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "formula");
    const std::string& file = context.file;
    PlaneFormula f;
    f.iterations = r.integer("iterations", f.iterations, 0, kMaxIterations);
    f.bailout = r.number("bailout", f.bailout, 1e-3, 1e10);
    if (r.has("start")) {
        f.start = parseNodeList(context, r, "start");
        for (size_t i = 0; i < f.start.size(); ++i)
            if (f.start[i].block->isEstimator())
                throw PresetError(file, r.child("start") + "[" + std::to_string(i) + "]",
                                  "estimator '" + std::string(f.start[i].block->id) + "' may only close the node list");
    }
    std::vector<PlaneNode> nodes = parseNodeList(context, r, "nodes");
    if (nodes.empty()) r.fail("the node list is empty: a formula needs at least a closing estimator", "nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string path = r.child("nodes") + "[" + std::to_string(i) + "]";
        const bool last = i + 1 == nodes.size();
        if (nodes[i].block->isEstimator() != last)
            throw PresetError(file, path,
                              last
                                  ? "the node list must end with a 2D estimator (escape, triangle, segment), found '" +
                                        std::string(nodes[i].block->id) + "'"
                                  : "estimator '" + std::string(nodes[i].block->id) + "' may only close the node list");
        if (last) checkEstimatorSchedule(nodes[i], file, path);
    }
    f.estimator = std::move(nodes.back());
    nodes.pop_back();
    f.nodes = std::move(nodes);
    r.finish();
    return f;
}

PlaneViewRect parseView(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "view");
    PlaneViewRect v;
    v.center = r.vector<2>("center", v.center, -1e4, 1e4);
    v.width = r.number("width", v.width, 1e-300, 1e4);
    r.finish();
    return v;
}

// The 2D renderer uses the image size and samples of the 3D "render" section; its colour
// management is the shared "colorManagement" section.
void parsePlaneRender(const ReadContext& context, const json& j, RenderSettings& s) {
    FieldReader r(context, j, "render");
    readImageSize(r, s);
    r.finish();
}

PlaneColouring parseColouring(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "colouring");
    PlaneColouring c;
    c.paletteA = r.vector<3>("paletteA", c.paletteA, -10.0, 10.0);
    c.paletteB = r.vector<3>("paletteB", c.paletteB, -10.0, 10.0);
    c.paletteC = r.vector<3>("paletteC", c.paletteC, -100.0, 100.0);
    c.paletteD = r.vector<3>("paletteD", c.paletteD, -100.0, 100.0);
    c.frequency = r.number("frequency", c.frequency, -1e3, 1e3);
    c.offset = r.number("offset", c.offset, -1e3, 1e3);
    c.interior = r.vector<3>("interior", c.interior, 0.0, 1e4);
    c.edgeWidth = r.number("edgeWidth", c.edgeWidth, 0.0, 100.0);
    r.finish();
    return c;
}

PlanePreset readPlanePreset(const PresetDocument& doc, const std::string& file) {
    PlanePreset p;
    const ReadContext context{file, &doc.json, doc.newer() ? &p.unknownFields : nullptr};
    FieldReader r(context, doc.json, "");
    r.skip("format");  // checked by readPresetDocument
    r.skip("version");
    if (r.integer("dimension", 3, 2, 3) != 2) r.fail("expected 2 for a 2D preset", "dimension");
    if (doc.newer()) p.formatVersion = doc.fileVersion;
    p.migrationNotes = doc.migration.notes;
    p.name = r.string("name", "");
    p.description = r.string("description", "", 65536);
    p.formula = parsePlaneFormula(context, r.at("formula"));
    if (r.has("view")) p.view = parseView(context, r.at("view"));
    if (r.has("render")) parsePlaneRender(context, r.at("render"), p.render);
    if (r.has("colorManagement")) parseColorManagement(context, r.at("colorManagement"), p.render);
    if (r.has("colouring")) p.colouring = parseColouring(context, r.at("colouring"));
    r.finish();
    return p;
}

}  // namespace

bool isPlanePresetText(std::string_view text) {
    const json j = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    return j.is_object() && j.contains("dimension") && j["dimension"] == 2;
}

bool isPlanePresetFile(const std::filesystem::path& path) {
    try {
        return isPlanePresetText(readGuardedFile(path));
    } catch (const PresetError&) {
        return false;  // not readable as a document: the 3D reader then says why
    }
}

PlanePreset parsePlanePreset(std::string_view text, const std::string& file) {
    const PresetDocument doc = readPresetDocument(text, file);
    try {
        return readPlanePreset(doc, file);
    } catch (const PresetError& e) {
        throw errorAsInFile(e, doc);
    }
}

PlanePreset loadPlanePreset(const std::filesystem::path& path) {
    return parsePlanePreset(readGuardedFile(path), path.string());
}

json planePresetToJson(const PlanePreset& p) {
    const PlaneFormula formulaDefaults;
    const PlaneColouring colourDefaults;
    json j = json::object();
    j["format"] = kPresetFormat;
    j["version"] = std::max(kPresetVersion, p.formatVersion);
    j["dimension"] = 2;
    if (!p.name.empty()) j["name"] = p.name;
    if (!p.description.empty()) j["description"] = p.description;
    json f = json::object();
    if (p.formula.iterations != formulaDefaults.iterations) f["iterations"] = p.formula.iterations;
    if (p.formula.bailout != formulaDefaults.bailout) f["bailout"] = p.formula.bailout;
    if (!p.formula.start.empty()) {
        f["start"] = json::array();
        for (const PlaneNode& n : p.formula.start) f["start"].push_back(nodeToJson(n));
    }
    f["nodes"] = json::array();
    for (const PlaneNode& n : p.formula.nodes) f["nodes"].push_back(nodeToJson(n));
    f["nodes"].push_back(nodeToJson(p.formula.estimator));
    j["formula"] = f;
    j["view"] = {{"center", {p.view.center.x, p.view.center.y}}, {"width", p.view.width}};
    json r = json::object();
    const RenderSettings& s = p.render;
    writeImageSize(s, r);
    if (!r.empty()) j["render"] = r;
    if (json cm = colorManagementJson(s); !cm.empty()) j["colorManagement"] = cm;
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
    p.unknownFields.writeBack(j);
    return j;
}

std::string serializePlanePreset(const PlanePreset& p) { return planePresetToJson(p).dump(2) + "\n"; }

std::string describePlaneFormula(const PlaneFormula& f) {
    std::ostringstream s;
    s << "iterations " << f.iterations << ", bailout " << f.bailout << "\n";
    auto describeNode = [&](const PlaneNode& n, const std::string& prefix) {
        s << prefix << n.block->id;
        if (!n.enabled) s << " (disabled)";
        if (!n.always()) s << " (" << n.describe() << ")";
        for (size_t i = 0; i < n.values.size(); ++i)
            s << (i == 0 ? ": " : ", ") << n.block->params[i].name << " = " << n.values[i].x;
        s << "\n";
    };
    for (size_t k = 0; k < f.start.size(); ++k) describeNode(f.start[k], "  start " + std::to_string(k) + ". ");
    for (size_t k = 0; k < f.nodes.size(); ++k) describeNode(f.nodes[k], "  " + std::to_string(k) + ". ");
    describeNode(f.estimator, "  => ");
    return s.str();
}

}  // namespace fraktal
