// The light volumes the DeferredRenderer draws to restrict lighting to the pixels a light can reach
// (Content.Load<Model>("PointLightGeometry") / ("SpotLightGeometry"), seed 000 lines 213-216).
// Each is one mesh with one primitive (the tutorial draws Meshes[0].MeshParts[0]) under a single
// root node, POSITION + NORMAL + TEXCOORD_0, no material, closed, counter-clockwise outward faces.
#pragma once

#include <filesystem>

namespace fxport::content {

// A UV sphere of radius 100 centred at the origin: PointLight.World() scales it by radius / 100
// (seed lines 1962-1973).
void WritePointLightGeometry(const std::filesystem::path& dir);

// A cone with its apex at the origin, its axis along -Z, length 1 and base radius 0.5: SpotLight's
// world matrix scales it by (2 tan(FOV / 2) farPlane, same, farPlane) and rotates -Z onto the light
// direction (seed lines 1237-1278), giving a cone of half-angle FOV / 2 reaching the far plane.
void WriteSpotLightGeometry(const std::filesystem::path& dir);

}  // namespace fxport::content
