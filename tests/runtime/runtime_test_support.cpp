#include "runtime_test_support.h"

#include <cstdint>
#include <cstring>

namespace fxport::test {

GraphicsDevice& testDevice() {
    static std::unique_ptr<GraphicsDevice> device = [] {
        PresentationParameters p;
        p.BackBufferWidth = 64;
        p.BackBufferHeight = 64;
        return std::make_unique<GraphicsDevice>(p);
    }();
    return *device;
}

std::string runtimeFixture(const std::string& name) { return std::string(FXPORT_RUNTIME_FIXTURES) + "/" + name; }

std::vector<VertexPositionTexture> fullscreenQuad(float z) {
    VertexPositionTexture tl(Vector3(-1, 1, z), Vector2(0, 0)), tr(Vector3(1, 1, z), Vector2(1, 0)),
        bl(Vector3(-1, -1, z), Vector2(0, 1)), br(Vector3(1, -1, z), Vector2(1, 1));
    // Each triangle goes top-left -> top-right -> bottom: clockwise on screen.
    return {tl, tr, bl, bl, tr, br};
}

void drawQuad(GraphicsDevice& device, float z) {
    std::vector<VertexPositionTexture> v = fullscreenQuad(z);
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v.data(), 0, 2);
}

std::vector<float> readFloats(RenderTarget2D& target) {
    std::size_t n = std::size_t(target.Width()) * std::size_t(target.Height());
    std::vector<float> out(n * 4);
    switch (target.Format()) {
    case SurfaceFormat::Vector4: target.GetData(out.data(), out.size()); break;
    case SurfaceFormat::Color: {
        std::vector<Color> c(n);
        target.GetData(c.data(), c.size());
        for (std::size_t i = 0; i < n; ++i) {
            out[i * 4 + 0] = c[i].R / 255.0f;
            out[i * 4 + 1] = c[i].G / 255.0f;
            out[i * 4 + 2] = c[i].B / 255.0f;
            out[i * 4 + 3] = c[i].A / 255.0f;
        }
        break;
    }
    default: throw std::runtime_error("readFloats: format not supported by the test helper");
    }
    return out;
}

}  // namespace fxport::test
