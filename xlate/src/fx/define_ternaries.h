// `?:` in a macro that an #if evaluates: Source SDK's portal_ps2x.fxc defines
// `USESTATICTEXTURE (((ADDSTATIC == 1) && (HASSTATICTEXTURE == 1))?(1):(0))` and tests it in
// `#if( (HASALPHAMASK == 1) || (USESTATICTEXTURE == 1) )`. A C preprocessor (fxc's) evaluates ?:
// there; glslang's #if evaluator has no ?: ("'preprocessor evaluation' : expected ')'"). Where both
// branches of a parenthesised ?: in a one-line #define body are integer literals, `C ? (a) : (b)` is spelled
// `(((C) != 0) * (a) + ((C) == 0) * (b))`, the same integer in #if and in code (both branches are
// constants, so evaluating both changes nothing). Other ?: are left as written.
#pragma once

#include <string>

namespace fxport::xlate {

// Rewrites the #define line text[start, end); `end` follows the line's new length.
void integerTernariesAsArithmetic(std::string& text, size_t start, size_t& end);

}  // namespace fxport::xlate
