// Tangent frames for meshes that come without them (internal to fxport_graphics; used by the glTF
// loader, tested directly by tests/runtime/model_test.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fxport/math.h"

namespace fxport::detail {

// Per-vertex tangents of an indexed triangle list, glTF style: xyz = the unit tangent, orthogonal to
// the vertex normal and pointing towards increasing u; w = +1 or -1, the handedness, chosen so that
// cross(normal, xyz) * w points towards decreasing v (the top of the image: glTF's normal-map +Y).
//
// Method (Lengyel): for each triangle, dP/du and dP/dv solved from its edges and UV deltas, summed
// into its three vertices; then per vertex Gram-Schmidt against the normal. Triangles whose UVs are
// degenerate (zero area in UV space) or whose positions coincide contribute nothing. A vertex left
// without a usable direction (no UVs, all its triangles degenerate, or a zero normal) gets an
// arbitrary unit tangent orthogonal to its normal (w = +1), so the frame is never NaN.
//
// `normals` must be unit length (or zero); `indices` must be < positions.size() and a multiple of 3.
std::vector<Vector4> generateTangents(std::span<const Vector3> positions, std::span<const Vector3> normals,
                                      std::span<const Vector2> uvs, std::span<const std::uint32_t> indices);

// A unit vector orthogonal to `normal` (any unit vector when normal is zero).
Vector3 anyPerpendicular(Vector3 normal);

}  // namespace fxport::detail
