#include "reference/d3d9_sampling.h"

#include <algorithm>
#include <cmath>

namespace fxport::reference {

namespace {

int address(int i, int n, Address a) {
    if (a == Address::Clamp) return std::clamp(i, 0, n - 1);
    int m = i % n;
    return m < 0 ? m + n : m;
}

// Texel indices a point sample at texel coordinate x (= u * W) may take: floor(x), and the
// neighbour across the nearer edge when x is within kPointBand of it.
int pointCandidates(double x, int out[2]) {
    double f = std::floor(x);
    int i = int(f);
    out[0] = i;
    double fr = x - f;
    if (fr < kPointBand) {
        out[1] = i - 1;
        return 2;
    }
    if (fr > 1 - kPointBand) {
        out[1] = i + 1;
        return 2;
    }
    return 1;
}

double filterRounding(TexelFormat f) {
    // llvmpipe (like D3D9-era hardware) filters 8-bit texels in 8-bit fixed point: measured up to
    // 1.0 LSB from the exact bilinear value even between texels 1-3 LSB apart (a rounding after
    // each of the two lerps). Float and 16-bit texels are filtered in float there.
    return f == TexelFormat::Unorm8 ? 1.0 / 255 : 0.0;
}

V4 masked(V4 v, unsigned used) {
    for (int c = 0; c < 4; ++c)
        if (!(used & (1u << c))) v[c] = 0;
    return v;
}

struct TexelRef {
    int x, y;
};

}  // namespace

std::vector<V4> tex2DPointCandidates(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used) {
    int cx[2], cy[2];
    int nx = pointCandidates(uv.x * t.width, cx), ny = pointCandidates(uv.y * t.height, cy);
    std::vector<TexelRef> cands;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            TexelRef r{address(cx[i], t.width, s.addressU), address(cy[j], t.height, s.addressV)};
            bool dup = false;
            for (const TexelRef& c : cands) dup = dup || (c.x == r.x && c.y == r.y);
            if (!dup) cands.push_back(r);
        }
    std::vector<V4> values;
    V4 tol;
    for (const TexelRef& c : cands) {
        values.push_back(t.at(c.x, c.y));
        V4 tt = t.tolAt(c.x, c.y);
        for (int k = 0; k < 4; ++k) tol[k] = std::max(tol[k], tt[k]);
    }
    V4 moved = ev.read(values[0], masked(tol, used));
    V4 delta = moved - values[0];
    for (V4& v : values) v = v + delta;
    return values;
}

Range4 tex2DPointRange(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used) {
    std::vector<V4> values = tex2DPointCandidates(ev, t, s, uv, used);
    Range4 r = Range4::of(values[0]);
    for (const V4& v : values) r = hull(r, Range4::of(v));
    return r;
}

V4 tex2D(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used) {
    if (s.filter == Filter::Point) {
        std::vector<V4> values = tex2DPointCandidates(ev, t, s, uv, used);
        return values[std::size_t(ev.choose(int(values.size())))];
    }
    double x = uv.x * t.width - 0.5, y = uv.y * t.height - 0.5;
    double fx = std::floor(x), fy = std::floor(y);
    double a = x - fx, b = y - fy;
    int x0 = address(int(fx), t.width, s.addressU), x1 = address(int(fx) + 1, t.width, s.addressU);
    int y0 = address(int(fy), t.height, s.addressV), y1 = address(int(fy) + 1, t.height, s.addressV);
    const V4 &t00 = t.at(x0, y0), &t10 = t.at(x1, y0), &t01 = t.at(x0, y1), &t11 = t.at(x1, y1);
    V4 v = lerp(lerp(t00, t10, a), lerp(t01, t11, a), b);
    V4 u;
    double rounding = filterRounding(t.format);
    V4 tol = t.tolAt(x0, y0) * ((1 - a) * (1 - b)) + t.tolAt(x1, y0) * (a * (1 - b)) + t.tolAt(x0, y1) * ((1 - a) * b) +
             t.tolAt(x1, y1) * (a * b);
    for (int c = 0; c < 4; ++c) {
        if (c >= t.channels || !(used & (1u << c))) continue;  // missing channels read an exact 1
        double dx = std::max(std::fabs(t10[c] - t00[c]), std::fabs(t11[c] - t01[c]));
        double dy = std::max(std::fabs(t01[c] - t00[c]), std::fabs(t11[c] - t10[c]));
        // Texture units quantise bilinear weights (8 fractional bits is the D3D10+ minimum and what
        // GPUs use): up to 1/256 of the texel difference per axis.
        u[c] = (dx + dy) / 256 + rounding + tol[c];
    }
    return ev.read(v, u);
}

CubeAddress cubeAddress(V3 d) {
    double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    int face;
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = d.x >= 0 ? 0 : 1;
        sc = d.x >= 0 ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = d.y >= 0 ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0 ? d.z : -d.z;
        ma = ay;
    } else {
        face = d.z >= 0 ? 4 : 5;
        sc = d.z >= 0 ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}

V3 cubeDirection(int face, double s, double t) {
    double sc = 2 * s - 1, tc = 2 * t - 1;
    switch (face) {
    case 0: return {1, -tc, -sc};
    case 1: return {-1, -tc, sc};
    case 2: return {sc, 1, tc};
    case 3: return {sc, -1, -tc};
    case 4: return {sc, -tc, 1};
    default: return {-sc, -tc, -1};
    }
}

Range4 texCUBEPointRange(Eval& ev, const CpuCube& cube, V3 d) {
    // Candidate faces: every axis whose magnitude ties with the largest (within float rounding).
    double m[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
    double mx = std::max({m[0], m[1], m[2]});
    Range4 r;
    V4 tol;
    bool first = true;
    for (int axis = 0; axis < 3; ++axis) {
        if (m[axis] < mx * (1 - 1e-6)) continue;
        // Address the direction as if this axis were the largest (nudge the others below it).
        V3 dd = d;
        double shrink = 1 - 2e-6;
        if (axis != 0) dd.x *= shrink;
        if (axis != 1) dd.y *= shrink;
        if (axis != 2) dd.z *= shrink;
        CubeAddress a = cubeAddress(dd);
        int cx[2], cy[2];
        int n = cube.size;
        int nx = pointCandidates(a.s * n, cx), ny = pointCandidates(a.t * n, cy);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const CpuTexture& f = cube.faces[std::size_t(a.face)];
                int x = std::clamp(cx[i], 0, n - 1), y = std::clamp(cy[j], 0, n - 1);
                Range4 one = Range4::of(f.at(x, y));
                r = first ? one : hull(r, one);
                V4 tt = f.tolAt(x, y);
                for (int c = 0; c < 4; ++c) tol[c] = std::max(tol[c], tt[c]);
                first = false;
            }
    }
    r.exact = false;
    return ev.read(r, masked(tol, kX));
}

}  // namespace fxport::reference
