// A bounding-volume hierarchy over world-space triangles, in double, for the exact references of
// `fxdemo report` (quality/report): shadow rays (is anything between a surface point and the light?) and light
// volumes (which triangles of a cone or sphere does a pixel's ray cross?). Median split on the
// longest axis of the centroids' box; Moller-Trumbore intersection.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "reference/ref_math.h"

namespace fxport::reference {

using Triangle = std::array<V3, 3>;

class TriangleBvh {
public:
    explicit TriangleBvh(std::vector<Triangle> triangles);

    // True when a triangle meets origin + t * direction for some t in [tMin, tMax].
    bool anyHit(V3 origin, V3 direction, double tMin, double tMax) const;
    // The smallest t in [tMin, tMax] at which a triangle meets the ray; infinity when none does.
    double closestHit(V3 origin, V3 direction, double tMin, double tMax) const;
    // Calls visit(triangle index) for every triangle met for t in [tMin, tMax].
    void forEachHit(V3 origin, V3 direction, double tMin, double tMax, const std::function<void(int)>& visit) const;

    const Triangle& triangle(int i) const { return triangles_[std::size_t(i)]; }
    int size() const { return int(triangles_.size()); }

private:
    struct Node {
        V3 lo, hi;
        int first = 0, count = 0;  // leaf: triangles order_[first .. first + count)
        int left = -1, right = -1;
    };
    int build(int first, int count);
    template <class Visit> bool walk(V3 origin, V3 direction, double tMin, double tMax, Visit&& visit) const;

    std::vector<Triangle> triangles_;
    std::vector<int> order_;
    std::vector<Node> nodes_;
    int used_ = 0;
};

}  // namespace fxport::reference
