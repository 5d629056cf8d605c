// INTERNAL to gl/: the OpenGL 4.5 backend (device/backend.h). Its state setting is in
// gl_backend.cpp, the objects it makes in gl_objects.cpp, the work it issues (draws, dispatches,
// clears, copies, transfers) in gl_work.cpp.
#pragma once

#include <unordered_map>

#include "device/backend.h"
#include "fxport/platform/gl.h"

namespace fxport {

// GL's primitive mode for a draw (GL_PATCHES for a patch draw).
GLenum glModeOf(const DrawCall& call);
inline GLenum glIndexTypeOf(const DrawCall& call) { return call.indexSize == 4 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT; }
// 1D textures (gl_line_textures.cpp): GL addresses a 1D array's layer as y in its 2D calls, where
// other arrays take it as z, and a plain 1D texture through 1D calls. Each returns false for a
// texture of another target, which the caller then handles.
bool writeLine(GLenum target, GLuint texture, SurfaceFormat format, int face, int level, const Rectangle& area, const void* data);
bool readLine(GLenum target, GLuint texture, GLenum format, GLenum type, int face, int level, std::size_t bytes, void* out);
// The (x, y, z) glCopyImageSubData takes for texel x of row y in `layer` (-1: not an array) of a texture of `target`.
void copyOrigin(GLenum target, int x, int y, int layer, GLint (&out)[3]);
// Moves each uniform block of a linked program from its HLSL binding b to `stage`'s range
// (backend.h, uniformBindingFor); compute passes' programs use it too.
void moveUniformBlocksToStage(GLuint program, int stage);

class GlBackend final : public Backend {
public:
    void setBlend(const BlendState& state, const BlendState* had) override;
    void setDepthStencil(const DepthStencilState& state, const DepthStencilState* had) override;
    void setRasterizer(const RasterizerState& state, const RasterizerState* had) override;
    void setViewport(const Viewport& viewport, ViewportShift shift) override;
    void setMoreViewports(const std::vector<Viewport>& more, ViewportShift shift) override;
    void setScissor(const Rectangle& rectangle) override;
    void setMoreScissors(const std::vector<Rectangle>& more) override;
    void setSrgbWrite(bool enabled) override;
    void setClipPlanes(int count) override;
    void setPointSize(float size, bool fromShader) override;
    BackendObject createSampler(const SamplerState& state) override;
    void deleteSampler(BackendObject sampler) override { glDeleteSamplers(1, &sampler); }
    void bindTexture(int unit, BackendObject texture) override { glBindTextureUnit(GLuint(unit), texture); }
    void bindSampler(int unit, BackendObject sampler) override { glBindSampler(GLuint(unit), sampler); }
    void writeBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, const void* data) override {
        glNamedBufferSubData(buffer, GLintptr(offset), GLsizeiptr(bytes), data);
    }
    void bindUniformBuffer(int binding, BackendObject buffer) override {
        glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(binding), buffer);
    }
    int uniformLocation(BackendObject program, const char* name) override { return glGetUniformLocation(program, name); }
    void setUniform(BackendObject program, int location, int value) override { glProgramUniform1i(program, location, value); }
    void setUniform(BackendObject program, int location, float value) override { glProgramUniform1f(program, location, value); }
    void setUniform(BackendObject program, int location, const float* vec4s, int count) override {
        glProgramUniform4fv(program, location, count, vec4s);
    }
    BackendObject createPipeline(const std::array<BackendObject, 5>& stagePrograms) override;
    void bindPipeline(BackendObject pipeline) override { glBindProgramPipeline(pipeline); }
    BackendObject createVertexArray(const std::vector<VertexAttribute>& attributes, const std::vector<int>& divisors) override;
    void deleteVertexArray(BackendObject vertexArray) override { glDeleteVertexArrays(1, &vertexArray); }
    void bindVertexArray(BackendObject vertexArray) override { glBindVertexArray(vertexArray); }
    void setVertexBuffer(BackendObject vertexArray, int binding, BackendObject buffer, std::size_t offset, int stride) override {
        glVertexArrayVertexBuffer(vertexArray, GLuint(binding), buffer, GLintptr(offset), GLsizei(stride));
    }
    void setIndexBuffer(BackendObject vertexArray, BackendObject buffer) override { glVertexArrayElementBuffer(vertexArray, buffer); }

    void adoptD3DConventions() override;
    int maxTextureSize() override;
    int maxSamples() override;
    void finish() override { glFinish(); }

    BackendObject createBuffer() override;
    void deleteBuffer(BackendObject buffer) override { glDeleteBuffers(1, &buffer); }
    void allocateBuffer(BackendObject buffer, std::size_t bytes, const void* initial, bool streaming) override;
    void orphanBuffer(BackendObject buffer, std::size_t bytes) override {
        glNamedBufferData(buffer, GLsizeiptr(bytes), nullptr, GL_STREAM_DRAW);
    }
    void readBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, void* out) override {
        glGetNamedBufferSubData(buffer, GLintptr(offset), GLsizeiptr(bytes), out);
    }
    void copyBuffer(BackendObject source, BackendObject destination, std::size_t sourceOffset, std::size_t destinationOffset,
                    std::size_t bytes) override {
        glCopyNamedBufferSubData(source, destination, GLintptr(sourceOffset), GLintptr(destinationOffset), GLsizeiptr(bytes));
    }

    bool isColorRenderable(SurfaceFormat format) override;
    bool isSampleable(SurfaceFormat format) override;
    const char* imageFormatName(SurfaceFormat format) override;
    BackendObject createTexture(bool cube, SurfaceFormat format, int levels, int width, int height) override;
    BackendObject createBufferTexture(BackendObject buffer, SurfaceFormat format, std::size_t offset, std::size_t bytes) override;
    std::size_t bufferOffsetAlignment(bool storage) override;
    void deleteTexture(BackendObject texture) override {
        lineTargets_.erase(texture);
        glDeleteTextures(1, &texture);
    }
    void writeTexture(BackendObject texture, SurfaceFormat format, int face, int level, const Rectangle& area,
                      const void* data) override;
    void readTexture(BackendObject texture, SurfaceFormat format, int face, int level, std::size_t bytes, void* out) override;
    void readTextureFloats(BackendObject texture, int face, int level, std::size_t bytes, void* out) override;
    Rectangle textureLevelSize(BackendObject texture, int level) override;
    void clearTexture(BackendObject texture, int level, const float (&rgba)[4]) override;
    void generateMipmaps(BackendObject texture) override { glGenerateTextureMipmap(texture); }
    void copyTexture(const TextureCopy& copy) override;
    BackendObject createVolumeTexture(SurfaceFormat format, int levels, int width, int height, int depth) override;
    void writeVolume(BackendObject texture, SurfaceFormat format, int level, int width, int height, int depth, const void* data) override;
    BackendObject createArrayTexture(SurfaceFormat format, int levels, int width, int height, int layers) override;
    BackendObject createLineTexture(SurfaceFormat format, int levels, int width, int layers, bool array) override;
    BackendObject createCubeArrayView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer, int layers) override;
    BackendObject createCubeView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer) override;
    BackendObject createTextureView(BackendObject source, SurfaceFormat format, bool array, int firstLevel, int levels, int firstLayer,
                                    int layers) override;
    BackendObject createMultisampleTexture(SurfaceFormat format, int samples, int width, int height, int& given) override;
    BackendObject createMultisampleArrayTexture(SurfaceFormat format, int samples, int width, int height, int layers, int& given) override;
    void copySamples(const SampleCopy& copy) override;
    unsigned multisampledUnits(BackendObject program) override;

    BackendObject createRenderbuffer() override;
    void deleteRenderbuffer(BackendObject renderbuffer) override { glDeleteRenderbuffers(1, &renderbuffer); }
    BackendObject createFramebuffer(const std::vector<ColorAttachment>& colour, BackendObject depth, bool depthHasStencil,
                                    bool depthIsTexture, std::string& problem) override;
    void deleteFramebuffer(BackendObject framebuffer) override { glDeleteFramebuffers(1, &framebuffer); }
    void bindFramebuffer(BackendObject framebuffer) override { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer); }
    void presentFlipped(BackendObject framebuffer, int width, int height) override;
    void clearDepthStencil(BackendObject renderbuffer, bool hasStencil, bool isTexture, bool depth, bool stencil, float depthValue,
                           int stencilValue) override;
    void allocateRenderbuffer(BackendObject renderbuffer, DepthFormat format, int width, int height, int samples) override;
    void clearFramebuffer(BackendObject framebuffer, const Rectangle& area, int colourTargets, bool colour, const Vector4& color,
                          bool depth, bool stencil, float depthValue, int stencilValue) override;
    void invalidateFramebuffer(int colourTargets, bool depth, bool stencil) override;

    BackendObject createProgram(int stage, const std::string& source, const std::vector<std::string>& captured, std::string& log) override;
    void beginStreamOutput(const std::array<StreamOutputBuffer, 4>& buffers, int primitiveVertices, BackendObject written,
                           BackendObject generated) override;
    void endStreamOutput() override;
    void setRasterizerDiscard(bool discard) override {
        if (discard) glEnable(GL_RASTERIZER_DISCARD);
        else glDisable(GL_RASTERIZER_DISCARD);
    }
    void deleteProgram(BackendObject program) override { glDeleteProgram(program); }
    BackendObject createComputePipeline(BackendObject program) override;
    void deletePipeline(BackendObject pipeline) override { glDeleteProgramPipelines(1, &pipeline); }

    void bindStorageBuffer(int binding, BackendObject buffer, std::size_t offset, std::size_t bytes) override {
        if (bytes == 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer);
        else glBindBufferRange(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer, GLintptr(offset), GLsizeiptr(bytes));
    }
    void bindStorageImage(int unit, BackendObject texture, SurfaceFormat format, bool writes) override;
    void storageBarrier() override { glMemoryBarrier(GL_ALL_BARRIER_BITS); }

    void draw(const DrawCall& call) override;
    void dispatch(int groupsX, int groupsY, int groupsZ) override {
        glDispatchCompute(GLuint(groupsX), GLuint(groupsY), GLuint(groupsZ));
    }

    BackendObject createQuery(QueryKind kind) override;
    void deleteQuery(BackendObject query) override { glDeleteQueries(1, &query); }
    void beginSamplesPassed(BackendObject query) override { glBeginQuery(GL_SAMPLES_PASSED, query); }
    void endSamplesPassed() override { glEndQuery(GL_SAMPLES_PASSED); }
    void writeTimestamp(BackendObject query) override { glQueryCounter(query, GL_TIMESTAMP); }
    bool hasPipelineStatistics() override;
    void beginStatistic(BackendObject query, QueryKind kind) override;
    void endStatistic(QueryKind kind) override;
    bool queryReady(BackendObject query) override {
        GLint ready = 0;
        glGetQueryObjectiv(query, GL_QUERY_RESULT_AVAILABLE, &ready);
        return ready != 0;
    }
    std::uint64_t queryResult(BackendObject query) override {
        GLuint64 result = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &result);
        return result;
    }

    GpuLimits measureLimits(const std::vector<SurfaceFormat>& formats, int size, int repeats) override;  // gl_limits_probe.cpp
    AdapterIdentity adapterIdentity() override;  // gl_adapter_identity.cpp

private:
    // GL_TEXTURE_1D or GL_TEXTURE_1D_ARRAY for the 1D textures and views this backend made,
    // GL_NONE for any other texture: remembered at creation, so uploads, copies and image binds
    // do not ask GL for a texture's target each time.
    GLenum lineTargetOf(BackendObject texture) const {
        auto it = lineTargets_.find(texture);
        return it == lineTargets_.end() ? GL_NONE : it->second;
    }
    std::unordered_map<BackendObject, GLenum> lineTargets_;
};

}  // namespace fxport
