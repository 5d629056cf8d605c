// Loose shader files (D3D10/11 style `.hlsl`/`.vs`/`.ps`, no technique), compiled the way hosts
// call D3DCompileFromFile(file, ..., entry, profile): an effect of one technique with one pass
// whose stages use the named entry points. Entry points of one file compile together; files
// compile one by one (each has its own structs and cbuffers, often with the same names) sharing
// custom varying locations, and the results are merged into one effect.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "fxport/xlate/effect_compiler.h"

namespace fxport::xlate {

class VaryingLocations;

// loose_shaders.cpp: whether `options` are those of a loose-shader compile (the one technique it
// appends), which fxc makes with a shader profile, not an effect profile.
bool isLooseShaderCompile(const CompileOptions& options);

// The technique a loose file is compiled with (one pass naming its entry points). Such a pass may
// hold one stage alone (a domain shader compiled by itself, as fxc /T ds_5_0 does).
inline constexpr const char* kLooseTechnique = "fxport_loose_shaders";

// effect_compiler.cpp: compiles text, with custom varying locations shared across calls when
// `sharedVaryings` is given.
CompiledEffect compileEffectText(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                                 const CompileOptions& options, VaryingLocations* sharedVaryings);

// effect_compiler.cpp: whether compiles run in this process (CompileOptions::inProcess,
// FXPORT_IN_PROCESS=1, or already inside a front-end worker) rather than in a worker.
bool compilesInThisProcess(const CompileOptions& options);

// effect_compiler.cpp: runs `compile` in one front-end worker (front_end_worker.h) and returns its
// effect, the rewritten HLSL of each shader included; a worker that crashes or runs past a limit
// is a CompileError at the shader it was compiling (FX9001..FX9003).
CompiledEffect compileContained(const std::function<CompiledEffect()>& compile, const std::string& displayPath);

// effect_compiler.cpp: the effect the cache holds for this text and options; nullopt without
// compiling anything when it holds none.
std::optional<CompiledEffect> cachedEffectText(const std::string& source, const std::string& displayPath,
                                               const std::string& absolutePath, const CompileOptions& options);

}  // namespace fxport::xlate
