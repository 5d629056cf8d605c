// Casts on the left of an assignment, as fxc takes them: `(float2) p = a.yz;` writes p.xy (a
// partial assignment), `(float4) p = v;` writes p, `(int4)(half4) p = v;` writes p with v
// converted by the outermost cast only (SM2-3; vkd3d's lhs-cast and lhs-partial-assignment pin
// these). glslang refuses them all ("l-value required"). The statement becomes a plain assignment:
// `p.xy = (float2)(a.yz);`, `p = (float4)(int4)(v);`.
// In shader model 4 and later fxc refuses a cast there that changes the component type
// (`(int4) p = ...` of a float4 p): findLvalueCastErrors (fxc_checks.h) says so.
// Only a variable, its struct members and a swizzle are taken as the target, numeric types as the
// casts; other forms are left to glslang. A cast in parentheses with a swizzle after it,
// `((int4) f).xy = v;` and `((float3)((int4) f).xyz).xy = v;`, writes the components of the target
// the swizzles reach (f.xy), the value converted by the outermost cast (SM2-3; refused from SM4 on
// as the casts change the component type).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

struct LvalueCast {
    size_t first = 0;       // the first cast's '('
    size_t target = 0;      // the target's first token
    size_t equals = 0;      // '='
    size_t semicolon = 0;   // the statement's ';'
    std::vector<BasicType> casts;  // outermost first
    BasicType targetType;
    const FxFunction* function = nullptr;
    // `((int4) f).xy = v;` (SM2-3): the components written, spelled (`f.xy`), and what the value
    // becomes (the outermost cast's component type, as many components: `int2`); empty otherwise.
    std::string swizzledTarget;
    std::string assignedType;
};

std::vector<LvalueCast> findLvalueCasts(const EffectSyntax& syntax);

std::vector<TextEdit> lvalueCastsAsAssignments(const EffectSyntax& syntax);

}  // namespace fxport::xlate
