// Step 3a of the compiler: turn the effect into plain HLSL that glslang accepts, once per effect.
//  - effect-framework syntax found by the parser is blanked (newlines kept, so line numbers hold);
//  - DX9 samplers get their dimension: an untyped `sampler` used with texCUBE (directly or through a
//    function parameter) becomes `samplerCUBE`; glslang would otherwise silently treat it as 2D;
//  - every sampler gets its texture unit: register(sN) where given, otherwise the lowest free unit in
//    declaration order.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

class SourceMap;

struct EffectSampler {
    std::string name;
    TextureKind kind = TextureKind::Texture2D;
    int unit = 0;
    bool dx10 = false;
    std::string textureParameter;  // DX9: Texture = <T>
    SamplerStateDesc state;
    std::vector<FxAssignment> parameterStates;          // `MinFilter = <Filter>;` as written
    std::vector<SamplerStateParameter> stateParameters; // the same, resolved (EffectBuilder)
};

struct RewrittenEffect {
    std::string hlsl;      // the whole effect as plain HLSL (no entry wrapper), geometry shaders left out
    // The effect for compiling geometry shader `entry`: glslang 12 crashes on a source holding two
    // functions that Append to streams, so every stream function `entry` does not call is left out.
    // `extra` edits are applied too (overloads for implicit conversions, see implicit_conversions.h).
    std::string hlslForGeometryShader(const std::string& entry, const std::vector<TextEdit>& extra = {}) const;
    bool dx9Samplers = false;  // compile with glslang's DX9-compatibility mode (tex2D, sampler2D ...)
    std::vector<EffectSampler> samplers;
    std::map<std::string, int> textureUnits;  // DX10 texture objects -> unit (register(tN) or order)

    // What hlsl is made from (kept to make the geometry-shader variants).
    const std::string* sourceText = nullptr;
    const EffectSyntax* syntax = nullptr;
    std::vector<TextEdit> edits;
};

// Throws CompileError on contradictions (a sampler used as 2D and cube); sampler-state problems are
// appended to `diagnostics`.
// `defaultMajority`: CompileOptions::defaultMatrixMajority.
RewrittenEffect rewriteEffect(const std::string& text, const EffectSyntax& syntax, const SourceMap& map,
                              std::vector<Diagnostic>& diagnostics, const std::string& defaultMajority = {});

TextureKind textureKindOfType(const std::string& type);  // texture2D, samplerCUBE, Texture3D ... (2D default)

}  // namespace fxport::xlate
