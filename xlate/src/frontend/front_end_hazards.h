// Shapes of HLSL that crash glslang 12.0 (Debian 12's) instead of getting a diagnostic, found by
// fuzzing: checked on the parsed effect before any shader reaches glslang, and reported as fxc
// would report them, at file:line. What this list misses is still contained: the front end runs in
// a worker process (front_end_worker.h), so a crash there is FX9001, not the caller's death.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"
#include "fx/source_map.h"

namespace fxport::xlate {

// Every hazard found, in source order; empty = the HLSL may go to glslang.
//  - a global declared twice (`float4 V; float2 V;`: glslang's global block grows inconsistently)
//  - a function parameter without a name in a definition (`void GS(VSOut[1], ...)`, `void GS(V[:])`),
//    a geometry shader input primitive that is not an array (`point V v` for `point V v[1]`)
//  - a closing bracket that does not match the open one (`const float2 W[)];`)
//  - a function defined inside another (`float4 o F() { ... }` in a body, a missing ';')
//  - `mul` with a float1/float1x1 argument and a matrix (glslang's argument conversion), also a
//    float1 member of a struct (`mul(input.Normal, World)`) or a call returning float1
//  - an undeclared name in a branch of a ternary (`return v ? 1 : stor;`)
//  - `vector<T, N>` / `matrix<T, R, C>` with a dimension outside 1..4 (`matrix<half, 8, 4>`)
std::vector<Diagnostic> findFrontEndHazards(const EffectSyntax& syntax, const SourceMap& map);

}  // namespace fxport::xlate
