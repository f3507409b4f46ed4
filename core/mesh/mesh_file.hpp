// Mesh files: PLY, OBJ, STL and glTF (binary, .glb), written and read with Assimp (Debian's
// libassimp-dev), one library that covers every format a slicer or a DCC tool opens, and reads
// back what it wrote.
#pragma once

#include <filesystem>
#include <string>

#include "core/mesh/triangle_mesh.hpp"

namespace fraktal::mesh {

// The extensions writeMesh takes, for messages: ".ply, .obj, .stl, .glb".
std::string meshExtensions();
// Whether writeMesh takes this extension (lower case, with the dot).
bool isMeshExtension(const std::string& extension);

// Whether the format keeps the mesh's vertex colours (PLY, OBJ and glTF do; STL does not).
bool carriesColors(const std::string& extension);

// Writes the mesh in the format its extension names (binary PLY and STL, OBJ without a material
// file, binary glTF 2), atomically (core/atomic_file.hpp), with its vertex colours where the
// format carries them. Throws std::runtime_error naming the path and the reason.
void writeMesh(const std::filesystem::path& path, const TriangleMesh& mesh);

// Reads a mesh file back into one indexed mesh (identical vertices joined: STL stores none
// shared), with its vertex colours as linear values when the file has them. Throws std::runtime_error naming the path
// and Assimp's reason.
TriangleMesh readMesh(const std::filesystem::path& path);

}  // namespace fraktal::mesh
