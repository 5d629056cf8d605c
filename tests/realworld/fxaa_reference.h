// A CPU port of FXAA 3.11's PC quality path (FXAA_PC 1, FXAA_GATHER4_ALPHA either way, luma in
// alpha, FXAA_DISCARD 0), written from the algorithm's description in docs/fxaa-check.md -- the
// oracle that tests/realworld/fxaa_check_test.cpp compares NVIDIA's Fxaa3_11.fxh against. Preset
// 12's five search steps (1, 1.5, 2, 4, 12 texels) are the default; others are a step list.
#pragma once

#include <array>
#include <vector>

namespace fxport::test {

struct FxaaImage {
    int width = 0, height = 0;
    std::vector<std::array<float, 4>> texels;  // RGBA in [0, 1], top row first; A holds luma
    // Bilinear, clamp-to-edge, at texture coordinates (u, v) in [0, 1] (the GPU's SampleLevel 0).
    std::array<float, 4> sample(float u, float v) const;
};

struct FxaaSettings {
    float subpix = 0.75f;              // fxaaQualitySubpix
    float edgeThreshold = 0.166f;      // fxaaQualityEdgeThreshold
    float edgeThresholdMin = 0.0833f;  // fxaaQualityEdgeThresholdMin
    std::vector<float> steps = {1.0f, 1.5f, 2.0f, 4.0f, 12.0f};  // FXAA_QUALITY__P0..P(PS-1), preset 12
    // Every decision `a >= b` (and `a < b` as its negation) is taken as `a >= b + tieBias`. 0 is
    // FXAA's own; a small bias either way shows which way an exact tie goes when the GPU's last-bit
    // rounding breaks it (a pixel FXAA can take either way on any GPU).
    float tieBias = 0;
    // Where the pixel's coordinate lies from its texel centre, in texels (both axes): 0 for D3D10+;
    // fxport's D3D9 path adds 1/256 (the attribute bias of its half-pixel offset, docs/DESIGN.md).
    float centreOffset = 0;
};

// FxaaPixelShader's output at the texel centre of (x, y), as float4.
std::array<float, 4> fxaaPixel(const FxaaImage& image, int x, int y, const FxaaSettings& settings);

}  // namespace fxport::test
