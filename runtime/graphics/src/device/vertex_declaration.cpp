#include "fxport/graphics/vertex_declaration.h"

#include <algorithm>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/vertex_types.h"

namespace fxport {

int vertexElementSize(VertexElementFormat format) {
    switch (format) {
    case VertexElementFormat::Single: return 4;
    case VertexElementFormat::Vector2: return 8;
    case VertexElementFormat::Vector3: return 12;
    case VertexElementFormat::Vector4: return 16;
    case VertexElementFormat::Color: return 4;
    case VertexElementFormat::Byte4: return 4;
    case VertexElementFormat::Short2: return 4;
    case VertexElementFormat::Short4: return 8;
    case VertexElementFormat::NormalizedShort2: return 4;
    case VertexElementFormat::NormalizedShort4: return 8;
    case VertexElementFormat::HalfVector2: return 4;
    case VertexElementFormat::HalfVector4: return 8;
    }
    return 0;
}

std::string vertexElementSemantic(const VertexElement& element) {
    static const char* const kNames[] = {
        "POSITION", "COLOR", "TEXCOORD", "NORMAL", "BINORMAL", "TANGENT", "BLENDINDICES", "BLENDWEIGHT",
        "DEPTH", "FOG", "PSIZE", "SAMPLE", "TESSFACTOR",
    };
    return std::string(kNames[std::size_t(element.VertexElementUsage)]) + std::to_string(element.UsageIndex);
}

VertexDeclaration::VertexDeclaration(std::vector<VertexElement> elements) : elements_(std::move(elements)) {
    for (const VertexElement& e : elements_)
        stride_ = std::max(stride_, e.Offset + vertexElementSize(e.VertexElementFormat));
}

VertexDeclaration::VertexDeclaration(int vertexStride, std::vector<VertexElement> elements)
    : stride_(vertexStride), elements_(std::move(elements)) {
    for (const VertexElement& e : elements_) {
        if (e.Offset < 0 || e.Offset + vertexElementSize(e.VertexElementFormat) > stride_)
            throw ArgumentError("VertexDeclaration: element " + vertexElementSemantic(e) + " at offset " +
                                std::to_string(e.Offset) + " does not fit in a vertex stride of " +
                                std::to_string(stride_) + " bytes");
    }
}

using F = VertexElementFormat;
using U = VertexElementUsage;

const VertexDeclaration VertexPositionColor::VertexDeclaration(
    16, {{0, F::Vector3, U::Position, 0}, {12, F::Color, U::Color, 0}});
const VertexDeclaration VertexPositionTexture::VertexDeclaration(
    20, {{0, F::Vector3, U::Position, 0}, {12, F::Vector2, U::TextureCoordinate, 0}});
const VertexDeclaration VertexPositionColorTexture::VertexDeclaration(
    24, {{0, F::Vector3, U::Position, 0}, {12, F::Color, U::Color, 0}, {16, F::Vector2, U::TextureCoordinate, 0}});
const VertexDeclaration VertexPositionNormalTexture::VertexDeclaration(
    32, {{0, F::Vector3, U::Position, 0}, {12, F::Vector3, U::Normal, 0}, {24, F::Vector2, U::TextureCoordinate, 0}});

static_assert(sizeof(VertexPositionColor) == 16);
static_assert(sizeof(VertexPositionTexture) == 20);
static_assert(sizeof(VertexPositionColorTexture) == 24);
static_assert(sizeof(VertexPositionNormalTexture) == 32);

}  // namespace fxport
