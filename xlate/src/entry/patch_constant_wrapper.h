// glslang 12 cannot compile a hull shader whose patch-constant function hands its results back
// through `out` parameters (`void PC(InputPatch<V, 3> p, out PatchData o)`: "unable to find patch
// constant function built-in variable"); it compiles the same function when it returns them. fxc
// takes both. This makes a function that calls the effect's one and returns what it wrote, and
// points the hull shader's [patchconstantfunc] at it (a front-end workaround, see front_end_hazards.h).
#pragma once

#include <optional>
#include <string>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

struct PatchConstantWrapper {
    std::string name;  // the function the hull shader is pointed at
    std::string code;  // HLSL to append after the effect's own
};

// A function returning what `function` returns or writes to its out parameters, under a name of
// its own (so an overloaded name is no longer ambiguous); nullopt where it has inout parameters
// the wrapper would have to pass in, or outputs nothing.
std::optional<PatchConstantWrapper> patchConstantWrapper(const FxFunction& function);

// fxc gives a hull shader whose control-point function outputs nothing (`void main(InputPatch<V, 3>
// p)`) a pass-through control-point phase: output point i is input point i. glslang leaves the
// outputs unwritten. This is an entry point with the same attributes that calls it and returns
// p[SV_OutputControlPointID]; nullopt where the entry outputs something or no InputPatch says
// what a control point is.
std::optional<PatchConstantWrapper> passThroughHullEntry(const FxFunction& entry, const FxFunction* patchConstantFunction);

// `source` with every [patchconstantfunc("from")] naming `to` instead (line count kept).
std::string redirectPatchConstantFunction(const std::string& source, const std::string& from, const std::string& to);

}  // namespace fxport::xlate
