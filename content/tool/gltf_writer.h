// Builds a glTF 2.0 document (.gltf JSON + one .bin buffer) from Meshes, materials and a node tree.
// Output is deterministic: JSON keys keep insertion order, numbers are float32 printed in their
// shortest round-trip form, the buffer is little-endian with every view 4-byte aligned.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh.h"

namespace fxport::content {

// JSON with ordered keys and float32 numbers (glTF stores float32; printing float keeps 0.1 as 0.1).
using Json = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                                  std::uint64_t, float>;

// A node's local transform (glTF TRS; XNA: CreateScale(s) * CreateFromQuaternion(r) * CreateTranslation(t)).
struct NodeTransform {
    Vec3 translation{0, 0, 0};
    Vec4 rotation{0, 0, 0, 1};  // unit quaternion (x, y, z, w)
    Vec3 scale{1, 1, 1};
};

// Rotation by `degrees` about +Y (counter-clockwise seen from above).
Vec4 RotationY(float degrees);

class GltfWriter {
public:
    // Files are written as <baseName>.gltf and <baseName>.bin.
    explicit GltfWriter(std::string baseName);

    // An image file (relative URI next to the .gltf) sampled with trilinear filtering and REPEAT;
    // returns its texture index.
    int AddTexture(const std::string& uri);
    // A material in the fxport convention: baseColorTexture = albedo, normalTexture = normal,
    // extras.fxportSpecularMap = specular map (see material_textures.h for channel meanings).
    int AddMaterial(const std::string& name, int albedoTexture, int normalTexture, int specularTexture);
    int AddMesh(const Mesh& mesh);
    // A node with an optional mesh (-1 = none); returns its index.
    int AddNode(const std::string& name, int mesh, const NodeTransform& transform = {});
    void AddChild(int parent, int child);
    // The scene (glTF scene 0) and its root nodes.
    void SetScene(const std::string& name, const std::vector<int>& roots);

    // Writes <dir>/<baseName>.gltf and <dir>/<baseName>.bin. Throws std::runtime_error on I/O errors.
    void Write(const std::filesystem::path& dir) const;

private:
    int AddView(const void* data, std::size_t bytes, int target);
    int AddAccessor(int view, int componentType, std::size_t count, const char* type);

    std::string baseName_;
    Json root_;
    std::vector<std::uint8_t> buffer_;
};

}  // namespace fxport::content
