// GpuLimits: measures fill, clear and fetch rates with raw GL (full-screen triangles into
// offscreen targets, GL_TIME_ELAPSED queries) and caches them per renderer string.
#include "fxport/graphics/gpu_limits.h"

#include "fxport/graphics/graphics_device.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"
#include "gl/gl_formats.h"

namespace fxport {

namespace {

const SurfaceFormat kFormats[] = {SurfaceFormat::Color,  SurfaceFormat::Rgba64, SurfaceFormat::HalfVector4,
                                  SurfaceFormat::Vector4, SurfaceFormat::Single, SurfaceFormat::Vector2};

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

std::string cacheFolder(const std::string& given) {
    if (!given.empty()) return given;
    if (const char* d = std::getenv("FXPORT_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/fxport";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/fxport";
    return ".fxport-cache";
}

}  // namespace

double GpuLimits::fillGBps(SurfaceFormat format, bool blended) const {
    auto rate = [&](const Fill& f) { return blended ? f.blendedGBps : f.opaqueGBps; };
    double slowest = 0;
    for (const Fill& f : fill) {
        if (f.format == format) return rate(f);
        slowest = slowest == 0 ? rate(f) : std::min(slowest, rate(f));
    }
    for (const Fill& f : fill)
        if (bytesPerPixel(f.format) == bytesPerPixel(format)) return rate(f);
    return slowest;
}

GpuLimits GpuLimits::Measure(GraphicsDevice& device, int size, int repeats) {
    GraphicsDevice::Impl& impl = deviceImpl(device);
    GpuLimits limits;
    limits.renderer = device.rendererName();
    const double pixels = double(size) * double(size) * repeats;

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
    auto draws = [&] {
        for (int i = 0; i < repeats; ++i) glDrawArrays(GL_TRIANGLES, 0, 3);
    };

    glUseProgram(fillProgram);
    for (SurfaceFormat format : kFormats) {
        Target target(format, size);
        const double bytes = pixels * detail::glFormat(format).bytesPerPixel;
        Fill f{format};
        glDisable(GL_BLEND);
        f.opaqueGBps = bytes / gpuSeconds(draws) * 1e-9;
        glEnable(GL_BLEND);
        f.blendedGBps = bytes / gpuSeconds(draws) * 1e-9;
        glDisable(GL_BLEND);
        limits.fill.push_back(f);
    }
    {
        Target target(SurfaceFormat::Color, size);
        const float color[4] = {0.25f, 0.5f, 0.75f, 1.0f};
        limits.clearGBps = pixels * 4 / gpuSeconds([&] {
            for (int i = 0; i < repeats; ++i) glClearNamedFramebufferfv(target.framebuffer, GL_COLOR, 0, color);
        }) * 1e-9;
    }
    {
        Target source(SurfaceFormat::Color, size);  // filled by the fill shader, then sampled
        glUseProgram(fillProgram);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        Target target(SurfaceFormat::Color, size);
        GLuint sampler = 0;
        glCreateSamplers(1, &sampler);
        glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTextureUnit(0, source.texture);
        glBindSampler(0, sampler);
        glUseProgram(fetchProgram);
        limits.fetchGTexelsPerSecond = pixels * kFetchesPerPixel / gpuSeconds(draws) * 1e-9;
        glBindSampler(0, impl.boundSamplers[0]);
        glBindTextureUnit(0, impl.boundTextures[0]);
        glDeleteSamplers(1, &sampler);
    }

    {
        Target target(SurfaceFormat::Color, size);
        GLuint computeProgram = linkCompute(kComputeWriteShader);
        glUseProgram(computeProgram);
        glBindImageTexture(0, target.texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        const GLuint groups = GLuint((size + 7) / 8);
        limits.computeWriteGBps = pixels * 4 / gpuSeconds([&] {
            for (int i = 0; i < repeats; ++i) {
                glDispatchCompute(groups, groups, 1);
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // as a compute pass ends
            }
        }) * 1e-9;
        glDeleteProgram(computeProgram);
    }

    // Hand GL back as the device's shadow says it is; what the shadow cannot say, it re-applies.
    glUseProgram(0);
    glDeleteProgram(fillProgram);
    glDeleteProgram(fetchProgram);
    glBindVertexArray(impl.boundVertexArray);
    glDeleteVertexArrays(1, &vertexArray);
    glBindProgramPipeline(impl.boundPipeline);
    impl.boundFramebuffer = 0;  // the next draw or clear binds its targets again
    impl.shadow.invalidate();   // and sets every fixed-function state
    return limits;
}

std::string GpuLimits::toText() const {
    std::ostringstream out;
    out.precision(6);
    out << "renderer " << renderer << "\n";
    for (const Fill& f : fill)
        out << "fill " << surfaceFormatName(f.format) << " " << f.opaqueGBps << " " << f.blendedGBps << "\n";
    out << "clear " << clearGBps << "\n";
    out << "fetch " << fetchGTexelsPerSecond << "\n";
    out << "compute " << computeWriteGBps << "\n";
    return out.str();
}

bool GpuLimits::fromText(const std::string& text, GpuLimits& out) {
    GpuLimits limits;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string key;
        fields >> key;
        if (key == "renderer") {
            limits.renderer = line.size() > 9 ? line.substr(9) : "";
        } else if (key == "fill") {
            std::string name;
            Fill f{};
            if (!(fields >> name >> f.opaqueGBps >> f.blendedGBps)) return false;
            bool known = false;
            for (SurfaceFormat format : kFormats)
                if (name == surfaceFormatName(format)) f.format = format, known = true;
            if (!known || !(f.opaqueGBps > 0 && f.blendedGBps > 0)) return false;
            limits.fill.push_back(f);
        } else if (key == "clear") {
            if (!(fields >> limits.clearGBps)) return false;
        } else if (key == "fetch") {
            if (!(fields >> limits.fetchGTexelsPerSecond)) return false;
        } else if (key == "compute") {
            if (!(fields >> limits.computeWriteGBps)) return false;
        } else if (!key.empty()) {
            return false;
        }
    }
    // A cache written before the compute rate was measured has none: measured again.
    if (limits.fill.size() != std::size(kFormats) || !(limits.clearGBps > 0) || !(limits.fetchGTexelsPerSecond > 0) ||
        !(limits.computeWriteGBps > 0))
        return false;
    out = limits;
    return true;
}

bool GpuLimits::softwareRenderer(const std::string& renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "swrast"})
        if (renderer.find(software) != std::string::npos) return true;
    return false;
}

bool GpuLimits::computePassesFaster() const {
    const double fragment = fillGBps(SurfaceFormat::Color, false);
    return fragment > 0 && computeWriteGBps >= kComputePassesWhereFaster * fragment;
}

GpuLimits GpuLimits::ForDevice(GraphicsDevice& device, const std::string& cacheDir) {
    const std::string renderer = device.rendererName();
    const std::filesystem::path file =
        std::filesystem::path(cacheFolder(cacheDir)) /
        ("gpu-limits-" + std::to_string(std::hash<std::string>{}(renderer)) + ".txt");
    if (std::ifstream in{file}) {
        std::stringstream text;
        text << in.rdbuf();
        GpuLimits cached;
        if (fromText(text.str(), cached) && cached.renderer == renderer) return cached;
    }
    // A software rasteriser (OSMesa's llvmpipe) draws a 2048-square target in tens of ms: a small probe.
    GpuLimits limits = softwareRenderer(renderer) ? Measure(device, 256, 2) : Measure(device);
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream(file) << limits.toText();  // a cache: a folder we cannot write only costs a re-measure
    return limits;
}

}  // namespace fxport
