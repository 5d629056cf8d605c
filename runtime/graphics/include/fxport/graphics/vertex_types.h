// XNA's built-in vertex structures, laid out byte for byte as XNA lays them out.
#pragma once

#include "fxport/graphics/vertex_declaration.h"
#include "fxport/math.h"

namespace fxport {

struct VertexPositionColor {
    Vector3 Position;
    fxport::Color Color;
    VertexPositionColor() = default;
    VertexPositionColor(Vector3 position, fxport::Color color) : Position(position), Color(color) {}
    static const fxport::VertexDeclaration VertexDeclaration;
};

struct VertexPositionTexture {
    Vector3 Position;
    Vector2 TextureCoordinate;
    VertexPositionTexture() = default;
    VertexPositionTexture(Vector3 position, Vector2 uv) : Position(position), TextureCoordinate(uv) {}
    static const fxport::VertexDeclaration VertexDeclaration;
};

struct VertexPositionColorTexture {
    Vector3 Position;
    fxport::Color Color;
    Vector2 TextureCoordinate;
    VertexPositionColorTexture() = default;
    VertexPositionColorTexture(Vector3 position, fxport::Color color, Vector2 uv)
        : Position(position), Color(color), TextureCoordinate(uv) {}
    static const fxport::VertexDeclaration VertexDeclaration;
};

struct VertexPositionNormalTexture {
    Vector3 Position;
    Vector3 Normal;
    Vector2 TextureCoordinate;
    VertexPositionNormalTexture() = default;
    VertexPositionNormalTexture(Vector3 position, Vector3 normal, Vector2 uv)
        : Position(position), Normal(normal), TextureCoordinate(uv) {}
    static const fxport::VertexDeclaration VertexDeclaration;
};

}  // namespace fxport
