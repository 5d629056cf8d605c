#include "light_geometry.h"

#include <cmath>

#include "gltf_writer.h"
#include "mesh_builders.h"

namespace fxport::content {

namespace {

void WriteSingleMesh(const std::filesystem::path& dir, const std::string& name, Mesh mesh) {
    mesh.name = name;
    mesh.writeTangents = false;
    GltfWriter gltf(name);
    const int meshIndex = gltf.AddMesh(mesh);
    const int node = gltf.AddNode(name, meshIndex);
    gltf.SetScene(name, {node});
    gltf.Write(dir);
}

}  // namespace

void WritePointLightGeometry(const std::filesystem::path& dir) {
    Mesh mesh;
    mesh.primitives.emplace_back();
    SphereDesc sphere;
    sphere.radius = 100.0f;
    sphere.segments = 32;
    sphere.rings = 16;
    sphere.uRepeats = 1;
    AddUvSphere(mesh.primitives.back(), sphere);
    WriteSingleMesh(dir, "PointLightGeometry", std::move(mesh));
}

void WriteSpotLightGeometry(const std::filesystem::path& dir) {
    constexpr int kSegments = 32;
    // The polygon's vertices sit slightly outside radius 0.5 so that its edges (not only its
    // corners) enclose the exact circular cone: no lit pixel at the cone's rim is clipped.
    const float baseRadius = 0.5f / std::cos(kPi / static_cast<float>(kSegments));
    Mesh mesh;
    mesh.primitives.emplace_back();
    AddLightCone(mesh.primitives.back(), kSegments, baseRadius);
    WriteSingleMesh(dir, "SpotLightGeometry", std::move(mesh));
}

}  // namespace fxport::content
