#include "fxaa_reference.h"

#include <algorithm>
#include <cmath>

namespace fxport::test {

std::array<float, 4> FxaaImage::sample(float u, float v) const {
    // Texel centres at (i + 0.5) / size, as D3D10 and GL place them.
    const float x = u * float(width) - 0.5f, y = v * float(height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    auto texel = [&](int i, int j) {
        i = std::clamp(i, 0, width - 1);
        j = std::clamp(j, 0, height - 1);
        return texels[std::size_t(j) * std::size_t(width) + std::size_t(i)];
    };
    const auto a = texel(int(x0), int(y0)), b = texel(int(x0) + 1, int(y0));
    const auto c = texel(int(x0), int(y0) + 1), d = texel(int(x0) + 1, int(y0) + 1);
    std::array<float, 4> out{};
    for (int k = 0; k < 4; ++k) {
        const float top = a[k] + (b[k] - a[k]) * fx, bottom = c[k] + (d[k] - c[k]) * fx;
        out[std::size_t(k)] = top + (bottom - top) * fy;
    }
    return out;
}

namespace {

// One walk of the edge search: from the edge's midpoint (posB) outwards along the edge in both
// directions, stopping each side where the luma pair average has changed by a quarter of the
// local gradient (or after the last step).
// a >= b, with ties moved by the settings' tieBias (see fxaa_reference.h).
struct Compare {
    float bias;
    bool operator()(float a, float b) const { return a >= b + bias; }
};

struct EdgeEnds {
    float posN[2], posP[2];
    float lumaEndN, lumaEndP;
};

EdgeEnds searchEdge(const FxaaImage& image, const float posB[2], const float offNP[2], float lumaNN, float gradientScaled,
                    const std::vector<float>& steps, const Compare& ge) {
    EdgeEnds e{};
    e.posN[0] = posB[0] - offNP[0] * steps[0];
    e.posN[1] = posB[1] - offNP[1] * steps[0];
    e.posP[0] = posB[0] + offNP[0] * steps[0];
    e.posP[1] = posB[1] + offNP[1] * steps[0];
    e.lumaEndN = image.sample(e.posN[0], e.posN[1])[3] - lumaNN * 0.5f;
    e.lumaEndP = image.sample(e.posP[0], e.posP[1])[3] - lumaNN * 0.5f;
    bool doneN = ge(std::abs(e.lumaEndN), gradientScaled);
    bool doneP = ge(std::abs(e.lumaEndP), gradientScaled);
    for (std::size_t s = 1; s < steps.size(); ++s) {
        if (!doneN) e.posN[0] -= offNP[0] * steps[s], e.posN[1] -= offNP[1] * steps[s];
        if (!doneP) e.posP[0] += offNP[0] * steps[s], e.posP[1] += offNP[1] * steps[s];
        if (doneN && doneP) break;
        if (s + 1 == steps.size()) break;  // the last step moves without reading again
        if (!doneN) e.lumaEndN = image.sample(e.posN[0], e.posN[1])[3] - lumaNN * 0.5f;
        if (!doneP) e.lumaEndP = image.sample(e.posP[0], e.posP[1])[3] - lumaNN * 0.5f;
        doneN = ge(std::abs(e.lumaEndN), gradientScaled);
        doneP = ge(std::abs(e.lumaEndP), gradientScaled);
    }
    return e;
}

}  // namespace

std::array<float, 4> fxaaPixel(const FxaaImage& image, int x, int y, const FxaaSettings& settings) {
    const float rcp[2] = {1.0f / float(image.width), 1.0f / float(image.height)};
    float posM[2] = {(float(x) + 0.5f + settings.centreOffset) * rcp[0], (float(y) + 0.5f + settings.centreOffset) * rcp[1]};
    auto luma = [&](float dx, float dy) { return image.sample(posM[0] + dx * rcp[0], posM[1] + dy * rcp[1])[3]; };

    // Local contrast over the 4-neighbourhood: below the threshold the pixel is left alone.
    const std::array<float, 4> rgbyM = image.sample(posM[0], posM[1]);
    const float lumaM = rgbyM[3];
    float lumaS = luma(0, 1), lumaE = luma(1, 0), lumaN = luma(0, -1), lumaW = luma(-1, 0);
    const float rangeMax = std::max(std::max(lumaN, lumaW), std::max(lumaE, std::max(lumaS, lumaM)));
    const float rangeMin = std::min(std::min(lumaN, lumaW), std::min(lumaE, std::min(lumaS, lumaM)));
    const float range = rangeMax - rangeMin;
    const Compare ge{settings.tieBias};
    if (!ge(range, std::max(settings.edgeThresholdMin, rangeMax * settings.edgeThreshold))) return rgbyM;

    // Edge orientation from the 3x3 second differences (horizontal edge: luma changes along y).
    const float lumaNW = luma(-1, -1), lumaSE = luma(1, 1), lumaNE = luma(1, -1), lumaSW = luma(-1, 1);
    const float edgeHorz = std::abs(-2 * lumaW + lumaNW + lumaSW) + 2 * std::abs(-2 * lumaM + lumaN + lumaS) +
                           std::abs(-2 * lumaE + lumaNE + lumaSE);
    const float edgeVert = std::abs(-2 * lumaS + lumaSW + lumaSE) + 2 * std::abs(-2 * lumaM + lumaW + lumaE) +
                           std::abs(-2 * lumaN + lumaNW + lumaNE);
    const bool horzSpan = ge(edgeHorz, edgeVert);

    // Sub-pixel aliasing amount: the 3x3 low-pass against the centre, relative to the range.
    const float subpixA = (lumaN + lumaS + lumaW + lumaE) * 2 + (lumaNW + lumaSW + lumaNE + lumaSE);
    const float subpixC = std::clamp(std::abs(subpixA * (1.0f / 12.0f) - lumaM) * (1.0f / range), 0.0f, 1.0f);
    const float subpixF = (-2 * subpixC + 3) * subpixC * subpixC;
    const float subpixH = subpixF * subpixF * settings.subpix;

    // Which side of the pixel the edge lies on (the neighbour with the larger gradient).
    if (!horzSpan) lumaN = lumaW, lumaS = lumaE;
    float lengthSign = horzSpan ? rcp[1] : rcp[0];
    const float gradientN = lumaN - lumaM, gradientS = lumaS - lumaM;
    const bool pairN = ge(std::abs(gradientN), std::abs(gradientS));
    const float gradient = std::max(std::abs(gradientN), std::abs(gradientS));
    if (pairN) lengthSign = -lengthSign;
    const float lumaNN = (pairN ? lumaN : lumaS) + lumaM;

    // Search both ways along the edge, half a texel towards that neighbour.
    float posB[2] = {posM[0], posM[1]};
    if (horzSpan) posB[1] += lengthSign * 0.5f;
    else posB[0] += lengthSign * 0.5f;
    const float offNP[2] = {horzSpan ? rcp[0] : 0.0f, horzSpan ? 0.0f : rcp[1]};
    const EdgeEnds e = searchEdge(image, posB, offNP, lumaNN, gradient * 0.25f, settings.steps, ge);

    // Nearer end decides: shift the sample across the edge by how far this pixel is from it.
    const float dstN = horzSpan ? posM[0] - e.posN[0] : posM[1] - e.posN[1];
    const float dstP = horzSpan ? e.posP[0] - posM[0] : e.posP[1] - posM[1];
    const bool lumaMLTZero = !ge(lumaM - lumaNN * 0.5f, 0.0f);
    const bool goodSpan = !ge(dstN, dstP) ? !ge(e.lumaEndN, 0.0f) != lumaMLTZero : !ge(e.lumaEndP, 0.0f) != lumaMLTZero;
    const float pixelOffset = std::min(dstN, dstP) * (-1.0f / (dstP + dstN)) + 0.5f;
    const float offset = std::max(goodSpan ? pixelOffset : 0.0f, subpixH);
    if (horzSpan) posM[1] += offset * lengthSign;
    else posM[0] += offset * lengthSign;
    std::array<float, 4> out = image.sample(posM[0], posM[1]);
    out[3] = lumaM;  // FXAA_DISCARD 0 returns the centre's luma in alpha
    return out;
}

}  // namespace fxport::test
