// The numeric components of a variable in fxc's order, each as an expression that names it:
// array elements in order, struct members in order, matrix rows (`m[0][0]`, `m[0][1]` ...), vector
// components (`v[0]` ...). fxc flattens aggregates this way for component-wise casts, constructors
// and brace initializers; the rewrites that spell those out for glslang share it.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

struct AggregateComponent {
    std::string access;  // `f[2]`, `a.bb[1]`
    std::string scalar;  // float, int ... (an object's type with `withObjects`)
    bool object = false;
};

// Appends the components of `access`, of type `type` with array sizes `dims`; false when one is not
// numeric (an object in a struct, unless `withObjects`: then the object is one component) or there
// are more than 64. `inStruct`: `access` is a struct member (a one-row or one-column matrix there
// is one glslang cannot build, so false too).
bool aggregateComponents(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims, const std::string& access,
                         bool inStruct, std::vector<AggregateComponent>& out, bool withObjects = false);

// Texture, sampler and buffer types (`Texture2D`, `sampler`, `RWStructuredBuffer<float>` ...).
bool isResourceType(const std::string& type);
// The register class a resource type binds to: 's' a sampler, 'u' a read-write view (RW*,
// Append/ConsumeStructuredBuffer), 't' the others; 0 for a type that is no resource.
char resourceRegisterClass(const std::string& type);

}  // namespace fxport::xlate
