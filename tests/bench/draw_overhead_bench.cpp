// CPU cost of the runtime's draw path against raw GL doing the same work (issue 3's benchmark):
//   fxport: 5 x Parameters[...].SetValue + Apply() + DrawPrimitives
//   raw GL: the same 5 values written to a CPU copy of the uniform block, one glNamedBufferSubData
//           of the changed bytes, the same program pipeline, VAO and glDrawArrays.
// On OSMesa (llvmpipe) with a 4x4 target so the GPU side is as small as it gets. Both loops
// glFinish every 256 iterations so neither queues unboundedly. Each side has its own device (GL
// context), made current when its benchmark starts, so repetitions can be interleaved (llvmpipe's
// timing drifts with machine load; interleaving makes the two sides see the same drift).
// Run: scripts/bench-draw.
#include <benchmark/benchmark.h>

#include <cstring>

#include "fxport/graphics.h"
#include "fxport/platform/gl.h"
#include "fxport/xlate/compiled_effect.h"

using namespace fxport;

namespace {

struct Scene {
    GraphicsDevice device{[] {
        PresentationParameters p;
        p.BackBufferWidth = p.BackBufferHeight = 4;
        return p;
    }()};
    Effect effect{device, std::string(FXPORT_BENCH_FIXTURES) + "/Conventions.fx"};
    VertexBuffer quad{device, VertexPositionTexture::VertexDeclaration, 3};
    Scene() {
        VertexPositionTexture v[3] = {{Vector3(-1, 1, 0), Vector2()}, {Vector3(3, 1, 0), Vector2()},
                                      {Vector3(-1, -3, 0), Vector2()}};
        quad.SetData(v, 3);
        device.RasterizerState = RasterizerState::CullNone;
        device.DepthStencilState = DepthStencilState::None;
        effect.CurrentTechnique = effect.Techniques["SolidColor"];
    }
};

Scene& scene() {
    static Scene s;
    return s;
}

// Both loops must really draw: the 4x4 target's red channel must hold the colour's 0.5 and GL must
// report no error, else the run is marked failed rather than reported fast.
void checkDrew(benchmark::State& state) {
    std::uint8_t px[4] = {0, 0, 0, 0};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    GLenum error = glGetError();
    if (error != GL_NO_ERROR || px[0] < 120 || px[0] > 135)
        state.SkipWithError(("nothing drawn: GL error " + std::to_string(error) + ", red " + std::to_string(px[0])).c_str());
}

Scene& rawScene() {
    static Scene s;
    return s;
}

// Sets five parameters, applies the effect's current pass and draws, as a game's inner loop does.
void setValueApplyDraw(benchmark::State& state, Scene& s) {
    EffectParameter& transform = s.effect.Parameters["Transform"];
    EffectParameter& rowMajor = s.effect.Parameters["TransformRowMajor"];
    EffectParameter& vector = s.effect.Parameters["Vector"];
    EffectParameter& color = s.effect.Parameters["Color"];
    EffectParameter& direction = s.effect.Parameters["Direction"];
    EffectPass& pass = s.effect.CurrentTechnique->Passes[0];
    s.device.SetVertexBuffer(s.quad);
    Matrix m = Matrix::CreateTranslation(1, 2, 3);
    int i = 0;
    for (auto _ : state) {
        m.M41 = float(i & 7);
        transform.SetValue(m);
        rowMajor.SetValue(m);
        vector.SetValue(Vector4(float(i), 0, 0, 1));
        color.SetValue(Vector4(0.5f, 0.5f, float(i & 1), 1));
        direction.SetValue(Vector4(1, 0, 0, 0));
        pass.Apply();
        s.device.DrawPrimitives(PrimitiveType::TriangleList, 0, 1);
        if ((++i & 255) == 0) glFinish();
    }
    glFinish();
    checkDrew(state);
}

void BM_FxportSetValueApplyDraw(benchmark::State& state) {
    Scene& s = scene();
    s.device.makeCurrent();
    setValueApplyDraw(state, s);
}
BENCHMARK(BM_FxportSetValueApplyDraw);

// The same with a pass that sets render states (MinBlend: AlphaBlendEnable, BlendOp, SrcBlend,
// DestBlend), the part of Apply that typed pass states changed (decoded once instead of looked up
// and converted per Apply). Its own device: the pass's blend state stays set on it. The target
// starts white, so Min(0.5, white) leaves the 0.5 that checkDrew looks for.
Scene& statesScene() {
    static Scene s;
    return s;
}

void BM_FxportSetValueApplyDrawWithPassStates(benchmark::State& state) {
    Scene& s = statesScene();
    s.device.makeCurrent();
    s.effect.CurrentTechnique = s.effect.Techniques["MinBlend"];
    s.device.Clear(Color::White);
    setValueApplyDraw(state, s);
}
BENCHMARK(BM_FxportSetValueApplyDrawWithPassStates);

void BM_RawGLSameWork(benchmark::State& state) {
    Scene& s = rawScene();  // its own context: the raw GL below never disturbs the fxport device
    s.device.makeCurrent();
    const xlate::CompiledEffect& c = s.effect.compiled();
    const xlate::Pass& pass = c.techniques[std::size_t(c.findTechnique("SolidColor"))].passes[0];
    const std::string& vsText = c.shaders[std::size_t(pass.vertexShader.shaders[0])].glsl;
    const std::string& psText = c.shaders[std::size_t(pass.pixelShader.shaders[0])].glsl;
    const char* vsSrc = vsText.c_str();
    const char* psSrc = psText.c_str();
    GLuint vs = glCreateShaderProgramv(GL_VERTEX_SHADER, 1, &vsSrc);
    GLuint ps = glCreateShaderProgramv(GL_FRAGMENT_SHADER, 1, &psSrc);
    GLuint pipeline = 0;
    glCreateProgramPipelines(1, &pipeline);
    glUseProgramStages(pipeline, GL_VERTEX_SHADER_BIT, vs);
    glUseProgramStages(pipeline, GL_FRAGMENT_SHADER_BIT, ps);
    int size = c.uniformBlocks[0].size;
    std::vector<std::uint8_t> block(std::size_t(size), 0);
    GLuint ubo = 0, internal = 0, vbo = 0, vao = 0;
    glCreateBuffers(1, &ubo);
    glNamedBufferStorage(ubo, size, nullptr, GL_DYNAMIC_STORAGE_BIT);
    glCreateBuffers(1, &internal);
    const float offset[4] = {0.5f, -0.5f, 0, 0};
    glNamedBufferStorage(internal, 16, offset, 0);
    const float tri[15] = {-1, 1, 0, 0, 0, 3, 1, 0, 0, 0, -1, -3, 0, 0, 0};
    glCreateBuffers(1, &vbo);
    glNamedBufferStorage(vbo, sizeof tri, tri, 0);
    glCreateVertexArrays(1, &vao);
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 0, 0);
    glVertexArrayVertexBuffer(vao, 0, vbo, 0, 20);
    glBindProgramPipeline(pipeline);
    glBindVertexArray(vao);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo);
    glBindBufferBase(GL_UNIFORM_BUFFER, 8, ubo);
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, internal);
    auto offsetOf = [&](const char* name) { return c.findParameter(name)->offset; };
    int oT = offsetOf("Transform"), oR = offsetOf("TransformRowMajor"), oV = offsetOf("Vector"), oC = offsetOf("Color"),
        oD = offsetOf("Direction");
    Matrix m = Matrix::CreateTranslation(1, 2, 3);
    int i = 0;
    for (auto _ : state) {
        m.M41 = float(i & 7);
        const float v[4] = {float(i), 0, 0, 1}, col[4] = {0.5f, 0.5f, float(i & 1), 1}, d[4] = {1, 0, 0, 0};
        std::memcpy(&block[std::size_t(oT)], m.data(), 64);
        std::memcpy(&block[std::size_t(oR)], m.data(), 64);
        std::memcpy(&block[std::size_t(oV)], v, 16);
        std::memcpy(&block[std::size_t(oC)], col, 16);
        std::memcpy(&block[std::size_t(oD)], d, 16);
        glNamedBufferSubData(ubo, 0, size, block.data());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if ((++i & 255) == 0) glFinish();
    }
    glFinish();
    checkDrew(state);
    glBindProgramPipeline(0);
    glBindVertexArray(0);
    glDeleteProgramPipelines(1, &pipeline);
    glDeleteProgram(vs);
    glDeleteProgram(ps);
    glDeleteBuffers(1, &ubo);
    glDeleteBuffers(1, &internal);
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    // This context's device shadow no longer matches GL; only this benchmark uses it.
}
BENCHMARK(BM_RawGLSameWork);

}  // namespace

BENCHMARK_MAIN();
