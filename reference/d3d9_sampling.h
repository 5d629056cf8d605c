// CPU textures and Direct3D 9 texture sampling for the CPU references (reference/): the render tests, the demos' --check, quality/.
//
// D3D9's rules, as the effects were written against them (not the runtime's code):
//  * texel (i, j) covers u in [i/W, (i+1)/W), v in [j/H, (j+1)/H); row 0 is the top row;
//  * point sampling takes texel floor(u*W), floor(v*H);
//  * linear sampling blends texels floor(u*W - 0.5) and the next with weight frac(u*W - 0.5)
//    (texel centres at (i + 0.5)/W), the same in v;
//  * Clamp clamps the texel index to [0, W-1], Wrap takes it modulo W;
//  * formats with fewer than four channels read the missing ones as 1 (R32F -> (r,1,1,1),
//    G32R32F -> (r,g,1,1));
//  * cube maps pick the face of the direction's largest component and map the other two to
//    (s, t) in [0,1]^2 with the table of the D3D9/D3D10 documentation (the same as OpenGL's):
//    +X (-z,-y)  -X (+z,-y)  +Y (+x,+z)  -Y (+x,-z)  +Z (+x,-y)  -Z (-x,-y), s = (sc/|ma| + 1)/2.
//
// Where a coordinate lies within kPointBand of a texel edge (or two cube axes tie), the hardware's
// rounding decides: the point samplers below offer every candidate (Eval::choose, or a range).
// Linear samples register their uncertainty with Eval::read: the 1/256 weight quantisation of
// texture units times the texel differences, the 8-bit rounding of filtered 8-bit texels, and the
// texels' own tolerance (end-to-end test).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reference/reference_eval.h"
#include "reference/ref_math.h"

namespace fxport::reference {

// Precision of the stored texels (what the GPU's filter and the target's rounding work with).
enum class TexelFormat : std::uint8_t { Unorm8, Unorm16, Float32 };

struct CpuTexture {
    int width = 0, height = 0;
    TexelFormat format = TexelFormat::Float32;
    int channels = 4;        // stored channels; the others read as 1
    std::vector<V4> texels;  // top row first, as sampled
    std::vector<V4> tol;     // empty, or per texel: how far the GPU's texel may be from texels[]

    CpuTexture() = default;
    CpuTexture(int w, int h, TexelFormat f, int c) : width(w), height(h), format(f), channels(c), texels(std::size_t(w) * std::size_t(h)) {}
    V4& at(int x, int y) { return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const V4& at(int x, int y) const { return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    V4 tolAt(int x, int y) const { return tol.empty() ? V4{} : tol[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// XNA's face order: +X, -X, +Y, -Y, +Z, -Z.
struct CpuCube {
    int size = 0;
    std::array<CpuTexture, 6> faces;
};

enum class Filter : std::uint8_t { Point, Linear };
enum class Address : std::uint8_t { Clamp, Wrap };
struct SamplerDesc {
    Filter filter;
    Address addressU, addressV;
};
inline constexpr SamplerDesc kPointClamp{Filter::Point, Address::Clamp, Address::Clamp};
inline constexpr SamplerDesc kPointWrap{Filter::Point, Address::Wrap, Address::Wrap};
inline constexpr SamplerDesc kLinearClamp{Filter::Linear, Address::Clamp, Address::Clamp};
inline constexpr SamplerDesc kLinearWrap{Filter::Linear, Address::Wrap, Address::Wrap};

// Texel-coordinate distance from an edge below which a point sample may go either way.
inline constexpr double kPointBand = 1e-3;

// Channel masks: which channels of a sample the shader goes on to use (bit c = channel c). Only
// those register an uncertainty (the others cannot change the result; skipping them saves time).
inline constexpr unsigned kX = 1, kY = 2, kZ = 4, kW = 8, kXYZ = 7, kXYZW = 15;

// tex2D. Point sampling with several candidate texels asks ev.choose().
V4 tex2D(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used = kXYZW);
// tex2D with point sampling: every candidate texel's value (the exact-arithmetic one first), as
// one read (a perturbation moves them all).
std::vector<V4> tex2DPointCandidates(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used = kXYZW);
// Their range (for values the shader only combines monotonically, e.g. a shadow map's depths).
Range4 tex2DPointRange(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, unsigned used = kXYZW);
// texCUBE with point sampling (the only filter the seed uses on cubes): range over candidates
// (channel x: the seed reads .r of R32F cube maps).
Range4 texCUBEPointRange(Eval& ev, const CpuCube& c, V3 dir);

// The face and (s, t) D3D9 addresses for a direction (no tie handling): for building inputs.
struct CubeAddress {
    int face;
    double s, t;
};
CubeAddress cubeAddress(V3 dir);
// The direction through (s, t) of a face: the inverse of cubeAddress.
V3 cubeDirection(int face, double s, double t);

}  // namespace fxport::reference
