// Compute passes (compute_pass.h): the per-draw checks that a dispatch gives the fragment
// stage's pixels, the transform-feedback capture of the draw's vertices, the compare step, the
// fill of the replay store, the dispatch and the fragment fall-back. Programs are cached per
// shader (and target formats, blend, masks), replay entries per draw key in a byte-bounded LRU;
// like the device's sampler objects they are internal caches, released with the device and not
// counted in liveGpuObjects() (ComputePassStatistics reports the entries and their bytes).
#include "gl/passes/compute_pass.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture.h"
#include "fxport/xlate/compiled_effect.h"
#include "gl/gl_formats.h"
#include "device/sampler_filter.h"

namespace fxport {

namespace {

DepthFormat targetDepthFormat(const Texture* target) {
    if (target->kind() == Texture::Kind::TextureCube) return static_cast<const RenderTargetCube*>(target)->DepthStencilFormat();
    return static_cast<const RenderTarget2D*>(target)->DepthStencilFormat();
}

bool isFullFloat(SurfaceFormat format) {
    return format == SurfaceFormat::Vector4 || format == SurfaceFormat::Single || format == SurfaceFormat::Vector2;
}

// A blend function as a read-modify-write, or false when it is not one this path reproduces.
bool blendOpOf(BlendFunction function, Blend source, Blend destination, bool fullFloat, detail::BlendOp& op) {
    switch (function) {
    case BlendFunction::Min: op = detail::BlendOp::Min; return true;  // GL and D3D ignore the factors
    case BlendFunction::Max: op = detail::BlendOp::Max; return true;
    case BlendFunction::Add:
        if (source == Blend::One && destination == Blend::Zero) {
            op = detail::BlendOp::Write;
            return true;
        }
        // One/One in fp32 is the same addition the blender does; narrower formats may blend at
        // another precision, so they are drawn as usual.
        if (source == Blend::One && destination == Blend::One && fullFloat) {
            op = detail::BlendOp::Add;
            return true;
        }
        return false;
    default: return false;
    }
}

// Draws in a row whose user vertices differ from the previous draw's under one replay key before
// the next such draw is drawn as usual (until one comes with the previous one's bytes again).
constexpr int kChangesBeforeFragments = 3;

}  // namespace

namespace detail {

// The image format a compute shader stores `format` with; null when GL has none for it (packed
// 16-bit formats, sRGB).
const char* imageFormatOf(SurfaceFormat format) {
    switch (format) {
    case SurfaceFormat::Color: return "rgba8";
    case SurfaceFormat::Rgba64: return "rgba16";
    case SurfaceFormat::HalfVector4:
    case SurfaceFormat::HdrBlendable: return "rgba16f";
    case SurfaceFormat::Vector4: return "rgba32f";
    case SurfaceFormat::Single: return "r32f";
    case SurfaceFormat::Vector2: return "rg32f";
    case SurfaceFormat::HalfSingle: return "r16f";
    case SurfaceFormat::HalfVector2: return "rg16f";
    case SurfaceFormat::Rg32: return "rg16";
    case SurfaceFormat::Alpha8: return "r8";
    case SurfaceFormat::Rgba1010102: return "rgb10_a2";
    default: return nullptr;
    }
}

// Compiles and links one stage; 0 and the log's first line on failure.
GLuint linkProgram(GLenum stage, const std::string& source, const std::vector<std::string>& captured, bool printLog,
                   std::string& error, bool separable) {
    GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    // The line that says what is wrong: NVIDIA's log opens with "Compute info", a rule and warnings.
    auto firstLine = [](std::string log) {
        log.resize(std::strlen(log.c_str()));
        std::string first;
        for (std::size_t begin = 0; begin < log.size();) {
            std::size_t end = log.find('\n', begin);
            if (end == std::string::npos) end = log.size();
            std::string line = log.substr(begin, end - begin);
            if (line.find("error") != std::string::npos) return line;
            if (first.empty() && line.find_first_not_of(" -\t") != std::string::npos) first = line;
            begin = end + 1;
        }
        return first;
    };
    if (!ok) {
        std::string log(4096, '\0');
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        error = "does not compile: " + firstLine(log);
        if (printLog) std::fprintf(stderr, "%s\n%s\n", log.c_str(), source.c_str());
        return 0;
    }
    GLuint program = glCreateProgram();
    if (separable) glProgramParameteri(program, GL_PROGRAM_SEPARABLE, GL_TRUE);
    glAttachShader(program, shader);
    if (!captured.empty()) {
        std::vector<const char*> names;
        for (const std::string& n : captured) names.push_back(n.c_str());
        glTransformFeedbackVaryings(program, GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program);
    glDetachShader(program, shader);
    glDeleteShader(shader);
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        glDeleteProgram(program);
        error = "does not link: " + firstLine(log);
        if (printLog) std::fprintf(stderr, "%s\n%s\n", log.c_str(), source.c_str());
        return 0;
    }
    // The uniform blocks keep the binding points the device gives this stage (the compute program
    // stands in for the pixel stage).
    moveUniformBlocksToStage(program, stage == GL_VERTEX_SHADER ? 0 : 1);
    return program;
}

PixelBox drawablePixels(const GraphicsDevice& device, int targetWidth, int targetHeight) {
    const Viewport& viewport = device.Viewport;
    PixelBox b{std::max(viewport.X, 0), std::max(viewport.Y, 0), std::min(viewport.X + viewport.Width, targetWidth),
               std::min(viewport.Y + viewport.Height, targetHeight)};
    if (device.RasterizerState.ScissorTestEnable) {
        const Rectangle& s = device.ScissorRectangle;
        b.x0 = std::max(b.x0, s.X), b.y0 = std::max(b.y0, s.Y);
        b.x1 = std::min(b.x1, s.X + s.Width), b.y1 = std::min(b.y1, s.Y + s.Height);
    }
    return b;
}

}  // namespace detail

using detail::imageFormatOf;
using detail::linkProgram;

std::shared_ptr<ComputePasses> createComputePasses(GraphicsDevice& device) { return std::make_shared<GlComputePasses>(device); }

GlComputePasses::GlComputePasses(GraphicsDevice& owner)
    : device(owner), printOutcomes(std::getenv("FXPORT_COMPUTE_PASSES_DEBUG") != nullptr) {
    if (const char* mb = std::getenv("FXPORT_COMPUTE_PASS_CACHE_MB")) {
        char* end = nullptr;
        const long value = std::strtol(mb, &end, 10);
        if (end != mb && *end == '\0' && value >= 0 && value <= (1l << 20))
            byteBudget = std::int64_t(value) << 20;
        else
            std::fprintf(stderr, "fxport: FXPORT_COMPUTE_PASS_CACHE_MB='%s' is not a number of MiB (0..1048576); using %lld\n", mb,
                         static_cast<long long>(byteBudget >> 20));
    }
}

GlComputePasses::~GlComputePasses() {
    for (auto& [serial, capture] : capturePrograms)
        if (capture.program) glDeleteProgram(capture.program);
    for (auto& [key, dispatcher] : computePrograms)
        if (dispatcher.program) glDeleteProgram(dispatcher.program);
    for (auto& [serial, fill] : fillPrograms)
        if (fill.program) glDeleteProgram(fill.program);
    for (auto& [key, pipeline] : fillPipelines)
        if (pipeline) glDeleteProgramPipelines(1, &pipeline);
    while (!entries.empty()) dropEntry(entries.begin());
    if (fillFramebuffer) glDeleteFramebuffers(1, &fillFramebuffer);
    if (captureBuffer) glDeleteBuffers(1, &captureBuffer);
    for (auto& [key, reduction] : reductionPrograms)
        if (reduction.program) glDeleteProgram(reduction.program);
    if (copiesBuffer) glDeleteBuffers(1, &copiesBuffer);
    if (compare.program) glDeleteProgram(compare.program);
    if (compare.commands) glDeleteBuffers(1, &compare.commands);
    if (compare.counters) {
        glUnmapNamedBuffer(compare.counters);
        glDeleteBuffers(1, &compare.counters);
    }
}

void GlComputePasses::dropEntry(std::map<EntryKey, ReplayEntry>::iterator it) {
    glDeleteTextures(1, &it->second.store);
    glDeleteBuffers(1, &it->second.vertices);
    entryBytes -= it->second.bytes;
    recency.erase(it->second.recency);
    entries.erase(it);
}

void GlComputePasses::forget(const ComputeAnalysis& analysis) {
    const int serial = analysis.serial;
    if (auto it = capturePrograms.find(serial); it != capturePrograms.end()) {
        if (it->second.program) glDeleteProgram(it->second.program);
        capturePrograms.erase(it);
    }
    if (auto it = fillPrograms.find(serial); it != fillPrograms.end()) {
        if (it->second.program) glDeleteProgram(it->second.program);
        fillPrograms.erase(it);
    }
    std::erase_if(computePrograms, [&](const auto& item) {
        if (item.first.first != serial) return false;
        if (item.second.program) glDeleteProgram(item.second.program);
        return true;
    });
    std::erase_if(fillPipelines, [&](const auto& item) {
        if (item.first.first != serial && item.first.second != serial) return false;
        if (item.second) glDeleteProgramPipelines(1, &item.second);
        return true;
    });
    for (auto it = entries.begin(); it != entries.end();) {
        auto next = std::next(it);
        if (it->first.vertexSerial == serial) dropEntry(it);
        it = next;
    }
    std::erase_if(userDataHistory, [&](const auto& item) { return item.first.vertexSerial == serial; });
}

bool GlComputePasses::fallBack(const std::string& reason) {
    if (printOutcomes) std::fprintf(stderr, "compute pass: %s falls back: %s\n", prepared::shader(device, 1)->label.c_str(), reason.c_str());
    ++statistics.fellBack[reason];
    return false;
}

const ComputeAnalysis& GlComputePasses::analysisOf(const ShaderProgram& program) {
    if (!program.computeAnalysis) {
        auto analysis = std::make_shared<ComputeAnalysis>();
        analysis->serial = nextSerial++;
        if (program.stage == 0) {
            analysis->vertex = detail::parseVertexOutputs(program.shader->glsl);
            analysis->refusal = analysis->vertex.refusal;
            // Its capture program is linked apart, without the draw's start vertex (xlate::kStartVertexUniform).
            if (analysis->refusal.empty() && program.shader->glsl.find(xlate::kStartVertexUniform) != std::string::npos)
                analysis->refusal = "reads SV_VertexID";
        } else {
            analysis->pixel = detail::pixelFunctionFromShader(program.shader->glsl);
            analysis->refusal = analysis->pixel.refusal;
            analysis->inputsId =
                inputSignatures.emplace(detail::inputSignature(analysis->pixel), int(inputSignatures.size()) + 1).first->second;
        }
        program.computeAnalysis = analysis;
    }
    return *program.computeAnalysis;
}

GLuint GlComputePasses::captureProgram(const ShaderProgram& vertex, const ComputeAnalysis& analysis, std::string& refusal) {
    auto it = capturePrograms.find(analysis.serial);
    if (it == capturePrograms.end()) {
        std::vector<std::string> captured{"gl_Position"};
        for (const detail::GlslVarying& v : analysis.vertex.varyings) captured.push_back(v.name);
        Capture made;
        made.program = linkProgram(GL_VERTEX_SHADER, vertex.shader->glsl, captured, printOutcomes, made.failure);
        if (!made.program) made.failure = "vertex capture " + made.failure;
        it = capturePrograms.emplace(analysis.serial, made).first;
    }
    if (!it->second.program) refusal = it->second.failure;
    return it->second.program;
}

GLuint GlComputePasses::fillPipeline(const ShaderProgram& vertex, int vertexSerial, const ComputeAnalysis& pixel, std::string& refusal) {
    auto fill = fillPrograms.find(pixel.serial);
    if (fill == fillPrograms.end()) {
        Fill made;
        made.program = linkProgram(GL_FRAGMENT_SHADER, detail::fillShaderSource(pixel.pixel), {}, printOutcomes, made.failure, true);
        if (made.program) made.stamp = glGetUniformLocation(made.program, "fxport_stamp");
        else made.failure = "fill shader " + made.failure;
        fill = fillPrograms.emplace(pixel.serial, made).first;
    }
    if (!fill->second.program) {
        refusal = fill->second.failure;
        return 0;
    }
    const std::pair<int, int> key(vertexSerial, pixel.serial);
    auto it = fillPipelines.find(key);
    if (it == fillPipelines.end()) {
        // The draw's own separable vertex program: the rasteriser interpolates exactly what it
        // feeds the pixel shader in the device's pipeline.
        GLuint pipeline = 0;
        glCreateProgramPipelines(1, &pipeline);
        glUseProgramStages(pipeline, GL_VERTEX_SHADER_BIT, vertex.program);
        glUseProgramStages(pipeline, GL_FRAGMENT_SHADER_BIT, fill->second.program);
        it = fillPipelines.emplace(key, pipeline).first;
    }
    return it->second;
}

GlComputePasses::ReplayEntry* GlComputePasses::entryFor(const EntryKey& key, int width, int height, int layers, int capturedFloats,
                                                    std::string& refusal) {
    auto it = entries.find(key);
    if (it != entries.end()) {
        recency.splice(recency.end(), recency, it->second.recency);
        return &it->second;
    }
    const GLsizeiptr vertexBytes = GLsizeiptr((detail::kEntryHeaderWords + capturedFloats) * 4);
    const std::int64_t bytes = std::int64_t(width) * height * layers * 4 + vertexBytes;
    if (bytes > byteBudget) {
        refusal = "replay store of " + std::to_string((bytes + (1 << 20) - 1) >> 20) +
                  " MiB over FXPORT_COMPUTE_PASS_CACHE_MB=" + std::to_string(byteBudget >> 20);
        return nullptr;
    }
    while (entryBytes + bytes > byteBudget && !recency.empty()) {
        dropEntry(entries.find(recency.front()));
        ++statistics.evicted;
    }
    ReplayEntry entry;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &entry.store);
    glTextureStorage3D(entry.store, 1, GL_R32UI, width, height, layers);
    const GLuint zero = 0;  // stamp 0: no fill covered the pixel (stamps start at 1)
    glClearTexImage(entry.store, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    const std::vector<std::uint32_t> words(std::size_t(vertexBytes / 4), 0u);  // stamp 0: never filled
    glCreateBuffers(1, &entry.vertices);
    glNamedBufferStorage(entry.vertices, vertexBytes, words.data(), 0);
    entry.bytes = bytes;
    entryBytes += bytes;
    entry.recency = recency.insert(recency.end(), key);
    if (printOutcomes)
        std::fprintf(stderr, "compute pass: new replay entry for vertex shader %d, inputs %d: %dx%d, %d layers, %.1f MiB\n",
                     key.vertexSerial, key.inputsId, width, height, layers, double(bytes) / (1 << 20));
    return &entries.emplace(key, entry).first->second;
}

void GlComputePasses::readCounters() {
    if (!compare.mapped) return;
    for (int i = 0; i < 4; ++i) counters[i] = compare.mapped[i];
}

ComputePassStatistics GlComputePasses::currentStatistics() {
    readCounters();
    ComputePassStatistics s = statistics;
    s.dispatched += long(counters[0]) + long(counters[1]);
    s.replayed += long(counters[1]);
    if (counters[2]) s.fellBack["w != 1 with a perspective-interpolated input"] += long(counters[2]);
    if (counters[3]) s.fellBack["triangles that may cover a pixel twice"] += long(counters[3]);
    s.entries = long(entries.size());
    s.entryBytes = entryBytes;
    return s;
}

// Over 120 lines, knowingly: the eligibility checks, the program and replay-entry lookups and the
// five GPU steps (capture, compare, fill, dispatch, fall-back) share some twenty locals (targets,
// keys, analyses, programs, the entry, the pixel rectangle), and the steps must stay in this order
// with the device's GL state restored between them. Splitting it belongs with making compute
// passes a registered pass with plan/try steps (issue 22 item 2), not with moving the file.
bool GlComputePasses::tryDraw(PrimitiveType type, int primitiveCount, const DrawCall& call) {
    if ((type != PrimitiveType::TriangleList && type != PrimitiveType::TriangleStrip) || primitiveCount > 2) return false;
    const GraphicsDevice& dev = device;
    const std::vector<RenderTargetBinding>& boundTargets = prepared::targets(dev);
    const int targetWidth = prepared::targetWidth(dev), targetHeight = prepared::targetHeight(dev);
    const PassEmulation& emulation = prepared::emulation(dev);
    const ShaderProgram* vertex = prepared::shader(dev, 0);
    const ShaderProgram* pixel = prepared::shader(dev, 1);
    if (prepared::shader(dev, 2)) return fallBack("geometry shader");
    if (prepared::shader(dev, kHullStage) || prepared::shader(dev, kDomainStage)) return fallBack("tessellation");
    if (prepared::storageWritten(dev) || !vertex->shader->storage.empty() || !pixel->shader->storage.empty()) return fallBack("UAVs");
    // Without a depth buffer GL passes every depth and stencil test and writes nothing (the first
    // target's format says whether it has one, however its storage is made).
    const DepthFormat depthFormat = boundTargets.empty() ? dev.PresentationParameters().DepthStencilFormat
                                                         : targetDepthFormat(boundTargets[0].RenderTarget);
    const DepthStencilState& depth = dev.DepthStencilState;
    if (depthFormat != DepthFormat::None) {
        // A moot test (flush's drawDepthTestMoot: it cannot fail against the buffer's known clear
        // and nothing is written; the G-buffer clear quad under DepthRead) draws what no test draws.
        if (depth.DepthBufferEnable && !prepared::depthTestMoot(dev) &&
            (depth.DepthBufferWriteEnable || depth.DepthBufferFunction != CompareFunction::Always))
            return fallBack("depth test or write");
        if (depth.StencilEnable) return fallBack("stencil test");
    }
    if (emulation.alphaTest) return fallBack("alpha test");
    if (emulation.fixedFunction) return fallBack("D3D9 fixed-function emulation");
    if (emulation.srgbWrite) return fallBack("sRGB write");
    const RasterizerState& raster = dev.RasterizerState;
    if (raster.FillMode != FillMode::Solid) return fallBack("wireframe");
    const BlendState& blend = prepared::blend(dev);  // flush's: a blend onto a zero clear may be a write
    if (blend.MultiSampleMask != -1) return fallBack("multisample mask");

    // Targets: formats, blend and masks.
    const RenderTargetBinding backBuffer(prepared::backBuffer(dev));
    const RenderTargetBinding* bindings = boundTargets.empty() ? &backBuffer : boundTargets.data();
    const std::size_t boundCount = std::max<std::size_t>(boundTargets.size(), 1);
    const ColorWriteChannels masks[4] = {blend.ColorWriteChannels, blend.ColorWriteChannels1, blend.ColorWriteChannels2,
                                         blend.ColorWriteChannels3};
    std::array<detail::ComputeTarget, kMaxRenderTargets> targets{};
    TargetKeys targetKeys{};
    for (std::size_t i = 0; i < boundCount; ++i) {
        const SurfaceFormat format = bindings[i].RenderTarget->Format();
        if (bindings[i].RenderTarget->sampleCount() > 0) return fallBack("multisampled target");  // an image2D cannot hold its samples
        detail::ComputeTarget t;
        // Targets past the pixel shader's outputs are left alone (draw_state.cpp, blendForPixelShader).
        t.writeMask = int(i) < pixel->shader->outputTargets ? unsigned(masks[i]) & 15u : 0u;
        if (t.writeMask != 0) {
            const char* image = imageFormatOf(format);
            if (!image) return fallBack(std::string("target format ") + surfaceFormatName(format));
            t.imageFormat = image;
            t.normalized = !detail::glFormat(format).isFloat;
            if (blend.blendingEnabled()) {
                const bool fullFloat = isFullFloat(format);
                if (!blendOpOf(blend.ColorBlendFunction, blend.ColorSourceBlend, blend.ColorDestinationBlend, fullFloat, t.color) ||
                    !blendOpOf(blend.AlphaBlendFunction, blend.AlphaSourceBlend, blend.AlphaDestinationBlend, fullFloat, t.alpha))
                    return fallBack(std::string("blend state on a ") + surfaceFormatName(format) + " target");
            }
        }
        // The image format and normalization follow from the format.
        targetKeys[i] = 1u + (unsigned(format) << 12 | unsigned(t.color) << 8 | unsigned(t.alpha) << 4 | t.writeMask);
        targets[i] = t;
    }

    // Textures the pixel shader samples: in a compute shader implicit LOD is the base level with
    // the magnification filter, so the fragment stage must sample the same way.
    for (const xlate::SamplerBinding& sampler : pixel->shader->samplers) {
        if (sampler.unit < 0 || sampler.unit >= kMaxTextureSlots) continue;
        const Texture* texture = dev.Textures[sampler.unit].get();
        if (!texture) continue;
        const SamplerState& state = dev.SamplerStates[sampler.unit];
        FilterParts filter = splitFilter(state.Filter);
        if (filter.anisotropic) return fallBack("anisotropic sampler");
        if (filter.minLinear != filter.magLinear) return fallBack("sampler min filter != mag filter");
        if (state.UseMipMaps && texture->LevelCount() > 1) return fallBack("mipmapped texture");
    }

    const ComputeAnalysis& vertexAnalysis = analysisOf(*vertex);
    if (!vertexAnalysis.refusal.empty()) return fallBack("vertex shader: " + vertexAnalysis.refusal);
    const ComputeAnalysis& pixelAnalysis = analysisOf(*pixel);
    if (!pixelAnalysis.refusal.empty()) return fallBack("pixel shader: " + pixelAnalysis.refusal);
    std::string refusal = detail::inputsRefusal(pixelAnalysis.pixel, vertexAnalysis.vertex.varyings);
    if (!refusal.empty()) return fallBack(refusal);

    GLuint capture = captureProgram(*vertex, vertexAnalysis, refusal);
    if (!capture) return fallBack(refusal);
    const GLuint fill = fillPipeline(*vertex, vertexAnalysis.serial, pixelAnalysis, refusal);
    if (!fill) return fallBack(refusal);
    const std::pair<int, TargetKeys> programKey(pixelAnalysis.serial, targetKeys);
    auto found = computePrograms.find(programKey);
    if (found == computePrograms.end()) {
        Dispatcher made;
        const std::string source = detail::computeShaderSource(
            pixelAnalysis.pixel, std::vector<detail::ComputeTarget>(targets.begin(), targets.begin() + std::ptrdiff_t(boundCount)),
            made.failure);
        if (!source.empty()) {
            made.program = linkProgram(GL_COMPUTE_SHADER, source, {}, printOutcomes, made.failure);
            if (!made.program) made.failure = "compute shader " + made.failure;
        }
        if (made.program) made.rect = glGetUniformLocation(made.program, "fxport_rect");
        found = computePrograms.emplace(programKey, made).first;
    }
    const Dispatcher& dispatcher = found->second;
    if (!dispatcher.program) return fallBack(dispatcher.failure);
    const GLuint program = dispatcher.program;

    if (!compare.program && !compare.failed) {
        std::string error;
        compare.program = linkProgram(GL_COMPUTE_SHADER, detail::compareShaderSource(), {}, printOutcomes, error);
        compare.failed = compare.program == 0;
        if (compare.failed) {
            compare.failure = "compare shader " + error;
        } else {
            compare.rect = glGetUniformLocation(compare.program, "fxport_rect");
            compare.viewport = glGetUniformLocation(compare.program, "fxport_viewport");
            compare.vertices = glGetUniformLocation(compare.program, "fxport_vertices");
            compare.stride = glGetUniformLocation(compare.program, "fxport_stride");
            compare.unitW = glGetUniformLocation(compare.program, "fxport_unitW");
            compare.stamp = glGetUniformLocation(compare.program, "fxport_stamp");
            compare.draw = glGetUniformLocation(compare.program, "fxport_draw");
            const std::vector<std::uint32_t> zeros(detail::kCommandsWords, 0u);
            glCreateBuffers(1, &compare.commands);
            glNamedBufferStorage(compare.commands, GLsizeiptr(zeros.size() * 4), zeros.data(), 0);
            // Statistics read the counters here without a read-back (no stall when a host asks per pass).
            const GLbitfield mapping = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
            glCreateBuffers(1, &compare.counters);
            glNamedBufferStorage(compare.counters, 16, zeros.data(), mapping);
            compare.mapped = static_cast<const volatile std::uint32_t*>(glMapNamedBufferRange(compare.counters, 0, 16, mapping));
        }
    }
    if (compare.failed) return fallBack(compare.failure);

    // The replay entry: everything besides the vertices that decides what the rasteriser
    // produces for the pixel shader's inputs (scissor is not part: the fill draws without it).
    const Viewport& viewport = dev.Viewport;
    const int floatsPerVertex = detail::capturedFloatsPerVertex(vertexAnalysis.vertex.varyings);
    const int vertexCount = primitiveCount * 3;
    const EntryKey entryKey{vertexAnalysis.serial,
                            pixelAnalysis.inputsId,
                            viewport.X,
                            viewport.Y,
                            viewport.Width,
                            viewport.Height,
                            std::bit_cast<std::uint32_t>(viewport.MinDepth),
                            std::bit_cast<std::uint32_t>(viewport.MaxDepth),
                            int(raster.CullMode),
                            std::bit_cast<std::uint32_t>(raster.DepthBias),
                            std::bit_cast<std::uint32_t>(raster.SlopeScaleDepthBias),
                            int(type),
                            primitiveCount,
                            targetWidth,
                            targetHeight};
    if (call.userDataHash != 0) {
        UserDataHistory& history = userDataHistory[entryKey];
        if (history.lastHash == call.userDataHash) history.changedInARow = 0;
        else if (history.lastHash != 0) ++history.changedInARow;
        history.lastHash = call.userDataHash;
        if (history.changedInARow >= kChangesBeforeFragments) return fallBack("user vertices change from draw to draw");
    }
    ReplayEntry* entry = entryFor(entryKey, targetWidth, targetHeight, detail::replayLayers(pixelAnalysis.pixel),
                                  vertexCount * floatsPerVertex, refusal);
    if (!entry) return fallBack(refusal);

    // The pixels the draw may touch: the viewport (GL clips to it), the targets, the scissor.
    const auto [x0, y0, x1, y1] = detail::drawablePixels(dev, targetWidth, targetHeight);
    ++statistics.issued;
    if (x1 <= x0 || y1 <= y0) {  // the fragment stage would draw nothing either
        ++statistics.dispatched;
        if (printOutcomes) std::fprintf(stderr, "compute pass: %s covers no pixel\n", pixel->label.c_str());
        return true;
    }

    // 1. Vertex stage: the draw's own vertex shader, its outputs captured, nothing rasterised.
    // The compare step reads whole vertices; 4 floats of slack keep reads past a short last vertex in range.
    const GLsizeiptr bytes = GLsizeiptr((vertexCount * floatsPerVertex + 4) * sizeof(float));
    if (bytes > captureBytes) {
        if (captureBuffer) glDeleteBuffers(1, &captureBuffer);
        captureBytes = std::max<GLsizeiptr>(bytes, 4096);
        glCreateBuffers(1, &captureBuffer);
        glNamedBufferStorage(captureBuffer, captureBytes, nullptr, 0);
    }
    glUseProgram(capture);
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captureBuffer, 0, captureBytes);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_TRIANGLES);
    prepared::backend(device).draw(call);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);  // transform feedback's writes need no barrier before later commands read them

    // 2. Compare step: the commands for what follows, decided on the GPU (no read-back).
    std::uint32_t before[4] = {};
    if (printOutcomes) glFinish(), readCounters(), std::copy(std::begin(counters), std::end(counters), before);
    const std::uint32_t stamp = nextStamp++;
    if (nextStamp == 0) nextStamp = 1;  // 0 means "never filled"
    const GLint rect[4] = {x0, y0, x1, y1};
    const GLfloat view[4] = {float(viewport.X), float(viewport.Y), float(viewport.Width), float(viewport.Height)};
    const GLint drawCommand[4] = {call.count, call.first, call.baseVertex, call.indexed ? 1 : 0};
    glUseProgram(compare.program);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kCaptureBinding, captureBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kCommandsBinding, compare.commands);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kEntryBinding, entry->vertices);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kCountersBinding, compare.counters);
    glProgramUniform4iv(compare.program, compare.rect, 1, rect);
    glProgramUniform4fv(compare.program, compare.viewport, 1, view);
    glProgramUniform1i(compare.program, compare.vertices, vertexCount);
    glProgramUniform1i(compare.program, compare.stride, floatsPerVertex);
    glProgramUniform1i(compare.program, compare.unitW, detail::hasPerspectiveInput(pixelAnalysis.pixel) ? 1 : 0);
    glProgramUniform1ui(compare.program, compare.stamp, stamp);
    glProgramUniform4iv(compare.program, compare.draw, 1, drawCommand);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);

    // 3. Fill (instance count 0 when the capture matched): the draw itself, scissor off, into no
    // attachments, storing the interpolated inputs where it covers.
    glUseProgram(0);
    glBindProgramPipeline(fill);
    if (!fillFramebuffer) glCreateFramebuffers(1, &fillFramebuffer);
    if (fillWidth != targetWidth || fillHeight != targetHeight) {
        glNamedFramebufferParameteri(fillFramebuffer, GL_FRAMEBUFFER_DEFAULT_WIDTH, targetWidth);
        glNamedFramebufferParameteri(fillFramebuffer, GL_FRAMEBUFFER_DEFAULT_HEIGHT, targetHeight);
        fillWidth = targetWidth, fillHeight = targetHeight;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fillFramebuffer);
    if (raster.ScissorTestEnable) glDisable(GL_SCISSOR_TEST);
    const Fill& fillProgram = fillPrograms[pixelAnalysis.serial];
    glProgramUniform1ui(fillProgram.program, fillProgram.stamp, stamp);
    glBindImageTexture(detail::kStoreUnit, entry->store, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32UI);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, compare.commands);
    issueDrawIndirect(call, detail::kCommandsFill * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, prepared::framebuffer(dev));
    if (raster.ScissorTestEnable) glEnable(GL_SCISSOR_TEST);
    glBindProgramPipeline(prepared::pipeline(dev));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // 4. Pixel stage, over the compare step's rectangle (no groups when the draw may not replay).
    glUseProgram(program);
    for (std::size_t i = 0; i < boundCount; ++i) {
        if (targets[i].writeMask == 0) continue;
        const Texture* t = bindings[i].RenderTarget;
        const bool cube = t->kind() == Texture::Kind::TextureCube;
        glBindImageTexture(GLuint(i), t->backendObject(), 0, GL_FALSE, cube ? GLint(bindings[i].CubeMapFace) : 0, GL_READ_WRITE,
                           detail::glFormat(t->Format()).internalFormat);
    }
    glBindImageTexture(detail::kStoreUnit, entry->store, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glProgramUniform4iv(program, dispatcher.rect, 1, rect);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, compare.commands);
    glDispatchComputeIndirect(detail::kCommandsGroups * 4);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    // Later draws, texture fetches, read-backs and dispatches see the stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    glUseProgram(0);  // the device's program pipeline is in use again

    // 5. Fragment fall-back (instance count 0 when the dispatch ran): the draw as usual.
    issueDrawIndirect(call, detail::kCommandsFallBack * 4);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);

    if (printOutcomes) {
        glFinish();  // debugging only: this draw's outcome
        readCounters();
        const char* outcome = counters[0] != before[0]   ? "dispatched, refilled the replay store"
                              : counters[1] != before[1] ? "dispatched from the replay store"
                              : counters[2] != before[2] ? "falls back on the GPU: w != 1 with a perspective-interpolated input"
                                                         : "falls back on the GPU: triangles that may cover a pixel twice";
        std::fprintf(stderr, "compute pass: %s %s\n", pixel->label.c_str(), outcome);
    }
    return true;
}

}  // namespace fxport
