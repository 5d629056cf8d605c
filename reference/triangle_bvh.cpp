#include "reference/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fxport::reference {


namespace {

constexpr int kLeafSize = 4;

V3 minOf(V3 a, V3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
V3 maxOf(V3 a, V3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
double axis(V3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

// Slab test: does the segment [tMin, tMax] of the ray meet the box?
bool hitsBox(V3 lo, V3 hi, V3 origin, V3 inverseDirection, double tMin, double tMax) {
    for (int k = 0; k < 3; ++k) {
        double t0 = (axis(lo, k) - axis(origin, k)) * axis(inverseDirection, k);
        double t1 = (axis(hi, k) - axis(origin, k)) * axis(inverseDirection, k);
        if (std::isnan(t0) || std::isnan(t1)) {  // direction 0 on this axis and origin on a face
            if (axis(origin, k) < axis(lo, k) || axis(origin, k) > axis(hi, k)) return false;
            continue;
        }
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

// Moller-Trumbore; true with the ray parameter t when the ray meets the triangle (edges included).
bool intersect(const Triangle& tri, V3 origin, V3 direction, double& t) {
    const V3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const V3 p = cross(direction, e2);
    const double det = dot(e1, p);
    if (det == 0) return false;
    const double inv = 1 / det;
    const V3 s = origin - tri[0];
    const double u = dot(s, p) * inv;
    if (u < 0 || u > 1) return false;
    const V3 q = cross(s, e1);
    const double v = dot(direction, q) * inv;
    if (v < 0 || u + v > 1) return false;
    t = dot(e2, q) * inv;
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
    order_.reserve(triangles_.size());
    for (std::size_t i = 0; i < triangles_.size(); ++i) order_.push_back(int(i));
    // A binary tree with at most one leaf per triangle has fewer than 2n nodes.
    nodes_.resize(2 * triangles_.size() + 1);
    if (!triangles_.empty()) build(0, int(triangles_.size()));
    nodes_.resize(std::size_t(used_));
}

int TriangleBvh::build(int first, int count) {
    Node node;
    const double inf = std::numeric_limits<double>::infinity();
    node.lo = {inf, inf, inf};
    node.hi = {-inf, -inf, -inf};
    V3 clo = node.lo, chi = node.hi;
    for (int i = first; i < first + count; ++i) {
        const Triangle& t = triangles_[std::size_t(order_[std::size_t(i)])];
        for (const V3& v : t) node.lo = minOf(node.lo, v), node.hi = maxOf(node.hi, v);
        const V3 c = (t[0] + t[1] + t[2]) / 3.0;
        clo = minOf(clo, c), chi = maxOf(chi, c);
    }
    const int index = used_++;
    nodes_[std::size_t(index)] = node;
    if (count <= kLeafSize) {
        nodes_[std::size_t(index)].first = first;
        nodes_[std::size_t(index)].count = count;
        return index;
    }
    const V3 extent = chi - clo;
    const int k = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    auto centre = [&](int tri) {
        const Triangle& t = triangles_[std::size_t(tri)];
        return axis(t[0], k) + axis(t[1], k) + axis(t[2], k);
    };
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int a, int b) { return centre(a) < centre(b); });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[std::size_t(index)].left = left;
    nodes_[std::size_t(index)].right = right;
    return index;
}

template <class Visit>
bool TriangleBvh::walk(V3 origin, V3 direction, double tMin, double tMax, Visit&& visit) const {
    if (used_ == 0) return false;
    const V3 inverse{1 / direction.x, 1 / direction.y, 1 / direction.z};
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[std::size_t(stack[--top])];
        if (!hitsBox(n.lo, n.hi, origin, inverse, tMin, tMax)) continue;
        if (n.left < 0) {
            for (int i = n.first; i < n.first + n.count; ++i) {
                const int tri = order_[std::size_t(i)];
                double t = 0;
                if (intersect(triangles_[std::size_t(tri)], origin, direction, t) && t >= tMin && t <= tMax && visit(tri, t))
                    return true;
            }
        } else {
            stack[top++] = n.left;
            stack[top++] = n.right;
        }
    }
    return false;
}

bool TriangleBvh::anyHit(V3 origin, V3 direction, double tMin, double tMax) const {
    return walk(origin, direction, tMin, tMax, [&](int, double) { return true; });
}

double TriangleBvh::closestHit(V3 origin, V3 direction, double tMin, double tMax) const {
    double closest = std::numeric_limits<double>::infinity();
    walk(origin, direction, tMin, tMax, [&](int, double t) {
        closest = std::min(closest, t);
        return false;
    });
    return closest;
}

void TriangleBvh::forEachHit(V3 origin, V3 direction, double tMin, double tMax, const std::function<void(int)>& visit) const {
    walk(origin, direction, tMin, tMax, [&](int tri, double) {
        visit(tri);
        return false;
    });
}

}  // namespace fxport::reference
