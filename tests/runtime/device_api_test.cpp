// Surface formats, API misuse and resource lifetime of the runtime.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "fxport/platform/gl.h"
#include "fxport/xlate/effect_file.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::runtimeFixture;
using test::testDevice;

std::uint16_t toHalf(float f) {
    // Exact for the values used here (small dyadic fractions).
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    std::uint32_t sign = (bits >> 16) & 0x8000u;
    int exponent = int((bits >> 23) & 0xff) - 127 + 15;
    std::uint32_t mantissa = (bits >> 13) & 0x3ffu;
    if ((bits & 0x7fffffffu) == 0) return std::uint16_t(sign);
    return std::uint16_t(sign | (std::uint32_t(exponent) << 10) | mantissa);
}

// Every format the seeds use keeps what SetData wrote (bit for bit), and a render of
// (0.25, 0.5, 0.75, 1) into it reads back within the format's precision.
TEST(SurfaceFormats, SetDataGetDataRoundTripAndRenderPrecision) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    effect.CurrentTechnique = effect.Techniques["SolidColor"];
    effect.Parameters["Color"].SetValue(Vector4(0.25f, 0.5f, 0.75f, 1.0f));
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;

    struct Case {
        SurfaceFormat format;
        int channels;
        double tolerance;  // of the rendered value
    } cases[] = {
        {SurfaceFormat::Color, 4, 0.5 / 255},      {SurfaceFormat::Rgba64, 4, 0.5 / 65535},
        {SurfaceFormat::Vector2, 2, 0},            {SurfaceFormat::Vector4, 4, 0},
        {SurfaceFormat::Single, 1, 0},             {SurfaceFormat::HalfSingle, 1, 0},
        {SurfaceFormat::HalfVector2, 2, 0},        {SurfaceFormat::HalfVector4, 4, 0},
        {SurfaceFormat::HdrBlendable, 4, 0},
    };
    const float rendered[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    for (const Case& c : cases) {
        SCOPED_TRACE(surfaceFormatName(c.format));
        const int W = 3, H = 2, bpp = bytesPerPixel(c.format);
        RenderTarget2D target(device, W, H, false, c.format);
        // Round trip of arbitrary bytes that are valid values of the format.
        std::vector<std::uint8_t> bytes(std::size_t(W * H * bpp));
        for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::uint8_t(i * 37 + 11);
        if (c.format == SurfaceFormat::Single || c.format == SurfaceFormat::Vector2 || c.format == SurfaceFormat::Vector4) {
            for (std::size_t i = 0; i < bytes.size() / 4; ++i) {
                float f = float(i) * 0.375f - 2.0f;
                std::memcpy(&bytes[i * 4], &f, 4);
            }
        } else if (c.format == SurfaceFormat::HalfSingle || c.format == SurfaceFormat::HalfVector2 ||
                   c.format == SurfaceFormat::HalfVector4 || c.format == SurfaceFormat::HdrBlendable) {
            for (std::size_t i = 0; i < bytes.size() / 2; ++i) {
                std::uint16_t h = toHalf(float(i) * 0.125f - 1.0f);
                std::memcpy(&bytes[i * 2], &h, 2);
            }
        }
        target.setData(0, nullptr, bytes.data(), bytes.size());
        std::vector<std::uint8_t> back(bytes.size());
        target.getData(0, back.data(), back.size());
        EXPECT_EQ(back, bytes);

        device.SetRenderTarget(target);
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        target.getData(0, back.data(), back.size());
        for (int ch = 0; ch < c.channels; ++ch) {
            double value = 0;
            if (c.format == SurfaceFormat::Color) value = back[std::size_t(ch)] / 255.0;
            else if (c.format == SurfaceFormat::Rgba64) {
                std::uint16_t u;
                std::memcpy(&u, &back[std::size_t(ch) * 2], 2);
                value = u / 65535.0;
            } else if (bpp / c.channels == 4) {
                float f;
                std::memcpy(&f, &back[std::size_t(ch) * 4], 4);
                value = f;
            } else {
                std::uint16_t h;
                std::memcpy(&h, &back[std::size_t(ch) * 2], 2);
                EXPECT_EQ(h, toHalf(rendered[ch])) << "channel " << ch;
                continue;
            }
            EXPECT_NEAR(value, rendered[ch], c.tolerance + 1e-9) << "channel " << ch;
        }
    }
}

// D3D9 reads missing channels of one/two-channel formats as 1 (R32F samples as (r,1,1,1)).
// An integer target cleared through Clear holds integers (D3D's rule: truncated toward zero,
// clamped to the channel), not what GL makes of a float clear of an integer buffer (undefined).
TEST(SurfaceFormats, IntegerTargetsClearWithIntegers) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Rgba32SInt);
    device.SetRenderTarget(&target);
    device.Clear(ClearOptions::Target, Vector4(-3.75f, 7.9f, 1e10f, 0.0f), 1.0f, 0);
    device.SetRenderTarget(nullptr);
    std::vector<std::int32_t> got(16, 12345);
    target.GetData(got.data(), got.size());
    const std::int32_t want[4] = {-3, 7, 2147483647, 0};
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], want[i % 4]) << "word " << i;
}

TEST(SurfaceFormats, MissingChannelsSampleAsOneLikeD3D9) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    Texture2D tex(device, 1, 1, false, SurfaceFormat::Single);
    const float value = 0.5f;
    tex.SetData(&value, 1);
    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    effect.Parameters["Tex"].SetValue(tex);
    effect.CurrentTechnique = effect.Techniques["Sample"];
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    float px[4];
    target.GetData(px, 4);
    EXPECT_EQ(px[0], 0.5f);
    EXPECT_EQ(px[1], 1.0f);
    EXPECT_EQ(px[2], 1.0f);
    EXPECT_EQ(px[3], 1.0f);
}

template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ApiMisuse, ClearErrorsNamingTheThing) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));

    std::string unknown = errorOf([&] { effect.Parameters["Wrold"].SetValue(1.0f); });
    EXPECT_NE(unknown.find("Conventions.fx"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("'Wrold'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("Transform"), std::string::npos) << unknown;  // lists what exists
    EXPECT_THROW(effect.Parameters["Wrold"], ArgumentError);

    std::string wrongType = errorOf([&] { effect.Parameters["Transform"].SetValue(Vector3(1, 2, 3)); });
    EXPECT_NE(wrongType.find("'Transform' (float4x4)"), std::string::npos) << wrongType;
    EXPECT_NE(wrongType.find("SetValue(Vector3)"), std::string::npos) << wrongType;
    EXPECT_THROW(effect.Parameters["Color"].SetValue(1.0f), ArgumentError);
    EXPECT_THROW(effect.Parameters["Color"].SetValue(true), ArgumentError);  // a float4 is not a scalar
    Texture2D tex(device, 1, 1);
    EXPECT_THROW(effect.Parameters["Color"].SetValue(tex), ArgumentError);
    EXPECT_THROW(effect.Parameters["Tex"].SetValue(Vector4()), ArgumentError);

    std::vector<Vector4> tooMany(2);
    std::string size = errorOf([&] { effect.Parameters["Color"].SetValue(tooMany); });
    EXPECT_NE(size.find("'Color'"), std::string::npos) << size;
    std::vector<float> floats(17);
    EXPECT_THROW(effect.Parameters["Transform"].SetValue(floats), ArgumentError);

    std::string technique = errorOf([&] { effect.Techniques["Nope"]; });
    EXPECT_NE(technique.find("'Nope'"), std::string::npos) << technique;
    EXPECT_NE(technique.find("SolidColor"), std::string::npos) << technique;

    int limit = device.maxTextureSize();
    std::string tooLarge = errorOf([&] { RenderTarget2D big(device, limit + 1, 4); });
    EXPECT_NE(tooLarge.find("RenderTarget2D"), std::string::npos) << tooLarge;
    EXPECT_NE(tooLarge.find(std::to_string(limit + 1)), std::string::npos) << tooLarge;
    EXPECT_THROW(RenderTarget2D(device, 0, 4), ArgumentError);

    // Sampling the texture that is being rendered to.
    RenderTarget2D target(device, 2, 2);
    target.Name = "LightMap";
    device.SetRenderTarget(target);
    effect.Parameters["Tex"].SetValue(target);
    effect.CurrentTechnique = effect.Techniques["Sample"];
    effect.CurrentTechnique->Passes[0].Apply();
    std::string feedback = errorOf([&] { drawQuad(device); });
    EXPECT_NE(feedback.find("'LightMap'"), std::string::npos) << feedback;
    EXPECT_NE(feedback.find("Textures[0]"), std::string::npos) << feedback;
    EXPECT_THROW(drawQuad(device), InvalidOperation);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    device.Textures[0] = nullptr;

    // Mismatched MRT sizes.
    RenderTarget2D a(device, 2, 2), b(device, 4, 4);
    EXPECT_THROW(device.SetRenderTargets({a, b}), ArgumentError);
    // A plain texture is not a render target.
    EXPECT_THROW(device.SetRenderTargets({RenderTargetBinding(reinterpret_cast<RenderTarget2D*>(&tex))}), ArgumentError);
    // Use after Dispose.
    Texture2D gone(device, 1, 1);
    gone.Dispose();
    Color c;
    EXPECT_THROW(gone.GetData(&c, 1), InvalidOperation);
    // Wrong SetData size, said in the caller's units (elements), not bytes.
    EXPECT_THROW(tex.SetData(std::vector<Color>(2)), ArgumentError);
    Texture2D square(device, 16, 16);
    std::string count = errorOf([&] { square.SetData(std::vector<Color>(100)); });
    EXPECT_NE(count.find("got 100 elements of 4 bytes"), std::string::npos) << count;
    EXPECT_NE(count.find("needs 256 elements of 4 bytes"), std::string::npos) << count;
}

TEST(ApiMisuse, DrawingWithNoPassAppliedThrows) {
    PresentationParameters p;
    p.BackBufferWidth = p.BackBufferHeight = 4;
    GraphicsDevice fresh(p);  // nothing applied yet on this device
    std::string message = errorOf([&] { drawQuad(fresh); });
    EXPECT_NE(message.find("no effect pass is applied"), std::string::npos) << message;
    EXPECT_NE(message.find("DrawUserPrimitives"), std::string::npos) << message;
}

// After every resource is destroyed, no GL object made for it is left alive: the device's count
// returns to where it was, and GL no longer knows the names.
TEST(ResourceLifetime, NothingLeftAliveAfterDestruction) {
    GraphicsDevice& device = testDevice();
    GpuObjectCounts before = device.liveGpuObjects();
    std::vector<GLuint> textureNames, bufferNames;
    {
        Effect effect(device, runtimeFixture("Conventions.fx"));
        RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8);
        RenderTargetCube cube(device, 4, false, SurfaceFormat::Single, DepthFormat::Depth16);
        Texture2D texture(device, 2, 2, true);
        VertexBuffer vb(device, VertexPositionTexture::VertexDeclaration, 6);
        IndexBuffer ib(device, IndexElementSize::SixteenBits, 6);
        std::vector<VertexPositionTexture> quad = test::fullscreenQuad();
        vb.SetData(quad);
        const std::uint16_t idx[6] = {0, 1, 2, 3, 4, 5};
        ib.SetData(idx, 6);
        GpuTimer timer(device);
        timer.Begin("draw");
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        effect.CurrentTechnique = effect.Techniques["Sample"];
        effect.Parameters["Tex"].SetValue(texture);
        effect.CurrentTechnique->Passes[0].Apply();
        device.SetVertexBuffer(vb);
        device.Indices = &ib;
        device.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, 6, 0, 2);
        device.SetRenderTarget(cube, CubeMapFace::NegativeY);
        device.Clear(Color::White);
        timer.End();
        timer.EndFrame();
        timer.Finish();
        EXPECT_EQ(timer.Sections().size(), 2u);
        textureNames = {target.backendObject(), cube.backendObject(), texture.backendObject()};
        bufferNames = {vb.backendObject(), ib.backendObject()};
        EXPECT_GT(device.liveGpuObjects().total(), before.total());
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    }
    GpuObjectCounts after = device.liveGpuObjects();
    EXPECT_EQ(after.textures, before.textures);
    EXPECT_EQ(after.renderbuffers, before.renderbuffers);
    EXPECT_EQ(after.buffers, before.buffers);
    EXPECT_EQ(after.programs, before.programs);
    EXPECT_EQ(after.pipelines, before.pipelines);
    EXPECT_EQ(after.framebuffers, before.framebuffers);
    EXPECT_EQ(after.vertexArrays, before.vertexArrays);
    EXPECT_EQ(after.queries, before.queries);
    for (GLuint name : textureNames) EXPECT_FALSE(glIsTexture(name)) << name;
    for (GLuint name : bufferNames) EXPECT_FALSE(glIsBuffer(name)) << name;
    EXPECT_EQ(device.Indices, nullptr);  // the destroyed index buffer was unbound
}

// A resource destroyed while bound is unbound everywhere (slots, effect parameters, targets).
TEST(Buffers, GetIndicesWidensEitherElementSize) {
    GraphicsDevice& device = testDevice();
    IndexBuffer narrow(device, IndexElementSize::SixteenBits, 4);
    const std::uint16_t small[4] = {0, 65535, 7, 1};
    narrow.SetData(small, 4);
    EXPECT_EQ(narrow.GetIndices(), (std::vector<std::uint32_t>{0, 65535, 7, 1}));
    IndexBuffer wide(device, IndexElementSize::ThirtyTwoBits, 3);
    const std::uint32_t large[3] = {70000, 0, 4000000000u};
    wide.SetData(large, 3);
    EXPECT_EQ(wide.GetIndices(), (std::vector<std::uint32_t>{70000, 0, 4000000000u}));
}

TEST(ResourceLifetime, DestroyedTextureIsUnboundEverywhere) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    {
        auto target = std::make_unique<RenderTarget2D>(device, 2, 2);
        device.Textures[3] = target;
        effect.Parameters["Tex"].SetValue(target);
        device.SetRenderTarget(*target);
        target.reset();
    }
    EXPECT_EQ(device.Textures[3].get(), nullptr);
    EXPECT_EQ(effect.Parameters["Tex"].GetValueTexture(), nullptr);
    EXPECT_TRUE(device.GetRenderTargets().empty());
}

// PNG out and back in: the bytes survive, top row first.
TEST(Textures, PngRoundTripKeepsTopRowFirst) {
    GraphicsDevice& device = testDevice();
    Texture2D tex(device, 3, 2);
    const Color texels[6] = {Color(255, 0, 0), Color(0, 255, 0), Color(0, 0, 255),
                             Color(10, 20, 30, 40), Color(255, 255, 255), Color(0, 0, 0)};
    tex.SetData(texels, 6);
    std::string path = ::testing::TempDir() + "/fxport_png_roundtrip.png";
    tex.SaveAsPng(path);
    std::unique_ptr<Texture2D> back = Texture2D::FromFile(device, path);
    ASSERT_EQ(back->Width(), 3);
    ASSERT_EQ(back->Height(), 2);
    std::vector<Color> px = back->GetData<Color>();
    for (int i = 0; i < 6; ++i) EXPECT_EQ(px[std::size_t(i)], texels[i]) << i;
    std::string missing = errorOf([&] { Texture2D::FromFile(device, "/nonexistent/cookie.png"); });
    EXPECT_NE(missing.find("/nonexistent/cookie.png"), std::string::npos) << missing;
}

// An effect written by `fxport compile` loads without glslang and behaves like the source.
TEST(Effects, FromCompiledFileMatchesSource) {
    GraphicsDevice& device = testDevice();
    Effect source(device, runtimeFixture("Conventions.fx"));
    std::string path = ::testing::TempDir() + "/Conventions.fxeffect";
    xlate::saveEffectFile(source.compiled(), path);
    std::unique_ptr<Effect> loaded = Effect::FromCompiledFile(device, path);
    EXPECT_EQ(loaded->Techniques.Count(), source.Techniques.Count());
    EXPECT_EQ(loaded->Parameters["Color"].GetValueVector4(), Vector4(1, 1, 1, 1));
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.BlendState = BlendState::Opaque;
    device.RasterizerState = RasterizerState::CullNone;
    device.DepthStencilState = DepthStencilState::None;
    loaded->Parameters["Color"].SetValue(Vector4(0.125f, 0.25f, 0.5f, 1));
    loaded->CurrentTechnique = loaded->Techniques["SolidColor"];
    loaded->CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<float> px = test::readFloats(target);
    EXPECT_EQ(px[0], 0.125f);
    EXPECT_EQ(px[1], 0.25f);
    EXPECT_EQ(px[2], 0.5f);
}

// Row "scissor": only the scissor rectangle is drawn when ScissorTestEnable is on; Clear ignores it.
// XNA 4 (Windows) clears a DiscardContents target when it is set -- colour to purple, depth to 1 --
// and keeps a PreserveContents one.
TEST(DeviceState, DiscardContentsTargetsAreClearedWhenSet) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    RenderTarget2D discard(device, 2, 2, false, SurfaceFormat::Color, DepthFormat::Depth24);
    RenderTarget2D preserve(device, 2, 2, false, SurfaceFormat::Color, DepthFormat::Depth24, 0,
                            RenderTargetUsage::PreserveContents);
    for (RenderTarget2D* t : {&discard, &preserve}) {
        device.SetRenderTarget(t);
        device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Color::White, 0.0f, 0);  // depth 0: nothing passes
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        device.SetRenderTarget(t);
        device.BlendState = BlendState::Opaque;
        device.RasterizerState = RasterizerState::CullNone;
        device.DepthStencilState = DepthStencilState::Default;
        effect.Parameters["Color"].SetValue(Vector4(0, 1, 0, 1));
        effect.CurrentTechnique = effect.Techniques["SolidColor"];
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device, 0.5f);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    }
    // Discard: cleared to purple and depth 1 on the second set, so the quad at z=0.5 is drawn.
    EXPECT_EQ(discard.GetData<Color>()[0], Color(0, 255, 0, 255));
    // Preserve: still white with depth 0, so the quad fails the depth test.
    EXPECT_EQ(preserve.GetData<Color>()[0], Color(255, 255, 255, 255));
    RenderTarget2D fresh(device, 1, 1);
    device.SetRenderTarget(fresh);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    EXPECT_EQ(fresh.GetData<Color>()[0], Color(68, 34, 136, 255));
    device.DepthStencilState = DepthStencilState::None;
}

// Scalars convert between int, float and bool as D3DX does (the tutorial sets a float from an int).
TEST(Effects, ScalarSettersConvertLikeD3DX) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    std::string path = ::testing::TempDir() + "/Scalars.fx";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs("float size; int count; bool flag;\n"
                   "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return float4(size, count, flag, 1); }\n"
                   "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n", f);
        std::fclose(f);
    }
    Effect scalars(device, path);
    scalars.Parameters["size"].SetValue(2048);
    EXPECT_EQ(scalars.Parameters["size"].GetValueSingle(), 2048.0f);
    scalars.Parameters["count"].SetValue(3.0f);
    EXPECT_EQ(scalars.Parameters["count"].GetValueInt32(), 3);
    scalars.Parameters["flag"].SetValue(1);
    EXPECT_TRUE(scalars.Parameters["flag"].GetValueBoolean());
    EXPECT_THROW(scalars.Parameters["size"].SetValue(Vector2(1, 2)), ArgumentError);
}

TEST(DeviceState, ScissorRectangle) {
    GraphicsDevice& device = testDevice();
    Effect effect(device, runtimeFixture("Conventions.fx"));
    RenderTarget2D target(device, 4, 4);
    device.SetRenderTarget(target);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    RasterizerState scissor = RasterizerState::CullNone;
    scissor.ScissorTestEnable = true;
    device.RasterizerState = scissor;
    device.ScissorRectangle = Rectangle(1, 0, 2, 3);  // x 1..2, y 0..2 from the top
    device.Clear(Color::Black);                       // whole target, scissor or not
    effect.Parameters["Color"].SetValue(Vector4(1, 1, 1, 1));
    effect.CurrentTechnique = effect.Techniques["SolidColor"];
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    device.RasterizerState = RasterizerState::CullNone;
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<Color> px = target.GetData<Color>();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(px[std::size_t(y * 4 + x)].R, (x >= 1 && x <= 2 && y <= 2) ? 255 : 0) << x << "," << y;
}

}  // namespace
}  // namespace fxport
