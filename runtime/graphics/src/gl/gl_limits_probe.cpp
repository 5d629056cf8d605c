// The GL half of GpuLimits::Measure (diagnostics/gpu_limits.cpp): full-screen triangles drawn by raw GL
// programs into offscreen targets of each format, timed with GL_TIME_ELAPSED queries. It works outside the
// device's state shadow; the caller binds the device's objects again and invalidates the shadow.
#include <functional>

#include "gl/gl_backend.h"
#include "fxport/graphics/errors.h"
#include "gl/gl_formats.h"

namespace fxport {

namespace {

const char* kVertexShader = R"(#version 450
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";
// Colours that change per pixel: a constant colour would let a driver compress the writes.
const char* kFillShader = R"(#version 450
layout(location = 0) out vec4 color;
void main() { color = fract(gl_FragCoord.xyxy * vec4(0.013, 0.017, 0.019, 0.023)); })";
// 16 bilinear fetches per pixel around it (each half a texel apart, so mostly cache hits: the
// texture unit's rate, not memory's).
const char* kFetchShader = R"(#version 450
layout(binding = 0) uniform sampler2D source;
layout(location = 0) out vec4 color;
void main() {
    vec2 texel = 1.0 / vec2(textureSize(source, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 16; ++i) sum += texture(source, uv + texel * 0.5 * vec2(i % 4, i / 4));
    color = sum * 0.0625;
})";
constexpr int kFetchesPerPixel = 16;
// What a compute pass (compute_pass.cpp) does at the least: one imageStore per pixel.
const char* kComputeWriteShader = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) writeonly uniform image2D target;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    imageStore(target, p, fract(vec4(p.xyxy) * vec4(0.013, 0.017, 0.019, 0.023)));
})";

GLuint compile(GLenum stage, const char* source) {
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        glDeleteShader(shader);
        throw InvalidOperation(std::string("GpuLimits: probe shader does not compile: ") + log);
    }
    return shader;
}

GLuint linkCompute(const char* source) {
    GLuint cs = compile(GL_COMPUTE_SHADER, source);
    GLuint program = glCreateProgram();
    glAttachShader(program, cs);
    glLinkProgram(program);
    glDeleteShader(cs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        glDeleteProgram(program);
        throw InvalidOperation("GpuLimits: compute probe program does not link");
    }
    return program;
}

GLuint link(const char* pixelSource) {
    GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), ps = compile(GL_FRAGMENT_SHADER, pixelSource);
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, ps);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(ps);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        glDeleteProgram(program);
        throw InvalidOperation("GpuLimits: probe program does not link");
    }
    return program;
}

// Seconds the GPU took for `work`, after one untimed run of it.
double gpuSeconds(const std::function<void()>& work) {
    work();
    glFinish();  // a deferring rasteriser (llvmpipe) would otherwise compile and run it inside the timed query
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_TIME_ELAPSED, query);
    work();
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
    glDeleteQueries(1, &query);
    return double(ns) * 1e-9;
}

struct Target {
    GLuint texture = 0, framebuffer = 0;
    Target(SurfaceFormat format, int size) {
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, detail::glFormat(format).internalFormat, size, size);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    }
    ~Target() {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &texture);
    }
};

struct Probe {
    int size, repeats;
    double pixels;
    std::function<void()> draws;
};

void measureFills(const Probe& p, const std::vector<SurfaceFormat>& formats, GLuint fillProgram, GpuLimits& limits) {
    glUseProgram(fillProgram);
    for (SurfaceFormat format : formats) {
        Target target(format, p.size);
        const double bytes = p.pixels * detail::glFormat(format).bytesPerPixel;
        GpuLimits::Fill f{format};
        glDisable(GL_BLEND);
        f.opaqueGBps = bytes / gpuSeconds(p.draws) * 1e-9;
        glEnable(GL_BLEND);
        f.blendedGBps = bytes / gpuSeconds(p.draws) * 1e-9;
        glDisable(GL_BLEND);
        limits.fill.push_back(f);
    }
}

double measureClear(const Probe& p) {
    Target target(SurfaceFormat::Color, p.size);
    const float color[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    return p.pixels * 4 / gpuSeconds([&] {
        for (int i = 0; i < p.repeats; ++i) glClearNamedFramebufferfv(target.framebuffer, GL_COLOR, 0, color);
    }) * 1e-9;
}

// Leaves texture unit 0 and its sampler bound to the probe's (deleted) objects: the caller re-binds.
double measureFetch(const Probe& p, GLuint fillProgram, GLuint fetchProgram) {
    Target source(SurfaceFormat::Color, p.size);  // filled by the fill shader, then sampled
    glUseProgram(fillProgram);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    Target target(SurfaceFormat::Color, p.size);
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTextureUnit(0, source.texture);
    glBindSampler(0, sampler);
    glUseProgram(fetchProgram);
    const double rate = p.pixels * kFetchesPerPixel / gpuSeconds(p.draws) * 1e-9;
    glDeleteSamplers(1, &sampler);
    return rate;
}

double measureComputeWrites(const Probe& p) {
    Target target(SurfaceFormat::Color, p.size);
    GLuint computeProgram = linkCompute(kComputeWriteShader);
    glUseProgram(computeProgram);
    glBindImageTexture(0, target.texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    const GLuint groups = GLuint((p.size + 7) / 8);
    const double rate = p.pixels * 4 / gpuSeconds([&] {
        for (int i = 0; i < p.repeats; ++i) {
            glDispatchCompute(groups, groups, 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // as a compute pass ends
        }
    }) * 1e-9;
    glDeleteProgram(computeProgram);
    return rate;
}

}  // namespace

GpuLimits GlBackend::measureLimits(const std::vector<SurfaceFormat>& formats, int size, int repeats) {
    GpuLimits limits;
    GLuint fillProgram = link(kFillShader), fetchProgram = link(kFetchShader);
    GLuint vertexArray = 0;
    glCreateVertexArrays(1, &vertexArray);
    glBindVertexArray(vertexArray);
    glBindProgramPipeline(0);
    for (GLenum cap : {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CULL_FACE, GL_FRAMEBUFFER_SRGB})
        glDisable(cap);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glViewport(0, 0, size, size);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_ADD);
    Probe p{size, repeats, double(size) * double(size) * repeats, [repeats] {
                for (int i = 0; i < repeats; ++i) glDrawArrays(GL_TRIANGLES, 0, 3);
            }};
    measureFills(p, formats, fillProgram, limits);
    limits.clearGBps = measureClear(p);
    limits.fetchGTexelsPerSecond = measureFetch(p, fillProgram, fetchProgram);
    limits.computeWriteGBps = measureComputeWrites(p);
    glUseProgram(0);  // the device draws with program pipelines, which a bound program would override
    glDeleteProgram(fillProgram);
    glDeleteProgram(fetchProgram);
    glDeleteVertexArrays(1, &vertexArray);
    return limits;
}

}  // namespace fxport
