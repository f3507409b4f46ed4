#include "core/mesh/mesh_file.hpp"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <stdexcept>

#include "core/atomic_file.hpp"

namespace fraktal::mesh {

namespace {

struct Format {
    const char* extension;
    const char* assimpId;  // Assimp's exporter id (Assimp::Exporter::GetExportFormatDescription)
};
// Binary PLY and STL (a third of the text forms' size); OBJ without the .mtl file beside it (a
// mesh with no material needs none, and a second file could not be written atomically with it).
constexpr Format kFormats[] = {{".ply", "plyb"}, {".obj", "objnomtl"}, {".stl", "stlb"}, {".glb", "glb2"}};

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

void writeMesh(const std::filesystem::path& path, const TriangleMesh& mesh) {
    const Format* format = formatFor(path.extension().string());
    if (!format)
        throw std::runtime_error(path.string() + ": unknown mesh format \"" + path.extension().string() +
                                 "\" (one of " + meshExtensions() + ")");
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
    m.mNumFaces = unsigned(mesh.triangles.size());
    m.mFaces = new aiFace[mesh.triangles.size()];
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        m.mFaces[i].mNumIndices = 3;
        m.mFaces[i].mIndices = new unsigned[3]{mesh.triangles[i][0], mesh.triangles[i][1], mesh.triangles[i][2]};
    }
    AtomicFile out(path);
    Assimp::Exporter exporter;
    if (exporter.Export(&scene, format->assimpId, out.tempPath().string()) != aiReturn_SUCCESS)
        throw std::runtime_error(path.string() + ": writing the mesh failed: " + exporter.GetErrorString());
    out.commit();
}

TriangleMesh readMesh(const std::filesystem::path& path) {
    Assimp::Importer importer;
    // Vertices are joined by position alone: STL's per-face normals would keep them apart.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                                            aiComponent_COLORS | aiComponent_TEXCOORDS);
    const aiScene* scene = importer.ReadFile(
        path.string(), aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices | aiProcess_Triangulate);
    if (!scene || !scene->mRootNode)
        throw std::runtime_error(path.string() + ": cannot read the mesh: " + importer.GetErrorString());
    TriangleMesh mesh;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
        const aiMesh& m = *scene->mMeshes[k];
        const uint32_t base = uint32_t(mesh.points.size());
        for (unsigned i = 0; i < m.mNumVertices; ++i)
            mesh.points.push_back({m.mVertices[i].x, m.mVertices[i].y, m.mVertices[i].z});
        for (unsigned i = 0; i < m.mNumFaces; ++i) {
            const aiFace& f = m.mFaces[i];
            if (f.mNumIndices != 3) continue;
            mesh.triangles.push_back({base + f.mIndices[0], base + f.mIndices[1], base + f.mIndices[2]});
        }
    }
    return mesh;
}

}  // namespace fraktal::mesh
