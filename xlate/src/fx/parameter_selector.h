// An index the effect framework evaluates at Apply() over the current parameter values:
// `VertexShader = (VSArray[VSIndices[ShaderIndex]])` picks a shader, `ZWriteEnable =
// <ZWrites[Mode]>` picks an element of a parameter array. The index is `3`, `Name` or
// `Name[index]`; it becomes a small stack program (SelectorOp) the runtime runs.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

struct SelectorError {
    std::string message;      // e.g. "'Mode' is not a parameter of this effect"
    bool unsupported = false;  // valid HLSL, but more than the three forms above
};

// Appends the program of `span` to `ops`. `parameterIndex` maps a name to the effect's parameter
// (-1: none). Returns what is wrong, or nothing.
std::optional<SelectorError> appendSelector(const std::vector<Token>& tokens, TokenSpan span,
                                          const std::function<int(const std::string&)>& parameterIndex,
                                          std::vector<SelectorOp>& ops);

}  // namespace fxport::xlate
