// Vertex inputs matched to declaration elements (vertex_input.h).
#include "device/vertex_input.h"

#include <cctype>

#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

std::string withoutSvPrefix(const std::string& semantic) {
    return semantic.rfind("SV_POSITION", 0) == 0 ? semantic.substr(3) : semantic;
}

}  // namespace

std::string vertexSemantic(const std::string& name, int index) {
    std::string s = name;
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s + std::to_string(index);
}

bool feedsInput(const std::string& elementSemantic, const xlate::VertexInput& input) {
    return elementSemantic == input.semantic || withoutSvPrefix(elementSemantic) == withoutSvPrefix(input.semantic);
}

// The element feeding a vertex-shader input: matched by semantic, as D3D does. An `SV_Position`
// input of an SM4+ shader takes the Position element (MonoGame's rule for XNA's usages; fxc already
// reads it as POSITION at SM2/3). An input the shader reads and the declaration lacks is an error,
// as in XNA ("...Normal0 is missing"), never a silent (0, 0, 0, 1).
const VertexElement& vertexElementFor(const VertexDeclaration& declaration, const xlate::VertexInput& input, const std::string& shaderName) {
    const VertexElement* element = nullptr;
    for (const VertexElement& e : declaration.GetVertexElements())
        if (feedsInput(vertexElementSemantic(e), input)) element = &e;
    if (!element)
        throw InvalidOperation("the current vertex declaration does not include all the elements required by the current vertex shader " +
                               shaderName + ": " + input.semantic + " is missing (a VertexElement of that usage and usage index)");
    return *element;
}

std::vector<const VertexElement*> vertexElementsFor(const VertexDeclaration& declaration,
                                                     const std::vector<xlate::VertexInput>& inputs,
                                                     const std::string& shaderName) {
    std::vector<const VertexElement*> elements;
    for (const xlate::VertexInput& input : inputs) elements.push_back(&vertexElementFor(declaration, input, shaderName));
    return elements;
}

}  // namespace fxport
