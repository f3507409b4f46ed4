#include "core/mesh/mesh_file.hpp"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "core/atomic_file.hpp"

namespace fraktal::mesh {

namespace {

// How a format stores vertex colours: glTF's COLOR_0 is linear (glTF 2.0, 3.7.2.1); PLY's 8-bit
// red/green/blue and OBJ's "v x y z r g b" are read by MeshLab, Blender and slicers as display
// (sRGB-encoded) values.
enum class ColorEncoding { None, Display, Linear };

// Binary PLY and STL (a third of the text forms' size) are streamed from the mesh by
// writeBinaryPly / writeBinaryStl below; OBJ (without the .mtl file beside it: a mesh with no
// material needs none, and a second file could not be written atomically with it) and glTF go
// through Assimp's exporters.
//
// Why not Assimp for PLY and STL, the formats big prints use: Assimp copies the mesh into an
// aiScene with a heap block per face, and its exporters build the whole file in a string stream
// before writing it: about 60 bytes a triangle beside the mesh's own 12 (at 2048^3 the
// Mandelbulb's 190 million triangles would need 11 GB more than the mesh). And Assimp 5.2's
// binary PLY exporter declares vertex colours as uchar but writes them as four floats each,
// which every reader misreads. Both formats are a fixed header and packed records (PLY: Turk
// 1994, as Paul Bourke's page describes it; STL: 3D Systems' binary layout), and Assimp's
// importers read them back in the tests.
enum class Writer { BinaryPly, BinaryStl, Assimp };

struct Format {
    const char* extension;
    Writer writer;
    const char* assimpId;  // Assimp's exporter id (Assimp::Exporter::GetExportFormatDescription)
    ColorEncoding colors;
};
constexpr Format kFormats[] = {{".ply", Writer::BinaryPly, "", ColorEncoding::Display},
                               {".obj", Writer::Assimp, "objnomtl", ColorEncoding::Display},
                               {".stl", Writer::BinaryStl, "", ColorEncoding::None},
                               {".glb", Writer::Assimp, "glb2", ColorEncoding::Linear}};

// The sRGB transfer function (IEC 61966-2-1) and its inverse.
float encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
float decodeSrgb(float display) {
    const float c = std::clamp(display, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

const Format* formatFor(const std::string& extension) {
    for (const Format& f : kFormats)
        if (extension == f.extension) return &f;
    return nullptr;
}

}  // namespace

std::string meshExtensions() {
    std::string list;
    for (const Format& f : kFormats) list += (list.empty() ? "" : ", ") + std::string(f.extension);
    return list;
}

bool isMeshExtension(const std::string& extension) { return formatFor(extension) != nullptr; }

bool carriesColors(const std::string& extension) {
    const Format* f = formatFor(extension);
    return f && f->colors != ColorEncoding::None;
}

namespace {

// Little-endian records in a buffered stream (the formats are little-endian, as is every
// machine fraktal builds for: static_assert below).
static_assert(std::endian::native == std::endian::little, "the PLY and STL writers assume a little-endian machine");

template <class T>
void put(std::ofstream& out, const T& value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

uint8_t displayByte(float linear) { return uint8_t(std::lround(encodeSrgb(linear) * 255.0f)); }

void checkWritten(const std::ofstream& out, const std::filesystem::path& path) {
    if (!out) throw std::runtime_error(path.string() + ": writing the mesh failed (disk full or not writable)");
}

void writeBinaryPly(const std::filesystem::path& temp, const std::filesystem::path& path, const TriangleMesh& mesh) {
    const bool colored = mesh.colors.size() == mesh.points.size() && !mesh.points.empty();
    std::ofstream out(temp, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\ncomment written by fraktal mesh\n"
        << "element vertex " << mesh.points.size() << "\nproperty float x\nproperty float y\nproperty float z\n";
    if (colored) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (size_t i = 0; i < mesh.points.size(); ++i) {
        put(out, mesh.points[i]);
        if (colored)
            for (float c : mesh.colors[i]) put(out, displayByte(c));
    }
    for (const auto& t : mesh.triangles) {
        put(out, uint8_t(3));
        put(out, t);
    }
    out.close();
    checkWritten(out, path);
}

void writeBinaryStl(const std::filesystem::path& temp, const std::filesystem::path& path, const TriangleMesh& mesh) {
    if (mesh.triangles.size() > std::numeric_limits<uint32_t>::max())
        throw std::runtime_error(path.string() + ": binary STL holds at most 2^32 - 1 triangles");
    std::ofstream out(temp, std::ios::binary);
    std::array<char, 80> header{};
    const std::string_view note = "binary STL written by fraktal mesh";
    std::copy(note.begin(), note.end(), header.begin());
    out.write(header.data(), header.size());
    put(out, uint32_t(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const vec3 a = mesh.point(t[0]), b = mesh.point(t[1]), c = mesh.point(t[2]);
        const vec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        const vec3 unit = length > 0.0 ? n / length : vec3(0.0);
        put(out, std::array<float, 3>{float(unit.x), float(unit.y), float(unit.z)});
        for (uint32_t v : t) put(out, mesh.points[v]);
        put(out, uint16_t(0));  // attribute byte count
    }
    out.close();
    checkWritten(out, path);
}

void writeWithAssimp(const Format* format, const std::filesystem::path& temp, const std::filesystem::path& path,
                     const TriangleMesh& mesh) {
    // aiScene owns what it points to and frees it with delete / delete[].
    aiScene scene;
    scene.mRootNode = new aiNode();
    scene.mRootNode->mNumMeshes = 1;
    scene.mRootNode->mMeshes = new unsigned[1]{0};
    // glTF needs a material for its mesh: Assimp's default one.
    scene.mNumMaterials = 1;
    scene.mMaterials = new aiMaterial* [1] { new aiMaterial() };
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh* [1] { new aiMesh() };
    aiMesh& m = *scene.mMeshes[0];
    m.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    m.mMaterialIndex = 0;
    m.mNumVertices = unsigned(mesh.points.size());
    m.mVertices = new aiVector3D[mesh.points.size()];
    for (size_t i = 0; i < mesh.points.size(); ++i)
        m.mVertices[i] = aiVector3D(mesh.points[i][0], mesh.points[i][1], mesh.points[i][2]);
    if (format->colors != ColorEncoding::None && mesh.colors.size() == mesh.points.size()) {
        const bool display = format->colors == ColorEncoding::Display;
        m.mColors[0] = new aiColor4D[mesh.points.size()];
        for (size_t i = 0; i < mesh.colors.size(); ++i) {
            const auto& c = mesh.colors[i];
            m.mColors[0][i] = display ? aiColor4D(encodeSrgb(c[0]), encodeSrgb(c[1]), encodeSrgb(c[2]), 1.0f)
                                      : aiColor4D(c[0], c[1], c[2], 1.0f);
        }
    }
    m.mNumFaces = unsigned(mesh.triangles.size());
    m.mFaces = new aiFace[mesh.triangles.size()];
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        m.mFaces[i].mNumIndices = 3;
        m.mFaces[i].mIndices = new unsigned[3]{mesh.triangles[i][0], mesh.triangles[i][1], mesh.triangles[i][2]};
    }
    Assimp::Exporter exporter;
    if (exporter.Export(&scene, format->assimpId, temp.string()) != aiReturn_SUCCESS)
        throw std::runtime_error(path.string() + ": writing the mesh failed: " + exporter.GetErrorString());
}

}  // namespace

void writeMesh(const std::filesystem::path& path, const TriangleMesh& mesh) {
    const Format* format = formatFor(path.extension().string());
    if (!format)
        throw std::runtime_error(path.string() + ": unknown mesh format \"" + path.extension().string() +
                                 "\" (one of " + meshExtensions() + ")");
    AtomicFile out(path);
    switch (format->writer) {
        case Writer::BinaryPly: writeBinaryPly(out.tempPath(), path, mesh); break;
        case Writer::BinaryStl: writeBinaryStl(out.tempPath(), path, mesh); break;
        case Writer::Assimp: writeWithAssimp(format, out.tempPath(), path, mesh); break;
    }
    out.commit();
}

TriangleMesh readMesh(const std::filesystem::path& path) {
    Assimp::Importer importer;
    // Vertices are joined by position alone: STL's per-face normals would keep them apart.
    // Colours stay: a point has one colour, so they keep no vertex apart that its position joins.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                                aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_TEXCOORDS);
    const aiScene* scene =
        importer.ReadFile(path.string(), aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices);
    if (!scene || !scene->mRootNode)
        throw std::runtime_error(path.string() + ": cannot read the mesh: " + importer.GetErrorString());
    const Format* format = formatFor(path.extension().string());
    const bool display = format && format->colors == ColorEncoding::Display;
    TriangleMesh mesh;
    bool colored = scene->mNumMeshes > 0;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) colored = colored && scene->mMeshes[k]->HasVertexColors(0);
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
        const aiMesh& m = *scene->mMeshes[k];
        const uint32_t base = uint32_t(mesh.points.size());
        for (unsigned i = 0; i < m.mNumVertices; ++i) {
            mesh.points.push_back({m.mVertices[i].x, m.mVertices[i].y, m.mVertices[i].z});
            if (!colored) continue;
            const aiColor4D& c = m.mColors[0][i];
            mesh.colors.push_back(display ? std::array<float, 3>{decodeSrgb(c.r), decodeSrgb(c.g), decodeSrgb(c.b)}
                                          : std::array<float, 3>{c.r, c.g, c.b});
        }
        for (unsigned i = 0; i < m.mNumFaces; ++i) {
            // Polygons as fans (points and lines have no area and are left out).
            const aiFace& f = m.mFaces[i];
            for (unsigned k = 2; k < f.mNumIndices; ++k)
                mesh.triangles.push_back({base + f.mIndices[0], base + f.mIndices[k - 1], base + f.mIndices[k]});
        }
    }
    return mesh;
}

}  // namespace fraktal::mesh
