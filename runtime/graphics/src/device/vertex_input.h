// INTERNAL, GL-free: which element of a VertexDeclaration feeds each input of a vertex shader, by
// semantic as D3D matches them (device/vertex_input.cpp). The VAO built from the answer is the
// backend's; the matching and its error are the device core's.
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics/vertex_declaration.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

// The semantic a vertex element feeds, normalised for matching: upper case with its index
// ("TEXCOORD" 1 -> "TEXCOORD1"). Any name is a semantic (D3D11's "CASCADE2" as much as XNA's).
std::string vertexSemantic(const std::string& name, int index);

// Whether an element whose semantic is `elementSemantic` (vertexSemantic's form) feeds `input`:
// equal semantics, and POSITIONn with SV_POSITIONn either way (an SM4+ `SV_Position` input takes
// XNA's Position element, MonoGame's rule; a D3D11 "SV_POSITION" element feeds a POSITION input).
bool feedsInput(const std::string& elementSemantic, const xlate::VertexInput& input);

// The element feeding `input`. Throws InvalidOperation naming `shaderName` and the missing
// semantic when the declaration has none (XNA's "...Normal0 is missing"), never a silent default.
const VertexElement& vertexElementFor(const VertexDeclaration& declaration, const xlate::VertexInput& input,
                                      const std::string& shaderName);

// vertexElementFor for every input of a vertex shader, in the shader's input order.
std::vector<const VertexElement*> vertexElementsFor(const VertexDeclaration& declaration,
                                                     const std::vector<xlate::VertexInput>& inputs,
                                                     const std::string& shaderName);

}  // namespace fxport
