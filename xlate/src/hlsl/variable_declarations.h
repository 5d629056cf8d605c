// What the source declares a variable as, seen from a place in a function body: the nearest
// earlier `T name` of the body (T a numeric type or a struct), else a parameter, else a global.
// The token-level type lookup the HLSL rewrites and fxc checks share where glslang's types are
// not at hand (before glslang runs).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

struct DeclaredVariable {
    std::string type;       // as written (typedefs not resolved)
    std::vector<int> dims;  // array sizes; a size not written as a literal gives nothing at all
};

// FxFunction::declarationSites of a body.
std::unordered_map<std::string, std::vector<size_t>> declarationSites(const std::vector<Token>& tokens, TokenSpan body);

std::optional<DeclaredVariable> declaredVariable(const EffectSyntax& syntax, const FxFunction& f, const std::string& name, size_t at);

// Whether global `g` is a uniform of a one-row or one-column matrix type, which the rewrite gives
// register storage and reads as a vector (degenerate_matrices.h): not static, not an array, the
// type spelled out (not a typedef).
bool isVectorUniform(const EffectSyntax& syntax, const FxGlobal& g);

}  // namespace fxport::xlate
