// Image read-back helpers that need no GL: texels as a target stores them (8/16-bit UNORM, float32)
// and the byte layout SetData/GetData exchange, so a reference can quantise its values exactly as
// the GPU does and read a target's bytes back as doubles.
#pragma once

#include <vector>

#include "reference/d3d9_sampling.h"

namespace fxport::reference {

// One step of the format (0 for float targets).
double lsb(TexelFormat f);
// v as the format stores it: UNORM clamped to [0, 1] and rounded to its step, float to float32.
double store(TexelFormat f, double v);
// The per-pixel bound of a format (value = the reference value, for the relative float bound):
//   Color (8-bit) 1/255, Rgba64 (16-bit) 1/65535, float 1e-5 relative.
double formatBound(TexelFormat f, double value);

// The texels' stored channels packed as SetData/GetData exchange them (little-endian 16-bit).
std::vector<unsigned char> packTexels(const CpuTexture& t);
// The inverse: bytes of a width x height image in format f with `channels` channels (the others read 1).
CpuTexture unpackTexels(int width, int height, TexelFormat f, int channels, const std::vector<unsigned char>& bytes);

}  // namespace fxport::reference
