// A DX9 `sampler sam;` that a shader uses both ways: `tex.Sample(sam, uv)` (a DX10 sampler state)
// and `tex2D(sam, uv)` (a DX9 combined sampler). fxc (backcompat) compiles it by making the
// tex2D's texture a texture object of its own, allocated before the declared textures, in the
// order the shader first samples each such sampler (vkd3d's combined-samplers and
// texture-ordering pin the registers). The parser makes `sam` a SamplerState (its .Sample use), so
// glslang was left with tex2D on a sampler state, which the GL driver refuses. Before the parser,
// each `tex2D(sam, uv)` becomes `sam_fxport_texture2D.Sample(sam, uv)` (tex1D, tex3D, texCUBE
// alike), with `Texture2D sam_fxport_texture2D;` declared ahead of everything, first use first.
// Only the plain intrinsics of two arguments are rewritten (not tex2Dlod, tex2Dproj ...).
#pragma once

#include <string>

namespace fxport::xlate {

std::string samplerTexturesDeclared(const std::string& preprocessed);

}  // namespace fxport::xlate
