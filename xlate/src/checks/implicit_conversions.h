// Implicit conversions in calls of the effect's own functions that fxc accepts with warning X3206
// ("implicit truncation of vector type") and glslang either rejects or accepts silently:
//  - a vector passed to a scalar parameter: glslang finds no matching overload; fxc uses .x. We
//    add overloads taking vectors there that call the function with the first component (asked
//    for only after glslang rejected a call, so calls that already resolve never change meaning);
//  - a longer vector passed to a shorter vector parameter: glslang truncates silently, as fxc
//    does; we only add fxc's warning, where the argument's type is evident from the source.
// Scalar -> vector promotion is accepted by both without a warning.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

class SourceMap;

// X3206 warnings for arguments whose type is known (a parameter, local or global, its members and
// swizzles, or a constructor) and wider than the parameter of the called function.
std::vector<Diagnostic> findImplicitTruncations(const EffectSyntax& syntax, const SourceMap& map);

// Edits inserting, after each named function, overloads that take float2..4 (int2.., ...) where
// it takes a scalar and call it with `.x`. Inserted on the function's last line: lines keep.
std::vector<TextEdit> vectorToScalarOverloads(const EffectSyntax& syntax, const std::set<std::string>& functions);

// The fxc wording, for diagnostics made elsewhere.
inline constexpr const char* kTruncationWarning = "implicit truncation of vector type (fxc X3206)";

}  // namespace fxport::xlate
