// fxc binds every texture, sampler and UAV a shader reads to a register; a `static` resource
// variable is no register but an alias, and fxc (10.0) accepts one only when the code it keeps
// gives it a value before use: `static Texture2D tex = real_tex;` or `tex = real_tex;` compile,
// a `static Texture2D tex;` read with no value refuses, through another static too (vkd3d's
// static-initializer: `static Texture2D tex2 = tex1`). Reads in code fxc drops (`if (0)`, a
// result nobody uses) do not count, so this is judged on the legalised module, after dead-code
// elimination: a Private variable of image, sampler or sampled-image type (or an array of them)
// with no initializer that is loaded but never stored.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fxport::xlate {

// The name (OpName) of the first static resource read without a value, "" when there is none.
std::string staticResourceReadWithoutValue(const std::vector<std::uint32_t>& words);
// The line (1-based) of `source` that declares `static ... name`, 0 when none is found.
int staticDeclarationLine(const std::string& source, const std::string& name);

// A local resource variable (or array of them) that legalisation could not replace by the one
// resource it holds (`Texture2D b[1]; b[(int)v.x] = t;`: fxc copy-propagates such stores, glslang
// does not): GLSL has no such variables, so SPIRV-Cross would write GLSL no driver takes. Its name
// (OpName), "(unnamed)" without one, "" when there is none.
std::string localResourceVariableLeft(const std::vector<std::uint32_t>& words);
// The line (1-based) of `source` that declares resource variable `name`, 0 when none is found.
int resourceDeclarationLine(const std::string& source, const std::string& name);

}  // namespace fxport::xlate
