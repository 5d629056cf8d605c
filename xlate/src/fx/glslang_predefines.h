// `#undef` lines for every macro glslang's preprocessor predefines for GLSL (fxc predefines none).
#pragma once

#include <string>

namespace fxport::xlate {
const std::string& undefineGlslangPredefines();
}
