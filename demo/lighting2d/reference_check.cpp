#include "lighting2d/reference_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "reference/ref_image.h"

namespace _2DLightingSystem {

namespace {

const double kPI = 3.14159265;         // the effects' #define PI
// texCoord at pixel (x, y) of a w-wide destination is (x + kBiasX) / w: XNA 4's SpriteBatch matrix moves
// sprites by -0.5 pixel (so that on D3D9, whose pixel centres are at integer positions, texel centres
// land on pixel centres: +0.5), and the runtime's D3D9 pixel-centre emulation adds +1/256 pixel down
// the rows (kBiasY), nothing across.
const double kBiasX = 0.5;
const double kBiasY = 0.5 + 1.0 / 256.0;
const double kEdge = 1e-3;             // a sample this close to a texel edge may go either way
// RGBA16F: 10 mantissa bits. GL leaves the rounding of float -> half conversion on render target
// writes to the implementation (llvmpipe rounds towards zero), so one ulp: |error| <= 2^-10 |v|.
// The light maps' occlusion U comes from acos, which GPUs approximate: fxc expands HLSL acos for
// SM2 into a polynomial (Abramowitz & Stegun 4.4.45 form, |error| <= ~7e-5 rad) and Mesa lowers
// GLSL acos to a polynomial of similar accuracy (llvmpipe here: observed >= 4e-5 rad); GLSL itself
// only promises atan's 4096 ulp. So near an occlusion texel edge, within 1e-4 rad of the ray angle,
// either texel is accepted.
const double kAcosTol = 1e-4;
const double kHalfRel = 1.0 / 1024.0;

double halfToDouble(std::uint16_t h) {
    const int s = h >> 15, e = (h >> 10) & 31, m = h & 1023;
    double v;
    if (e == 0) v = std::ldexp(double(m), -24);
    else if (e == 31) v = m ? NAN : INFINITY;
    else v = std::ldexp(double(m | 1024), e - 25);
    return s ? -v : v;
}

// Point sampling with clamp: the texel(s) a coordinate in texels selects (two near an edge).
struct Pick {
    int a, b;
};
Pick pick(double p, int n, double window = kEdge) {
    auto cl = [n](int i) { return std::clamp(i, 0, n - 1); };
    const int f = int(std::floor(p));
    const double r = std::round(p);
    if (std::fabs(p - r) < window) return {cl(int(r) - 1), cl(int(r))};
    return {cl(f), cl(f)};
}

// A reference value that may be one of two (lo <= hi) where the GPU may legitimately go either way.
struct Range {
    double lo, hi;
};
Range one(double v) { return {v, v}; }
Range either(double a, double b) { return {std::min(a, b), std::max(a, b)}; }

struct Stats {
    const char* name;
    std::string bound;
    double max = 0, sumSq = 0;
    long n = 0, fails = 0, ambiguous = 0;
    int worstX = 0, worstY = 0, worstC = 0;
    double worstGpu = 0, worstLo = 0, worstHi = 0;
    // err: distance of gpu from [lo, hi]; tol: the bound for this texel.
    void add(double gpu, Range ref, double tol, int x, int y, int c) {
        const double err = gpu < ref.lo ? ref.lo - gpu : gpu > ref.hi ? gpu - ref.hi : 0.0;
        ++n;
        sumSq += err * err;
        if (ref.lo != ref.hi) ++ambiguous;
        if (err > tol) ++fails;
        if (err > max || n == 1) {
            max = std::max(max, err);
            worstX = x, worstY = y, worstC = c, worstGpu = gpu, worstLo = ref.lo, worstHi = ref.hi;
        }
    }
    bool report() const {
        std::printf("  %-26s max %.3g  RMS %.3g  over %ld values (%ld with two accepted values); bound %s: %s",
                    name, max, n ? std::sqrt(sumSq / double(n)) : 0.0, n, ambiguous, bound.c_str(),
                    fails ? "FAIL" : "ok");
        if (fails)
            std::printf(" (%ld over; worst at (%d,%d) ch %d: gpu %.6g, ref [%.6g, %.6g])", fails, worstX, worstY,
                        worstC, worstGpu, worstLo, worstHi);
        std::printf("\n");
        return fails == 0;
    }
};

struct Setup {
    int W, H;
    double TW, TH, Diag;  // the float uniforms, as doubles
    std::vector<Color> casters;
};

// Unwrap.fx / UnwrapSpotlight.fx for texel (x, y) of the W x W unwrap target: r, g ranges.
void unwrapRef(const Setup& s, const LightCapture& l, int x, int y, Range out[2]) {
    const double u = (x + kBiasX) / s.W, v = (y + kBiasY) / s.W;
    const double Lx = l.posX, Ly = l.posY, TW = s.TW, TH = s.TH;
    // 1 if the caster texel(s) at (px, py) are empty (alpha < 0.01), else `dist`; both if it may go
    // either way.
    auto sampleTest = [&](double px, double py, double dist) {
        const Pick pxk = pick(px, s.W), pyk = pick(py, s.H);
        bool anyEmpty = false, anyFull = false;
        for (int ix : {pxk.a, pxk.b})
            for (int iy : {pyk.a, pyk.b}) {
                const bool empty = s.casters[std::size_t(iy) * std::size_t(s.W) + std::size_t(ix)].A / 255.0 < 0.01;
                (empty ? anyEmpty : anyFull) = true;
            }
        if (anyEmpty && anyFull) return either(1.0, dist);
        return one(anyEmpty ? 1.0 : dist);
    };
    auto neg = [&](double h) { return h < 0 ? 2 * TW : h; };
    if (!l.isSpot) {
        const double sn = std::sin(u * kPI), cs = std::cos(u * kPI);
        double n1x = -sn, n1y = cs, n2x = sn, n2y = cs;
        double LDx, LDy;
        if (cs == 0) LDx = TW - Lx, LDy = Lx;
        else if (sn == 0) LDx = LDy = std::fabs(((cs + 1) / 2.0) * TH - Ly);
        else {
            const double hx = neg(-Ly / cs), hy = neg(Lx / sn), hz = neg((TH - Ly) / cs), hw = neg((TW - Lx) / sn);
            LDx = std::min(hw, std::min(hx, hz));  // hit.wy
            LDy = std::min(hy, std::min(hx, hz));
        }
        LDx *= v, LDy *= v;
        n1x *= LDy, n1y *= LDy;  // norm1 (left ray) goes LightDist.y ...
        n2x *= LDx, n2y *= LDx;
        // ... but r reports LightDist.x with sample1's test: the effect's left/right swap, as written.
        out[0] = sampleTest(Lx + n1x, Ly + n1y, LDx / s.Diag);
        out[1] = sampleTest(Lx + n2x, Ly + n2y, LDy / s.Diag);
    } else {
        const double mn = double(l.lightDirAngle - l.outerAngle / 2.f), mx = double(l.lightDirAngle + l.outerAngle / 2.f);
        const double a = mn + u * (mx - mn);  // lerp
        const double sn = std::sin(a), cs = std::cos(a);
        double LD;
        if (cs == 0) LD = std::fabs(((sn + 1) / 2.0) * TW - Lx);
        else if (sn == 0) LD = std::fabs(((cs + 1) / 2.0) * TH - Ly);
        else {
            const double hx = neg(-Ly / cs), hy = neg(-Lx / sn), hz = neg((TH - Ly) / cs), hw = neg((TW - Lx) / sn);
            LD = std::min(std::min(hx, hz), std::min(hy, hw));
        }
        LD *= v;
        out[0] = sampleTest(Lx + sn * LD, Ly + cs * LD, LD / s.Diag);
        out[1] = one(0.0);
    }
}

// ---- per-pixel intervals (accumulation and final image) ------------------------------------

// What the GPU may have written: per pixel and channel, [lo, hi] in LSB (reference/ref_image.h).
using fxport::reference::RefImage;

double channel(const Color& p, int c) { return c == 0 ? p.R : c == 1 ? p.G : c == 2 ? p.B : p.A; }

fxport::reference::GpuImage asGpuImage(const std::vector<Color>& gpu, int W, int H) {
    static_assert(sizeof(Color) == 4, "Color is R, G, B, A bytes");
    return fxport::reference::GpuImage::fromRgba8(reinterpret_cast<const unsigned char*>(gpu.data()), W, H);
}

// The one-pixel-shift check alone (changes of more than 1 LSB); prints one line.
bool shiftTest(const char* name, const RefImage& ref, const std::vector<Color>& gpu) {
    return fxport::reference::checkShift(name, ref, asGpuImage(gpu, ref.width, ref.height), 1.0);
}

// Every sample inside its interval, and the one-pixel-shift check.
bool compare(const char* name, const char* bound, const RefImage& ref, const std::vector<Color>& gpu) {
    return fxport::reference::checkImage(name, bound, ref, asGpuImage(gpu, ref.width, ref.height), 1.0);
}

// A SpriteBatch LINEAR sample of a W x H Color texture drawn 1:1 at pixel (x, y): texel (x, y) with
// weight 255/256 per axis, its right/lower neighbours with 1/256 (clamped, or wrapped with `wrap`).
// The interval spans the texel and the filtered value, +-1 LSB where the texels differ (8-bit
// filters round after the horizontal lerps and again after the vertical one). Channel c, LSB.
void linearSample(const std::vector<Color>& img, int W, int H, int x, int y, int c, bool wrap, double& lo, double& hi) {
    fxport::reference::linearSample8(W, H, x, y, wrap, [&](int i, int j) {
        return channel(img[std::size_t(j) * std::size_t(W) + std::size_t(i)], c);
    }, lo, hi);
}

// 8-bit rounding of a value in [lo, hi] LSB, with float32 shader error around a half.
void roundRange(double& lo, double& hi) {
    lo = std::clamp(std::floor(lo - 0.05 + 0.5), 0.0, 255.0);
    hi = std::clamp(std::floor(hi + 0.05 + 0.5), 0.0, 255.0);
}

bool checkLight(LightRenderer& r, const Setup& s, const LightCapture& l, int index) {
    const int W = s.W, H = s.H;
    std::printf(" light %d: %s light at (%g, %g), radius %g, power %g\n", index, l.isSpot ? "spot" : "point", l.posX,
                l.posY, double(l.radius), double(l.power));
    if (!l.valid) {
        std::printf("  not captured: FAIL\n");
        return false;
    }
    bool pass = true;
    // (1) unwrap
    std::vector<Range> uref(std::size_t(W) * std::size_t(W) * 2);
    Stats su{l.isSpot ? "unwrap (UnwrapSpotlight.fx)" : "unwrap (Unwrap.fx)",
             "2^-10|ref| (one RGBA16F ulp) + 2e-6 (float32 trig/division)"};
    for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
            Range ref[2];
            unwrapRef(s, l, x, y, ref);
            const std::size_t t = std::size_t(y) * std::size_t(W) + std::size_t(x);
            uref[t * 2] = ref[0], uref[t * 2 + 1] = ref[1];
            const double want[4][2] = {{ref[0].lo, ref[0].hi}, {ref[1].lo, ref[1].hi}, {0, 0}, {1, 1}};
            for (int c = 0; c < 4; ++c) {
                const double gpu = halfToDouble(l.unwrap[t * 4 + std::size_t(c)]);
                const Range rg{want[c][0], want[c][1]};
                su.add(gpu, rg, rg.hi * kHalfRel + 2e-6, x, y, c);
            }
        }
    pass &= su.report();
    // (2) occlusion map: Min over the rows (and the white clear)
    Stats so{"occlusion vs reference", "as unwrap"};
    Stats sx{"occlusion vs GPU unwrap", "0 (Min of half values is exact)"};
    for (int x = 0; x < W; ++x) {
        for (int c = 0; c < 4; ++c) {
            double lo = 1, hi = 1, exact = 1;
            for (int y = 0; y < W; ++y) {
                const std::size_t t = std::size_t(y) * std::size_t(W) + std::size_t(x);
                if (c < 2) lo = std::min(lo, uref[t * 2 + std::size_t(c)].lo), hi = std::min(hi, uref[t * 2 + std::size_t(c)].hi);
                else if (c == 2) lo = hi = 0;
                exact = std::min(exact, halfToDouble(l.unwrap[t * 4 + std::size_t(c)]));
            }
            const double gpu = halfToDouble(l.occlusion[std::size_t(x) * 4 + std::size_t(c)]);
            so.add(gpu, {lo, hi}, hi * kHalfRel + 2e-6, x, 0, c);
            sx.add(gpu, one(exact), 0.0, x, 0, c);
        }
    }
    pass &= so.report();
    pass &= sx.report();
    // (3) light map from the GPU's occlusion map
    Stats sl{l.isSpot ? "light map (SpotLight.fx)" : "light map (PointLight.fx)",
             "1 LSB (8-bit rounding of a float32 result)"};
    const double Lx = l.posX, Ly = l.posY, R = l.radius, Pow = l.power, Bias = r.lightBias;
    auto occ = [&](int i, int c) { return halfToDouble(l.occlusion[std::size_t(i) * 4 + std::size_t(c)]); };
    RefImage lightRef(W, H, 4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double sx_ = double(W) * ((x + kBiasX) / W), sy_ = double(H) * ((y + kBiasY) / H);
            const double dx = sx_ - Lx, dy = sy_ - Ly;
            const double pixDist = std::sqrt(dx * dx + dy * dy);
            double lighting = (1 - pixDist / R) * Pow;
            Pick p{0, 0};
            bool lit[2];
            if (!l.isSpot) {
                const double U = std::acos(dy / pixDist) / kPI;
                p = pick(U * W, W, std::max(kEdge, kAcosTol / kPI * W));
                const int i[2] = {p.a, p.b};
                for (int k = 0; k < 2; ++k) {
                    const double dist = (sx_ < Lx ? occ(i[k], 0) : occ(i[k], 1)) * s.Diag;
                    const double m = std::min(R, dist);
                    // the comparison itself may go either way within float32 error of the operands
                    lit[k] = pixDist - Bias < m;
                    if (std::fabs(pixDist - Bias - m) < kEdge) p.b = -1;  // marker: both outcomes accepted
                }
            } else {
                double pa = std::acos(dy / pixDist);
                pa = dx < 0 ? -pa : pa;
                pa += pa < 0 ? double(l.angleBias) : 0;
                const double oMin = double(l.lightDirAngle - l.outerAngle / 2.f);
                const double oMax = double(l.lightDirAngle + l.outerAngle / 2.f);
                const double U = (pa - oMin) / (oMax - oMin);
                const double ad = std::fabs(pa - double(l.lightDirAngle));
                const double hi = double(l.innerAngle / 2.f), ho = double(l.outerAngle / 2.f);
                lighting *= ad < hi ? 1.0 : std::clamp((ho - ad) / (ho - hi), 0.0, 1.0);
                p = pick(U * W, W, std::max(kEdge, kAcosTol / (oMax - oMin) * W));
                const int i[2] = {p.a, p.b};
                for (int k = 0; k < 2; ++k) {
                    const double dist = occ(i[k], 0) * s.Diag;
                    const double m = std::min(R, dist);
                    lit[k] = ad < ho && pixDist - Bias < m;
                    if (ad < ho && std::fabs(pixDist - Bias - m) < kEdge) p.b = -1;
                }
            }
            const double litV = std::round(std::clamp(lighting, 0.0, 1.0) * 255);
            Range ref = (p.b == -1 || lit[0] != lit[1]) ? either(0.0, litV) : one(lit[0] ? litV : 0.0);
            const Color& g = l.lightMap[std::size_t(y) * std::size_t(W) + std::size_t(x)];
            const int gpu[4] = {g.R, g.G, g.B, g.A};
            for (int c = 0; c < 4; ++c) {
                const Range rc = c < 3 ? ref : one(255.0);
                sl.add(double(gpu[c]), rc, 1.0, x, y, c);
                lightRef.set(x, y, c, rc.lo - 1.0, rc.hi + 1.0);
            }
        }
    pass &= sl.report();
    pass &= shiftTest("", lightRef, l.lightMap);
    // (4) blur: HorizontalBlur.fx / VerticalBlur.fx (LinearClamp) from the GPU's previous target
    for (int pass2 = 0; pass2 < 2; ++pass2) {
        const bool horizontal = pass2 == 0;
        const std::vector<Color>& in = horizontal ? l.lightMap : l.hBlur;
        const std::vector<Color>& outGpu = horizontal ? l.hBlur : l.vBlur;
        Stats sb{horizontal ? "blur (HorizontalBlur.fx)" : "blur (VerticalBlur.fx)",
                 "1 LSB + per pixel sum of w_i * (max - min of the 4 texels) * 2/256 (bilinear weights: "
                 "8-bit sub-texel precision)"};
        auto T = [&](int x, int y) {
            x = std::clamp(x, 0, W - 1), y = std::clamp(y, 0, H - 1);
            return double(in[std::size_t(y) * std::size_t(W) + std::size_t(x)].R);
        };
        static const double ow[13][2] = {{-6, 0.002216}, {-5, 0.008764}, {-4, 0.026995}, {-3, 0.064759},
                                         {-2, 0.120985}, {-1, 0.176033}, {0, 0.199471},  {1, 0.176033},
                                         {2, 0.120985},  {3, 0.064759},  {4, 0.026995},  {5, 0.008764},
                                         {6, 0.002216}};
        const double minB = double(r.minBlur), maxB = double(r.maxBlur);
        RefImage blurRef(W, H, 4);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double u = (x + kBiasX) / W, v = (y + kBiasY) / H;
                const double spx = u * W, spy = v * H;
                const double dist = std::sqrt((spx - Lx) * (spx - Lx) + (spy - Ly) * (spy - Ly));
                const double blur = minB + std::clamp(dist / R, 0.0, 1.0) * (maxB - minB);
                double sum = 0, slack = 0;
                for (const auto& k : ow) {
                    const double su = u + (horizontal ? k[0] * blur / W : 0.0);
                    const double sv = v + (horizontal ? 0.0 : k[0] * blur / H);
                    const double tx = su * W - 0.5, ty = sv * H - 0.5;
                    const int ix = int(std::floor(tx)), iy = int(std::floor(ty));
                    const double fx = tx - ix, fy = ty - iy;
                    const double t00 = T(ix, iy), t10 = T(ix + 1, iy), t01 = T(ix, iy + 1), t11 = T(ix + 1, iy + 1);
                    const double val = (1 - fy) * ((1 - fx) * t00 + fx * t10) + fy * ((1 - fx) * t01 + fx * t11);
                    sum += val / 255.0 * k[1];
                    slack += k[1] * (std::max({t00, t10, t01, t11}) - std::min({t00, t10, t01, t11})) * 2.0 / 256.0;
                }
                const double ref = std::round(std::clamp(sum, 0.0, 1.0) * 255);
                const Color& g = outGpu[std::size_t(y) * std::size_t(W) + std::size_t(x)];
                const int gpu[4] = {g.R, g.G, g.B, g.A};
                for (int c = 0; c < 4; ++c) {
                    const double rc = c < 3 ? ref : 255.0;
                    sb.add(double(gpu[c]), one(rc), 1.0 + slack, x, y, c);
                    blurRef.set(x, y, c, rc - 1.0 - slack, rc + 1.0 + slack);
                }
            }
        pass &= sb.report();
        pass &= shiftTest("", blurRef, outGpu);
    }
    return pass;
}


// AccumulateLightMaps: lightMap cleared to black, then for each light
// spriteBatch.Draw(verticalBlurTarget, fullScreen, light.color) with BlendState.Additive
// (SourceAlpha, One): every blurred map (alpha 255), tinted, rounded to 8 bits, added, saturating.
bool checkAccumulation(LightRenderer& r, const CheckCapture& capture, int W, int H, const std::vector<Color>& gpu) {
    RefImage ref(W, H, 4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double sumLo[4] = {0, 0, 0, 255}, sumHi[4] = {0, 0, 0, 255};
            for (const LightCapture& l : capture.lights) {
                double aLo, aHi;
                linearSample(l.vBlur, W, H, x, y, 3, false, aLo, aHi);
                for (int c = 0; c < 3; ++c) {
                    double lo, hi;
                    linearSample(l.vBlur, W, H, x, y, c, false, lo, hi);
                    const double tint = channel(l.color, c) / 255.0, alpha = channel(l.color, 3) / 255.0;
                    lo *= tint * aLo / 255 * alpha, hi *= tint * aHi / 255 * alpha;  // colour * SourceAlpha
                    roundRange(lo, hi);
                    sumLo[c] += lo, sumHi[c] += hi;
                }
            }
            for (int c = 0; c < 4; ++c) ref.set(x, y, c, std::min(sumLo[c], 255.0), std::min(sumHi[c], 255.0));
        }
    (void)r;
    std::printf(" accumulation of %zu lights (AccumulateLightMaps, from the GPU's blurred maps):\n", capture.lights.size());
    return compare("lightMap", "per light: LINEAR sample +-1 LSB, tint, 8-bit rounding; summed, saturating", ref, gpu);
}

// RenderFinalScene: LightBlend.fx over backBufferCache (s0, SpriteBatch's LinearClamp) and lightMap
// (s1: Textures[1], its sampler state the device's: clamp or wrap accepted), AlphaBlend; then
// midGroundTarget with SpriteBatch's defaults (AlphaBlend, LinearClamp).
bool checkFinal(LightRenderer& r, int W, int H, const std::vector<Color>& lightMap, const std::vector<Color>& back) {
    const std::vector<Color> background = r.backBufferCache->GetData<Color>();
    const std::vector<Color> casters = r.midGroundTarget->GetData<Color>();
    const double minLight = double(r.minLight);
    RefImage ref(W, H, 4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            // LightBlend.fx's output, rounded to 8 bits
            double out[4][2];
            for (int c = 0; c < 4; ++c) {
                double bLo, bHi, lLo, lHi, wLo, wHi;
                linearSample(background, W, H, x, y, c, false, bLo, bHi);
                linearSample(lightMap, W, H, x, y, c, false, lLo, lHi);
                linearSample(lightMap, W, H, x, y, c, true, wLo, wHi);
                lLo = std::min(lLo, wLo), lHi = std::max(lHi, wHi);
                if (c < 3) {
                    lLo = lLo * (1 - minLight) + minLight * 255, lHi = lHi * (1 - minLight) + minLight * 255;
                }
                out[c][0] = bLo * lLo / 255, out[c][1] = bHi * lHi / 255;
                roundRange(out[c][0], out[c][1]);
            }
            // AlphaBlend (One, InverseSourceAlpha) over what the back buffer held: only an opaque
            // result makes that irrelevant; otherwise anything is accepted.
            const bool opaque = out[3][0] == 255;
            double gA[2];
            linearSample(casters, W, H, x, y, 3, false, gA[0], gA[1]);
            for (int c = 0; c < 4; ++c) {
                double dst[2] = {opaque ? out[c][0] : 0.0, opaque ? out[c][1] : 255.0};
                double g[2];
                linearSample(casters, W, H, x, y, c, false, g[0], g[1]);
                double lo = g[0] + dst[0] * (1 - gA[1] / 255), hi = g[1] + dst[1] * (1 - gA[0] / 255);
                if (gA[0] > 0 && gA[1] < 255) lo -= 1, hi += 1;  // the blend's 8-bit multiply
                roundRange(lo, hi);
                ref.set(x, y, c, lo, hi);
            }
        }
    std::printf(" final image (RenderFinalScene, from the GPU's backBufferCache, lightMap and midGroundTarget; MinLight %g):\n",
                minLight);
    return compare("back buffer", "LINEAR samples +-1 LSB, LightBlend.fx, 8-bit rounding, AlphaBlend of the casters",
                   ref, back);
}

}  // namespace

void CaptureLight(LightRenderer& r, const Light& light, bool isSpot, LightCapture& out) {
    out.valid = true;
    out.isSpot = isSpot;
    out.color = light.color;
    out.posX = light.Position.X, out.posY = light.Position.Y;
    out.power = light.Power, out.radius = light.radius;
    if (isSpot) {
        const auto& s = static_cast<const SpotLight&>(light);
        out.lightDirAngle = s.GetBiasedAngle();
        out.innerAngle = s.innerAngle, out.outerAngle = s.outerAngle;
        out.angleBias = s.GetAngleBias();
    }
    out.unwrap = r.unwrapTarget->GetData<std::uint16_t>();
    out.occlusion = r.occlusionMap->GetData<std::uint16_t>();
    out.lightMap = r.postProcessTarget->GetData<Color>();
    out.hBlur = r.horizontalBlurTarget->GetData<Color>();
    out.vBlur = r.verticalBlurTarget->GetData<Color>();
}

bool CheckLighting(LightRenderer& r, const CheckCapture& capture) {
    Setup s;
    s.W = r.midGroundTarget->Width(), s.H = r.midGroundTarget->Height();
    // Read first: the back buffer as RenderFinalScene left it.
    const std::vector<Color> back = r.GraphicsDevice.GetBackBufferData();
    if (r.unwrapTarget->Width() != s.W || r.unwrapTarget->Format() != SurfaceFormat::HdrBlendable) {
        std::printf("CPU reference: models the seed's W x W RGBA16F unwrap target only (here %d rays, format %d): FAIL\n",
                    r.unwrapTarget->Width(), int(r.unwrapTarget->Format()));
        return false;
    }
    const float fw = float(s.W), fh = float(s.H);
    s.TW = fw, s.TH = fh, s.Diag = double(Vector2(fw, fh).Length());
    s.casters = r.midGroundTarget->GetData<Color>();
    const std::size_t lights = r.spotLights.size() + r.pointLights.size();
    std::printf("CPU reference (double) of every step, %dx%d, lightBias %g, %zu lights:\n", s.W, s.H, double(r.lightBias),
                lights);
    bool pass = capture.lights.size() == lights;
    if (!pass) std::printf("  %zu lights captured of %zu: FAIL\n", capture.lights.size(), lights);
    for (std::size_t i = 0; i < capture.lights.size(); ++i) pass &= checkLight(r, s, capture.lights[i], int(i));
    const std::vector<Color> lightMap = r.lightMap->GetData<Color>();
    pass &= checkAccumulation(r, capture, s.W, s.H, lightMap);
    pass &= checkFinal(r, s.W, s.H, lightMap, back);
    std::printf("  %s\n", pass ? "PASS" : "FAIL");
    return pass;
}

}  // namespace _2DLightingSystem
