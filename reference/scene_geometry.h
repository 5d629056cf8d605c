// Geometry of the render tests: the meshes drawn (a small scene of floor, wall and boxes; the light
// volumes), and the CPU side of rasterisation: which triangle D3D9 shows at a pixel, found by
// casting the ray through the pixel's D3D9 sample point.
//
// Pixel (i, j) of a W x H target samples D3D9 screen position (i, j) (pixel centres on integers,
// NDC -1 at screen -0.5), which fxport moves by +1/256 pixel down the rows and not at all across
// the columns (docs/DESIGN.md, "D3D9 pixel centres"; pinned by
// Conventions.HalfPixelAndOrientationUnderShaderModel3: UV = (i + [0,1/256])/W).
// So the reference samples NDC (2i/W - 1, 1 - 2(j + 1/256)/H).
//
// Culling follows XNA: a triangle is clockwise as seen when (c-a) x (b-a) points at the eye;
// CullCounterClockwiseFace (the default) keeps those, CullClockwiseFace keeps the others.
#pragma once

#include <array>
#include <vector>

#include "reference/ref_math.h"

namespace fxport::reference {

inline constexpr double kPixelBiasX = 0;          // across the columns
inline constexpr double kPixelBiasY = 1.0 / 256;  // down the rows

struct MeshVertex {
    V3 position, normal;
    V2 uv;
    V3 tangent, binormal;
};
struct Mesh {
    std::vector<MeshVertex> vertices;
    std::vector<std::array<int, 3>> triangles;
};

// Floor (y = 0), back wall, three boxes sunk slightly into the floor; tiled UVs, tangent frames as
// content/README.md describes them, vertex normals tilted a little so that interpolation matters.
Mesh makeTestScene();
// The light volumes as content/ makes them: a sphere of radius 100; a cone with its apex at the
// origin, axis -Z, length 1, base radius 0.5, closed by its base. Outward faces clockwise.
Mesh makeSphere(double radius, int rings, int segments);
Mesh makeCone(int segments);

// Rounds every attribute to float: what the vertex buffer holds, so that the GPU and the
// reference start from the same numbers.
void roundToFloat(Mesh& mesh);

enum class Cull { None, ClockwiseFace, CounterClockwiseFace };

struct WorldMesh {
    std::vector<V3> positions;
    std::vector<std::array<int, 3>> triangles;
};
WorldMesh toWorld(const Mesh& mesh, const M4& world);

// A perspective view as the GPU receives it.
struct View3D {
    M4 view, projection, viewProjection, inverseViewProjection;
    V3 eye;
    int width = 0, height = 0;
};
View3D makeView(const M4& view, const M4& projection, int width, int height);

// NDC of pixel (x, y)'s sample point, moved by `shift` pixels.
V2 pixelNdc(int x, int y, int width, int height, V2 shift = {});

struct Ray {
    V3 origin, direction;  // from the near plane (t = 0) to the far plane (t = 1)
};
Ray ndcRay(const View3D& v, V2 ndc);

// Barycentric coordinates of the point where `ray` meets the plane of triangle `tri`.
V3 planeBarycentrics(const WorldMesh& m, int tri, const Ray& ray);

// Distance along the unit direction `dir` from `origin` to the nearest kept triangle (seen from
// `eye`), or -1: for building plausible synthetic inputs (shadow maps, G-buffers).
double nearestDistance(const WorldMesh& m, V3 origin, V3 dir, V3 eye, Cull cull, int* triangle = nullptr);

// Candidate triangles D3D9 may show at pixel (x, y) with a LessEqual depth test: the nearest kept
// triangle at the sample point and at points 1/128 pixel around it (snapping and the top-left rule
// decide between them), and triangles within depth rounding of the nearest. -1 = none. The first
// entry is the exact-arithmetic answer.
std::vector<int> visibleCandidates(const WorldMesh& m, const View3D& v, Cull cull, int x, int y);
// How many kept triangles cover the pixel (light volumes drawn without depth writes), with the same
// candidates as above.
std::vector<int> coverageCandidates(const WorldMesh& m, const View3D& v, Cull cull, int x, int y);

}  // namespace fxport::reference
