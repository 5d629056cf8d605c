// VertexDeclaration: the layout of one vertex, as XNA describes it. At draw time each element is
// matched to the vertex shader input with the same semantic (Position0 -> POSITION0,
// TextureCoordinate1 -> TEXCOORD1 ...); shader inputs without an element read (0,0,0,1) as in D3D.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fxport {

enum class VertexElementFormat : std::uint8_t {
    Single, Vector2, Vector3, Vector4, Color, Byte4, Short2, Short4,
    NormalizedShort2, NormalizedShort4, HalfVector2, HalfVector4,
};
enum class VertexElementUsage : std::uint8_t {
    Position, Color, TextureCoordinate, Normal, Binormal, Tangent, BlendIndices, BlendWeight,
    Depth, Fog, PointSize, Sample, TessellateFactor,
};

struct VertexElement {
    int Offset = 0;
    fxport::VertexElementFormat VertexElementFormat = fxport::VertexElementFormat::Vector3;
    fxport::VertexElementUsage VertexElementUsage = fxport::VertexElementUsage::Position;
    int UsageIndex = 0;

    VertexElement() = default;
    VertexElement(int offset, fxport::VertexElementFormat format, fxport::VertexElementUsage usage, int usageIndex)
        : Offset(offset), VertexElementFormat(format), VertexElementUsage(usage), UsageIndex(usageIndex) {}
    bool operator==(const VertexElement&) const = default;
};

class VertexDeclaration {
public:
    VertexDeclaration() = default;
    // Stride = end of the last element.
    explicit VertexDeclaration(std::vector<VertexElement> elements);
    VertexDeclaration(int vertexStride, std::vector<VertexElement> elements);

    int VertexStride() const { return stride_; }
    const std::vector<VertexElement>& GetVertexElements() const { return elements_; }
    bool operator==(const VertexDeclaration& other) const {
        return stride_ == other.stride_ && elements_ == other.elements_;
    }

private:
    int stride_ = 0;
    std::vector<VertexElement> elements_;
};

int vertexElementSize(VertexElementFormat format);
// "POSITION0", "TEXCOORD1", ...: the HLSL semantic an element feeds.
std::string vertexElementSemantic(const VertexElement& element);

}  // namespace fxport
