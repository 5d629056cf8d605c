// Globals whose initializer calls one of the effect's functions (`static float a = f() + 0.2;`),
// as fxc runs them: before the entry point. glslang takes such a call as made by the function
// defined last before the declaration, so `float f() {...} static float a = f();` is f calling
// itself to its linker ("Recursion detected"), and where that function is not reached from the
// entry point glslang drops the callee and then crashes on the call. Each such declaration gets a
// function of its own just before it (the caller glslang records) that calls the function placed
// before the previous one; the entry wrapper calls the last (kStaticInitializerScopes) first, and
// so does every function defined after it (geometry, hull, domain and compute entries have no
// wrapper; the links are empty, so a call from elsewhere changes nothing): every callee stays
// reachable.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

inline constexpr const char* kStaticInitializerScopes = "fxport_static_initializer_scopes";

// Whether any global's initializer calls a function the effect defines.
bool hasInitializerCalls(const EffectSyntax& syntax);

// Those functions, one before each such declaration.
std::vector<TextEdit> initializerCallScopes(const EffectSyntax& syntax);

}  // namespace fxport::xlate
