// Compute passes (compute_pass.h): the per-draw checks that a dispatch gives the fragment
// stage's pixels, the transform-feedback capture of the draw's vertices, and the dispatch.
// Programs are cached per (vertex shader, pixel shader, target formats, blend, masks); like the
// device's sampler objects they are an internal cache, released with the device and not counted
// in liveGpuObjects().
#include "compute_pass.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "device_impl.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture.h"
#include "fxport/xlate/compiled_effect.h"
#include "gl_formats.h"
#include "sampler_filter.h"

namespace fxport {

namespace {

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

// Compiles and links one stage; 0 and the log's first line on failure.
GLuint linkProgram(GLenum stage, const std::string& source, const std::vector<std::string>& captured, bool printLog,
                   std::string& error) {
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

}  // namespace

ComputePasses::ComputePasses(GraphicsDevice::Impl& owner)
    : device(owner), printOutcomes(std::getenv("FXPORT_COMPUTE_PASSES_DEBUG") != nullptr) {}

ComputePasses::~ComputePasses() {
    for (auto& [serial, program] : captureProgramsBySerial)
        if (program) glDeleteProgram(program);
    for (auto& [key, dispatcher] : computePrograms)
        if (dispatcher.program) glDeleteProgram(dispatcher.program);
    if (captureBuffer) glDeleteBuffers(1, &captureBuffer);
    if (bounds.program) glDeleteProgram(bounds.program);
    if (bounds.buffer) glDeleteBuffers(1, &bounds.buffer);
}

void ComputePasses::forget(const ComputeAnalysis& analysis) {
    const std::string serial = std::to_string(analysis.serial);
    if (auto it = captureProgramsBySerial.find(analysis.serial); it != captureProgramsBySerial.end()) {
        if (it->second) glDeleteProgram(it->second);
        captureProgramsBySerial.erase(it);
    }
    failures.erase("capture/" + serial);
    // Keys are "vertex serial/pixel serial/targets".
    for (auto it = computePrograms.begin(); it != computePrograms.end();) {
        const std::string& key = it->first;
        const std::size_t slash = key.find('/'), second = key.find('/', slash + 1);
        if (key.compare(0, slash, serial) == 0 || key.compare(slash + 1, second - slash - 1, serial) == 0) {
            if (it->second.program) glDeleteProgram(it->second.program);
            failures.erase(key);
            it = computePrograms.erase(it);
        } else {
            ++it;
        }
    }
}

bool ComputePasses::fallBack(const std::string& reason) {
    if (printOutcomes) std::fprintf(stderr, "compute pass: %s falls back: %s\n", device.shaders[1]->label.c_str(), reason.c_str());
    ++statistics.fellBack[reason];
    return false;
}

const ComputeAnalysis& ComputePasses::analysisOf(const ShaderProgram& program) {
    if (!program.computeAnalysis) {
        auto analysis = std::make_shared<ComputeAnalysis>();
        analysis->serial = nextSerial++;
        if (program.stage == 0) {
            analysis->vertex = detail::parseVertexOutputs(program.shader->glsl);
            analysis->refusal = analysis->vertex.refusal;
        } else {
            analysis->pixel = detail::pixelFunctionFromShader(program.shader->glsl);
            analysis->refusal = analysis->pixel.refusal;
        }
        program.computeAnalysis = analysis;
    }
    return *program.computeAnalysis;
}

GLuint ComputePasses::captureProgram(const ShaderProgram& vertex, const ComputeAnalysis& analysis, std::string& refusal) {
    auto it = captureProgramsBySerial.find(analysis.serial);
    if (it == captureProgramsBySerial.end()) {
        std::vector<std::string> captured{"gl_Position"};
        for (const detail::GlslVarying& v : analysis.vertex.varyings) captured.push_back(v.name);
        std::string error;
        GLuint program = linkProgram(GL_VERTEX_SHADER, vertex.shader->glsl, captured, printOutcomes, error);
        it = captureProgramsBySerial.emplace(analysis.serial, program).first;
        if (!program) failures["capture/" + std::to_string(analysis.serial)] = "vertex capture " + error;
    }
    if (!it->second) refusal = failures["capture/" + std::to_string(analysis.serial)];
    return it->second;
}

bool ComputePasses::tryDraw(PrimitiveType type, int primitiveCount, const std::function<void()>& issueDraw) {
    if ((type != PrimitiveType::TriangleList && type != PrimitiveType::TriangleStrip) || primitiveCount > 2) return false;
    GraphicsDevice::Impl& d = device;
    const GraphicsDevice& dev = d.device;
    const ShaderProgram* vertex = d.shaders[0];
    const ShaderProgram* pixel = d.shaders[1];
    if (d.shaders[2]) return fallBack("geometry shader");
    // Without a depth buffer GL passes every depth and stencil test and writes nothing (the first
    // target's format says whether it has one, however its storage is made).
    const DepthFormat depthFormat = d.targets.empty() ? dev.PresentationParameters().DepthStencilFormat
                                                      : targetDepthFormat(d.targets[0].RenderTarget);
    const DepthStencilState& depth = dev.DepthStencilState;
    if (depthFormat != DepthFormat::None) {
        if (depth.DepthBufferEnable && (depth.DepthBufferWriteEnable || depth.DepthBufferFunction != CompareFunction::Always))
            return fallBack("depth test or write");
        if (depth.StencilEnable) return fallBack("stencil test");
    }
    if (d.emulation.alphaTest) return fallBack("alpha test");
    if (d.emulation.srgbWrite) return fallBack("sRGB write");
    const RasterizerState& raster = dev.RasterizerState;
    if (raster.FillMode != FillMode::Solid) return fallBack("wireframe");
    const BlendState& blend = dev.BlendState;
    if (blend.MultiSampleMask != -1) return fallBack("multisample mask");

    // Targets: formats, blend and masks.
    std::vector<RenderTargetBinding> bindings = d.targets;
    if (bindings.empty()) bindings.push_back(RenderTargetBinding(d.backBuffer.get()));
    const ColorWriteChannels masks[4] = {blend.ColorWriteChannels, blend.ColorWriteChannels1, blend.ColorWriteChannels2,
                                         blend.ColorWriteChannels3};
    std::vector<detail::ComputeTarget> targets;
    std::string key;
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        const SurfaceFormat format = bindings[i].RenderTarget->Format();
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
        key += t.imageFormat + ":" + std::to_string(int(t.color)) + std::to_string(int(t.alpha)) + std::to_string(t.writeMask) +
               (t.normalized ? "n" : "") + ";";
        targets.push_back(t);
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

    std::string refusal;
    GLuint capture = captureProgram(*vertex, vertexAnalysis, refusal);
    if (!capture) return fallBack(refusal);
    key = std::to_string(vertexAnalysis.serial) + "/" + std::to_string(pixelAnalysis.serial) + "/" + key;
    auto found = computePrograms.find(key);
    if (found == computePrograms.end()) {
        std::string source = detail::computeShaderSource(pixelAnalysis.pixel, vertexAnalysis.vertex.varyings, targets, refusal);
        Dispatcher made;
        if (!source.empty()) {
            made.program = linkProgram(GL_COMPUTE_SHADER, source, {}, printOutcomes, refusal);
            if (!made.program) refusal = "compute shader " + refusal;
        }
        if (made.program) {
            made.rect = glGetUniformLocation(made.program, "fxport_rect");
            made.viewport = glGetUniformLocation(made.program, "fxport_viewport");
            made.depthRange = glGetUniformLocation(made.program, "fxport_depthRange");
            made.triangles = glGetUniformLocation(made.program, "fxport_triangles");
            made.cull = glGetUniformLocation(made.program, "fxport_cull");
        } else {
            failures[key] = refusal;
        }
        found = computePrograms.emplace(key, made).first;
    }
    const Dispatcher& dispatcher = found->second;
    if (!dispatcher.program) return fallBack(failures[key]);
    const GLuint program = dispatcher.program;

    // The pixels the draw may touch: the viewport (GL clips to it), the targets, the scissor.
    const Viewport& viewport = dev.Viewport;
    int x0 = std::max(viewport.X, 0), y0 = std::max(viewport.Y, 0);
    int x1 = std::min(viewport.X + viewport.Width, d.targetWidth), y1 = std::min(viewport.Y + viewport.Height, d.targetHeight);
    if (raster.ScissorTestEnable) {
        const Rectangle& s = dev.ScissorRectangle;
        x0 = std::max(x0, s.X), y0 = std::max(y0, s.Y);
        x1 = std::min(x1, s.X + s.Width), y1 = std::min(y1, s.Y + s.Height);
    }
    if (!bounds.program && !bounds.failed) {
        std::string error;
        bounds.program = linkProgram(GL_COMPUTE_SHADER, detail::boundsShaderSource(), {}, printOutcomes, error);
        bounds.failed = bounds.program == 0;
        if (bounds.failed) {
            failures["bounds"] = "bounds shader " + error;
        } else {
            bounds.rect = glGetUniformLocation(bounds.program, "fxport_rect");
            bounds.viewport = glGetUniformLocation(bounds.program, "fxport_viewport");
            bounds.vertices = glGetUniformLocation(bounds.program, "fxport_vertices");
            bounds.stride = glGetUniformLocation(bounds.program, "fxport_stride");
            glCreateBuffers(1, &bounds.buffer);
            glNamedBufferStorage(bounds.buffer, 32, nullptr, 0);
        }
    }
    if (bounds.failed) return fallBack(failures["bounds"]);
    ++statistics.dispatched;
    if (printOutcomes) std::fprintf(stderr, "compute pass: %s dispatched\n", pixel->label.c_str());
    if (x1 <= x0 || y1 <= y0) return true;

    // Vertex stage: the draw's own vertex shader, its outputs captured, nothing rasterised.
    const int floatsPerVertex = detail::capturedFloatsPerVertex(vertexAnalysis.vertex.varyings);
    // fxport_read fetches four floats from a varying's offset: room for the last vertex's tail.
    const GLsizeiptr bytes = GLsizeiptr((primitiveCount * 3 * floatsPerVertex + 4) * sizeof(float));
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
    issueDraw();
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);

    const GLint rect[4] = {x0, y0, x1, y1};
    const GLfloat view[4] = {float(viewport.X), float(viewport.Y), float(viewport.Width), float(viewport.Height)};

    // Bounds: the groups of a dispatch over the captured triangles' rectangle, on the GPU (no read-back).
    glUseProgram(bounds.program);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kCaptureBinding, captureBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kDispatchBinding, bounds.buffer);
    glProgramUniform4iv(bounds.program, bounds.rect, 1, rect);
    glProgramUniform4fv(bounds.program, bounds.viewport, 1, view);
    glProgramUniform1i(bounds.program, bounds.vertices, primitiveCount * 3);
    glProgramUniform1i(bounds.program, bounds.stride, floatsPerVertex);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);

    // Pixel stage.
    glUseProgram(program);
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        if (targets[i].writeMask == 0) continue;
        const Texture* t = bindings[i].RenderTarget;
        const bool cube = t->kind() == Texture::Kind::TextureCube;
        glBindImageTexture(GLuint(i), t->glName(), 0, GL_FALSE, cube ? GLint(bindings[i].CubeMapFace) : 0, GL_READ_WRITE,
                           detail::glFormat(t->Format()).internalFormat);
    }
    const GLfloat range[2] = {viewport.MinDepth, viewport.MaxDepth};
    glProgramUniform4iv(program, dispatcher.rect, 1, rect);
    glProgramUniform4fv(program, dispatcher.viewport, 1, view);
    glProgramUniform2fv(program, dispatcher.depthRange, 1, range);
    glProgramUniform1i(program, dispatcher.triangles, primitiveCount);
    const int cull = raster.CullMode == CullMode::None ? 0 : raster.CullMode == CullMode::CullCounterClockwiseFace ? 1 : 2;
    glProgramUniform1i(program, dispatcher.cull, cull);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, bounds.buffer);
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    // Later draws, texture fetches, read-backs and dispatches see the stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    glUseProgram(0);  // the device's program pipeline is in use again
    return true;
}

}  // namespace fxport
