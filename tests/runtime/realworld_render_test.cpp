// Pixel tests of real-world effect constructs (issue 14): each fixture under
// tests/fixtures/realworld/wild/ is drawn headless and compared with what fxc's semantics say,
// computed here in double precision.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::testDevice;

std::string wild(const std::string& name) { return std::string(FXPORT_WILD_FIXTURES) + "/" + name; }

class RealWorldRender : public test::OpaqueDrawTest {
};

// Item 2: Texture2D/TextureCube named in SamplerState blocks, then used as objects.
TEST_F(RealWorldRender, TextureObjectsNamedInSamplersSampleLoadAndSampleLevel) {
    const int W = 4, H = 4;
    Effect effect(device, wild("texture_objects/TextureInSampler.fx"), noCache());
    Texture2D tex(device, W, H, false, SurfaceFormat::Color);
    std::vector<Color> texels(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) texels[size_t(y * W + x)] = Color(x * 60 + 7, y * 70 + 3, 200 - 10 * (x + y * W), 255 - 16 * x);
    tex.SetData(texels);
    TextureCube env(device, 1, false, SurfaceFormat::Color);
    const std::array<Color, 6> faces = {Color(255, 0, 0, 255), Color(0, 255, 0, 255), Color(0, 0, 255, 255),
                                        Color(255, 255, 0, 255), Color(0, 255, 255, 255), Color(255, 0, 255, 255)};
    for (int f = 0; f < 6; ++f) env.SetData(static_cast<CubeMapFace>(f), &faces[size_t(f)], 1);
    effect.Parameters["Tex"].SetValue(tex);
    effect.Parameters["Env"].SetValue(env);

    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    auto channel = [](const Color& c, int k) { return double(k == 0 ? c.R : k == 1 ? c.G : k == 2 ? c.B : c.A) / 255.0; };
    for (auto [direction, face] : {std::pair{Vector3(1, 0, 0), 0}, std::pair{Vector3(0, -1, 0), 3}, std::pair{Vector3(0, 0, 1), 4}}) {
        effect.Parameters["EnvDirection"].SetValue(direction);
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        std::vector<float> px = readFloats(target);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                for (int k = 0; k < 4; ++k) {
                    // SM4: pixel centre (x+0.5)/W, point filter -> texel (x, y); Load(3, 0); cube face.
                    double expected = 0.5 * channel(texels[size_t(y * W + x)], k) + 0.25 * channel(texels[3], k) +
                                      0.25 * channel(faces[size_t(face)], k);
                    EXPECT_NEAR(px[size_t(y * W + x) * 4 + size_t(k)], expected, 1e-5) << "pixel " << x << "," << y << " channel " << k << " face " << face;
                }
    }
}

// Item 5 (and 6): a pixel shader without outputs writes depth only; clip() discards. A second draw
// behind it shows where depth was written; ColorWriteEnable = false keeps the colour untouched.
void expectDepthOnlyClip(GraphicsDevice& device, Effect& effect, const char* technique, bool d3d9) {
    const int W = 8, H = 2;
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4, DepthFormat::Depth24);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Color(0, 0, 0, 0), 1.0f, 0);
    device.DepthStencilState = DepthStencilState::Default;
    effect.CurrentTechnique = effect.Techniques[technique];
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device, 0.5f);
    if (d3d9) {  // ColorWriteEnable = false: the colour is still the clear colour
        std::vector<float> px = readFloats(target);
        for (size_t i = 0; i < px.size(); ++i) EXPECT_EQ(px[i], 0.0f) << technique << " value " << i;
    }
    device.BlendState = BlendState::Opaque;  // the pass's ColorWriteEnable stays set, as on D3D9
    static Effect marker(device, test::runtimeFixture("Conventions.fx"));
    marker.Parameters["Color"].SetValue(Vector4(0.25f, 0.5f, 0.75f, 1));
    marker.CurrentTechnique = marker.Techniques["SolidColor"];
    marker.CurrentTechnique->Passes[0].Apply();
    drawQuad(device, 0.7f);  // LessEqual: drawn only where the first pass wrote no depth
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            // clip(uv.x - 0.5): SM4 pixel centres are at (x + 0.5)/W, D3D9's at x/W.
            double u = d3d9 ? double(x) / W : (x + 0.5) / W;
            bool depthWritten = u - 0.5 >= 0;
            EXPECT_EQ(px[size_t(y * W + x) * 4 + 2], depthWritten ? 0.0f : 0.75f) << technique << " pixel " << x << "," << y;
        }
    device.DepthStencilState = DepthStencilState::None;
}

TEST_F(RealWorldRender, PixelShaderWithoutOutputWritesDepthOnlyAndClips) {
    Effect effect(device, wild("depth_only/DepthOnlyClip.fx"), noCache());
    expectDepthOnlyClip(device, effect, "DepthOnly", false);
    expectDepthOnlyClip(device, effect, "DepthOnly9", true);
}

// Item 6: MonoGame's true/false/None and fxc's masks write exactly the channels they name.
TEST_F(RealWorldRender, ColorWriteEnableSpellingsMaskChannels) {
    Effect effect(device, wild("states/ColorWriteSpellings.fx"), noCache());
    Effect vertex(device, test::runtimeFixture("Conventions.fx"));
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    const std::pair<const char*, std::array<float, 4>> cases[] = {
        {"AllOn", {1, 1, 1, 1}}, {"AllOff", {0.5f, 0.5f, 0.5f, 0.5f}}, {"NoneOff", {0.5f, 0.5f, 0.5f, 0.5f}},
        {"RedGreen", {1, 1, 0.5f, 0.5f}}, {"Numeric", {0.5f, 0.5f, 0.5f, 1}}, {"Targets", {1, 1, 1, 1}}};
    for (const auto& [pass, expected] : cases) {
        device.SetRenderTarget(target);
        device.Clear(Color(0.5f, 0.5f, 0.5f, 0.5f));
        vertex.CurrentTechnique = vertex.Techniques["SolidColor"];
        vertex.CurrentTechnique->Passes[0].Apply();  // binds a vertex shader the pixel-only passes keep
        effect.CurrentTechnique->Passes[pass].Apply();
        drawQuad(device);
        std::vector<float> px = readFloats(target);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[size_t(k)], 1.0 / 255) << pass << " channel " << k;
        device.BlendState = BlendState::Opaque;
    }
}

// Item 4: fxc's implicit conversions: HalfOf(float4) uses .x, Scale(float3, float4) uses .xy and
// .x, Tint(0.5) promotes the scalar to a float4.
TEST_F(RealWorldRender, ImplicitConversionsComputeWhatFxcDoes) {
    Effect effect(device, wild("conversions/ImplicitConversions.fx"), noCache());
    const double in[4] = {0.3, 0.9, 0.5, 0.7};
    effect.Parameters["Input"].SetValue(Vector4(float(in[0]), float(in[1]), float(in[2]), float(in[3])));
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    const double expected[4] = {float(in[0]) * 0.5, double(float(in[0])) * float(in[0]), double(float(in[1])) * float(in[0]),
                                0.5 * 0.5 + 0.5 * 0.25};
    for (size_t p = 0; p < 4; ++p)
        for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(px[p * 4 + k], expected[k], 1e-6) << "pixel " << p << " channel " << k;
}

// Item 8: a vertex shader file and a pixel shader file (each with its own structs and cbuffers)
// make one Effect; cbuffer members of both are set by name.
TEST_F(RealWorldRender, LooseShaderFilesMakeAnEffectWithNamedCBufferMembers) {
    auto effect = Effect::FromShaderFiles(device, {wild("loose/Textured.vs"), "TexturedVertexShader", "vs_5_0"},
                                          {wild("loose/Textured.ps"), "TexturedPixelShader", "ps_5_0"}, noCache());
    ASSERT_EQ(effect->Techniques.Count(), 1);
    const int W = 8, H = 8, T = 4;
    Texture2D tex(device, T, T, false, SurfaceFormat::Color);
    std::vector<Color> texels(T * T);
    for (int i = 0; i < T * T; ++i) texels[size_t(i)] = Color(16 * i, 255 - 12 * i, (i * 37) % 256, 255);
    tex.SetData(texels);
    const double diffuse[4] = {0.5, 1.0, 0.25, 1.0}, tint[4] = {0.25, 0.125, 0.5, 0.0};
    effect->Parameters["worldMatrix"].SetValue(Matrix::CreateScale(0.5f));
    effect->Parameters["viewMatrix"].SetValue(Matrix::Identity);
    effect->Parameters["projectionMatrix"].SetValue(Matrix::Identity);
    effect->Parameters["diffuseColor"].SetValue(Vector4(float(diffuse[0]), float(diffuse[1]), float(diffuse[2]), float(diffuse[3])));
    effect->Parameters["vertexTint"].SetValue(Vector4(float(tint[0]), float(tint[1]), float(tint[2]), float(tint[3])));
    effect->Parameters["shaderTexture"].SetValue(tex);

    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect->CurrentTechnique->Passes[0].Apply();
    device.SamplerStates[0] = SamplerState::PointClamp;
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            // The quad scaled by 0.5 covers NDC [-0.5, 0.5]: pixels 2..5; its UV there (SM4 pixel
            // centres) is (x + 0.5) / 4 - 0.5, point-sampled from the 4x4 texture.
            bool inside = x >= 2 && x <= 5 && y >= 2 && y <= 5;
            const Color& c = texels[size_t(std::max(0, std::min(T - 1, int(std::floor(((y + 0.5) / 4 - 0.5) * T)))) * T +
                                           std::max(0, std::min(T - 1, int(std::floor(((x + 0.5) / 4 - 0.5) * T)))))];
            const double sample[4] = {c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
            for (int k = 0; k < 4; ++k) {
                double expected = inside ? sample[k] * diffuse[k] + tint[k] * 0.5 : (k == 3 ? 1.0 : 0.0);
                EXPECT_NEAR(px[size_t(y * W + x) * 4 + size_t(k)], expected, 1e-5) << "pixel " << x << "," << y << " channel " << k;
            }
        }
}

// Found in the real-world sample: matrix swizzles read from parameters (glslang's SPIR-V for them
// crashed spirv-opt). HLSL M[r][c] is XNA's M(r+1)(c+1).
TEST_F(RealWorldRender, MatrixSwizzlesReadTheElementsTheyName) {
    Effect effect(device, wild("matrix_swizzle/MatrixSwizzles.fx"), noCache());
    double v[4][4], w[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            v[r][c] = 0.1 * (r + 1) - 0.03 * c + (r == c ? 0.5 : 0.0);
            w[r][c] = 0.05 * (c + 1) + 0.2 * r;
        }
    auto toMatrix = [](const double (&m)[4][4]) {
        return Matrix(float(m[0][0]), float(m[0][1]), float(m[0][2]), float(m[0][3]), float(m[1][0]), float(m[1][1]), float(m[1][2]),
                      float(m[1][3]), float(m[2][0]), float(m[2][1]), float(m[2][2]), float(m[2][3]), float(m[3][0]), float(m[3][1]),
                      float(m[3][2]), float(m[3][3]));
    };
    effect.Parameters["View"].SetValue(toMatrix(v));
    effect.Parameters["World"].SetValue(toMatrix(w));
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    double eyeX = 0;
    for (int i = 0; i < 3; ++i) eyeX += -v[3][i] * v[0][i];  // mul(-V[3].xyz, transpose(V3x3)).x
    const double expected[4] = {eyeX, w[3][1] + w[0][0], w[1][1] * v[0][1], v[0][1] + v[2][2]};
    for (size_t p = 0; p < 4; ++p)
        for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(px[p * 4 + k], expected[k], 1e-5) << "pixel " << p << " channel " << k;
}

}  // namespace
}  // namespace fxport
