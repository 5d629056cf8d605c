// .x, .fbx, .obj, .dae (and Assimp's other formats) -> the CPU side of an XNA Model, the same
// structure the glTF loader fills (internal to fxport_graphics; model.cpp makes the GPU side).
// The conventions are those of fxport/graphics/model.h: bones depth-first from the file's root
// node, one ModelMesh per node with meshes (one part per Assimp mesh), XNA's clockwise winding,
// texture coordinates with v down, flat normals where the file has none, tangent frames as for glTF.
#pragma once

#include <string>

#include "helpers/gltf_loader.h"

namespace fxport::detail {

// Throws ArgumentError whose message starts with `path`: a file that is not a regular file or is
// larger than kMaxModelFileBytes, Assimp's reason for refusing it, a texture it names that cannot
// be read, a mesh without triangles.
GltfModel loadWithAssimp(const std::string& path);

// The largest model file handed to Assimp (it reads the whole file).
inline constexpr long long kMaxModelFileBytes = 256LL << 20;

}  // namespace fxport::detail
