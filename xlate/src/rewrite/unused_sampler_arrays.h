// Sampler arrays that nothing uses: `sampler sams[2] { { Filter = ANISOTROPIC; }, { ... } };`.
// fxc compiles them and drops them (an unused sampler gets no register); fxport, which binds no
// sampler arrays (FX1404), drops them too, before the parser: a file-scope declaration of one
// sampler array whose name appears nowhere else is blanked, lines kept (vkd3d's state-block-syntax
// declares such arrays to test the state-block syntax only). A sampler array that is used is still
// refused with FX1404.
#pragma once

#include <string>

namespace fxport::xlate {

std::string dropUnusedSamplerArrays(const std::string& preprocessed);

}  // namespace fxport::xlate
