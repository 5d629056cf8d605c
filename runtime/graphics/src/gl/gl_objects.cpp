// The objects the OpenGL backend makes (gl_backend.h): buffers, textures, renderbuffers,
// framebuffers, programs, compute pipelines and queries, and the device-wide conventions.
#include <algorithm>
#include <string_view>

#include "gl/gl_backend.h"
#include "gl/gl_formats.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// D3D9 returns 1 for the channels a format lacks (R32F reads (r,1,1,1)), GL returns 0 for green and
// blue; Alpha8 reads (0,0,0,a) in D3D. Swizzles make GL read what the effects were written against.
void applyD3D9Swizzle(GLuint name, SurfaceFormat format) {
    // The formats after ColorSRgb are D3D10+'s (none is an XNA format): they read missing channels
    // as (0, 0, 1), which GL does too.
    if (format > SurfaceFormat::ColorSRgb) return;
    int channels = detail::glFormat(format).channels;
    if (format == SurfaceFormat::Alpha8) {
        glTextureParameteri(name, GL_TEXTURE_SWIZZLE_R, GL_ZERO);
        glTextureParameteri(name, GL_TEXTURE_SWIZZLE_G, GL_ZERO);
        glTextureParameteri(name, GL_TEXTURE_SWIZZLE_B, GL_ZERO);
        glTextureParameteri(name, GL_TEXTURE_SWIZZLE_A, GL_RED);
        return;
    }
    if (channels <= 1) glTextureParameteri(name, GL_TEXTURE_SWIZZLE_G, GL_ONE);
    if (channels <= 2) glTextureParameteri(name, GL_TEXTURE_SWIZZLE_B, GL_ONE);
}

// A view of a depth-stencil texture's stencil (D3D's X24_TYPELESS_G8_UINT ...): GL reads the
// stencil index into red; D3D's views hold it in green, with 0 in red and blue and 1 in alpha.
void applyStencilRead(GLuint name, SurfaceFormat format) {
    if (format != SurfaceFormat::StencilOfDepth24Stencil8 && format != SurfaceFormat::StencilOfDepth32Stencil8) return;
    glTextureParameteri(name, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    glTextureParameteri(name, GL_TEXTURE_SWIZZLE_R, GL_ZERO);
    glTextureParameteri(name, GL_TEXTURE_SWIZZLE_G, GL_RED);
    glTextureParameteri(name, GL_TEXTURE_SWIZZLE_B, GL_ZERO);
    glTextureParameteri(name, GL_TEXTURE_SWIZZLE_A, GL_ONE);
}

GLenum glStageOf(int stage) {
    switch (stage) {
    case 0: return GL_VERTEX_SHADER;
    case 1: return GL_FRAGMENT_SHADER;
    case 2: return GL_GEOMETRY_SHADER;
    case kHullStage: return GL_TESS_CONTROL_SHADER;
    case kDomainStage: return GL_TESS_EVALUATION_SHADER;
    default: return GL_COMPUTE_SHADER;
    }
}

}  // namespace

void GlBackend::adoptD3DConventions() {
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // D3D10+ filter across cube faces; D3D9 hardware did too
    // nointerpolation (flat) values come from a primitive's first vertex on D3D, its last on GL.
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
}

int GlBackend::maxSamples() {
    GLint samples = 0;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &samples);  // multisampled targets are textures
    return samples;
}

int GlBackend::maxTextureSize() {
    GLint size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    return size;
}

BackendObject GlBackend::createBuffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return name;
}

void GlBackend::allocateBuffer(BackendObject buffer, std::size_t bytes, const void* initial, bool streaming) {
    glNamedBufferStorage(buffer, GLsizeiptr(bytes), initial, GL_DYNAMIC_STORAGE_BIT | (streaming ? GL_CLIENT_STORAGE_BIT : 0));
}

bool GlBackend::isColorRenderable(SurfaceFormat format) { return detail::isColorRenderable(format); }

bool GlBackend::isSampleable(SurfaceFormat format) {
    GLint supported = GL_FALSE;
    glGetInternalformativ(GL_TEXTURE_2D, detail::glFormat(format).internalFormat, GL_INTERNALFORMAT_SUPPORTED, 1, &supported);
    return supported == GL_TRUE;
}

const char* GlBackend::imageFormatName(SurfaceFormat format) {
    // Alpha8 is stored as red with a swizzle: an image load would not read what a sample does.
    if (format == SurfaceFormat::Alpha8) return "";
    switch (detail::glFormat(format).internalFormat) {
    case GL_R32F: return "r32f";
    case GL_RG32F: return "rg32f";
    case GL_RGBA32F: return "rgba32f";
    case GL_R16F: return "r16f";
    case GL_RG16F: return "rg16f";
    case GL_RGBA16F: return "rgba16f";
    case GL_RGBA8: return "rgba8";
    case GL_RGBA16: return "rgba16";
    case GL_RG16: return "rg16";
    case GL_R32UI: return "r32ui";
    case GL_R32I: return "r32i";
    case GL_RGBA32UI: return "rgba32ui";
    case GL_RGBA32I: return "rgba32i";
    case GL_RG32UI: return "rg32ui";
    case GL_RG32I: return "rg32i";
    case GL_R16UI: return "r16ui";
    case GL_R16I: return "r16i";
    case GL_RG16UI: return "rg16ui";
    case GL_RG16I: return "rg16i";
    case GL_RGBA16UI: return "rgba16ui";
    case GL_RGBA16I: return "rgba16i";
    case GL_R8UI: return "r8ui";
    case GL_R8I: return "r8i";
    case GL_RG8UI: return "rg8ui";
    case GL_RG8I: return "rg8i";
    case GL_RGBA8UI: return "rgba8ui";
    case GL_RGBA8I: return "rgba8i";
    case GL_R16: return "r16";
    case GL_RG8: return "rg8";
    case GL_R8: return "r8";
    default: return "";
    }
}

BackendObject GlBackend::createTexture(bool cube, SurfaceFormat format, int levels, int width, int height) {
    GLuint name = 0;
    glCreateTextures(cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D, 1, &name);
    glTextureStorage2D(name, levels, detail::glFormat(format).internalFormat, width, height);
    applyD3D9Swizzle(name, format);
    return name;
}

BackendObject GlBackend::createVolumeTexture(SurfaceFormat format, int levels, int width, int height, int depth) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &name);
    glTextureStorage3D(name, levels, detail::glFormat(format).internalFormat, width, height, depth);
    applyD3D9Swizzle(name, format);
    return name;
}

BackendObject GlBackend::createArrayTexture(SurfaceFormat format, int levels, int width, int height, int layers) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &name);
    glTextureStorage3D(name, levels, detail::glFormat(format).internalFormat, width, height, layers);
    applyD3D9Swizzle(name, format);
    return name;
}

// A 1D array's layers are GL's rows: glTextureStorage2D with the layer count as its height.
BackendObject GlBackend::createLineTexture(SurfaceFormat format, int levels, int width, int layers, bool array) {
    GLuint name = 0;
    glCreateTextures(array ? GL_TEXTURE_1D_ARRAY : GL_TEXTURE_1D, 1, &name);
    if (array)
        glTextureStorage2D(name, levels, detail::glFormat(format).internalFormat, width, layers);
    else
        glTextureStorage1D(name, levels, detail::glFormat(format).internalFormat, width);
    applyD3D9Swizzle(name, format);
    lineTargets_[name] = array ? GL_TEXTURE_1D_ARRAY : GL_TEXTURE_1D;
    return name;
}

// glTextureView (core since 4.3) needs a name never bound: glGenTextures, not glCreateTextures.
// The view's own parameters start at GL's defaults, so the swizzle is applied again.
BackendObject GlBackend::createTextureView(BackendObject source, SurfaceFormat format, bool array, int firstLevel, int levels, int firstLayer,
                                           int layers) {
    GLuint name = 0;
    glGenTextures(1, &name);
    // A view keeps its source's dimension: a 1D texture's views are 1D (GL allows no other).
    const GLenum sourceTarget = lineTargetOf(source);
    const bool line = sourceTarget == GL_TEXTURE_1D || sourceTarget == GL_TEXTURE_1D_ARRAY;
    // A multisampled array's views are multisampled (GL allows no other); asked once per view made.
    GLint made = GL_NONE;
    if (!line) glGetTextureParameteriv(source, GL_TEXTURE_TARGET, &made);
    const bool samples = made == GL_TEXTURE_2D_MULTISAMPLE_ARRAY || made == GL_TEXTURE_2D_MULTISAMPLE;
    const GLenum target = line      ? (array ? GL_TEXTURE_1D_ARRAY : GL_TEXTURE_1D)
                          : samples ? (array ? GL_TEXTURE_2D_MULTISAMPLE_ARRAY : GL_TEXTURE_2D_MULTISAMPLE)
                                    : (array ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D);
    glTextureView(name, target, source, detail::glFormat(format).internalFormat, GLuint(firstLevel),
                  GLuint(levels), GLuint(firstLayer), GLuint(layers));
    if (!glIsTexture(name)) {  // refused (no GL_ARB_texture_view, or a range outside the source)
        glDeleteTextures(1, &name);
        return 0;
    }
    applyD3D9Swizzle(name, format);
    applyStencilRead(name, format);
    if (line) lineTargets_[name] = target;
    return name;
}

// GL lets a 2D array texture be viewed as a cube map array (ARB_texture_view's compatible targets).
BackendObject GlBackend::createCubeArrayView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer, int layers) {
    GLuint name = 0;
    glGenTextures(1, &name);
    glTextureView(name, GL_TEXTURE_CUBE_MAP_ARRAY, source, detail::glFormat(format).internalFormat, GLuint(firstLevel), GLuint(levels),
                  GLuint(firstLayer), GLuint(layers));
    if (!glIsTexture(name)) {
        glDeleteTextures(1, &name);
        return 0;
    }
    applyD3D9Swizzle(name, format);
    return name;
}

// Six layers of a 2D array read as one cube map (ARB_texture_view's compatible targets too).
BackendObject GlBackend::createCubeView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer) {
    GLuint name = 0;
    glGenTextures(1, &name);
    glTextureView(name, GL_TEXTURE_CUBE_MAP, source, detail::glFormat(format).internalFormat, GLuint(firstLevel), GLuint(levels), GLuint(firstLayer), 6);
    if (!glIsTexture(name)) {
        glDeleteTextures(1, &name);
        return 0;
    }
    applyD3D9Swizzle(name, format);
    return name;
}

BackendObject GlBackend::createMultisampleTexture(SurfaceFormat format, int samples, int width, int height, int& given) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &name);
    glTextureStorage2DMultisample(name, samples, detail::glFormat(format).internalFormat, width, height, GL_TRUE);
    GLint made = 0;
    glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_SAMPLES, &made);
    given = made;
    applyD3D9Swizzle(name, format);
    return name;
}

BackendObject GlBackend::createMultisampleArrayTexture(SurfaceFormat format, int samples, int width, int height, int layers, int& given) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, 1, &name);
    glTextureStorage3DMultisample(name, samples, detail::glFormat(format).internalFormat, width, height, layers, GL_TRUE);
    GLint made = 0;
    glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_SAMPLES, &made);
    given = made;
    applyD3D9Swizzle(name, format);
    return name;
}

unsigned GlBackend::multisampledUnits(BackendObject program) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    unsigned units = 0;
    for (GLint i = 0; i < count; ++i) {
        const GLenum properties[3] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE};
        GLint values[3] = {0, -1, 0};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), 3, properties, 3, nullptr, values);
        const GLenum type = GLenum(values[0]);
        const bool samples = type == GL_SAMPLER_2D_MULTISAMPLE || type == GL_INT_SAMPLER_2D_MULTISAMPLE ||
                             type == GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE || type == GL_SAMPLER_2D_MULTISAMPLE_ARRAY ||
                             type == GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY || type == GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY;
        if (values[1] < 0 || !samples) continue;
        for (GLint element = 0; element < std::max(values[2], 1); ++element) {
            GLint unit = -1;
            glGetUniformiv(program, values[1] + element, &unit);
            if (unit >= 0 && unit < 32) units |= 1u << unit;
        }
    }
    return units;
}

BackendObject GlBackend::createBufferTexture(BackendObject buffer, SurfaceFormat format, std::size_t offset, std::size_t bytes) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &name);
    glTextureBufferRange(name, detail::glFormat(format).internalFormat, buffer, GLintptr(offset), GLsizeiptr(bytes));
    return name;
}

std::size_t GlBackend::bufferOffsetAlignment(bool storage) {
    GLint alignment = 0;
    glGetIntegerv(storage ? GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT : GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    return std::size_t(std::max(alignment, 1));
}

BackendObject GlBackend::createRenderbuffer() {
    GLuint name = 0;
    glCreateRenderbuffers(1, &name);
    return name;
}

void GlBackend::allocateRenderbuffer(BackendObject renderbuffer, DepthFormat format, int width, int height, int samples) {
    if (samples == 0) return glNamedRenderbufferStorage(renderbuffer, detail::glDepthFormat(format), width, height);
    glNamedRenderbufferStorageMultisample(renderbuffer, samples, detail::glDepthFormat(format), width, height);
    // A framebuffer needs every attachment at one count; the colour targets have exactly theirs.
    GLint given = 0;
    glGetNamedRenderbufferParameteriv(renderbuffer, GL_RENDERBUFFER_SAMPLES, &given);
    if (given != samples)
        throw InvalidOperation("the graphics driver made a depth buffer of " + std::to_string(given) + " samples for " + std::to_string(samples) +
                               " (" + depthFormatName(format) + ")");
}

BackendObject GlBackend::createFramebuffer(const std::vector<ColorAttachment>& colour, BackendObject depth, bool depthHasStencil,
                                           bool depthIsTexture, std::string& problem) {
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    std::vector<GLenum> drawBuffers;
    for (std::size_t i = 0; i < colour.size(); ++i) {
        GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + i);
        if (colour[i].face >= 0) glNamedFramebufferTextureLayer(fbo, attachment, colour[i].texture, 0, GLint(colour[i].face));
        else glNamedFramebufferTexture(fbo, attachment, colour[i].texture, 0);
        drawBuffers.push_back(attachment);
    }
    glNamedFramebufferDrawBuffers(fbo, GLsizei(drawBuffers.size()), drawBuffers.data());
    const GLenum depthAttachment = depthHasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (depth != 0 && depthIsTexture) glNamedFramebufferTexture(fbo, depthAttachment, depth, 0);
    else if (depth != 0) glNamedFramebufferRenderbuffer(fbo, depthAttachment, GL_RENDERBUFFER, depth);
    // A depth-only pass (no colour targets) draws no colour.
    if (colour.empty()) glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo);
        problem = "framebuffer status 0x" + std::to_string(status);
        return 0;
    }
    return fbo;
}

namespace {

// glCreateShaderProgramv's steps with the captured varyings named before the link (GL reads them
// then). A shader that does not compile leaves its log in `log` and gives 0.
GLuint createCapturingProgram(GLenum stage, const char* text, const std::vector<std::string>& captured, std::string& log) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint compiled = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (!compiled) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        log.assign(std::size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        return 0;
    }
    const GLuint program = glCreateProgram();
    glProgramParameteri(program, GL_PROGRAM_SEPARABLE, GL_TRUE);
    std::vector<const char*> names;
    for (const std::string& n : captured) names.push_back(n.c_str());
    glTransformFeedbackVaryings(program, GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
    glAttachShader(program, shader);
    glLinkProgram(program);
    glDetachShader(program, shader);
    glDeleteShader(shader);
    return program;
}

}  // namespace

BackendObject GlBackend::createProgram(int stage, const std::string& source, const std::vector<std::string>& captured, std::string& log) {
    const char* text = source.c_str();
    GLuint program = 0;
    if (captured.empty()) program = glCreateShaderProgramv(glStageOf(stage), 1, &text);
    else if (!(program = createCapturingProgram(glStageOf(stage), text, captured, log))) return 0;
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        log.assign(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        glDeleteProgram(program);
        return 0;
    }
    // D3D has constant slots per stage: each block moves to this stage's range (backend.h).
    moveUniformBlocksToStage(program, stage);
    return program;
}

void moveUniformBlocksToStage(GLuint program, int stage) {
    GLint blockCount = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blockCount);
    for (GLint i = 0; i < blockCount; ++i) {
        GLint binding = 0;
        glGetActiveUniformBlockiv(program, GLuint(i), GL_UNIFORM_BLOCK_BINDING, &binding);
        glUniformBlockBinding(program, GLuint(i), GLuint(uniformBindingFor(stage, binding)));
    }
}

BackendObject GlBackend::createComputePipeline(BackendObject program) {
    GLuint pipeline = 0;
    glCreateProgramPipelines(1, &pipeline);
    glUseProgramStages(pipeline, GL_COMPUTE_SHADER_BIT, program);
    return pipeline;
}

namespace {

// GL_ARB_pipeline_statistics_query's targets (core in GL 4.6 only), in QueryKind's order.
GLenum queryTarget(QueryKind kind) {
    switch (kind) {
    case QueryKind::SamplesPassed: return GL_SAMPLES_PASSED;
    case QueryKind::Timestamp: return GL_TIMESTAMP;
    case QueryKind::VerticesSubmitted: return GL_VERTICES_SUBMITTED_ARB;
    case QueryKind::PrimitivesSubmitted: return GL_PRIMITIVES_SUBMITTED_ARB;
    case QueryKind::VertexShaderInvocations: return GL_VERTEX_SHADER_INVOCATIONS_ARB;
    case QueryKind::GeometryShaderInvocations: return GL_GEOMETRY_SHADER_INVOCATIONS;
    case QueryKind::GeometryShaderPrimitives: return GL_GEOMETRY_SHADER_PRIMITIVES_EMITTED_ARB;
    case QueryKind::ClippingInputPrimitives: return GL_CLIPPING_INPUT_PRIMITIVES_ARB;
    case QueryKind::ClippingOutputPrimitives: return GL_CLIPPING_OUTPUT_PRIMITIVES_ARB;
    case QueryKind::FragmentShaderInvocations: return GL_FRAGMENT_SHADER_INVOCATIONS_ARB;
    case QueryKind::TessControlPatches: return GL_TESS_CONTROL_SHADER_PATCHES_ARB;
    case QueryKind::TessEvaluationInvocations: return GL_TESS_EVALUATION_SHADER_INVOCATIONS_ARB;
    case QueryKind::ComputeShaderInvocations: return GL_COMPUTE_SHADER_INVOCATIONS_ARB;
    case QueryKind::PrimitivesWritten: return GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN;
    case QueryKind::PrimitivesGenerated: return GL_PRIMITIVES_GENERATED;
    }
    return GL_SAMPLES_PASSED;
}

}  // namespace

BackendObject GlBackend::createQuery(QueryKind kind) {
    GLuint name = 0;
    // Mesa's glCreateQueries refuses the pipeline-statistics targets it otherwise counts (GL_INVALID_ENUM
    // with the extension advertised): a name from glGenQueries becomes the query at its first glBeginQuery.
    if (kind == QueryKind::SamplesPassed || kind == QueryKind::Timestamp) glCreateQueries(queryTarget(kind), 1, &name);
    else glGenQueries(1, &name);
    return name;
}

bool GlBackend::hasPipelineStatistics() {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name && std::string_view(name) == "GL_ARB_pipeline_statistics_query") return true;
    }
    return false;
}

void GlBackend::beginStatistic(BackendObject query, QueryKind kind) { glBeginQuery(queryTarget(kind), query); }
void GlBackend::endStatistic(QueryKind kind) { glEndQuery(queryTarget(kind)); }

// Transform feedback on GL's default object: D3D binds its stream-output targets per draw from the
// device's state, so no object needs to outlive a draw.
void GlBackend::beginStreamOutput(const std::array<StreamOutputBuffer, 4>& buffers, int primitiveVertices, BackendObject written,
                                  BackendObject generated) {
    for (std::size_t slot = 0; slot < buffers.size(); ++slot) {
        const StreamOutputBuffer& b = buffers[slot];
        if (b.bytes == 0) glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(slot), 0);
        else glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(slot), b.buffer, GLintptr(b.offset), GLsizeiptr(b.bytes));
    }
    glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
    glBeginQuery(GL_PRIMITIVES_GENERATED, generated);
    glBeginTransformFeedback(primitiveVertices == 1 ? GL_POINTS : primitiveVertices == 2 ? GL_LINES : GL_TRIANGLES);
}

void GlBackend::endStreamOutput() {
    glEndTransformFeedback();
    glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    for (GLuint slot = 0; slot < 4; ++slot) glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, slot, 0);
}

}  // namespace fxport
