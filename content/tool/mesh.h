// Triangle meshes as the glTF writer stores them: one glTF mesh per Mesh, one primitive per
// Primitive. Conventions (glTF 2.0, right-handed, +Y up, same axes and units as XNA):
//   * triangles are counter-clockwise seen from the side the normal points to (glTF front faces);
//   * uv (0, 0) is the top-left of the image, v grows downwards (glTF = D3D/XNA);
//   * tangent.xyz points towards increasing u, tangent.w = +1 or -1 such that
//     cross(normal, tangent.xyz) * w points towards decreasing v (the top of the image), the
//     direction normal maps encode as +Y (green up).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vec.h"

namespace fxport::content {

struct Vertex {
    Vec3 position;
    Vec3 normal;
    Vec2 uv;
    Vec4 tangent;
};

struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list
    int material = -1;                   // glTF material index; -1 = none
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    bool writeTangents = true;  // false for the light volumes, which only need positions
};

}  // namespace fxport::content
