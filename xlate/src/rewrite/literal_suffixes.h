// Integer literals with fxc's `l` suffix (`3l`, `3lu`, `0x10L`): a 32-bit int (or uint with `u`)
// to fxc; glslang's HLSL scanner stops at the `l` ("')' : Expected"; vkd3d's function-overload
// pins `func(3lu)`; glslang's preprocessor even hands `3lu` on as `3 u`). The `l` is dropped on
// the preprocessed text (`3 u` joined again), before the parser, so every later rewrite and check
// sees `3u`, and `int(3)`, `int(0x10)` for an int: fxc's `3l` is typed, its `3` is a literal
// that int and uint overloads tie for (the line stays: only the literal's text changes).
#pragma once

#include <string>

namespace fxport::xlate {

std::string longLiteralSuffixesDropped(const std::string& preprocessed);

// Floating literals with fxc's `h` suffix (`0.1h`, OpenXRay's `#define DEPTH_EPSILON 0.1h`): fxc
// computes `half` as `float` (a 32-bit value in every profile it compiles to), so `2 * 0.1h` is a
// float product to fxc. glslang refuses an int operand beside the literal ("Could not perform
// requested binary operation", glslangValidator alike). The suffix is dropped on the
// preprocessed text, so every later rewrite and check sees the float literal fxc computes with.
std::string halfLiteralSuffixesDropped(const std::string& preprocessed);

}  // namespace fxport::xlate
