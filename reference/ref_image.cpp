#include "reference/ref_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "reference/texel_bytes.h"

namespace fxport::reference {

RefImage evaluateImage(int width, int height, TexelFormat format, int channels, bool rasterSlack, const ImagePixel& pixel) {
    RefImage ref(width, height, channels);
    ref.format = format;
    ref.slack.assign(ref.lo.size(), 0.0);
    ref.exact.assign(std::size_t(width) * std::size_t(height), 0);
    ref.leaves.assign(ref.exact.size(), 1);
    EvalOptions options;
    options.rasterSlack = rasterSlack;
    if (format != TexelFormat::Float32) {
        options.clampLo = 0;
        options.clampHi = 1;
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const PixelResult r = evaluatePixel([&](Eval& ev) { return pixel(ev, x, y); }, options);
            const std::size_t p = std::size_t(y) * std::size_t(width) + std::size_t(x);
            ref.exact[p] = r.exact;
            ref.leaves[p] = r.leaves;
            for (int c = 0; c < channels; ++c) {
                ref.set(x, y, c, r.lo[c], r.hi[c]);
                ref.slack[ref.index(x, y, c)] = r.slack[c];
            }
        }
    return ref;
}

CpuTexture asInput(const RefImage& ref) {
    const TexelFormat f = ref.format;
    CpuTexture t(ref.width, ref.height, f, ref.channels);
    t.tol.resize(t.texels.size());
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            V4& texel = t.at(x, y);
            V4& tol = t.tol[std::size_t(y) * std::size_t(ref.width) + std::size_t(x)];
            for (int c = 0; c < 4; ++c) {
                if (c >= t.channels) {
                    texel[c] = 1;
                    continue;
                }
                const std::size_t i = ref.index(x, y, c);
                const double mid = (ref.lo[i] + ref.hi[i]) / 2;
                texel[c] = store(f, mid);
                tol[c] = ref.exactAt(x, y) ? lsb(f)
                                           : (ref.hi[i] - ref.lo[i]) / 2 + ref.boundScale * formatBound(f, mid) + ref.slackAt(i);
            }
        }
    return t;
}

namespace {

struct Counts {
    long samples = 0, failures = 0, slackSamples = 0, ambiguous = 0, wide = 0;
    double maxError = 0, sumSquares = 0, maxAllowed = 0, maxSlack = 0, maxRel = 0;
    std::vector<double> allowed;
    std::string text;
};

Counts count(const CpuTexture& gpu, const RefImage& ref, int channels, int shift) {
    Counts k;
    const TexelFormat f = ref.format;
    std::ostringstream text;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const V4& gv = gpu.at(std::max(0, x - shift), y);
            bool ambiguous = ref.leavesAt(x, y) > 1, wide = false;
            for (int ch = 0; ch < channels; ++ch) {
                const std::size_t i = ref.index(x, y, ch);
                const double lo = ref.lo[i], hi = ref.hi[i], slack = ref.slackAt(i);
                ambiguous = ambiguous || lo != hi;
                double g = gv[ch];
                double e = std::max({0.0, lo - g, g - hi});
                if (std::isnan(g)) e = std::numeric_limits<double>::infinity();
                double mid = (lo + hi) / 2;
                double bound = ref.boundScale * formatBound(f, mid);
                double allowed = bound + slack;
                ++k.samples;
                k.sumSquares += e * e;
                k.maxError = std::max(k.maxError, e);
                if (e > 0 && f == TexelFormat::Float32) k.maxRel = std::max(k.maxRel, e / std::max(std::fabs(mid), 1e-30));
                if (hi - lo > bound) wide = true;
                k.maxAllowed = std::max(k.maxAllowed, allowed);
                k.maxSlack = std::max(k.maxSlack, slack);
                k.allowed.push_back(allowed);
                if (slack > bound) ++k.slackSamples;
                if (!(e <= allowed)) {
                    if (k.failures < 12) {
                        char line[256];
                        std::snprintf(line, sizeof line,
                                      "  pixel (%d,%d) channel %d: GPU %.7g, reference [%.7g, %.7g], |error| %.3g > bound %.3g\n", x, y,
                                      ch, g, lo, hi, e, allowed);
                        text << line;
                    }
                    ++k.failures;
                }
            }
            if (ambiguous) ++k.ambiguous;
            if (wide) ++k.wide;
        }
    k.text = text.str();
    return k;
}

}  // namespace

Comparison compare(const std::string& pass, const CpuTexture& gpu, const RefImage& ref, int maxChannels) {
    if (gpu.width != ref.width || gpu.height != ref.height) throw std::runtime_error(pass + ": size mismatch");
    const int channels = std::min(ref.channels, maxChannels);
    Counts k = count(gpu, ref, channels, 0);
    Comparison c;
    c.pass = pass;
    c.samples = k.samples;
    c.maxError = k.maxError;
    c.rmsError = std::sqrt(k.sumSquares / double(std::max<long>(k.samples, 1)));
    c.maxAllowed = k.maxAllowed;
    c.maxSlack = k.maxSlack;
    c.slackSamples = k.slackSamples;
    c.ambiguousPixels = k.ambiguous;
    c.wideRangePixels = k.wide;
    c.failures = k.failures;
    c.failureText = k.text;
    c.maxRelError = k.maxRel;
    std::sort(k.allowed.begin(), k.allowed.end());
    c.medianAllowed = k.allowed[k.allowed.size() / 2];
    c.p95Allowed = k.allowed[k.allowed.size() * 95 / 100];
    c.shiftedFailureFraction = double(count(gpu, ref, channels, 1).failures) / double(k.samples);
    // What a shift could reveal: samples whose reference differs from the left neighbour's by more
    // than the bound.
    long visible = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 1; x < ref.width; ++x)
            for (int ch = 0; ch < channels; ++ch) {
                const std::size_t r = ref.index(x, y, ch), l = ref.index(x - 1, y, ch);
                const double mid = (ref.lo[r] + ref.hi[r]) / 2, left = (ref.lo[l] + ref.hi[l]) / 2;
                if (std::fabs(mid - left) > ref.boundScale * formatBound(ref.format, mid) + ref.slackAt(r) + (ref.hi[r] - ref.lo[r]) / 2)
                    ++visible;
            }
    c.shiftVisibleFraction = double(visible) / double(k.samples);
    return c;
}

GpuImage GpuImage::fromRgba8(const unsigned char* rgba, int width, int height) {
    GpuImage g{width, height, 4, std::vector<double>(std::size_t(width) * std::size_t(height) * 4)};
    for (std::size_t i = 0; i < g.values.size(); ++i) g.values[i] = rgba[i];
    return g;
}

namespace {

// Every sample (x, y, channel, index) of the pixels in `mask` (null: all), row by row.
template <class F>
void forEachSample(const RefImage& ref, const std::vector<char>* mask, F f) {
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            if (mask && !(*mask)[std::size_t(y) * std::size_t(ref.width) + std::size_t(x)]) continue;
            for (int c = 0; c < ref.channels; ++c) f(x, y, c, ref.index(x, y, c));
        }
}

}  // namespace

ShiftCheck shiftCheck(const RefImage& ref, const GpuImage& gpu, double changeThreshold, const std::vector<char>* mask) {
    ShiftCheck k;
    forEachSample(ref, mask, [&](int x, int y, int c, std::size_t i) {
        const double g = gpu.at(x, y, c);
        if (g < ref.lo[i] || g > ref.hi[i]) return;
        for (int s = 0; s < 2; ++s) {
            const int sx = s == 0 ? x - 1 : x, sy = s == 0 ? y : y - 1;
            if (sx < 0 || sy < 0) continue;
            const double shifted = gpu.at(sx, sy, c);
            if (std::fabs(shifted - g) <= changeThreshold) continue;
            ++k.changed[s];
            if (shifted < ref.lo[i] || shifted > ref.hi[i]) ++k.shiftedFails[s];
        }
    });
    return k;
}

namespace {

bool printShift(const char* name, const ShiftCheck& k) {
    std::printf("  %-34s 1-pixel shift: fails %ld of %ld changed samples in x, %ld of %ld in y: %s\n", name,
                k.shiftedFails[0], k.changed[0], k.shiftedFails[1], k.changed[1], k.seen() ? "seen" : "NOT SEEN");
    return k.seen();
}

}  // namespace

bool checkShift(const char* name, const RefImage& ref, const GpuImage& gpu, double changeThreshold) {
    return printShift(name, shiftCheck(ref, gpu, changeThreshold));
}

bool checkImage(const char* name, const char* bound, const RefImage& ref, const GpuImage& gpu, double changeThreshold,
                const std::vector<char>* mask) {
    long samples = 0, fails = 0;
    double maxExcess = 0, widthSum = 0;
    int wx = 0, wy = 0, wc = 0;
    forEachSample(ref, mask, [&](int x, int y, int c, std::size_t i) {
        const double g = gpu.at(x, y, c);
        const double excess = std::max(ref.lo[i] - g, g - ref.hi[i]);
        ++samples;
        widthSum += ref.hi[i] - ref.lo[i];
        if (excess > 0) {
            ++fails;
            if (excess > maxExcess) maxExcess = excess, wx = x, wy = y, wc = c;
        }
    });
    std::printf("  %-34s %ld of %ld samples outside (max by %.3g); mean interval width %.3g; bound: %s\n", name, fails,
                samples, maxExcess, samples ? widthSum / double(samples) : 0.0, bound);
    if (fails) {
        const std::size_t i = ref.index(wx, wy, wc);
        std::printf("  %-34s worst at (%d, %d) channel %d: gpu %.7g, reference [%.7g, %.7g]\n", "", wx, wy, wc,
                    gpu.at(wx, wy, wc), ref.lo[i], ref.hi[i]);
    }
    const bool shiftSeen = printShift("", shiftCheck(ref, gpu, changeThreshold, mask));
    const bool pass = fails == 0 && shiftSeen;
    std::printf("  %-34s %s\n", "", pass ? "ok" : "FAIL");
    return pass;
}

void linearSample8(int width, int height, int x0, int y0, bool wrap, const std::function<double(int i, int j)>& texel,
                   double& lo, double& hi) {
    auto T = [&](int i, int j) {
        i = wrap ? (i % width + width) % width : std::clamp(i, 0, width - 1);
        j = wrap ? (j % height + height) % height : std::clamp(j, 0, height - 1);
        return texel(i, j);
    };
    const double f = 1.0 / 256.0;
    const double t00 = T(x0, y0), t10 = T(x0 + 1, y0), t01 = T(x0, y0 + 1), t11 = T(x0 + 1, y0 + 1);
    const double filtered = (1 - f) * ((1 - f) * t00 + f * t10) + f * ((1 - f) * t01 + f * t11);
    lo = std::min(t00, filtered), hi = std::max(t00, filtered);
    if (t00 != t10 || t00 != t01 || t00 != t11) lo -= 1.0, hi += 1.0;
    lo = std::max(lo, 0.0), hi = std::min(hi, 255.0);
}

}  // namespace fxport::reference
