// Shader profile names: "vs_3_0" -> {Vertex, 3, 0}, "ps_2_a" -> {Pixel, 2, 1},
// "ps_4_0_level_9_1" -> {Pixel, 4, 0}. Shared by the compiler and the effect-file reader.
#pragma once

#include <optional>
#include <string>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

std::optional<ShaderProfile> parseShaderProfile(const std::string& name);

}  // namespace fxport::xlate
