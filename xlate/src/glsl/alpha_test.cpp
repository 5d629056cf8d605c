// The alpha-test variant of a pixel shader's GLSL (see alpha_test.h): the alpha test alone of the
// fixed-function variants (fixed_function.h).
#include "fxport/xlate/alpha_test.h"

#include "fxport/xlate/fixed_function.h"

namespace fxport::xlate {

std::optional<std::string> alphaTestVariant(const std::string& glsl) {
    PixelFixedFunction wanted;
    wanted.alphaTest = true;
    std::string why;
    return pixelFixedFunctionVariant(glsl, wanted, why);
}

}  // namespace fxport::xlate
