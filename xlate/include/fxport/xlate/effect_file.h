// The compiled-effect file: a CompiledEffect serialised as JSON, so the runtime can load effects
// without glslang (and people can read what the compiler decided).
#pragma once

#include <string>
#include <string_view>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// Format version of the file; bump when the layout changes.
// 2: uniformBlocks, Parameter::block, ranges per block; 3: typed pass-state values, parameters by
// index; 4: "checksum" over the whole file and "glslHash" per shader, and every size, offset and
// index validated on load (effect_validation.h); 5: SM1-3 vertex shaders without the
// fxport_Internal block (D3D9 pixel centres are the viewport's), which the runtime no longer binds.
inline constexpr int kEffectFileVersion = 5;

// `compact` leaves out the indentation (what the compile cache stores); both forms load alike.
std::string serializeEffect(const CompiledEffect& effect, bool compact = false);
// Throws CompileError (id FX3101) naming `nameForErrors` if the text is not a compiled effect of
// this version, its checksum or a shader's GLSL hash does not match, or its content is inconsistent
// (sizes, offsets, indices, enums out of range): such files are untrusted input.
CompiledEffect deserializeEffect(std::string_view text, const std::string& nameForErrors);

void saveEffectFile(const CompiledEffect& effect, const std::string& path);
CompiledEffect loadEffectFile(const std::string& path);

// "SrcBlend = SourceAlpha", "ColorWriteEnable[1] = 7", "AlphaRef = <AlphaReference>": one state
// assignment as people read it (for `fxport dump`).
std::string describeStateAssignment(const StateAssignment& assignment, const CompiledEffect& effect);

// Reflection only (no GLSL, no absolute paths): what the golden tests compare, and what
// `fxport dump --reflection` prints.
std::string reflectionJson(const CompiledEffect& effect);

}  // namespace fxport::xlate
