// countTextureFetches against hand counts: real effects under hlsl/ compiled as the runtime gets
// them, and small GLSL texts for each rule (loops multiplied out, branches as ranges, unknown trip
// counts unbounded, query functions not counted).
#include <gtest/gtest.h>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/texture_fetches.h"

using namespace fxport::xlate;

namespace {

// The count of the one pixel shader of `path` (paths relative to the repository root).
TextureFetches pixelShaderFetches(const std::string& path) {
    CompileOptions options;
    options.useCache = false;
    CompiledEffect e = compileEffectFile(path, options);
    EXPECT_FALSE(e.hasErrors()) << path;
    const CompiledShader* pixel = nullptr;
    for (const CompiledShader& s : e.shaders)
        if (s.profile.stage == ShaderStage::Pixel) {
            EXPECT_EQ(pixel, nullptr) << path << " has more than one pixel shader";
            pixel = &s;
        }
    if (!pixel) {
        ADD_FAILURE() << path << " has no pixel shader";
        return {};
    }
    return countTextureFetches(pixel->glsl);
}

void expectExact(const TextureFetches& f, int count) {
    EXPECT_TRUE(f.exact()) << f.text();
    EXPECT_EQ(f.least, count) << f.text();
    EXPECT_EQ(f.most, count) << f.text();
}

}  // namespace

// lighting2d's blurs: `for (int i = 0; i < KernelSize; i++) sum += tex2D(...)` with KernelSize 13;
// SPIRV-Cross keeps the loop and moves the increment into the body (`_263++; continue;`).
TEST(TextureFetches, Lighting2dBlursSample13Times) {
    expectExact(pixelShaderFetches("hlsl/lighting2d/HorizontalBlur.fx"), 13);
    expectExact(pixelShaderFetches("hlsl/lighting2d/VerticalBlur.fx"), 13);
}

// pointlights' PointLight.fx reads normalMap, colorMap and depthMap once each (3 tex2D, no loop).
TEST(TextureFetches, PointlightsPointLightSamples3Times) {
    expectExact(pixelShaderFetches("hlsl/zima-lights/PointLight.fx"), 3);
    expectExact(pixelShaderFetches("hlsl/zima-lights/DirectionalLight.fx"), 3);
}

// deferred's SSAOBlur as written: 4 (manualSample of the depth) + 1 (normal) + 1 (SSAO) + 9 x (4 + 1)
// in the loop from -4 to 4 = 51 tex2D per pixel. The depth it samples first is never used, and
// the compiler drops those 4 fetches: the shader the GPU runs makes 1 + 1 + 9 x 5 = 47.
TEST(TextureFetches, SsaoBlurSamples47TimesAfterTheUnusedDepthIsDropped) {
    expectExact(pixelShaderFetches("hlsl/xna-deferred/SSAOBlur.fx"), 47);
}

// deferred's PointLight.fx: normal 1 + colour 1 + depth by manualSample 4 + the shadow cube's
// 8-tap trilinear filter 8 = 14; the shadow term's `if (Shadows)` only chooses the result, the
// compiler hoists the fetches above it, so every fragment makes all 14.
TEST(TextureFetches, DeferredPointLightSamples14Times) {
    expectExact(pixelShaderFetches("hlsl/xna-deferred/PointLight.fx"), 14);
}

// lighting2d's light shaders return early; SPIRV-Cross writes that as do { ... break; } while (false).
// PointLight.fx samples the occlusion map once before its test; SpotLight.fx samples it on the
// right of an && (only inside the spot's arc): 0..1.
TEST(TextureFetches, Lighting2dLightsEarlyOutBlocks) {
    expectExact(pixelShaderFetches("hlsl/lighting2d/PointLight.fx"), 1);
    const TextureFetches spot = pixelShaderFetches("hlsl/lighting2d/SpotLight.fx");
    EXPECT_FALSE(spot.unbounded);
    EXPECT_EQ(spot.least, 0);
    EXPECT_EQ(spot.most, 1);
}

TEST(TextureFetches, ConstantLoopsMultiplyAndNest) {
    const char* glsl = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(location = 0) out vec4 o;
void main() {
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; i++)
        for (int j = 10; j > 0; j -= 2)   // 5 trips
            sum += texture(s, vec2(i, j));
    for (uint k = 0u; k <= 6u; k += 3)    // 0, 3, 6: 3 trips
        sum += textureLod(s, vec2(k), 0.0) + texelFetch(s, ivec2(k), 0);
    o = sum * float(textureSize(s, 0).x);  // a query, not a fetch
})";
    expectExact(countTextureFetches(glsl), 4 * 5 + 3 * 2);
}

TEST(TextureFetches, BranchesGiveARange) {
    const char* glsl = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(binding = 0, std140) uniform U { int mode; } u;
layout(location = 0) out vec4 o;
void main() {
    vec4 c = texture(s, vec2(0.0));
    if (u.mode == 1) { c += texture(s, vec2(1.0)); c += texture(s, vec2(2.0)); }
    else if (u.mode == 2) c += texture(s, vec2(3.0));
    c += u.mode > 3 ? texture(s, vec2(4.0)) : vec4(0.0);
    o = c;
})";
    const TextureFetches f = countTextureFetches(glsl);
    EXPECT_FALSE(f.exact());
    EXPECT_FALSE(f.unbounded);
    EXPECT_EQ(f.least, 1);
    EXPECT_EQ(f.most, 1 + 2 + 1);
    EXPECT_EQ(f.text(), "1..4");
}

TEST(TextureFetches, UniformTripCountsAndBreaksAreNotGuessed) {
    const char* uniformLoop = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(binding = 0, std140) uniform U { int taps; } u;
layout(location = 0) out vec4 o;
void main() {
    vec4 c = texture(s, vec2(0.0));
    for (int i = 0; i < u.taps; i++) c += texture(s, vec2(float(i)));
    o = c;
})";
    TextureFetches f = countTextureFetches(uniformLoop);
    EXPECT_TRUE(f.unbounded);
    EXPECT_EQ(f.least, 1);
    EXPECT_EQ(f.text(), ">=1");

    const char* breaking = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(location = 0) out vec4 o;
void main() {
    vec4 c = vec4(0.0);
    for (int i = 0; i < 8; i++) {
        c += texture(s, vec2(float(i)));
        if (c.x > 1.0) break;
    }
    o = c;
})";
    f = countTextureFetches(breaking);
    EXPECT_FALSE(f.unbounded);
    EXPECT_EQ(f.least, 0);
    EXPECT_EQ(f.most, 8);

    // The counter assigned inside the body (not the loop's own trailing step): unknown.
    const char* counterMoved = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(location = 0) out vec4 o;
void main() {
    vec4 c = vec4(0.0);
    for (int i = 0; i < 8; i++) { c += texture(s, vec2(float(i))); if (c.x > 0.5) i += 2; }
    o = c;
})";
    f = countTextureFetches(counterMoved);
    EXPECT_TRUE(f.unbounded);
    EXPECT_EQ(f.least, 0);

    // After a conditional break in a run-once block the rest may not run.
    const char* earlyOut = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(location = 0) out vec4 o;
void main() {
    vec4 c;
    do {
        c = texture(s, vec2(0.0));
        if (c.x > 0.5) { break; }
        c += texture(s, vec2(1.0)) + texture(s, vec2(2.0));
        break;
    } while (false);
    o = c;
})";
    f = countTextureFetches(earlyOut);
    EXPECT_FALSE(f.unbounded);
    EXPECT_EQ(f.least, 1);
    EXPECT_EQ(f.most, 3);
}

TEST(TextureFetches, CalledFunctionsAndConditionalReturns) {
    const char* glsl = R"(#version 450
layout(binding = 0) uniform sampler2D s;
layout(location = 0) out vec4 o;
layout(location = 0) in vec2 uv;
vec4 textureTwice(vec2 p) { return texture(s, p) + texture(s, -p); }  // a texture* name of the shader's own
vec4 fourTaps(vec2 p) {
    vec4 r = vec4(0.0);
    for (int i = 0; i < 4; ) { r += texture(s, p + vec2(float(i))); i++; continue; }
    return r;
}
void main() {
    vec4 c = fourTaps(uv) + fourTaps(uv * 2.0);
    if (c.w < 0.5) { o = c; return; }
    o = c + textureTwice(uv);
})";
    const TextureFetches f = countTextureFetches(glsl);
    EXPECT_FALSE(f.unbounded);
    EXPECT_EQ(f.least, 8);
    EXPECT_EQ(f.most, 10);
}

TEST(TextureFetches, ShaderWithoutSamplingCountsNothing) {
    expectExact(countTextureFetches("#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n"), 0);
    expectExact(countTextureFetches(""), 0);
}
