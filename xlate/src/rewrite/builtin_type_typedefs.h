// A typedef inside a function may name a built-in scalar, vector or matrix type: fxc then reads
// that name as the alias until the block closes (`typedef fLoat float; float v = {2, 3};` declares
// a float2 when fLoat is float2; `typedef float float;` changes nothing), as vkd3d's type-names L1
// pins. glslang refuses a keyword as a typedef's name. Such a typedef is blanked and the name, where
// it stands in the rest of its block, is spelled as the aliased type (itself read with the aliases
// of the enclosing blocks). Runs on the preprocessed text, before the parser; lines stay.
#pragma once

#include <string>

namespace fxport::xlate {

std::string builtinTypeTypedefsResolved(const std::string& preprocessed);

}  // namespace fxport::xlate
