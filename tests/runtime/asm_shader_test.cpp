// Shader assembly (asm { } blocks) through the whole pipeline: the effects under
// tests/fixtures/realworld/asm_sm1 are drawn on the headless device and every pixel is compared
// with a double-precision CPU evaluation of the same instructions as D3D9 defines them (modifier
// order, co-issue, ps_1_x's [-1, 1] range, constant registers filled from parameters, matrix
// columns in consecutive registers, vertex-shader results interpolated over each triangle).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::readFloats;
using test::testDevice;
using V4 = std::array<double, 4>;

// Target and quad: 7x7 pixels, texture 4x4: pixel centres (i / 7) never fall on a texel edge (i / 7 * 4
// is never a half), so point samples have one right answer (D3D9 leaves an edge to the hardware).
constexpr int kSize = 7;

std::string asmFixture(const std::string& name) { return std::string(FXPORT_ASM_FIXTURES) + "/" + name; }

double clamp1(double x) { return std::clamp(x, -1.0, 1.0); }
double sat(double x) { return std::clamp(x, 0.0, 1.0); }

// Texel (tx, ty) of the test texture, as stored (Color, 8 bits per channel).
Color texel(int tx, int ty) {
    return Color(std::uint8_t(30 + 60 * tx), std::uint8_t(200 - 40 * ty), std::uint8_t(30 + 70 * ty), std::uint8_t(255 - 80 * tx));
}
V4 texelValue(double u, double v) {
    int tx = std::min(3, int(std::floor(u * 4))), ty = std::min(3, int(std::floor(v * 4)));
    Color c = texel(tx, ty);
    return {c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
}

std::unique_ptr<Texture2D> makeTexture(GraphicsDevice& device) {
    auto tex = std::make_unique<Texture2D>(device, 4, 4);
    std::vector<Color> data;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) data.push_back(texel(x, y));
    tex->SetData(data);
    return tex;
}

// Two triangles over the target, position (u, 1 - v) in [0, 1]^2 and texture coordinate (u, v):
// (0,0) (1,0) (0,1), then (0,1) (1,0) (1,1), as tests/runtime's full-screen quad.
void drawUnitQuad(GraphicsDevice& device) {
    auto vertex = [](float u, float v) { return VertexPositionTexture(Vector3(u, 1 - v, 0), Vector2(u, v)); };
    std::vector<VertexPositionTexture> q = {vertex(0, 0), vertex(1, 0), vertex(0, 1), vertex(0, 1), vertex(1, 0), vertex(1, 1)};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, q.data(), 0, 2);
}

// The texture coordinate D3D9 rasterisation gives pixel i: its centre i / size, plus the bias
// fxport's half-pixel fix-up leaves: none across the columns, 1/256 pixel down the rows
// (docs/DESIGN.md, "D3D9 pixel centres").
double columnCoordinate(int i) { return double(i) / kSize; }
double rowCoordinate(int i) { return (i + 1.0 / 256) / kSize; }

// A vertex-shader output f(u, v) computed at the four corners, interpolated at (u, v) over the
// triangle of the quad that holds it (the diagonal is u + v = 1).
template <class F> V4 interpolate(F f, double u, double v) {
    V4 out{};
    V4 f00 = f(0, 0), f10 = f(1, 0), f01 = f(0, 1), f11 = f(1, 1);
    for (int k = 0; k < 4; ++k)
        out[k] = u + v <= 1 ? (1 - u - v) * f00[k] + u * f10[k] + v * f01[k] : (1 - v) * f10[k] + (u + v - 1) * f11[k] + (1 - u) * f01[k];
    return out;
}

class AsmShaders : public test::OpaqueDrawTest {
protected:
    template <class Expected> void expectPixels(RenderTarget2D& target, Expected expected, double tolerance) {
        std::vector<float> px = readFloats(target);
        int mismatches = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                V4 e = expected(columnCoordinate(x), rowCoordinate(y));
                for (int k = 0; k < 4; ++k) {
                    double got = px[std::size_t((y * kSize + x) * 4 + k)];
                    if (std::abs(got - e[k]) > tolerance && ++mismatches <= 12)
                        ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": got " << got << ", expected " << e[k];
                }
            }
        EXPECT_EQ(mismatches, 0);
    }
};

// ps_1_1: tex, texcoord, def, _bx2/_bias/1-/- sources, _x2/_d2/_x4/_sat results, masks, selectors,
// co-issued pairs reading the register their partner writes, cnd on r0.a, lrp, and constants
// clamped to ps_1_x's [-1, 1] (Tint.x = 1.5 and Tint.z = -2 read as 1 and -1).
TEST_F(AsmShaders, Ps11ModifiersCoissueAndRange) {
    Effect effect(device, asmFixture("AsmPs11Modifiers.fx"));
    auto tex = makeTexture(device);
    effect.Parameters["Tex"].SetValue(tex);
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawUnitQuad(device);

    const V4 c0{clamp1(1.5), 0.5, clamp1(-2.0), 1.0}, c1{0.6, -0.3, 0.9, 0.0}, c2{0.25, 0.5, 0.75, 1.0};
    expectPixels(
        target,
        [&](double u, double v) {
            V4 t0 = texelValue(u, v);
            V4 t1{sat(u), sat(v), sat(0.5 * (u + v)), 1.0};
            V4 v0{u, 1 - v, 0.5, 0.25 + 0.5 * v};
            V4 r0, r1;
            for (int k = 0; k < 4; ++k) r0[k] = clamp1(t0[k] * c0[k]);                                       // mul
            for (int k = 0; k < 4; ++k) r1[k] = clamp1(2 * ((2 * (t1[k] - 0.5)) * (v0[k] - 0.5) + c2[k]));  // mad_x2
            double dp = clamp1(sat(r1[0] * c1[0] + r1[1] * c1[1] + r1[2] * c1[2]));                       // dp3_sat r1.rgb
            double r1b = r1[2];                                                                              // +mov r1.a, r1.b
            r1 = {dp, dp, dp, clamp1(r1b)};
            double oldA = r0[3];
            for (int k = 0; k < 3; ++k) r0[k] = clamp1((1 - t1[k]) + v0[3] * (r0[k] - (1 - t1[k])));  // lrp r0.rgb
            r0[3] = clamp1(0.5 * (t0[2] + -(oldA - 0.5)));                                             // +add_d2 r0.a, t0.b, -r0.a_bias
            for (int k = 0; k < 2; ++k) r1[k] = clamp1((r1[k] - c2[2]) * 4);                           // sub_x4 r1.rg
            V4 out = r0[3] > 0.5 ? r0 : r1;                                                            // cnd r0, r0.a, r0, r1
            for (double& x : out) x = sat(x);                                                          // r0 -> colour
            return out;
        },
        2e-3);
}

// vs_1_1 (m4x4 with the matrix from VertexShaderConstant4[0] = <WorldViewProj>, a constant set
// through VertexShaderConstant1[4], slt/sge/min/max/frc/mad, masks) feeding ps_2_0 (texld through
// Texture[0] = <Tex> and MinFilter[0] = Point, cmp, rsq, rcp, log, exp, pow, nrm, abs, mad).
TEST_F(AsmShaders, Vs11WithPs20) {
    Effect effect(device, asmFixture("AsmVs11Ps20.fx"));
    auto tex = makeTexture(device);
    effect.Parameters["Tex"].SetValue(tex);
    // Position (x, y) in [0, 1]^2 -> NDC (2x - 1, 2y - 1). A transposed upload would put the
    // translation into w and draw nothing like the quad.
    effect.Parameters["WorldViewProj"].SetValue(Matrix::CreateScale(2, 2, 1) * Matrix::CreateTranslation(-1, -1, 0));
    effect.Parameters["Scale"].SetValue(Vector4(0.75f, 1.25f, 0, 0));
    const V4 gain{0.5, -0.25, 1.0, 2.0};
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawUnitQuad(device);

    auto oT1 = [](double u, double v) { return V4{u * 0.75, v * 1.25, u * v, 1.0}; };
    auto oD0 = [](double u, double v) {
        double f = 3 * u - std::floor(3 * u);
        V4 r1{u < 0.5 ? 1.0 : 0.0, v >= 0.5 ? 1.0 : 0.0, std::max(u, v), std::min(f, 0.5)};
        for (double& x : r1) x = sat(x * 0.5);  // mad oD0, r1, 0.5, 0; D3D9 clamps oD# to [0, 1]
        return r1;
    };
    expectPixels(
        target,
        [&](double u, double v) {
            V4 t1 = interpolate(oT1, u, v), v0 = interpolate(oD0, u, v), r0 = texelValue(u, v);
            V4 r1, r2, r3, r4, r6, r7, r8;
            for (int k = 0; k < 4; ++k) {
                r1[k] = t1[k] - 0.5;
                r2[k] = r1[k] >= 0 ? r0[k] : v0[k];
                r3[k] = r1[k] * r1[k] + 0.25;
                r7[k] = std::abs(r1[k]);
            }
            r4 = {1 / std::sqrt(std::abs(r3[0])), 1 / r3[1], std::log2(std::abs(r3[2])), std::exp2(r1[0])};
            double r5 = std::pow(std::abs(r3[0]), 2.0);
            double len = std::sqrt(r1[0] * r1[0] + r1[1] * r1[1] + r1[2] * r1[2]);
            for (int k = 0; k < 4; ++k) {
                r6[k] = r1[k] / len;
                r8[k] = r4[k] * 0.25 + r2[k];
                r8[k] = r6[k] * gain[k] + r8[k];
                r8[k] += r7[k];
                r8[k] = r5 * 0.25 + r8[k];
            }
            return r8;
        },
        2e-3);
}

// vs_2_0 registers filled from pass states (a macro of them, repeated per technique): a row_major
// matrix (rows in c0..c3), a float4x3 (column_major: its three columns in c4..c6), an array read
// through mova + c[a0.x + 8], literal constants; lit, dst, sincos, expp, logp. Each technique's HLSL
// pixel shader shows one output; vertex results are interpolated over each triangle.
TEST_F(AsmShaders, Vs20RegisterBindingsAndMacros) {
    Effect effect(device, asmFixture("AsmVs20Registers.fx"));
    // row_major: register i holds row i, so the shader computes M * p; the host sets the transpose
    // of XNA's row-vector matrix, as D3D9 code for row_major constants did.
    effect.Parameters["ViewProj"].SetValueTranspose(Matrix::CreateScale(2, 2, 1) * Matrix::CreateTranslation(-1, -1, 0));
    Matrix world = Matrix::Identity;
    world.M13 = 0.5f;  // r0.z = 0.5 x: a transposed upload would move the quad instead
    effect.Parameters["World"].SetValue(world);
    const std::vector<Vector4> palette = {Vector4(0.1f, 0.2f, 0.3f, 0.4f), Vector4(0.9f, 0.9f, 0.9f, 0.9f), Vector4(0.8f, 0.6f, 0.4f, 0.2f)};
    effect.Parameters["Palette"].SetValue(palette);
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);

    auto draw = [&](const char* technique) {
        device.Clear(Color::Black);
        effect.CurrentTechnique = effect.Techniques[technique];
        effect.CurrentTechnique->Passes[0].Apply();
        drawUnitQuad(device);
    };
    // Per-vertex values at texture coordinate (u, v); the position is (u, 1 - v, 0, 1).
    draw("OutWorld");
    expectPixels(target, [](double u, double v) { return interpolate([](double a, double b) { return V4{a, 1 - b, 0.5 * a, 1}; }, u, v); }, 2e-3);
    draw("OutDst");
    expectPixels(target, [](double u, double v) { return interpolate([](double, double b) { return V4{1, 2 * b, 0, 1}; }, u, v); }, 2e-3);
    draw("OutLit");
    auto lit = [](double a, double b) {
        double x = a - 0.25, y = b;
        return V4{1, std::max(x, 0.0), x > 0 && y > 0 ? std::pow(y, 16.0) : 0.0, 1};
    };
    expectPixels(target, [&](double u, double v) { return interpolate(lit, u, v); }, 2e-3);
    draw("OutSinCos");
    auto trig = [](double a, double b) { return V4{std::cos(3 * b), std::sin(3 * b), std::exp2(a), 4.0}; };
    expectPixels(target, [&](double u, double v) { return interpolate(trig, u, v); }, 2e-3);
    draw("OutPalette");
    auto pal = [&](double a, double) {
        const Vector4& p = palette[std::size_t(std::floor(2 * a + 0.5))];  // mova rounds 2u to the nearest
        return V4{p.X, p.Y, p.Z, p.W};
    };
    expectPixels(target, [&](double u, double v) { return interpolate(pal, u, v); }, 2e-3);
}

// ps_1_1/1_2 texture-address instructions: texm3x2pad + texm3x2tex read a second texture at
// (texcoord1 . n, texcoord2 . n) with n = t0_bx2, texreg2ar at (t0.a, t0.r), texm3x3pad x2 +
// texm3x3 give the three rows as a colour, texdp3 the dot with texcoord set 1, texbeml offsets
// stage 1's coordinates by the bump-environment matrix of pass states, and a ps.1.4 shader reads
// through texcrd/texld/_dz and a phase-2 dependent texld. Point sampling with
// clamping; a pixel whose dependent coordinate lies within 1e-4 of a texel edge is not checked
// (which texel a tie picks is the rasteriser's business).
TEST_F(AsmShaders, Ps11TextureAddressing) {
    Effect effect(device, asmFixture("AsmPs11TextureAddressing.fx"));
    auto tex = makeTexture(device);
    auto tex2 = std::make_unique<Texture2D>(device, 4, 4);
    auto texel2 = [](int x, int y) { return Color(std::uint8_t(20 + 75 * y), std::uint8_t(240 - 50 * x), std::uint8_t(60 * ((x + y) % 4)), std::uint8_t(100 + 40 * x)); };
    std::vector<Color> data2;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) data2.push_back(texel2(x, y));
    tex2->SetData(data2);
    effect.Parameters["Tex"].SetValue(tex);
    effect.Parameters["Tex2"].SetValue(tex2);
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);

    int skipped = 0;
    auto edgeTie = [](double c) {
        double x = std::clamp(c, 0.0, 1.0) * 4;
        return c > 0 && c < 1 && std::abs(x - std::round(x)) < 1e-4 * 4;
    };
    auto sample2 = [&](double a, double b, bool& tie) {
        tie = tie || edgeTie(a) || edgeTie(b);
        int x = std::clamp(int(std::floor(a * 4)), 0, 3), y = std::clamp(int(std::floor(b * 4)), 0, 3);
        Color c = texel2(x, y);
        return V4{c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
    };
    struct Inputs {
        V4 t0, n;
        std::array<double, 3> tc1, tc2, tc3;
    };
    auto inputs = [](double u, double v) {
        Inputs in;
        in.t0 = texelValue(u, v);
        for (int k = 0; k < 4; ++k) in.n[k] = 2 * (in.t0[k] - 0.5);
        in.tc1 = {u, v, 0.5};
        in.tc2 = {v, 0.25, u};
        in.tc3 = {0.5, u, 0.5 * v};
        return in;
    };
    auto dot3 = [](const std::array<double, 3>& a, const V4& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    // Like expectPixels, but a tie leaves the pixel out.
    auto check = [&](const char* technique, auto expected) {
        device.Clear(Color::Black);
        effect.CurrentTechnique = effect.Techniques[technique];
        effect.CurrentTechnique->Passes[0].Apply();
        drawUnitQuad(device);
        std::vector<float> px = readFloats(target);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                bool tie = false;
                V4 e = expected(columnCoordinate(x), rowCoordinate(y), tie);
                if (tie) {
                    ++skipped;
                    continue;
                }
                for (int k = 0; k < 4; ++k)
                    EXPECT_NEAR(px[std::size_t((y * kSize + x) * 4 + k)], e[k], 2e-3) << technique << " pixel " << x << "," << y << " channel " << k;
            }
    };
    check("DependentReads", [&](double u, double v, bool& tie) {
        Inputs in = inputs(u, v);
        V4 t2 = sample2(dot3(in.tc1, in.n), dot3(in.tc2, in.n), tie);
        V4 t3 = sample2(in.t0[3], in.t0[0], tie);
        V4 out;
        for (int k = 0; k < 4; ++k) out[k] = sat(clamp1(t3[k] + 0.5 * (t2[k] - t3[k])));
        return out;
    });
    check("MatrixRows", [&](double u, double v, bool&) {
        Inputs in = inputs(u, v);
        return V4{sat(dot3(in.tc1, in.n)), sat(dot3(in.tc2, in.n)), sat(dot3(in.tc3, in.n)), 1.0};
    });
    check("Dot3", [&](double u, double v, bool&) {
        Inputs in = inputs(u, v);
        double d = clamp1(dot3(in.tc1, in.t0));
        V4 out;
        for (int k = 0; k < 4; ++k) out[k] = sat(clamp1(d * in.t0[k]));
        return out;
    });
    // texbeml: stage 1 read at texcoord1 + [[0.25, BumpScale], [-0.125, 0.5]] (t0.r, t0.g), times
    // saturate(t0.b * 0.5 + 0.25).
    check("BumpEnv", [&](double u, double v, bool& tie) {
        Inputs in = inputs(u, v);
        const V4& t0 = in.t0;
        V4 s = sample2(u + 0.25 * t0[0] + double(0.2f) * t0[1], v - 0.125 * t0[0] + 0.5 * t0[1], tie);
        double l = sat(t0[2] * 0.5 + 0.25);
        V4 out;
        for (int k = 0; k < 4; ++k) out[k] = sat(clamp1(s[k] * l));
        return out;
    });
    // ps_1_4: r0 = texcoord set 1 (u, v, 0.5); r1 = Tex at (u, v); r3 = Tex2 at (u, v) / 0.5;
    // phase 2: r2 = Tex2 at r0; per component r1 > 0.5 ? r2 : 0.5; then (r0 + r3) / 2, alpha r3.b.
    check("Ps14Phases", [&](double u, double v, bool& tie) {
        V4 r1 = texelValue(u, v);
        V4 r3 = sample2(u / 0.5, v / 0.5, tie);
        V4 r2 = sample2(u, v, tie);
        V4 out;
        for (int k = 0; k < 4; ++k) out[k] = r1[k] > 0.5 ? r2[k] : 0.5;
        for (int k = 0; k < 3; ++k) out[k] = clamp1(0.5 * (out[k] + r3[k]));
        out[3] = r3[2];
        for (double& x : out) x = sat(x);
        return out;
    });
    EXPECT_LT(skipped, 8) << "too many texel-edge ties for the check to mean much";
}

}  // namespace
}  // namespace fxport
