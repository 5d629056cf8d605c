// The CPU rasteriser of the stock-effect and Model tests (see cpu_raster.h).
#include "cpu_raster.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "reference/ref_math.h"

namespace fxport::stock_test {

// reference/ref_math.h's Gauss-Jordan inverse (the same row-major double layout).
DMat inverse(const DMat& a) {
    reference::M4 m;
    std::copy(&a.m[0][0], &a.m[0][0] + 16, &m.m[0][0]);
    const reference::M4 inv = reference::inverse(m);
    DMat r;
    std::copy(&inv.m[0][0], &inv.m[0][0] + 16, &r.m[0][0]);
    return r;
}

DMat transpose(const DMat& a) {
    DMat r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

namespace {

struct ScreenTriangle {
    double x[3], y[3];  // screen position, y down
    double z[3];        // NDC depth
    double invW[3];
    double area;        // > 0: clockwise on screen
    std::uint32_t index[3];
    int surface;
};

struct Hit {
    int triangle = -1;
    double depth = std::numeric_limits<double>::infinity();
    double l[3] = {};  // screen-space barycentrics
};

// Front-most front-facing triangle at screen point (px, py).
Hit hitAt(const std::vector<ScreenTriangle>& triangles, double px, double py) {
    Hit best;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const ScreenTriangle& s = triangles[t];
        double l[3];
        for (int k = 0; k < 3; ++k) {
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            l[k] = ((s.x[b] - s.x[a]) * (py - s.y[a]) - (s.y[b] - s.y[a]) * (px - s.x[a])) / s.area;
        }
        if (l[0] < 0 || l[1] < 0 || l[2] < 0) continue;
        const double depth = l[0] * s.z[0] + l[1] * s.z[1] + l[2] * s.z[2];
        if (depth < best.depth) {
            best.triangle = int(t);
            best.depth = depth;
            std::copy(l, l + 3, best.l);
        }
    }
    return best;
}

}  // namespace

std::vector<RasterPixel> rasterize(int width, int height, const std::vector<RasterVertex>& vertices,
                                   const std::vector<std::uint32_t>& indices, const std::vector<int>& surface) {
    std::vector<ScreenTriangle> triangles;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        ScreenTriangle s{};
        for (int k = 0; k < 3; ++k) {
            const RasterVertex& v = vertices[indices[t + std::size_t(k)]];
            s.index[k] = indices[t + std::size_t(k)];
            s.invW[k] = 1.0 / v.clip.w;
            s.x[k] = (v.clip.x * s.invW[k] + 1) * 0.5 * width;
            s.y[k] = (1 - v.clip.y * s.invW[k]) * 0.5 * height;
            s.z[k] = v.clip.z * s.invW[k];
        }
        s.area = (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
        if (s.area <= 0) continue;  // counter-clockwise (culled) or degenerate
        s.surface = surface.empty() ? 0 : surface[t / 3];
        triangles.push_back(s);
    }

    std::vector<RasterPixel> out(std::size_t(width) * std::size_t(height));
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            RasterPixel& pixel = out[std::size_t(j) * std::size_t(width) + std::size_t(i)];
            const Hit centre = hitAt(triangles, i, j);
            const int centreSurface = centre.triangle < 0 ? -1 : triangles[std::size_t(centre.triangle)].surface;
            bool same = true;
            for (int dy = -1; dy <= 1 && same; ++dy)
                for (int dx = -1; dx <= 1 && same; ++dx) {
                    if (dx == 0 && dy == 0) continue;
                    const Hit h = hitAt(triangles, i + dx, j + dy);
                    same = (h.triangle < 0 ? -1 : triangles[std::size_t(h.triangle)].surface) == centreSurface;
                }
            if (!same) {
                pixel.kind = PixelKind::Unsure;
                continue;
            }
            if (centre.triangle < 0) continue;  // background
            const ScreenTriangle& s = triangles[std::size_t(centre.triangle)];
            double w[3], sum = 0;
            for (int k = 0; k < 3; ++k) sum += w[k] = centre.l[k] * s.invW[k];
            const std::size_t count = vertices[s.index[0]].varyings.size();
            pixel.varyings.assign(count, 0.0);
            for (int k = 0; k < 3; ++k) {
                const std::vector<double>& v = vertices[s.index[k]].varyings;
                for (std::size_t c = 0; c < count; ++c) pixel.varyings[c] += v[c] * w[k] / sum;
            }
            pixel.kind = PixelKind::Covered;
            pixel.surface = centreSurface;
        }
    }
    return out;
}

}  // namespace fxport::stock_test
