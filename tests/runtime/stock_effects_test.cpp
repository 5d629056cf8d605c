// The five stock effects (BasicEffect, AlphaTestEffect, DualTextureEffect, EnvironmentMapEffect,
// SkinnedEffect) drawn on OSMesa and compared pixel by pixel with a double-precision CPU
// evaluation of XNA's documented equations, written here independently of the shaders: a sphere
// (an ellipsoid after World's non-uniform scale) with analytic normals, a smooth vertex colour and
// planar texture coordinates, lit by three lights seen from a perspective camera, into a float
// target. Each case names its feature combination; the tolerance is stated at kTolerance and
// each case reports its largest error. FXPORT_TEST_OUTPUT=<folder> writes, per case, a PNG of the
// GPU image, the CPU image and their difference x 20.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cpu_raster.h"
#include "xna_lighting_reference.h"
#include "fxport/graphics.h"
#include "runtime_test_support.h"
#include "stb_image_write.h"

namespace fxport {
namespace {

using namespace stock_test;
using test::testDevice;

constexpr int kSize = 80;
// Largest |GPU - CPU| per channel allowed on a compared pixel (float target). Untextured: float32
// shader math and interpolation (measured <= 0.0005 on OSMesa). Textured: the texture unit's
// filter weights are 8-bit (llvmpipe), so a bilinear sample may be off by up to ~(texel step) /
// 256 in each direction; the test textures' neighbouring texels differ by up to 0.47 (measured
// <= 0.0045).
constexpr double kTolerance = 0.001;
constexpr double kTextureTolerance = 0.006;

// Every attribute any stock effect reads (the effects ignore what they do not use).
struct TestVertex {
    Vector3 Position;
    Vector3 Normal;
    Vector2 TexCoord;
    Vector2 TexCoord2;
    fxport::Color Colour;
    std::uint8_t Indices[4];
    Vector4 Weights;
    static const fxport::VertexDeclaration VertexDeclaration;
};
const fxport::VertexDeclaration TestVertex::VertexDeclaration(
    64, {VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
         VertexElement(12, VertexElementFormat::Vector3, VertexElementUsage::Normal, 0),
         VertexElement(24, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
         VertexElement(32, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 1),
         VertexElement(40, VertexElementFormat::Color, VertexElementUsage::Color, 0),
         VertexElement(44, VertexElementFormat::Byte4, VertexElementUsage::BlendIndices, 0),
         VertexElement(48, VertexElementFormat::Vector4, VertexElementUsage::BlendWeight, 0)});
static_assert(sizeof(TestVertex) == 64);

struct Mesh {
    std::vector<TestVertex> vertices;
    std::vector<std::uint32_t> indices;
};

// Unit sphere, one vertex per position (poles and the seam shared), so every attribute is
// continuous across inner edges. Triangles clockwise seen from outside (XNA's front faces).
// `weights` = 1, 2 or 4: how many blend weights are non-zero (they sum to 1).
Mesh sphere(int weights = 4) {
    const int rings = 14, segments = 20;
    Mesh mesh;
    auto add = [&](double theta, double phi) {
        TestVertex v{};
        const Vector3 p(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(std::sin(theta) * std::cos(phi)));
        v.Position = p;
        v.Normal = p;
        v.TexCoord = Vector2(0.5f + 0.3f * p.X, 0.5f - 0.3f * p.Y);
        v.TexCoord2 = Vector2(0.5f + 0.3f * p.Z, 0.5f + 0.3f * p.X);
        v.Colour = fxport::Color(int(std::lround(127.5 + 120 * p.X)), int(std::lround(127.5 + 120 * p.Y)),
                                 int(std::lround(127.5 - 120 * p.Z)), int(std::lround(200 + 50 * p.Y)));
        const int n = int(mesh.vertices.size());
        for (int k = 0; k < 4; ++k) v.Indices[k] = std::uint8_t((n * (k + 1) + k) % 5);
        const float raw[4] = {1.0f + 0.5f * p.X, 0.6f + 0.3f * p.Y, 0.4f + 0.2f * p.Z, 0.3f};
        float sum = 0;
        for (int k = 0; k < weights; ++k) sum += raw[k];
        v.Weights = Vector4(raw[0] / sum, weights > 1 ? raw[1] / sum : 0, weights > 2 ? raw[2] / sum : 0,
                            weights > 2 ? raw[3] / sum : 0);
        mesh.vertices.push_back(v);
    };
    add(0, 0);  // north pole
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) add(M_PI * r / rings, 2 * M_PI * s / segments);
    add(M_PI, 0);  // south pole
    const std::uint32_t south = std::uint32_t(mesh.vertices.size() - 1);
    auto ring = [&](int r, int s) { return std::uint32_t(1 + (r - 1) * segments + (s % segments)); };
    // Seen from outside with y up and phi increasing towards +x from +z, (a, b, c) below are clockwise.
    for (int s = 0; s < segments; ++s) {
        mesh.indices.insert(mesh.indices.end(), {0, ring(1, s + 1), ring(1, s)});
        for (int r = 1; r + 1 < rings; ++r) {
            mesh.indices.insert(mesh.indices.end(), {ring(r, s), ring(r, s + 1), ring(r + 1, s)});
            mesh.indices.insert(mesh.indices.end(), {ring(r + 1, s), ring(r, s + 1), ring(r + 1, s + 1)});
        }
        mesh.indices.insert(mesh.indices.end(), {ring(rings - 1, s), ring(rings - 1, s + 1), south});
    }
    return mesh;
}

// ---------------------------------------------------------------------------------------------
// The scene's inputs, as floats (what the GPU gets) read in double by the reference.

struct Scene {
    Matrix world = Matrix::CreateScale(1.0f, 0.85f, 1.1f) * Matrix::CreateRotationY(0.4f) * Matrix::CreateRotationX(0.25f);
    Matrix view = Matrix::CreateLookAt(Vector3(0.3f, 0.4f, 3.3f), Vector3(0, 0, 0), Vector3(0, 1, 0));
    Matrix projection = Matrix::CreatePerspectiveFieldOfView(0.8f, 1.0f, 0.5f, 10.0f);
};

void applyLights(IEffectLights& effect, const Lights& l) {
    DirectionalLight* all[3] = {&effect.DirectionalLight0, &effect.DirectionalLight1, &effect.DirectionalLight2};
    for (int i = 0; i < 3; ++i) {
        all[i]->Enabled = l.enabled[i];
        all[i]->Direction = l.direction[i];
        all[i]->DiffuseColor = l.diffuse[i];
        all[i]->SpecularColor = l.specular[i];
    }
}

struct Fog {
    bool enabled = false;
    double start = 2.6, end = 3.9;
    D3 color{0.3, 0.5, 0.7};
};

// Linear fog on the view-space depth of the vertex.
double fogFactor(const Fog& fog, const DMat& worldView, D4 objectPosition) {
    if (fog.start == fog.end) return 1;
    const double depth = -mul(objectPosition, worldView).z;
    return saturate((depth - fog.start) / (fog.end - fog.start));
}

D4 applyFog(D4 color, const Fog& fog, double factor) {
    const D3 rgb = lerp(color.xyz(), fog.color * color.w, factor);
    return {rgb.x, rgb.y, rgb.z, color.w};
}

// 2D texture with D3D's bilinear rule (texel centres at (i + 0.5) / W), clamped addressing.
struct CpuTexture {
    int width = 0, height = 0;
    std::vector<fxport::Color> texels;
    D4 texel(int x, int y) const {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        const fxport::Color c = texels[std::size_t(y * width + x)];
        return {c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
    }
    D4 sample(double u, double v) const {
        const double x = u * width - 0.5, y = v * height - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        return (texel(x0, y0) * (1 - fx) + texel(x0 + 1, y0) * fx) * (1 - fy) +
               (texel(x0, y0 + 1) * (1 - fx) + texel(x0 + 1, y0 + 1) * fx) * fy;
    }
};

// A 4x4 texture of smooth colours (neighbours differ by at most ~0.35), alpha varying too.
CpuTexture makeCpuTexture(int seed) {
    CpuTexture t;
    t.width = t.height = 4;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            t.texels.push_back(fxport::Color(60 + 50 * x + 5 * seed, 220 - 40 * y, 90 + 25 * ((x + y + seed) % 4),
                                             255 - 30 * ((x * 3 + y + seed) % 5)));
    return t;
}

// For AlphaTestEffect: smooth colours, and alpha constant over each 2x2 quadrant (255, 225 /
// 160, 100), so that between the texel centres of a quadrant the filtered alpha is exact and
// Equal/NotEqual have areas to keep and to discard.
CpuTexture makeAlphaTestTexture() {
    CpuTexture t = makeCpuTexture(2);
    const int quadrantAlpha[4] = {255, 225, 160, 100};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) t.texels[std::size_t(y * 4 + x)].A = std::uint8_t(quadrantAlpha[(y / 2) * 2 + x / 2]);
    return t;
}

std::unique_ptr<Texture2D> upload(GraphicsDevice& device, const CpuTexture& t) {
    auto texture = std::make_unique<Texture2D>(device, t.width, t.height, false, SurfaceFormat::Color);
    texture->SetData(t.texels.data(), t.texels.size());
    return texture;
}

// XNA's stock vertex shaders are vs_2_0: Direct3D 9 clamps their COLOR0/COLOR1 outputs (diffuse,
// and specular with the fog factor) to [0, 1] before interpolation.
D4 colorOutput(D4 c) { return {saturate(c.x), saturate(c.y), saturate(c.z), saturate(c.w)}; }
D3 colorOutput(D3 c) { return {saturate(c.x), saturate(c.y), saturate(c.z)}; }

D4 colourOf(const TestVertex& v) { return {v.Colour.R / 255.0, v.Colour.G / 255.0, v.Colour.B / 255.0, v.Colour.A / 255.0}; }

// ---------------------------------------------------------------------------------------------
// Running a case: GPU draw, CPU reference, comparison, PNG.

struct CaseResult {
    int compared = 0;
    int background = 0;
    int discarded = 0;
    int skipped = 0;
    double maxError = 0;
    int worstX = -1, worstY = -1;
};

const D4 kClear{0.1, 0.2, 0.3, 0.4};

using VertexStage = std::function<RasterVertex(const TestVertex&)>;
// What the reference expects of a covered pixel: a colour, the clear colour (discarded), or
// nothing (too close to a decision the GPU may take either way: not compared, and counted).
struct Expected {
    enum class Kind : std::uint8_t { Colour, Discarded, Skipped } kind = Kind::Colour;
    D4 colour;
};
Expected colour(D4 c) { return {Expected::Kind::Colour, c}; }
Expected discarded() { return {Expected::Kind::Discarded, {}}; }
Expected skipped() { return {Expected::Kind::Skipped, {}}; }
using PixelStage = std::function<Expected(const std::vector<double>&)>;

void writePng(const std::string& name, const std::vector<Vector4>& gpu, const std::vector<D4>& cpu) {
    const char* folder = std::getenv("FXPORT_TEST_OUTPUT");
    if (!folder) return;
    const int zoom = 3, w = kSize * 3 * zoom, h = kSize * zoom;
    std::vector<unsigned char> rgba(std::size_t(w) * std::size_t(h) * 4);
    auto put = [&](int x, int y, double r, double g, double b) {
        for (int dy = 0; dy < zoom; ++dy)
            for (int dx = 0; dx < zoom; ++dx) {
                unsigned char* p = &rgba[(std::size_t(y * zoom + dy) * std::size_t(w) + std::size_t(x * zoom + dx)) * 4];
                p[0] = (unsigned char)std::lround(saturate(r) * 255);
                p[1] = (unsigned char)std::lround(saturate(g) * 255);
                p[2] = (unsigned char)std::lround(saturate(b) * 255);
                p[3] = 255;
            }
    };
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Vector4& g = gpu[std::size_t(y * kSize + x)];
            const D4& c = cpu[std::size_t(y * kSize + x)];
            put(x, y, g.X, g.Y, g.Z);
            put(kSize + x, y, c.x, c.y, c.z);
            if (c.w < 0) put(2 * kSize + x, y, 0, 0, 0.5);  // not compared
            else put(2 * kSize + x, y, std::fabs(g.X - c.x) * 20, std::fabs(g.Y - c.y) * 20, std::fabs(g.Z - c.z) * 20);
        }
    const std::string path = std::string(folder) + "/stock_" + name + ".png";
    stbi_write_png(path.c_str(), w, h, 4, rgba.data(), w * 4);
}

CaseResult runCase(const std::string& name, Effect& effect, const Mesh& mesh, const VertexStage& vs, const PixelStage& ps) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4, DepthFormat::Depth24);
    device.SetRenderTarget(&target);
    device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(float(kClear.x), float(kClear.y), float(kClear.z), float(kClear.w)), 1.0f, 0);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.SamplerStates[0] = SamplerState::LinearClamp;
    device.SamplerStates[1] = SamplerState::LinearClamp;
    for (EffectPass& pass : effect.CurrentTechnique->Passes) {
        pass.Apply();
        device.DrawUserIndexedPrimitives(PrimitiveType::TriangleList, mesh.vertices.data(), 0, int(mesh.vertices.size()),
                                         mesh.indices.data(), 0, int(mesh.indices.size() / 3));
    }
    device.SetRenderTarget(nullptr);
    const std::vector<Vector4> gpu = target.GetDataAsVector4();

    std::vector<RasterVertex> vertices;
    for (const TestVertex& v : mesh.vertices) vertices.push_back(vs(v));
    const std::vector<RasterPixel> pixels = rasterize(kSize, kSize, vertices, mesh.indices);
    std::vector<D4> cpu(pixels.size(), D4{0, 0, 0, -1});
    CaseResult result;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        std::optional<D4> expected;
        if (pixels[i].kind == PixelKind::Unsure) continue;
        if (pixels[i].kind == PixelKind::Background) {
            expected = kClear;
            ++result.background;
        } else {
            const Expected e = ps(pixels[i].varyings);
            if (e.kind == Expected::Kind::Skipped) {
                ++result.skipped;
                continue;
            }
            expected = e.kind == Expected::Kind::Discarded ? kClear : e.colour;
            if (e.kind == Expected::Kind::Discarded) ++result.discarded;
        }
        cpu[i] = *expected;
        const Vector4& g = gpu[i];
        const double error = std::max({std::fabs(g.X - expected->x), std::fabs(g.Y - expected->y),
                                       std::fabs(g.Z - expected->z), std::fabs(g.W - expected->w)});
        ++result.compared;
        if (error > result.maxError) {
            result.maxError = error;
            result.worstX = int(i % kSize);
            result.worstY = int(i / kSize);
        }
    }
    writePng(name, gpu, cpu);
    std::printf("[stock] %-42s compared %4d (background %4d, discarded %4d; skipped %3d)  max |GPU - CPU| %.5f at (%d, %d)\n",
                name.c_str(), result.compared, result.background, result.discarded, result.skipped, result.maxError,
                result.worstX, result.worstY);
    return result;
}

void expectMatches(const CaseResult& r, double tolerance, int minimumShaded = 1500) {
    EXPECT_LE(r.maxError, tolerance) << "at pixel (" << r.worstX << ", " << r.worstY << ")";
    EXPECT_LE(r.skipped, r.compared / 5) << "too many pixels left out as ambiguous";
    EXPECT_GE(r.compared - r.background, minimumShaded) << "too few shaded pixels were compared";
    EXPECT_GE(r.background, 200) << "too few background pixels were compared";
}

// Common vertex work: clip position and world position/normal through World, View, Projection.
struct Transform {
    DMat world, worldView, worldViewProj, worldInverseTranspose;
    D3 eye;
    explicit Transform(const Scene& s) {
        world = toDMat(s.world);
        worldView = world * toDMat(s.view);
        worldViewProj = worldView * toDMat(s.projection);
        worldInverseTranspose = transpose(inverse(world));
        const DMat viewInverse = inverse(toDMat(s.view));
        eye = {viewInverse.m[3][0], viewInverse.m[3][1], viewInverse.m[3][2]};
    }
};

void setMatrices(IEffectMatrices& effect, const Scene& s) {
    effect.World = s.world;
    effect.View = s.view;
    effect.Projection = s.projection;
}

void setFog(IEffectFog& effect, const Fog& fog) {
    effect.FogEnabled = fog.enabled;
    effect.FogStart = float(fog.start);
    effect.FogEnd = float(fog.end);
    effect.FogColor = Vector3(float(fog.color.x), float(fog.color.y), float(fog.color.z));
}

// push_back one by one: GCC 12's -Wstringop-overflow misfires on insert(end, {...}).
void push(std::vector<double>& v, D3 a) {
    v.push_back(a.x);
    v.push_back(a.y);
    v.push_back(a.z);
}
void push(std::vector<double>& v, D4 a) {
    push(v, a.xyz());
    v.push_back(a.w);
}
void push(std::vector<double>& v, Vector2 a) {
    v.push_back(a.X);
    v.push_back(a.Y);
}
D3 d3At(const std::vector<double>& v, std::size_t i) { return {v[i], v[i + 1], v[i + 2]}; }
D4 d4At(const std::vector<double>& v, std::size_t i) { return {v[i], v[i + 1], v[i + 2], v[i + 3]}; }

// ---------------------------------------------------------------------------------------------
// BasicEffect

enum class Lighting { Off, PerVertex, PerPixel };

struct BasicCase {
    std::string name;
    Lighting lighting = Lighting::Off;
    bool texture = false, vertexColor = false, fog = false, defaultRig = false;
    std::string permutation;
    bool bright = false;  // a material whose per-vertex colours leave [0, 1] (XNA clamps them)
};

Material basicMaterial(bool lit, bool bright) {
    Material m;
    m.diffuse = bright ? D3{1.0, 0.95, 1.0} : D3{0.8, 0.7, 0.9};
    m.emissive = bright ? D3{0.45, 0.1, 0.3} : D3{0.05, 0.1, 0.0};
    m.specular = {0.6, 0.5, 0.4};
    m.specularPower = 12;
    m.alpha = bright ? 1.0 : 0.75;
    m.ambient = lit ? D3{0.15, 0.1, 0.2} : D3{0, 0, 0};
    return m;
}

CaseResult runBasic(const BasicCase& c, Effect** keep = nullptr) {
    GraphicsDevice& device = testDevice();
    static BasicEffect* reused = nullptr;  // one effect for every case: permutations compile as needed
    static std::unique_ptr<BasicEffect> owner;
    if (!owner) {
        owner = std::make_unique<BasicEffect>(device);
        reused = owner.get();
    }
    BasicEffect& effect = *reused;
    if (keep) *keep = &effect;
    const Scene scene;
    const Mesh mesh = sphere();
    const CpuTexture cpuTexture = makeCpuTexture(1);
    auto texture = upload(device, cpuTexture);
    const bool lit = c.lighting != Lighting::Off;
    Material m = basicMaterial(lit, c.bright);
    Lights lights;
    Fog fog;
    fog.enabled = c.fog;

    setMatrices(effect, scene);
    effect.DiffuseColor = Vector3(float(m.diffuse.x), float(m.diffuse.y), float(m.diffuse.z));
    effect.EmissiveColor = Vector3(float(m.emissive.x), float(m.emissive.y), float(m.emissive.z));
    effect.SpecularColor = Vector3(0.6f, 0.5f, 0.4f);
    effect.SpecularPower = 12;
    effect.Alpha = float(m.alpha);
    effect.AmbientLightColor = Vector3(0.15f, 0.1f, 0.2f);
    effect.LightingEnabled = lit;
    applyLights(effect, lights);
    if (c.defaultRig) {
        effect.EnableDefaultLighting();
        lights = lightsOf(effect);
        m.ambient = toD3(effect.AmbientLightColor);
    }
    effect.PreferPerPixelLighting = c.lighting == Lighting::PerPixel;
    effect.TextureEnabled = c.texture;
    effect.Texture = texture.get();
    effect.VertexColorEnabled = c.vertexColor;
    setFog(effect, fog);
    EXPECT_EQ(effect.PermutationName(), c.permutation);

    const Transform t(scene);
    // Varyings: diffuse (4), specular (3), fog (1), uv (2), world position (3), world normal (3).
    VertexStage vs = [&](const TestVertex& v) {
        RasterVertex out;
        const D4 position{v.Position.X, v.Position.Y, v.Position.Z, 1};
        out.clip = mul(position, t.worldViewProj);
        const D3 worldPosition = mul(position, t.world).xyz();
        const D3 worldNormal = normalize(mul3(toD3(v.Normal), t.worldInverseTranspose));
        D4 diffuse = lit ? D4{1, 1, 1, m.alpha} : D4{(m.diffuse.x + m.emissive.x) * m.alpha, (m.diffuse.y + m.emissive.y) * m.alpha,
                                                      (m.diffuse.z + m.emissive.z) * m.alpha, m.alpha};
        D3 specular;
        if (c.lighting == Lighting::PerVertex) {
            const LightResult r = light(lights, m, normalize(t.eye - worldPosition), worldNormal);
            diffuse = {r.diffuse.x, r.diffuse.y, r.diffuse.z, m.alpha};
            specular = r.specular;
        }
        if (c.vertexColor) diffuse = diffuse * colourOf(v);
        push(out.varyings, colorOutput(diffuse));
        push(out.varyings, colorOutput(specular));
        out.varyings.push_back(c.fog ? fogFactor(fog, t.worldView, position) : 0);
        push(out.varyings, v.TexCoord);
        push(out.varyings, worldPosition);
        push(out.varyings, worldNormal);
        return out;
    };
    PixelStage ps = [&](const std::vector<double>& in) {
        D4 color = d4At(in, 0);
        if (c.texture) color = color * cpuTexture.sample(in[8], in[9]);
        D3 specular = d3At(in, 4);
        if (c.lighting == Lighting::PerPixel) {
            bool nearTerminator = false;
            const LightResult r = light(lights, m, normalize(t.eye - d3At(in, 10)), normalize(d3At(in, 13)), &nearTerminator);
            if (nearTerminator) return skipped();
            const D3 rgb = color.xyz() * r.diffuse;  // per pixel: (1,1,1,alpha) * lit diffuse
            color = {rgb.x, rgb.y, rgb.z, color.w};
            specular = r.specular;
        }
        if (lit) {
            const D3 rgb = color.xyz() + specular * color.w;
            color = {rgb.x, rgb.y, rgb.z, color.w};
        }
        if (c.fog) color = applyFog(color, fog, in[7]);
        return colour(color);
    };
    return runCase(c.name, effect, mesh, vs, ps);
}

TEST(StockEffects, BasicEffectPermutationsMatchTheCpuReference) {
    const std::vector<BasicCase> cases = {
        {"basic_unlit", Lighting::Off, false, false, false, false, "BasicEffect_L0_T0_V0_F0"},
        {"basic_unlit_texture_vertexcolor_fog", Lighting::Off, true, true, true, false, "BasicEffect_L0_T1_V1_F1"},
        {"basic_vertexlit", Lighting::PerVertex, false, false, false, false, "BasicEffect_L1_T0_V0_F0"},
        {"basic_vertexlit_texture_fog", Lighting::PerVertex, true, false, true, false, "BasicEffect_L1_T1_V0_F1"},
        {"basic_vertexlit_vertexcolor", Lighting::PerVertex, false, true, false, false, "BasicEffect_L1_T0_V1_F0"},
        {"basic_pixellit", Lighting::PerPixel, false, false, false, false, "BasicEffect_L2_T0_V0_F0"},
        {"basic_pixellit_texture_vertexcolor_fog", Lighting::PerPixel, true, true, true, false, "BasicEffect_L2_T1_V1_F1"},
        {"basic_pixellit_default_lighting", Lighting::PerPixel, true, false, false, true, "BasicEffect_L2_T1_V0_F0"},
        // Per-vertex colours past 1, which XNA's vs_2_0 clamps: white diffuse under the default rig,
        // and unlit (Diffuse + Emissive) * Alpha > 1 with texture, vertex colour and fog.
        {"basic_vertexlit_default_lighting_bright", Lighting::PerVertex, false, false, false, true, "BasicEffect_L1_T0_V0_F0", true},
        {"basic_vertexlit_vertexcolor_fog_bright", Lighting::PerVertex, false, true, true, true, "BasicEffect_L1_T0_V1_F1", true},
        {"basic_unlit_texture_fog_bright", Lighting::Off, true, false, true, false, "BasicEffect_L0_T1_V0_F1", true},
        {"basic_unlit_vertexcolor_bright", Lighting::Off, false, true, false, false, "BasicEffect_L0_T0_V1_F0", true},
        {"basic_pixellit_vertexcolor_bright", Lighting::PerPixel, false, true, false, true, "BasicEffect_L2_T0_V1_F0", true},
    };
    Effect* effect = nullptr;
    for (const BasicCase& c : cases) {
        SCOPED_TRACE(c.name);
        expectMatches(runBasic(c, &effect), c.texture ? kTextureTolerance : kTolerance);
    }
    // Only the permutations drawn were compiled.
    const EffectStatistics stats = effect->statistics();
    EXPECT_EQ(stats.techniqueCount, 24);
    std::vector<std::string> permutations;
    for (const BasicCase& c : cases)
        if (std::find(permutations.begin(), permutations.end(), c.permutation) == permutations.end()) permutations.push_back(c.permutation);
    EXPECT_EQ(stats.compiledTechniques.size(), permutations.size());
}

TEST(StockEffects, EnableDefaultLightingSetsXnasRig) {
    BasicEffect effect(testDevice());
    // What a Model pays per part: the outline of BasicEffect.fx (24 techniques), cache warm.
    std::printf("[stock] BasicEffect constructed in %.2f ms (outline load)\n", effect.statistics().loadMilliseconds);
    EXPECT_FALSE(effect.LightingEnabled);
    EXPECT_TRUE(effect.DirectionalLight0.Enabled);
    EXPECT_FALSE(effect.DirectionalLight1.Enabled);
    effect.EnableDefaultLighting();
    EXPECT_TRUE(effect.LightingEnabled);
    EXPECT_TRUE(effect.DirectionalLight1.Enabled && effect.DirectionalLight2.Enabled);
    // XNA's documented key/fill/back values.
    EXPECT_EQ(effect.DirectionalLight0.Direction, Vector3(-0.5265408f, -0.5735765f, -0.6275069f));
    EXPECT_EQ(effect.DirectionalLight1.DiffuseColor, Vector3(0.9647059f, 0.7607844f, 0.4078432f));
    EXPECT_EQ(effect.DirectionalLight1.SpecularColor, Vector3(0, 0, 0));
    EXPECT_EQ(effect.DirectionalLight2.Direction, Vector3(0.4545195f, -0.7660444f, 0.4545195f));
    EXPECT_EQ(effect.AmbientLightColor, Vector3(0.05333332f, 0.09882354f, 0.1819608f));
    // A host reaches any stock effect's matrices, lights and fog through the interfaces.
    Effect& base = effect;
    EXPECT_NE(dynamic_cast<IEffectMatrices*>(&base), nullptr);
    EXPECT_NE(dynamic_cast<IEffectLights*>(&base), nullptr);
    EXPECT_NE(dynamic_cast<IEffectFog*>(&base), nullptr);
}

// ---------------------------------------------------------------------------------------------
// AlphaTestEffect

TEST(StockEffects, AlphaTestEffectMatchesTheCpuReference) {
    GraphicsDevice& device = testDevice();
    AlphaTestEffect effect(device);
    const Scene scene;
    const Mesh mesh = sphere();
    const CpuTexture cpuTexture = makeAlphaTestTexture();
    auto texture = upload(device, cpuTexture);
    const Transform t(scene);
    struct Case {
        std::string name;
        CompareFunction function;
        int reference;
        bool vertexColor, fog;
        bool bright = false;  // DiffuseColor past 1: the per-vertex colour is clamped (XNA's vs_2_0)
    };
    const std::vector<Case> cases = {
        {"alphatest_greater_190", CompareFunction::Greater, 190, false, false},
        {"alphatest_lessequal_130_vertexcolor_fog", CompareFunction::LessEqual, 130, true, true},
        {"alphatest_equal_225", CompareFunction::Equal, 225, false, false},
        {"alphatest_notequal_225_fog", CompareFunction::NotEqual, 225, false, true},
        {"alphatest_always", CompareFunction::Always, 0, true, false},
        {"alphatest_always_vertexcolor_fog_bright", CompareFunction::Always, 0, true, true, true},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Fog fog;
        fog.enabled = c.fog;
        setMatrices(effect, scene);
        setFog(effect, fog);
        const D3 diffuseColor = c.bright ? D3{1.6, 1.3, 0.7} : D3{0.9, 0.8, 0.7};
        effect.DiffuseColor = Vector3(float(diffuseColor.x), float(diffuseColor.y), float(diffuseColor.z));
        effect.Alpha = 1.0f;  // so that texel alphas (multiples of 1/255 when no vertex colour) hit Equal exactly
        effect.AlphaFunction = c.function;
        effect.ReferenceAlpha = c.reference;
        effect.Texture = texture.get();
        effect.VertexColorEnabled = c.vertexColor;
        const double reference = c.reference / 255.0;
        VertexStage vs = [&](const TestVertex& v) {
            RasterVertex out;
            const D4 position{v.Position.X, v.Position.Y, v.Position.Z, 1};
            out.clip = mul(position, t.worldViewProj);
            D4 diffuse{diffuseColor.x, diffuseColor.y, diffuseColor.z, 1.0};
            if (c.vertexColor) diffuse = diffuse * colourOf(v);
            push(out.varyings, colorOutput(diffuse));
            push(out.varyings, v.TexCoord);
            out.varyings.push_back(c.fog ? fogFactor(fog, t.worldView, position) : 0);
            return out;
        };
        PixelStage ps = [&](const std::vector<double>& in) {
            D4 color = d4At(in, 0) * cpuTexture.sample(in[4], in[5]);
            // The effect compares within half an 8-bit step (see alpha_test_effect.h). Filtered
            // alphas within 1.5/255 of a decision may go either way on the GPU (its filter
            // weights are 8-bit: up to ~0.6/255 on this texture) and are not compared; for
            // Equal/NotEqual only exactly equal alphas (inside a constant quadrant) count as equal.
            const double band = 0.5 / 255;
            bool keep = true, unsure = false;
            switch (c.function) {
            case CompareFunction::Greater:
            case CompareFunction::LessEqual: {
                const double edge = reference + band;
                keep = c.function == CompareFunction::Greater ? color.w >= edge : color.w < edge;
                unsure = std::fabs(color.w - edge) < 1.5 / 255;
                break;
            }
            case CompareFunction::Equal:
            case CompareFunction::NotEqual: {
                const double distance = std::fabs(color.w - reference);
                keep = (distance < 1e-9) == (c.function == CompareFunction::Equal);
                unsure = distance >= 1e-9 && distance < 2.0 / 255;
                break;
            }
            default: break;
            }
            if (unsure) return skipped();
            if (!keep) return discarded();
            if (c.fog) color = applyFog(color, fog, in[6]);
            return colour(color);
        };
        const CaseResult r = runCase(c.name, effect, mesh, vs, ps);
        expectMatches(r, kTextureTolerance, 400);
        if (c.function != CompareFunction::Always) {
            // Equal holds only where the filtered alpha is exact: one small area of the sphere.
            const bool equality = c.function == CompareFunction::Equal || c.function == CompareFunction::NotEqual;
            const int kept = r.compared - r.background - r.discarded;
            EXPECT_GT(c.function == CompareFunction::NotEqual ? r.discarded : kept, equality ? 25 : 100) << "too small a test";
            EXPECT_GT(c.function == CompareFunction::NotEqual ? kept : r.discarded, 100) << "too small a test";
        }
    }
}

// ---------------------------------------------------------------------------------------------
// DualTextureEffect

TEST(StockEffects, DualTextureEffectMatchesTheCpuReference) {
    GraphicsDevice& device = testDevice();
    DualTextureEffect effect(device);
    const Scene scene;
    const Mesh mesh = sphere();
    const CpuTexture cpu1 = makeCpuTexture(3), cpu2 = makeCpuTexture(0);
    auto texture1 = upload(device, cpu1), texture2 = upload(device, cpu2);
    const Transform t(scene);
    // Variants 4 and 5: DiffuseColor past 1, which XNA's vs_2_0 clamps per vertex.
    for (int variant = 0; variant < 6; ++variant) {
        const bool vertexColor = variant & 1, fogOn = variant & 2, bright = variant >= 4;
        const std::string name = std::string("dualtexture") + (vertexColor ? "_vertexcolor" : "") + (fogOn ? "_fog" : "") +
                                 (bright ? "_bright" : "");
        const D3 diffuseColor = bright ? D3{1.5, 0.9, 1.3} : D3{0.7, 0.9, 0.8};
        SCOPED_TRACE(name);
        Fog fog;
        fog.enabled = fogOn;
        setMatrices(effect, scene);
        setFog(effect, fog);
        effect.DiffuseColor = Vector3(float(diffuseColor.x), float(diffuseColor.y), float(diffuseColor.z));
        effect.Alpha = 0.8f;
        effect.Texture = texture1.get();
        effect.Texture2 = texture2.get();
        effect.VertexColorEnabled = vertexColor;
        VertexStage vs = [&](const TestVertex& v) {
            RasterVertex out;
            const D4 position{v.Position.X, v.Position.Y, v.Position.Z, 1};
            out.clip = mul(position, t.worldViewProj);
            D4 diffuse{diffuseColor.x * 0.8, diffuseColor.y * 0.8, diffuseColor.z * 0.8, 0.8};
            if (vertexColor) diffuse = diffuse * colourOf(v);
            push(out.varyings, colorOutput(diffuse));
            push(out.varyings, v.TexCoord);
            push(out.varyings, v.TexCoord2);
            out.varyings.push_back(fogOn ? fogFactor(fog, t.worldView, position) : 0);
            return out;
        };
        PixelStage ps = [&](const std::vector<double>& in) {
            // XNA: color.rgb *= 2; color *= overlay * diffuse -- on all four channels.
            const D4 overlay = cpu2.sample(in[6], in[7]);
            D4 color = cpu1.sample(in[4], in[5]) * D4{2, 2, 2, 1} * overlay * d4At(in, 0);
            if (fogOn) color = applyFog(color, fog, in[8]);
            return colour(color);
        };
        EXPECT_EQ(effect.PermutationName(), "DualTextureEffect_V" + std::to_string(int(vertexColor)) + "_F" + std::to_string(int(fogOn)));
        // The product of two filtered samples at up to twice their value: twice one sample's error.
        expectMatches(runCase(name, effect, mesh, vs, ps), 2 * kTextureTolerance);
    }
}

// ---------------------------------------------------------------------------------------------
// EnvironmentMapEffect

TEST(StockEffects, EnvironmentMapEffectMatchesTheCpuReference) {
    GraphicsDevice& device = testDevice();
    EnvironmentMapEffect effect(device);
    const Scene scene;
    const Mesh mesh = sphere();
    const CpuTexture cpuTexture = makeCpuTexture(1);
    auto texture = upload(device, cpuTexture);
    // A cube map of six flat colours (16x16 each): the reference needs only the face a direction
    // selects; directions within a few degrees of a face edge (where GL may filter across the seam)
    // are left out.
    const fxport::Color faceColors[6] = {fxport::Color(230, 40, 40, 255), fxport::Color(40, 200, 60, 128),
                                         fxport::Color(50, 70, 240, 64),  fxport::Color(240, 220, 40, 200),
                                         fxport::Color(200, 60, 220, 32), fxport::Color(40, 220, 220, 255)};
    TextureCube cube(device, 16, false, SurfaceFormat::Color);
    for (int f = 0; f < 6; ++f) {
        std::vector<fxport::Color> texels(256, faceColors[f]);
        cube.SetData(CubeMapFace(f), texels.data(), texels.size());
    }
    auto faceOf = [&](D3 d, bool& nearEdge) {
        const double a[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
        const int axis = a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
        const double second = std::max({axis == 0 ? 0 : a[0], axis == 1 ? 0 : a[1], axis == 2 ? 0 : a[2]});
        nearEdge = second > 0.9 * a[axis];
        const double v = axis == 0 ? d.x : axis == 1 ? d.y : d.z;
        const fxport::Color c = faceColors[axis * 2 + (v < 0 ? 1 : 0)];
        return D4{c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
    };
    const Transform t(scene);
    struct Case {
        std::string name;
        float amount, fresnel;
        Vector3 specular;
        bool fog, defaultRig;
        std::string permutation;
    };
    const std::vector<Case> cases = {
        {"envmap_plain", 0.6f, 0, Vector3(0, 0, 0), false, false, "EnvironmentMapEffect_R0_S0_F0"},
        {"envmap_fresnel", 0.9f, 1.5f, Vector3(0, 0, 0), false, false, "EnvironmentMapEffect_R1_S0_F0"},
        {"envmap_fresnel_specular_fog", 0.8f, 2.0f, Vector3(0.3f, 0.2f, 0.1f), true, false, "EnvironmentMapEffect_R1_S1_F1"},
        {"envmap_specular_default_lighting", 0.5f, 0, Vector3(0.2f, 0.2f, 0.3f), false, true, "EnvironmentMapEffect_R0_S1_F0"},
        // An amount past 1 and a lit diffuse past 1 under the default rig: both clamped per vertex.
        {"envmap_amount_past_one_default_lighting_fog", 1.4f, 0, Vector3(0, 0, 0), true, true, "EnvironmentMapEffect_R0_S0_F1"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Fog fog;
        fog.enabled = c.fog;
        Lights lights;
        Material m;
        m.diffuse = {0.9, 0.8, 0.7};
        m.emissive = {0.05, 0.05, 0.1};
        m.ambient = {0.1, 0.15, 0.1};
        m.alpha = 0.9;
        setMatrices(effect, scene);
        setFog(effect, fog);
        applyLights(effect, lights);
        effect.AmbientLightColor = Vector3(0.1f, 0.15f, 0.1f);
        if (c.defaultRig) {
            effect.EnableDefaultLighting();
            lights = lightsOf(effect);
            m.ambient = toD3(effect.AmbientLightColor);
        }
        effect.DiffuseColor = Vector3(0.9f, 0.8f, 0.7f);
        effect.EmissiveColor = Vector3(0.05f, 0.05f, 0.1f);
        effect.Alpha = 0.9f;
        effect.Texture = texture.get();
        effect.EnvironmentMap = &cube;
        effect.EnvironmentMapAmount = c.amount;
        effect.FresnelFactor = c.fresnel;
        effect.EnvironmentMapSpecular = c.specular;
        EXPECT_EQ(effect.PermutationName(), c.permutation);
        VertexStage vs = [&](const TestVertex& v) {
            RasterVertex out;
            const D4 position{v.Position.X, v.Position.Y, v.Position.Z, 1};
            out.clip = mul(position, t.worldViewProj);
            const D3 worldPosition = mul(position, t.world).xyz();
            const D3 normal = normalize(mul3(toD3(v.Normal), t.worldInverseTranspose));
            const D3 toEye = normalize(t.eye - worldPosition);
            const LightResult r = light(lights, m, toEye, normal);  // diffuse only
            double amount = c.amount;
            if (c.fresnel != 0) amount *= std::pow(std::max(1 - std::fabs(dot(toEye, normal)), 0.0), double(c.fresnel));
            push(out.varyings, colorOutput(D4{r.diffuse.x, r.diffuse.y, r.diffuse.z, m.alpha}));
            out.varyings.push_back(saturate(amount));
            out.varyings.push_back(c.fog ? fogFactor(fog, t.worldView, position) : 0);
            push(out.varyings, v.TexCoord);
            push(out.varyings, reflect(-toEye, normal));
            return out;
        };
        PixelStage ps = [&](const std::vector<double>& in) {
            D4 color = d4At(in, 0) * cpuTexture.sample(in[6], in[7]);
            bool nearEdge = false;
            const D4 env = faceOf(d3At(in, 8), nearEdge) * color.w;
            if (nearEdge) return skipped();
            D3 rgb = lerp(color.xyz(), env.xyz(), in[4]);
            rgb = rgb + D3{c.specular.X, c.specular.Y, c.specular.Z} * env.w;
            color = {rgb.x, rgb.y, rgb.z, color.w};
            if (c.fog) color = applyFog(color, fog, in[5]);
            return colour(color);
        };
        expectMatches(runCase(c.name, effect, mesh, vs, ps), kTextureTolerance, 1000);
    }
}

// ---------------------------------------------------------------------------------------------
// SkinnedEffect

TEST(StockEffects, SkinnedEffectMatchesTheCpuReference) {
    GraphicsDevice& device = testDevice();
    SkinnedEffect effect(device);
    const Scene scene;
    const CpuTexture cpuTexture = makeCpuTexture(2);
    auto texture = upload(device, cpuTexture);
    const Transform t(scene);
    // Five bones (the sphere's vertices use indices 0..4), mild so the surface does not fold;
    // bone 4 is placed at index 70 to reach the end of the 72-bone palette.
    std::vector<Matrix> bones(71, Matrix::Identity);
    bones[0] = Matrix::CreateRotationZ(0.15f) * Matrix::CreateTranslation(0.05f, 0.0f, 0.0f);
    bones[1] = Matrix::CreateScale(1.1f) * Matrix::CreateTranslation(0.0f, 0.08f, 0.0f);
    bones[2] = Matrix::CreateRotationY(-0.2f);
    bones[3] = Matrix::CreateRotationX(0.1f) * Matrix::CreateTranslation(0.0f, 0.0f, -0.05f);
    bones[70] = Matrix::CreateScale(0.95f, 1.05f, 1.0f);
    effect.SetBoneTransforms(bones);
    EXPECT_EQ(effect.GetBoneTransforms(71), bones);
    EXPECT_THROW(effect.SetBoneTransforms(std::vector<Matrix>(73, Matrix::Identity)), ArgumentError);

    struct Case {
        int weights;
        bool perPixel, fog;
        bool bright = false;  // per-vertex lit colours past 1 (clamped, as XNA's vs_2_0 does)
    };
    const std::vector<Case> cases = {{1, false, false}, {2, true, false}, {4, false, true}, {4, true, true}, {2, false, true},
                                     {4, false, false, true}, {2, true, true, true}};
    for (const Case& c : cases) {
        const std::string name = "skinned_w" + std::to_string(c.weights) + (c.perPixel ? "_pixellit" : "_vertexlit") +
                                 (c.fog ? "_fog" : "") + (c.bright ? "_bright" : "");
        SCOPED_TRACE(name);
        Mesh mesh = sphere(c.weights);
        for (TestVertex& v : mesh.vertices)
            for (std::uint8_t& index : v.Indices)
                if (index == 4) index = 70;
        Fog fog;
        fog.enabled = c.fog;
        Lights lights;
        Material m = basicMaterial(true, c.bright);
        setMatrices(effect, scene);
        setFog(effect, fog);
        applyLights(effect, lights);
        effect.DiffuseColor = Vector3(float(m.diffuse.x), float(m.diffuse.y), float(m.diffuse.z));
        effect.EmissiveColor = Vector3(float(m.emissive.x), float(m.emissive.y), float(m.emissive.z));
        effect.SpecularColor = Vector3(0.6f, 0.5f, 0.4f);
        effect.SpecularPower = 12;
        effect.Alpha = float(m.alpha);
        effect.AmbientLightColor = Vector3(0.15f, 0.1f, 0.2f);
        effect.PreferPerPixelLighting = c.perPixel;
        effect.WeightsPerVertex = c.weights;
        effect.Texture = texture.get();
        EXPECT_EQ(effect.PermutationName(), "SkinnedEffect_W" + std::to_string(c.weights) + "_P" +
                                                std::to_string(int(c.perPixel)) + "_F" + std::to_string(int(c.fog)));
        VertexStage vs = [&](const TestVertex& v) {
            // skin = sum of weight * bone (affine: the 4x3 part), then BasicEffect's lighting.
            DMat skin;
            const float weights[4] = {v.Weights.X, v.Weights.Y, v.Weights.Z, v.Weights.W};
            for (int k = 0; k < c.weights; ++k) {
                const DMat bone = toDMat(bones[v.Indices[k]]);
                for (int r = 0; r < 4; ++r)
                    for (int col = 0; col < 3; ++col) skin.m[r][col] += bone.m[r][col] * weights[k];
            }
            const D3 skinned = mul(D4{v.Position.X, v.Position.Y, v.Position.Z, 1}, skin).xyz();
            const D4 position{skinned.x, skinned.y, skinned.z, 1};
            const D3 normal = mul3(toD3(v.Normal), skin);
            RasterVertex out;
            out.clip = mul(position, t.worldViewProj);
            const D3 worldPosition = mul(position, t.world).xyz();
            const D3 worldNormal = normalize(mul3(normal, t.worldInverseTranspose));
            D4 diffuse{1, 1, 1, m.alpha};
            D3 specular;
            if (!c.perPixel) {
                const LightResult r = light(lights, m, normalize(t.eye - worldPosition), worldNormal);
                diffuse = {r.diffuse.x, r.diffuse.y, r.diffuse.z, m.alpha};
                specular = r.specular;
            }
            push(out.varyings, colorOutput(diffuse));
            push(out.varyings, colorOutput(specular));
            out.varyings.push_back(c.fog ? fogFactor(fog, t.worldView, position) : 0);
            push(out.varyings, v.TexCoord);
            push(out.varyings, worldPosition);
            push(out.varyings, worldNormal);
            return out;
        };
        PixelStage ps = [&](const std::vector<double>& in) {
            D4 color = d4At(in, 0) * cpuTexture.sample(in[8], in[9]);
            D3 specular = d3At(in, 4);
            if (c.perPixel) {
                bool nearTerminator = false;
                const LightResult r = light(lights, m, normalize(t.eye - d3At(in, 10)), normalize(d3At(in, 13)), &nearTerminator);
                if (nearTerminator) return skipped();
                const D3 rgb = color.xyz() * r.diffuse;
                color = {rgb.x, rgb.y, rgb.z, color.w};
                specular = r.specular;
            }
            const D3 rgb = color.xyz() + specular * color.w;
            color = {rgb.x, rgb.y, rgb.z, color.w};
            if (c.fog) color = applyFog(color, fog, in[7]);
            return colour(color);
        };
        expectMatches(runCase(name, effect, mesh, vs, ps), kTextureTolerance);
    }
    effect.WeightsPerVertex = 3;
    EXPECT_THROW(effect.CurrentTechnique->Passes[0].Apply(), ArgumentError);
}

TEST(StockEffects, AlwaysLitEffectsRefuseLightingOff) {
    EnvironmentMapEffect environment(testDevice());
    environment.LightingEnabled = false;
    EXPECT_THROW(environment.CurrentTechnique->Passes[0].Apply(), InvalidOperation);
    SkinnedEffect skinned(testDevice());
    skinned.LightingEnabled = false;
    EXPECT_THROW(skinned.CurrentTechnique->Passes[0].Apply(), InvalidOperation);
    AlphaTestEffect alphaTest(testDevice());
    alphaTest.ReferenceAlpha = 256;
    EXPECT_THROW(alphaTest.CurrentTechnique->Passes[0].Apply(), ArgumentError);
}

}  // namespace
}  // namespace fxport
