#include "helpers/tangent_generation.h"

#include <cmath>
#include <cstddef>

namespace fxport::detail {

namespace {

// Double-precision 3-vectors for the accumulation: UV deltas of small triangles divide by tiny
// determinants, and float sums of many triangles lose the direction of nearly cancelling ones.
struct D3 {
    double x = 0, y = 0, z = 0;
};
D3 toD3(Vector3 v) { return {v.X, v.Y, v.Z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(D3 a) { return std::sqrt(dot(a, a)); }

}  // namespace

Vector3 anyPerpendicular(Vector3 normal) {
    const D3 n = toD3(normal);
    if (length(n) == 0.0) {
        return Vector3::UnitX;
    }
    // Cross with the axis least aligned with the normal: never parallel, never short.
    const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    const D3 axis = (ax <= ay && ax <= az) ? D3{1, 0, 0} : (ay <= az ? D3{0, 1, 0} : D3{0, 0, 1});
    D3 t = cross(n, axis);
    t = t * (1.0 / length(t));
    return {float(t.x), float(t.y), float(t.z)};
}

std::vector<Vector4> generateTangents(std::span<const Vector3> positions, std::span<const Vector3> normals,
                                      std::span<const Vector2> uvs, std::span<const std::uint32_t> indices) {
    const std::size_t count = positions.size();
    std::vector<D3> sumU(count), sumV(count);  // dP/du and dP/dv summed per vertex
    if (uvs.size() == count) {
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
            const std::uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2];
            const D3 e1 = toD3(positions[b]) - toD3(positions[a]);
            const D3 e2 = toD3(positions[c]) - toD3(positions[a]);
            const double du1 = double(uvs[b].X) - uvs[a].X, dv1 = double(uvs[b].Y) - uvs[a].Y;
            const double du2 = double(uvs[c].X) - uvs[a].X, dv2 = double(uvs[c].Y) - uvs[a].Y;
            const double det = du1 * dv2 - du2 * dv1;
            if (!(std::fabs(det) > 1e-20) || length(cross(e1, e2)) == 0.0) {
                continue;
            }
            // e1 = du1 * dPdu + dv1 * dPdv, e2 = du2 * dPdu + dv2 * dPdv, solved for dPdu, dPdv.
            const D3 dPdu = (e1 * dv2 - e2 * dv1) * (1.0 / det);
            const D3 dPdv = (e2 * du1 - e1 * du2) * (1.0 / det);
            for (std::uint32_t v : {a, b, c}) {
                sumU[v] = sumU[v] + dPdu;
                sumV[v] = sumV[v] + dPdv;
            }
        }
    }

    std::vector<Vector4> tangents(count);
    for (std::size_t v = 0; v < count; ++v) {
        const D3 n = v < normals.size() ? toD3(normals[v]) : D3{};
        D3 t = sumU[v] - n * dot(n, sumU[v]);
        const double len = length(t);
        // Relative test: a tangent that is almost all normal carries no direction worth keeping.
        if (!(len > 1e-6 * length(sumU[v])) || len == 0.0 || length(n) == 0.0) {
            const Vector3 p = anyPerpendicular(v < normals.size() ? normals[v] : Vector3::Zero);
            tangents[v] = Vector4(p.X, p.Y, p.Z, 1.0f);
            continue;
        }
        t = t * (1.0 / len);
        // Binormal cross(n, t) * w must point where v decreases, i.e. against dP/dv.
        const double w = dot(cross(n, t), sumV[v]) > 0.0 ? -1.0 : 1.0;
        tangents[v] = Vector4(float(t.x), float(t.y), float(t.z), float(w));
    }
    return tangents;
}

}  // namespace fxport::detail
