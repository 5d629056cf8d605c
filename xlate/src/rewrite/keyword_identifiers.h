// Words glslang's HLSL front end reserves and fxc does not: `precise` is a modifier to both, but
// to fxc only where a type follows, so `float4 precise;` and `return precise;` are a variable
// (vkd3d's precise-modifier pins it). glslang stops with "';' : Expected". So do `ConstantBuffer` and
// `TextureBuffer` without template arguments (SM 5.1 types to glslang, names to fxc up to SM 5.0:
// `cbuffer ConstantBuffer`, which glslang takes but reflects under another name). Such a use is renamed
// before glslang (`fxport_kw_precise`), and the SPIR-V names glslang writes are renamed back
// (restoreKeywordIdentifiers), so reflection and parameters keep the name the effect wrote
// (SPIRV-Cross then spells a GLSL keyword its own way).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

std::vector<TextEdit> keywordIdentifiersRenamed(const EffectSyntax& syntax);

// How generated code spells a type the effect wrote: `precise` can only be a typedef's name there.
std::string keywordIdentifierSpelled(const std::string& type);

// OpName / OpMemberName strings `fxport_kw_NAME` become `NAME` again (a pass of parsed_spirv.h:
// true when it changed the module).
bool restoreKeywordIdentifiers(ParsedSpirv& m);

}  // namespace fxport::xlate
