// Matrix swizzles of several elements (`_m30_m31_m32`, `_41_42_43`, `_11_22_33_44`) in shaders:
// xlate lowers them (xlate/src/rewrite/matrix_swizzle.cpp) because glslang 12 crashes on them; each value is
// checked against the element HLSL names, taken from the XNA matrix on the CPU (HLSL M[r][c] is XNA
// M(r+1)(c+1), docs/DESIGN.md).
#include <gtest/gtest.h>

#include <array>
#include <functional>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::runtimeFixture;
using test::testDevice;

// HLSL m[r][c] (zero-based) of an XNA matrix.
float at(const Matrix& m, int r, int c) { return m.data()[r * 4 + c]; }

Matrix sample(float base) {
    Matrix m;
    for (int i = 0; i < 16; ++i) m.data()[i] = base + 0.25f * static_cast<float>(i) - 1.5f * static_cast<float>(i % 3);
    return m;
}

std::array<float, 4> run(Effect& effect, const std::string& technique) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    effect.CurrentTechnique = effect.Techniques[technique];
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    return {px[0], px[1], px[2], px[3]};
}

TEST(MatrixSwizzle, EachFormReadsTheElementsHlslNames) {
    Effect effect(testDevice(), runtimeFixture("MatrixSwizzle.fx"));
    const Matrix m = sample(0.5f), r = sample(-2.0f), p0 = sample(3.0f), p1 = sample(-0.75f);
    effect.Parameters["M"].SetValue(m);
    effect.Parameters["R"].SetValue(r);
    effect.Parameters["Pair"].SetValue(std::vector<Matrix>{p0, p1});

    // mul(-M._m30_m31_m32, transpose(M)): row vector times the transpose's upper 3x4 (fxc truncates
    // the matrix to the vector's size): component c = sum_k (-M[3][k]) * M[c][k].
    auto camera = [&](int c) {
        float s = 0;
        for (int k = 0; k < 3; ++k) s += -at(m, 3, k) * at(m, c, k);
        return s;
    };
    struct Case {
        const char* technique;
        std::array<float, 4> expected;
    };
    const Case cases[] = {
        {"RowZeroBased", {at(m, 3, 0), at(m, 3, 1), at(m, 3, 2), 1}},
        {"RowOneBased", {-at(m, 3, 0), -at(m, 3, 1), -at(m, 3, 2), 1}},
        {"Camera", {camera(0), camera(1), camera(2), 1}},
        {"Diagonal", {at(m, 0, 0), at(m, 1, 1), at(m, 2, 2), at(m, 3, 3)}},
        {"ColumnRowMajor", {at(r, 0, 1), at(r, 1, 1), at(r, 2, 1), 1}},
        {"Indexed", {at(p1, 1, 0), at(p1, 0, 1), at(p0, 2, 3), at(p0, 3, 2)}},
        {"OfCall", {at(m, 3, 0), at(m, 3, 1), at(m, 3, 2), 1}},
        {"Write", {7, 8, at(m, 1, 2), at(m, 1, 3)}},
    };
    for (const Case& c : cases) {
        std::array<float, 4> got = run(effect, c.technique);
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR(got[k], c.expected[k], 1e-4 * (1 + std::abs(c.expected[k]))) << c.technique << " component " << k;
    }
}

}  // namespace
}  // namespace fxport
