// glTF 2.0 -> the CPU side of an XNA Model (internal to fxport_graphics). model.cpp turns the result
// into GPU buffers, textures and effects; the conventions are documented in fxport/graphics/model.h.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fxport/graphics/model.h"
#include "fxport/graphics/skinning_data.h"
#include "fxport/math.h"

namespace fxport::detail {

struct GltfImage {
    std::string name;  // the glTF image's name, else its uri, else "image <i>"
    int width = 0;
    int height = 0;
    std::vector<Color> texels;  // RGBA8, top row first
};

// Texture fields: indices into GltfModel::images; -1 = use the default texture.
struct GltfMaterial {
    std::string name;
    int texture = -1;
    int normalMap = -1;
    int specularMap = -1;
    Vector4 baseColorFactor = Vector4(1, 1, 1, 1);  // pbrMetallicRoughness.baseColorFactor
    Vector3 emissiveFactor = Vector3(0, 0, 0);
};

struct GltfPart {
    int vertexOffset = 0;
    int numVertices = 0;
    int startIndex = 0;
    int primitiveCount = 0;
    int material = -1;  // index into GltfModel::materials, -1 = none
};

// One glTF mesh: the vertices and indices of all its triangle primitives, one after the other.
// Indices count from the part's first vertex and have XNA's (clockwise) winding.
struct GltfMesh {
    std::string name;
    std::vector<ModelVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<GltfPart> parts;
    BoundingSphere bounds;
    bool sixteenBitIndices = true;
    // Skinned meshes only (else empty), one per vertex: four skeleton bone indices and their
    // weights (summing to 1; unused slots weigh 0).
    std::vector<std::array<std::uint8_t, 4>> blendIndices;
    std::vector<Vector4> blendWeights;
};

struct GltfBone {
    std::string name;
    int parent = -1;  // index into GltfModel::bones (parents come first)
    Matrix transform = Matrix::Identity;
    int mesh = -1;    // index into GltfModel::meshes
};

struct GltfModel {
    std::vector<GltfBone> bones;  // bones[0] is the root
    std::vector<GltfMesh> meshes;
    std::vector<GltfMaterial> materials;
    std::vector<GltfImage> images;  // only the images some material uses
    std::optional<SkinningData> skinning;  // when the file has skin weights or animations
};

// The bounds ModelMesh::BoundingSphere holds: the centre of the vertices' bounding box, the radius to
// the farthest vertex (an empty sphere for no vertices).
BoundingSphere vertexBounds(const std::vector<ModelVertex>& vertices);

// Reads a .gltf or .glb file. Throws ArgumentError whose message starts with `path`.
GltfModel loadGltf(const std::string& path);

// glTF node transform -> XNA matrix (exposed for tests): `matrix` (16 numbers, column-major) when
// present, else translation/rotation/scale (each may be empty).
Matrix gltfNodeMatrix(const std::vector<double>& matrix, const std::vector<double>& translation,
                      const std::vector<double>& rotation, const std::vector<double>& scale);

}  // namespace fxport::detail
