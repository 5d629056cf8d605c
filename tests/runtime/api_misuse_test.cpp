// API misuse (issue 26 item 11): objects of another device, negative offsets, enum values made by
// casts, indices past the vertices, one target bound twice and sizes past what fxport makes are
// each an error naming the object and the value. Each case runs in a child process (a gtest
// death-test fork) that must exit normally having caught the error.
#include <gtest/gtest.h>

#include <climits>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/vertex_buffer.h"
#include "fxport/graphics/vertex_types.h"

namespace fxport {
namespace {

PresentationParameters small() {
    PresentationParameters p;
    p.BackBufferWidth = 64;
    p.BackBufferHeight = 64;
    return p;
}

// Runs `misuse` in the child: prints what it threw ("refused: ...") or "accepted", exits 0.
template <class F> void misuseAndExit(F&& misuse) {
    try {
        misuse();
        std::cerr << "accepted\n";
    } catch (const std::exception& e) {
        std::cerr << "refused: " << e.what() << "\n";
    }
    std::exit(0);
}

const std::vector<VertexPositionColor> kTriangle = {{Vector3(0, 0, 0), Color::White}, {Vector3(1, 0, 0), Color::White}, {Vector3(0, 1, 0), Color::White}};

TEST(ApiMisuse, VertexBufferOfAnotherDeviceIsRefused) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small()), b(small());
                    VertexBuffer buffer(b, VertexPositionColor::VertexDeclaration, 3, BufferUsage::None);
                    a.SetVertexBuffer(buffer);
                }),
                ::testing::ExitedWithCode(0), "refused: GraphicsDevice.SetVertexBuffer: VertexBuffer.* another GraphicsDevice");
}

TEST(ApiMisuse, TextureOfAnotherDeviceIsRefusedAtTheDraw) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small()), b(small());
                    Texture2D texture(b, 2, 2, false, SurfaceFormat::Color);
                    SpriteBatch batch(a);
                    batch.Begin();
                    batch.Draw(texture, Rectangle(0, 0, 8, 8), Color::White);
                    batch.End();
                }),
                ::testing::ExitedWithCode(0), "refused: .*another GraphicsDevice");
}

TEST(ApiMisuse, NegativeSetDataOffsetIsRefused) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small());
                    VertexBuffer buffer(a, VertexPositionColor::VertexDeclaration, 3, BufferUsage::None);
                    buffer.SetData(-16, kTriangle.data(), 1);
                }),
                ::testing::ExitedWithCode(0), "refused: VertexBuffer.*SetData at byte offset -16, which is negative");
}

TEST(ApiMisuse, IntMaxVertexBufferIsRefusedNamingItsSize) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small());
                    VertexBuffer buffer(a, VertexPositionColor::VertexDeclaration, INT_MAX, BufferUsage::None);
                }),
                ::testing::ExitedWithCode(0), "refused: VertexBuffer.*2147483647 elements of 16 bytes.*at most 1024 MiB");
}

TEST(ApiMisuse, PrimitiveTypeMadeByACastIsRefused) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small());
                    a.DrawUserPrimitives(static_cast<PrimitiveType>(77), kTriangle.data(), 0, 1);
                }),
                ::testing::ExitedWithCode(0), "refused: DrawUserPrimitives: PrimitiveType\\(77\\) is not a primitive type");
}

TEST(ApiMisuse, IndexBeyondTheVerticesIsRefused) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small());
                    const std::uint16_t indices[3] = {0, 1, 9};
                    a.DrawUserIndexedPrimitives(PrimitiveType::TriangleList, kTriangle.data(), 0, 3, indices, 0, 1);
                }),
                ::testing::ExitedWithCode(0), "refused: DrawUserIndexedPrimitives: index 2 is 9, beyond the 3 vertices given");
}

TEST(ApiMisuse, SameTargetTwiceIsRefused) {
    EXPECT_EXIT(misuseAndExit([] {
                    GraphicsDevice a(small());
                    RenderTarget2D target(a, 8, 8);
                    a.SetRenderTargets({RenderTargetBinding(&target), RenderTargetBinding(&target)});
                }),
                ::testing::ExitedWithCode(0), "refused: GraphicsDevice.SetRenderTargets: binding 1 .* is binding 0 too");
}

TEST(ApiMisuse, HugeBackBufferIsAnErrorNamingTheSize) {
    EXPECT_EXIT(misuseAndExit([] {
                    PresentationParameters p;
                    p.BackBufferWidth = 100000;
                    p.BackBufferHeight = 100000;
                    GraphicsDevice a(p);
                }),
                ::testing::ExitedWithCode(0), "refused: GraphicsDevice: back buffer size 100000x100000 is larger than 16384x16384");
}

}  // namespace
}  // namespace fxport
