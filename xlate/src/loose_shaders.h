// Loose shader files (D3D10/11 style `.hlsl`/`.vs`/`.ps`, no technique), compiled the way hosts
// call D3DCompileFromFile(file, ..., entry, profile): an effect of one technique with one pass
// whose stages use the named entry points. Entry points of one file compile together; files
// compile one by one (each has its own structs and cbuffers, often with the same names) sharing
// custom varying locations, and the results are merged into one effect.
#pragma once

#include <string>

#include "fxport/xlate/effect_compiler.h"

namespace fxport::xlate {

class VaryingLocations;

// effect_compiler.cpp: compiles text, with custom varying locations shared across calls when
// `sharedVaryings` is given.
CompiledEffect compileEffectText(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                                 const CompileOptions& options, VaryingLocations* sharedVaryings);

}  // namespace fxport::xlate
