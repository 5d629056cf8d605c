#include "mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fxport::content {

namespace {

std::uint32_t Base(const Primitive& p) { return static_cast<std::uint32_t>(p.vertices.size()); }

float Lerp(float a, float b, float t) { return a + (b - a) * t; }

void AddTriangle(Primitive& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    p.indices.insert(p.indices.end(), {a, b, c});
}

// Quad (a, b, c, d) counter-clockwise from the front: two triangles (a, b, c), (a, c, d).
void AddQuad(Primitive& p, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    AddTriangle(p, a, b, c);
    AddTriangle(p, a, c, d);
}

// Angle of column i of `segments` around a circle; the last column (i == segments) gets angle 0
// again, so the duplicated seam vertices have bit-identical positions (no crack, closed volumes).
float SeamAngle(int i, int segments) {
    return 2.0f * kPi * static_cast<float>(i % segments) / static_cast<float>(segments);
}

int Cells(float size, float cellSize) {
    if (cellSize <= 0) return 1;
    return std::max(1, static_cast<int>(std::lround(size / cellSize)));
}

}  // namespace

void AddPatch(Primitive& out, const PatchDesc& d) {
    const Vec3 normal = Cross(d.axisU, d.axisUp);
    const Vec4 tangent{d.axisU.x, d.axisU.y, d.axisU.z, 1.0f};
    const std::uint32_t base = Base(out);
    const int columns = d.cellsU + 1;
    for (int j = 0; j <= d.cellsUp; ++j) {      // j = 0 at the bottom edge
        const float tj = static_cast<float>(j) / static_cast<float>(d.cellsUp);
        for (int i = 0; i <= d.cellsU; ++i) {
            const float ti = static_cast<float>(i) / static_cast<float>(d.cellsU);
            Vertex v;
            v.position = d.center + d.axisU * (d.sizeU * (ti - 0.5f)) + d.axisUp * (d.sizeUp * (tj - 0.5f));
            v.normal = normal;
            v.uv = {Lerp(d.uvTopLeft.x, d.uvBottomRight.x, ti), Lerp(d.uvBottomRight.y, d.uvTopLeft.y, tj)};
            v.tangent = tangent;
            out.vertices.push_back(v);
        }
    }
    for (int j = 0; j < d.cellsUp; ++j) {
        for (int i = 0; i < d.cellsU; ++i) {
            const auto at = [&](int ii, int jj) { return base + static_cast<std::uint32_t>(jj * columns + ii); };
            AddQuad(out, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
}

void AddBox(Primitive& out, const BoxDesc& d) {
    struct Face {
        Vec3 normal, axisU, axisUp;
        float sizeU, sizeUp, depth;
    };
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const Vec3 s = d.size;
    const Face faces[6] = {
        {z, x, y, s.x, s.y, s.z},     // +Z
        {-z, -x, y, s.x, s.y, s.z},   // -Z
        {x, -z, y, s.z, s.y, s.x},    // +X
        {-x, z, y, s.z, s.y, s.x},    // -X
        {y, x, -z, s.x, s.z, s.y},    // +Y (top)
        {-y, x, z, s.x, s.z, s.y},    // -Y (bottom)
    };
    for (const Face& f : faces) {
        PatchDesc p;
        p.center = d.center + f.normal * (0.5f * f.depth);
        p.axisU = f.axisU;
        p.axisUp = f.axisUp;
        p.sizeU = f.sizeU;
        p.sizeUp = f.sizeUp;
        p.cellsU = Cells(f.sizeU, d.cellSize);
        p.cellsUp = Cells(f.sizeUp, d.cellSize);
        if (d.unitsPerRepeat > 0) {
            p.uvBottomRight = {f.sizeU / d.unitsPerRepeat, f.sizeUp / d.unitsPerRepeat};
        }
        AddPatch(out, p);
    }
}

void AddCylinderSide(Primitive& out, const CylinderDesc& d) {
    const std::uint32_t base = Base(out);
    const int columns = d.segments + 1;  // the seam column is duplicated (u = 0 and u = uRepeats)
    for (int j = 0; j <= d.rings; ++j) {
        const float h = d.height * static_cast<float>(j) / static_cast<float>(d.rings);
        for (int i = 0; i <= d.segments; ++i) {
            const float t = static_cast<float>(i) / static_cast<float>(d.segments);
            const float theta = SeamAngle(i, d.segments);
            const Vec3 n{std::sin(theta), 0.0f, std::cos(theta)};
            Vertex v;
            v.position = d.base + n * d.radius + Vec3{0, h, 0};
            v.normal = n;
            v.uv = {d.uRepeats * t, (d.height - h) / d.unitsPerRepeatV};
            // d(position)/d(theta) direction; cross(n, tangent) = +Y = towards decreasing v.
            v.tangent = {std::cos(theta), 0.0f, -std::sin(theta), 1.0f};
            out.vertices.push_back(v);
        }
    }
    for (int j = 0; j < d.rings; ++j) {
        for (int i = 0; i < d.segments; ++i) {
            const auto at = [&](int ii, int jj) { return base + static_cast<std::uint32_t>(jj * columns + ii); };
            AddQuad(out, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
}

void AddUvSphere(Primitive& out, const SphereDesc& d) {
    const std::uint32_t base = Base(out);
    const int columns = d.segments + 1;
    for (int j = 0; j <= d.rings; ++j) {  // j = 0 at the south pole
        const float tj = static_cast<float>(j) / static_cast<float>(d.rings);
        const float phi = kPi * (tj - 0.5f);
        for (int i = 0; i <= d.segments; ++i) {
            const float ti = static_cast<float>(i) / static_cast<float>(d.segments);
            const float theta = SeamAngle(i, d.segments);
            // Exact pole normals, so that poles of different rings meet in one point.
            const float cosPhi = (j == 0 || j == d.rings) ? 0.0f : std::cos(phi);
            const float sinPhi = (j == 0) ? -1.0f : (j == d.rings ? 1.0f : std::sin(phi));
            const Vec3 n{cosPhi * std::sin(theta), sinPhi, cosPhi * std::cos(theta)};
            Vertex v;
            v.position = d.center + n * d.radius;
            v.normal = n;
            v.uv = {d.uRepeats * ti, d.vRepeats * (1.0f - tj)};
            // Towards increasing theta; defined at the poles too. cross(n, t) = d(n)/d(phi) = up.
            v.tangent = {std::cos(theta), 0.0f, -std::sin(theta), 1.0f};
            out.vertices.push_back(v);
        }
    }
    for (int j = 0; j < d.rings; ++j) {
        for (int i = 0; i < d.segments; ++i) {
            const auto at = [&](int ii, int jj) { return base + static_cast<std::uint32_t>(jj * columns + ii); };
            // Skip the triangle that would collapse onto a pole.
            if (j != 0) AddTriangle(out, at(i, j), at(i + 1, j), at(i + 1, j + 1));
            if (j != d.rings - 1) AddTriangle(out, at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
}

void AddLightCone(Primitive& out, int segments, float baseRadius) {
    const std::uint32_t base = Base(out);
    // Side: per segment an apex vertex (normal at the segment's middle angle) and the base ring.
    // On the surface r = -z * baseRadius the outward normal is (cos, sin, baseRadius) normalised.
    for (int i = 0; i <= segments; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(segments);
        const float theta = SeamAngle(i, segments);
        Vertex ring;
        ring.position = {baseRadius * std::cos(theta), baseRadius * std::sin(theta), -1.0f};
        ring.normal = Normalize(Vec3{std::cos(theta), std::sin(theta), baseRadius});
        ring.uv = {t, 1.0f};
        out.vertices.push_back(ring);
    }
    const std::uint32_t apexBase = Base(out);
    for (int i = 0; i < segments; ++i) {
        const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(segments);
        const float theta = 2.0f * kPi * t;
        Vertex apex;
        apex.position = {0.0f, 0.0f, 0.0f};
        apex.normal = Normalize(Vec3{std::cos(theta), std::sin(theta), baseRadius});
        apex.uv = {t, 0.0f};
        out.vertices.push_back(apex);
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t ui = static_cast<std::uint32_t>(i);
        AddTriangle(out, apexBase + ui, base + ui, base + ui + 1);
    }
    // Base cap, facing -Z: a fan around the centre.
    const std::uint32_t capBase = Base(out);
    Vertex centre;
    centre.position = {0.0f, 0.0f, -1.0f};
    centre.normal = {0.0f, 0.0f, -1.0f};
    centre.uv = {0.5f, 0.5f};
    out.vertices.push_back(centre);
    for (int i = 0; i < segments; ++i) {
        const float theta = SeamAngle(i, segments);
        Vertex rim;
        rim.position = {baseRadius * std::cos(theta), baseRadius * std::sin(theta), -1.0f};
        rim.normal = {0.0f, 0.0f, -1.0f};
        rim.uv = {0.5f + 0.5f * std::cos(theta), 0.5f - 0.5f * std::sin(theta)};
        out.vertices.push_back(rim);
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t a = capBase + 1 + static_cast<std::uint32_t>(i);
        const std::uint32_t b = capBase + 1 + static_cast<std::uint32_t>((i + 1) % segments);
        AddTriangle(out, capBase, b, a);
    }
}

}  // namespace fxport::content
