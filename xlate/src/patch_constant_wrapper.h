// glslang 12 cannot compile a hull shader whose patch-constant function hands its results back
// through `out` parameters (`void PC(InputPatch<V, 3> p, out PatchData o)`: "unable to find patch
// constant function built-in variable"); it compiles the same function when it returns them. fxc
// takes both. This makes a function that calls the effect's one and returns what it wrote, and
// points the hull shader's [patchconstantfunc] at it (a front-end workaround, see front_end_hazards.h).
#pragma once

#include <optional>
#include <string>

#include "fx_syntax.h"

namespace fxport::xlate {

struct PatchConstantWrapper {
    std::string name;  // the function the hull shader is pointed at
    std::string code;  // HLSL to append after the effect's own
};

// nullopt when `function` needs none (it returns its results, or has no out parameters, or has
// inout ones the wrapper would have to pass in).
std::optional<PatchConstantWrapper> patchConstantWrapper(const FxFunction& function);

// `source` with every [patchconstantfunc("from")] naming `to` instead (line count kept).
std::string redirectPatchConstantFunction(const std::string& source, const std::string& from, const std::string& to);

}  // namespace fxport::xlate
