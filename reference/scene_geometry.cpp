#include "reference/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/deterministic_random.h"

namespace fxport::reference {

namespace {

// Adds triangle (i0, i1, i2), swapped if needed so that it is clockwise seen from `outward`.
void addTriangle(Mesh& m, int i0, int i1, int i2, V3 outward) {
    const V3 &a = m.vertices[std::size_t(i0)].position, &b = m.vertices[std::size_t(i1)].position,
             &c = m.vertices[std::size_t(i2)].position;
    if (dot(cross(c - a, b - a), outward) >= 0) m.triangles.push_back({i0, i1, i2});
    else m.triangles.push_back({i0, i2, i1});
}

V3 randomUnit(Random& r) {
    for (;;) {
        V3 v{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        double l = length(v);
        if (l > 0.1 && l <= 1) return v / l;
    }
}

// A quad from corner p0 along eu (increasing u) and ev (increasing v), facing `outward`.
void addQuad(Mesh& m, Random& rnd, V3 p0, V3 eu, V3 ev, V3 outward, V2 uvScale) {
    int base = int(m.vertices.size());
    V3 corners[4] = {p0, p0 + eu, p0 + eu + ev, p0 + ev};
    V2 uvs[4] = {{0, 0}, {uvScale.x, 0}, {uvScale.x, uvScale.y}, {0, uvScale.y}};
    for (int k = 0; k < 4; ++k) {
        MeshVertex v;
        v.position = corners[k];
        v.uv = uvs[k];
        v.tangent = normalize(eu);
        v.binormal = -normalize(ev);  // towards decreasing v, the top of the image (content/README.md)
        v.normal = normalize(outward + randomUnit(rnd) * 0.12);
        m.vertices.push_back(v);
    }
    addTriangle(m, base, base + 1, base + 2, outward);
    addTriangle(m, base, base + 2, base + 3, outward);
}

void addBox(Mesh& m, Random& rnd, V3 c, V3 h, double angle) {
    V3 ax{std::cos(angle), 0, -std::sin(angle)}, ay{0, 1, 0}, az{std::sin(angle), 0, std::cos(angle)};
    struct Face {
        V3 n, eu, ev;
        double depth;
    };
    Face faces[5] = {
        {ax, az * (-2 * h.z), ay * (-2 * h.y), h.x},  {ax * -1, az * (2 * h.z), ay * (-2 * h.y), h.x},
        {az, ax * (2 * h.x), ay * (-2 * h.y), h.z},   {az * -1, ax * (-2 * h.x), ay * (-2 * h.y), h.z},
        {ay, ax * (2 * h.x), az * (2 * h.z), h.y},
    };
    for (const Face& f : faces) {
        V3 centre = c + f.n * f.depth;
        V3 p0 = centre - f.eu * 0.5 - f.ev * 0.5;
        addQuad(m, rnd, p0, f.eu, f.ev, f.n, {length(f.eu) * 0.45, length(f.ev) * 0.45});
    }
}

}  // namespace

Mesh makeTestScene() {
    Mesh m;
    Random rnd(0x5CE7E);
    addQuad(m, rnd, {-12, 0, -10}, {24, 0, 0}, {0, 0, 24}, {0, 1, 0}, {7.2, 7.2});   // floor
    addQuad(m, rnd, {-12, 7, -10}, {24, 0, 0}, {0, -7, 0}, {0, 0, 1}, {7.2, 2.1});   // back wall
    addBox(m, rnd, {2.5, 1.0, -1.0}, {1.0, 1.25, 1.0}, 0.0);
    addBox(m, rnd, {-3.0, 0.9, 2.0}, {1.2, 1.2, 0.8}, 0.61);
    addBox(m, rnd, {-1.0, 2.5, -5.0}, {0.5, 2.75, 0.5}, 0.3);  // a pillar
    return m;
}

Mesh makeSphere(double radius, int rings, int segments) {
    Mesh m;
    auto add = [&](V3 p) {
        MeshVertex v;
        v.position = p;
        v.normal = normalize(p);
        m.vertices.push_back(v);
        return int(m.vertices.size()) - 1;
    };
    int top = add({0, radius, 0});
    std::vector<std::vector<int>> ring(std::size_t(rings - 1));
    for (int r = 1; r < rings; ++r) {
        double phi = std::numbers::pi * r / rings;
        for (int s = 0; s < segments; ++s) {
            double theta = 2 * std::numbers::pi * s / segments;
            ring[std::size_t(r - 1)].push_back(
                add({radius * std::sin(phi) * std::cos(theta), radius * std::cos(phi), radius * std::sin(phi) * std::sin(theta)}));
        }
    }
    int bottom = add({0, -radius, 0});
    auto centroid = [&](int a, int b, int c) {
        return (m.vertices[std::size_t(a)].position + m.vertices[std::size_t(b)].position + m.vertices[std::size_t(c)].position) / 3;
    };
    for (int s = 0; s < segments; ++s) {
        int s1 = (s + 1) % segments;
        const std::vector<int>& first = ring.front();
        const std::vector<int>& last = ring.back();
        int a = first[std::size_t(s)], b = first[std::size_t(s1)];
        addTriangle(m, top, a, b, centroid(top, a, b));
        a = last[std::size_t(s)];
        b = last[std::size_t(s1)];
        addTriangle(m, bottom, a, b, centroid(bottom, a, b));
        for (int r = 0; r + 1 < rings - 1; ++r) {
            int p = ring[std::size_t(r)][std::size_t(s)], q = ring[std::size_t(r)][std::size_t(s1)];
            int u = ring[std::size_t(r + 1)][std::size_t(s)], w = ring[std::size_t(r + 1)][std::size_t(s1)];
            addTriangle(m, p, q, w, centroid(p, q, w));
            addTriangle(m, p, w, u, centroid(p, w, u));
        }
    }
    return m;
}

Mesh makeCone(int segments) {
    Mesh m;
    auto add = [&](V3 p) {
        MeshVertex v;
        v.position = p;
        m.vertices.push_back(v);
        return int(m.vertices.size()) - 1;
    };
    int apex = add({0, 0, 0});
    int centre = add({0, 0, -1});
    std::vector<int> rim;
    for (int s = 0; s < segments; ++s) {
        double theta = 2 * std::numbers::pi * s / segments;
        rim.push_back(add({0.5 * std::cos(theta), 0.5 * std::sin(theta), -1}));
    }
    const V3 inside{0, 0, -0.7};
    for (int s = 0; s < segments; ++s) {
        int a = rim[std::size_t(s)], b = rim[std::size_t((s + 1) % segments)];
        V3 c = (m.vertices[std::size_t(a)].position + m.vertices[std::size_t(b)].position) / 3;
        addTriangle(m, apex, a, b, c - inside);
        addTriangle(m, centre, a, b, {0, 0, -1});
    }
    return m;
}

void roundToFloat(Mesh& mesh) {
    auto r = [](double& v) { v = double(float(v)); };
    for (MeshVertex& v : mesh.vertices) {
        for (V3* p : {&v.position, &v.normal, &v.tangent, &v.binormal}) {
            r(p->x);
            r(p->y);
            r(p->z);
        }
        r(v.uv.x);
        r(v.uv.y);
    }
}

WorldMesh toWorld(const Mesh& mesh, const M4& world) {
    WorldMesh w;
    w.triangles = mesh.triangles;
    for (const MeshVertex& v : mesh.vertices) {
        V4 p = mul(point(v.position), world);
        w.positions.push_back(p.xyz() / p.w);
    }
    return w;
}

View3D makeView(const M4& view, const M4& projection, int width, int height) {
    View3D v;
    v.view = view;
    v.projection = projection;
    v.viewProjection = view * projection;
    v.inverseViewProjection = inverse(v.viewProjection);
    V4 e = mul(V4{0, 0, 0, 1}, inverse(view));
    v.eye = e.xyz() / e.w;
    v.width = width;
    v.height = height;
    return v;
}

V2 pixelNdc(int x, int y, int width, int height, V2 shift) {
    return {2 * (x + kPixelBiasX + shift.x) / width - 1, 1 - 2 * (y + kPixelBiasY + shift.y) / height};
}

Ray ndcRay(const View3D& v, V2 ndc) {
    V4 n = mul(V4{ndc.x, ndc.y, 0, 1}, v.inverseViewProjection);
    V4 f = mul(V4{ndc.x, ndc.y, 1, 1}, v.inverseViewProjection);
    V3 a = n.xyz() / n.w, b = f.xyz() / f.w;
    return {a, b - a};
}

namespace {

// Moller-Trumbore: ray parameter and barycentrics (u, v) of triangle (a, b, c), unbounded.
bool intersect(V3 a, V3 b, V3 c, const Ray& ray, double& t, double& u, double& v) {
    V3 e1 = b - a, e2 = c - a;
    V3 p = cross(ray.direction, e2);
    double det = dot(e1, p);
    if (std::fabs(det) < 1e-300) return false;
    V3 s = ray.origin - a;
    u = dot(s, p) / det;
    V3 q = cross(s, e1);
    v = dot(ray.direction, q) / det;
    t = dot(e2, q) / det;
    return true;
}

bool kept(const WorldMesh& m, int tri, V3 eye, Cull cull) {
    if (cull == Cull::None) return true;
    const auto& t = m.triangles[std::size_t(tri)];
    V3 a = m.positions[std::size_t(t[0])], b = m.positions[std::size_t(t[1])], c = m.positions[std::size_t(t[2])];
    bool clockwise = dot(cross(c - a, b - a), eye - a) > 0;
    return cull == Cull::CounterClockwiseFace ? clockwise : !clockwise;
}

struct Hit {
    int tri;
    double ndcZ;
};

std::vector<Hit> hits(const WorldMesh& m, const View3D& v, Cull cull, const Ray& ray) {
    std::vector<Hit> out;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        if (!kept(m, int(i), v.eye, cull)) continue;
        const auto& t = m.triangles[i];
        double tt, u, w;
        if (!intersect(m.positions[std::size_t(t[0])], m.positions[std::size_t(t[1])], m.positions[std::size_t(t[2])], ray, tt,
                       u, w))
            continue;
        if (u < 0 || w < 0 || u + w > 1 || tt < 0 || tt > 1) continue;
        V4 clip = mul(point(ray.origin + ray.direction * tt), v.viewProjection);
        out.push_back({int(i), clip.z / clip.w});
    }
    return out;
}

const V2 kProbe[9] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
constexpr double kProbeDistance = 1.0 / 128;
// Depths closer than this (NDC) may resolve either way in a 24-bit depth buffer.
constexpr double kDepthTie = 4.0 / (1 << 24);

void addUnique(std::vector<int>& v, int x) {
    if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

}  // namespace

V3 planeBarycentrics(const WorldMesh& m, int tri, const Ray& ray) {
    const auto& t = m.triangles[std::size_t(tri)];
    double tt = 0, u = 0, w = 0;
    intersect(m.positions[std::size_t(t[0])], m.positions[std::size_t(t[1])], m.positions[std::size_t(t[2])], ray, tt, u, w);
    return {1 - u - w, u, w};
}

double nearestDistance(const WorldMesh& m, V3 origin, V3 dir, V3 eye, Cull cull, int* triangle) {
    double best = -1;
    int bestTri = -1;
    Ray ray{origin, dir};
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        if (!kept(m, int(i), eye, cull)) continue;
        const auto& t = m.triangles[i];
        double tt, u, w;
        if (!intersect(m.positions[std::size_t(t[0])], m.positions[std::size_t(t[1])], m.positions[std::size_t(t[2])], ray, tt,
                       u, w))
            continue;
        if (u < 0 || w < 0 || u + w > 1 || tt <= 0) continue;
        if (best < 0 || tt < best) {
            best = tt;
            bestTri = int(i);
        }
    }
    if (triangle) *triangle = bestTri;
    return best;
}

std::vector<int> visibleCandidates(const WorldMesh& m, const View3D& v, Cull cull, int x, int y) {
    std::vector<int> out;
    for (int k = 0; k < 9; ++k) {
        Ray ray = ndcRay(v, pixelNdc(x, y, v.width, v.height, kProbe[k] * kProbeDistance));
        std::vector<Hit> h = hits(m, v, cull, ray);
        if (h.empty()) {
            addUnique(out, -1);
            continue;
        }
        auto nearest = std::min_element(h.begin(), h.end(), [](const Hit& a, const Hit& b) { return a.ndcZ < b.ndcZ; });
        addUnique(out, nearest->tri);
        if (k == 0)
            for (const Hit& o : h)
                if (o.ndcZ - nearest->ndcZ < kDepthTie) addUnique(out, o.tri);
    }
    return out;
}

std::vector<int> coverageCandidates(const WorldMesh& m, const View3D& v, Cull cull, int x, int y) {
    std::vector<int> out;
    for (int k = 0; k < 9; ++k) {
        Ray ray = ndcRay(v, pixelNdc(x, y, v.width, v.height, kProbe[k] * kProbeDistance));
        addUnique(out, int(hits(m, v, cull, ray).size()));
    }
    return out;
}

}  // namespace fxport::reference
