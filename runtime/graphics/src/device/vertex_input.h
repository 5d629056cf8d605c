// INTERNAL, GL-free: which element of a VertexDeclaration feeds each input of a vertex shader, by
// semantic as D3D matches them (device/vertex_input.cpp). The VAO built from the answer is the
// backend's; the matching and its error are the device core's.
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics/vertex_declaration.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

// The element feeding `input`. Throws InvalidOperation naming `shaderName` and the missing
// semantic when the declaration has none (XNA's "...Normal0 is missing"), never a silent default.
const VertexElement& vertexElementFor(const VertexDeclaration& declaration, const xlate::VertexInput& input,
                                      const std::string& shaderName);

// vertexElementFor for every input of a vertex shader, in the shader's input order.
std::vector<const VertexElement*> vertexElementsFor(const VertexDeclaration& declaration,
                                                     const std::vector<xlate::VertexInput>& inputs,
                                                     const std::string& shaderName);

}  // namespace fxport
