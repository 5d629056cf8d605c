// Sampler arrays indexed by constants only: `sampler sam[2]; ... tex2D(sam[1], uv)`. fxc gives the
// elements consecutive s registers (`register(s3)` reserves s3 and s4); fxport binds no sampler
// arrays, so before the parser such an array becomes one sampler per element, `sam_fxport_0`,
// `sam_fxport_1` (the registers s3, s4 when the array reserved s3; each element's state block from
// the initializer list), and each `sam[1]` names its element. A sampler array indexed by anything
// but a literal (a loop counter at SM5), or whose elements DX9 intrinsics sample with different
// dimensions (tex2D and tex3D: an error to fxc at SM4+), stays as written, and the parser refuses
// it (FX1404).
// Lines are kept, so diagnostics still point at the source.
#pragma once

#include <string>

namespace fxport::xlate {

std::string samplerArraysAsElements(const std::string& preprocessed);

}  // namespace fxport::xlate
