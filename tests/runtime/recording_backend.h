// A Backend (runtime/graphics/src/device/backend.h) that does nothing but write down each call, one
// line each ("setBlend whole", "bindTexture 3 7", "createBuffer -> 104"), for tests of the device
// core's semantics with no GL context (in the manner of bgfx's renderer_noop.cpp). It keeps the
// objects it made, so a test can check that the core deletes each one exactly once.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "device/backend.h"

namespace fxport::test {

class RecordingBackend final : public Backend {
public:
    std::vector<std::string> calls;
    // The states of the last set* calls, to check what was sent.
    BlendState blend;
    DepthStencilState depthStencil;
    RasterizerState rasterizer;
    Viewport viewport;
    ViewportShift viewportShift;
    Rectangle scissor;
    BlendState hadBlend;  // what the last "changed" setBlend said the backend had
    BackendObject nextObject = 100;  // every object made: samplers, buffers, textures, programs ...

    void setBlend(const BlendState& state, const BlendState* had) override {
        note("setBlend", had);
        if (had) hadBlend = *had;
        blend = state;
    }
    void setDepthStencil(const DepthStencilState& state, const DepthStencilState* had) override {
        note("setDepthStencil", had);
        depthStencil = state;
    }
    void setRasterizer(const RasterizerState& state, const RasterizerState* had) override {
        note("setRasterizer", had);
        rasterizer = state;
    }
    void setViewport(const Viewport& v, ViewportShift shift) override {
        calls.push_back("setViewport " + std::to_string(v.Width) + "x" + std::to_string(v.Height) +
                        (shift == ViewportShift{} ? std::string() : " shifted"));
        viewport = v;
        viewportShift = shift;
    }
    void setScissor(const Rectangle& r) override {
        calls.push_back("setScissor " + std::to_string(r.Width) + "x" + std::to_string(r.Height));
        scissor = r;
    }
    void setMoreViewports(const std::vector<Viewport>& more, ViewportShift) override {
        calls.push_back("setMoreViewports " + std::to_string(more.size()));
    }
    void setMoreScissors(const std::vector<Rectangle>& more) override { calls.push_back("setMoreScissors " + std::to_string(more.size())); }
    void setSrgbWrite(bool enabled) override { calls.push_back(std::string("setSrgbWrite ") + (enabled ? "on" : "off")); }
    void setClipPlanes(int count) override { calls.push_back("setClipPlanes " + std::to_string(count)); }
    void setPointSize(float size, bool fromShader) override {
        calls.push_back("setPointSize " + std::to_string(size) + (fromShader ? " shader" : ""));
    }
    BackendObject createSampler(const SamplerState&) override { return make("createSampler"); }
    void deleteSampler(BackendObject sampler) override { release("deleteSampler", sampler); }
    void bindTexture(int unit, BackendObject texture) override {
        calls.push_back("bindTexture " + std::to_string(unit) + " " + std::to_string(texture));
    }
    void bindSampler(int unit, BackendObject sampler) override {
        calls.push_back("bindSampler " + std::to_string(unit) + " " + std::to_string(sampler));
    }
    void writeBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, const void*) override {
        calls.push_back("writeBuffer " + std::to_string(buffer) + " " + std::to_string(offset) + " " + std::to_string(bytes));
    }
    void bindUniformBuffer(int binding, BackendObject buffer) override {
        calls.push_back("bindUniformBuffer " + std::to_string(binding) + " " + std::to_string(buffer));
    }
    int uniformLocation(BackendObject, const char* name) override {
        calls.push_back(std::string("uniformLocation ") + name);
        return 0;
    }
    void setUniform(BackendObject, int location, int value) override {
        calls.push_back("setUniform " + std::to_string(location) + " " + std::to_string(value));
    }
    void setUniform(BackendObject, int location, float value) override {
        calls.push_back("setUniform " + std::to_string(location) + " " + std::to_string(value));
    }
    void setUniform(BackendObject, int location, const float*, int count) override {
        calls.push_back("setUniform " + std::to_string(location) + " vec4[" + std::to_string(count) + "]");
    }
    BackendObject createPipeline(const std::array<BackendObject, 5>& programs) override {
        std::string line = "createPipeline";
        for (BackendObject p : programs) line += " " + std::to_string(p);
        return make(line);
    }
    void bindPipeline(BackendObject pipeline) override { calls.push_back("bindPipeline " + std::to_string(pipeline)); }
    BackendObject createVertexArray(const std::vector<VertexAttribute>& attributes, const std::vector<int>& divisors) override {
        std::string line = "createVertexArray " + std::to_string(attributes.size()) + " attributes";
        for (const VertexAttribute& a : attributes)
            line += " " + std::to_string(a.location) + "@" + std::to_string(a.binding) + "+" + std::to_string(a.offset);
        if (!divisors.empty()) {
            line += " divisors";
            for (int d : divisors) line += " " + std::to_string(d);
        }
        return make(line);
    }
    void deleteVertexArray(BackendObject vertexArray) override { release("deleteVertexArray", vertexArray); }
    void bindVertexArray(BackendObject vertexArray) override {
        calls.push_back("bindVertexArray " + std::to_string(vertexArray));
    }
    void setVertexBuffer(BackendObject vertexArray, int binding, BackendObject buffer, std::size_t offset, int stride) override {
        calls.push_back("setVertexBuffer " + std::to_string(vertexArray) + " " + std::to_string(binding) + " " +
                        std::to_string(buffer) + " +" + std::to_string(offset) + " stride " + std::to_string(stride));
    }
    void setIndexBuffer(BackendObject vertexArray, BackendObject buffer) override {
        calls.push_back("setIndexBuffer " + std::to_string(vertexArray) + " " + std::to_string(buffer));
    }

    void adoptD3DConventions() override { calls.push_back("adoptD3DConventions"); }
    int maxTextureSize() override { return 16384; }
    int maxSamples() override { return 8; }
    AdapterIdentity adapterIdentity() override { return {"recording backend", "fxport", AdapterIdentity::Memory::Unknown, 0}; }
    void finish() override { calls.push_back("finish"); }
    GpuLimits measureLimits(const std::vector<SurfaceFormat>& formats, int size, int repeats) override {
        calls.push_back("measureLimits " + std::to_string(formats.size()) + " formats " + std::to_string(size) + " x" +
                        std::to_string(repeats));
        return {};
    }

    BackendObject createBuffer() override { return make("createBuffer"); }
    void deleteBuffer(BackendObject buffer) override { release("deleteBuffer", buffer); }
    void allocateBuffer(BackendObject buffer, std::size_t bytes, const void* initial, bool streaming) override {
        calls.push_back("allocateBuffer " + std::to_string(buffer) + " " + std::to_string(bytes) + (initial ? " filled" : "") +
                        (streaming ? " streaming" : ""));
    }
    void orphanBuffer(BackendObject buffer, std::size_t bytes) override {
        calls.push_back("orphanBuffer " + std::to_string(buffer) + " " + std::to_string(bytes));
    }
    void readBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, void*) override {
        calls.push_back("readBuffer " + std::to_string(buffer) + " " + std::to_string(offset) + " " + std::to_string(bytes));
    }
    void copyBuffer(BackendObject source, BackendObject destination, std::size_t sourceOffset, std::size_t destinationOffset,
                    std::size_t bytes) override {
        calls.push_back("copyBuffer " + std::to_string(source) + "+" + std::to_string(sourceOffset) + " -> " +
                        std::to_string(destination) + "+" + std::to_string(destinationOffset) + " " + std::to_string(bytes));
    }

    bool isColorRenderable(SurfaceFormat format) override { return format != SurfaceFormat::Depth32; }
    bool isSampleable(SurfaceFormat) override { return true; }
    const char* imageFormatName(SurfaceFormat format) override {
        return format == SurfaceFormat::Color ? "rgba8" : format == SurfaceFormat::Single ? "r32f" : "";
    }
    BackendObject createBufferTexture(BackendObject buffer, SurfaceFormat, std::size_t offset, std::size_t bytes) override {
        return make("createBufferTexture " + std::to_string(buffer) + (offset ? "+" + std::to_string(offset) : std::string()) + " " +
                    std::to_string(bytes));
    }
    std::size_t bufferOffsetAlignment(bool) override { return 16; }
    BackendObject createTexture(bool cube, SurfaceFormat, int levels, int width, int height) override {
        const BackendObject t = make(std::string("createTexture ") + (cube ? "cube " : "2d ") + std::to_string(width) + "x" +
                                     std::to_string(height) + " levels " + std::to_string(levels));
        textureSizes[t] = {width, height};
        return t;
    }
    BackendObject createVolumeTexture(SurfaceFormat, int levels, int width, int height, int depth) override {
        const BackendObject t = make("createVolumeTexture " + std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth) +
                                     " levels " + std::to_string(levels));
        textureSizes[t] = {width, height};
        return t;
    }
    void writeVolume(BackendObject texture, SurfaceFormat, int level, int width, int height, int depth, const void*) override {
        calls.push_back("writeVolume " + std::to_string(texture) + " level " + std::to_string(level) + " " + std::to_string(width) + "x" +
                        std::to_string(height) + "x" + std::to_string(depth));
    }
    BackendObject createArrayTexture(SurfaceFormat, int levels, int width, int height, int layers) override {
        const BackendObject t = make("createArrayTexture " + std::to_string(width) + "x" + std::to_string(height) + " layers " +
                                     std::to_string(layers) + " levels " + std::to_string(levels));
        textureSizes[t] = {width, height};
        return t;
    }
    BackendObject createLineTexture(SurfaceFormat, int levels, int width, int layers, bool array) override {
        const BackendObject t = make(std::string("createLineTexture ") + (array ? "array " : "1d ") + std::to_string(width) + " layers " +
                                     std::to_string(layers) + " levels " + std::to_string(levels));
        textureSizes[t] = {width, array ? layers : 1};
        return t;
    }
    BackendObject createTextureView(BackendObject source, SurfaceFormat, bool array, int firstLevel, int levels, int firstLayer, int layers) override {
        const BackendObject t = make("createTextureView " + std::to_string(source) + (array ? " array" : " 2d") + " levels " +
                                     std::to_string(firstLevel) + "+" + std::to_string(levels) + " layers " + std::to_string(firstLayer) + "+" +
                                     std::to_string(layers));
        textureSizes[t] = textureSizes[source];
        return t;
    }
    BackendObject createCubeArrayView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer, int layers) override {
        return createTextureView(source, format, true, firstLevel, levels, firstLayer, layers);
    }
    BackendObject createMultisampleTexture(SurfaceFormat, int samples, int width, int height, int& given) override {
        given = samples;
        const BackendObject t = make("createMultisampleTexture " + std::to_string(width) + "x" + std::to_string(height) + " samples " +
                                     std::to_string(samples));
        textureSizes[t] = {width, height};
        return t;
    }
    BackendObject createCubeView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer) override {
        return createTextureView(source, format, false, firstLevel, levels, firstLayer, 6);
    }
    BackendObject createMultisampleArrayTexture(SurfaceFormat, int samples, int width, int height, int layers, int& given) override {
        given = samples;
        const BackendObject t = make("createMultisampleArrayTexture " + std::to_string(width) + "x" + std::to_string(height) + " layers " +
                                     std::to_string(layers) + " samples " + std::to_string(samples));
        textureSizes[t] = {width, height};
        return t;
    }
    unsigned multisampledUnits(BackendObject) override { return 0; }
    void copySamples(const SampleCopy& copy) override {
        calls.push_back("copySamples " + std::to_string(copy.source) + " " + std::to_string(copy.destination));
    }
    void deleteTexture(BackendObject texture) override { release("deleteTexture", texture); }
    void writeTexture(BackendObject texture, SurfaceFormat, int face, int level, const Rectangle& a, const void*) override {
        calls.push_back("writeTexture " + std::to_string(texture) + " face " + std::to_string(face) + " level " + std::to_string(level) +
                        " " + std::to_string(a.Width) + "x" + std::to_string(a.Height));
    }
    void readTexture(BackendObject texture, SurfaceFormat, int face, int level, std::size_t bytes, void*) override {
        calls.push_back("readTexture " + std::to_string(texture) + " face " + std::to_string(face) + " level " + std::to_string(level) +
                        " " + std::to_string(bytes));
    }
    void readTextureFloats(BackendObject texture, int face, int level, std::size_t bytes, void*) override {
        calls.push_back("readTextureFloats " + std::to_string(texture) + " face " + std::to_string(face) + " level " +
                        std::to_string(level) + " " + std::to_string(bytes));
    }
    Rectangle textureLevelSize(BackendObject texture, int level) override {
        const auto size = textureSizes.at(texture);
        return Rectangle(0, 0, std::max(1, size.first >> level), std::max(1, size.second >> level));
    }
    void clearTexture(BackendObject texture, int level, const float (&rgba)[4]) override {
        calls.push_back("clearTexture " + std::to_string(texture) + " level " + std::to_string(level) + " " + std::to_string(rgba[0]));
    }
    void generateMipmaps(BackendObject texture) override { calls.push_back("generateMipmaps " + std::to_string(texture)); }
    void copyTexture(const TextureCopy& c) override {
        calls.push_back("copyTexture " + std::to_string(c.source) + " level " + std::to_string(c.sourceLevel) + " (" +
                        std::to_string(c.sourceX) + "," + std::to_string(c.sourceY) + ") -> " + std::to_string(c.destination) +
                        " level " + std::to_string(c.destinationLevel) + " (" + std::to_string(c.destinationX) + "," +
                        std::to_string(c.destinationY) + ") " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                        (c.cube ? " cube" : ""));
    }

    BackendObject createRenderbuffer() override { return make("createRenderbuffer"); }
    void deleteRenderbuffer(BackendObject renderbuffer) override { release("deleteRenderbuffer", renderbuffer); }
    void allocateRenderbuffer(BackendObject renderbuffer, DepthFormat, int width, int height, int) override {
        calls.push_back("allocateRenderbuffer " + std::to_string(renderbuffer) + " " + std::to_string(width) + "x" + std::to_string(height));
    }
    BackendObject createFramebuffer(const std::vector<ColorAttachment>& colour, BackendObject depth, bool, bool,
                                    std::string& problem) override {
        std::string line = "createFramebuffer";
        for (const ColorAttachment& a : colour)
            line += " " + std::to_string(a.texture) + (a.face >= 0 ? "/" + std::to_string(a.face) : "");
        line += " depth " + std::to_string(depth);
        if (rejectFramebuffers) {
            calls.push_back(line + " rejected");
            problem = "the recording backend rejects it";
            return 0;
        }
        return make(line);
    }
    void deleteFramebuffer(BackendObject framebuffer) override { release("deleteFramebuffer", framebuffer); }
    void bindFramebuffer(BackendObject framebuffer) override { calls.push_back("bindFramebuffer " + std::to_string(framebuffer)); }
    void presentFlipped(BackendObject framebuffer, int, int) override { calls.push_back("presentFlipped " + std::to_string(framebuffer)); }
    void clearDepthStencil(BackendObject renderbuffer, bool, bool, bool depth, bool stencil, float depthValue, int stencilValue) override {
        calls.push_back("clearDepthStencil " + std::to_string(renderbuffer) + (depth ? " depth " + std::to_string(depthValue) : "") +
                        (stencil ? " stencil " + std::to_string(stencilValue) : ""));
    }
    void clearFramebuffer(BackendObject framebuffer, const Rectangle& area, int colourTargets, bool colour, const Vector4&,
                          bool depth, bool stencil, float, int) override {
        calls.push_back("clearFramebuffer " + std::to_string(framebuffer) + " " + std::to_string(area.Width) + "x" +
                        std::to_string(area.Height) + (colour ? " colour " + std::to_string(colourTargets) : "") + (depth ? " depth" : "") +
                        (stencil ? " stencil" : ""));
    }
    void invalidateFramebuffer(int colourTargets, bool depth, bool stencil) override {
        calls.push_back("invalidateFramebuffer colour " + std::to_string(colourTargets) + (depth ? " depth" : "") + (stencil ? " stencil" : ""));
    }

    // A source holding `reject` fails to build (the log says so).
    BackendObject createProgram(int stage, const std::string& source, const std::vector<std::string>& captured, std::string& log) override {
        if (source.find("reject") != std::string::npos) {
            calls.push_back("createProgram stage " + std::to_string(stage) + " rejected");
            log = "0:1: the recording backend rejects this source";
            return 0;
        }
        std::string line = "createProgram stage " + std::to_string(stage);
        for (const std::string& c : captured) line += " " + c;
        return make(line);
    }
    void deleteProgram(BackendObject program) override { release("deleteProgram", program); }
    BackendObject createComputePipeline(BackendObject program) override {
        return make("createComputePipeline " + std::to_string(program));
    }
    void deletePipeline(BackendObject pipeline) override { release("deletePipeline", pipeline); }

    void bindStorageBuffer(int binding, BackendObject buffer, std::size_t offset, std::size_t bytes) override {
        calls.push_back("bindStorageBuffer " + std::to_string(binding) + " " + std::to_string(buffer) +
                        (bytes ? " " + std::to_string(offset) + "+" + std::to_string(bytes) : std::string()));
    }
    void bindStorageImage(int unit, BackendObject texture, SurfaceFormat, bool writes) override {
        calls.push_back("bindStorageImage " + std::to_string(unit) + " " + std::to_string(texture) + (writes ? " writes" : " reads"));
    }
    void storageBarrier() override { calls.push_back("storageBarrier"); }

    void draw(const DrawCall& c) override {
        std::string line = "draw " + std::to_string(int(c.type)) + " count " + std::to_string(c.count) + " first " + std::to_string(c.first);
        if (c.indexed) line += " indexed " + std::to_string(c.indexSize) + " base " + std::to_string(c.baseVertex);
        if (c.instanced) line += " instances " + std::to_string(c.instances) + " from " + std::to_string(c.firstInstance);
        if (c.controlPoints > 0) line += " patches of " + std::to_string(c.controlPoints);
        calls.push_back(line);
    }
    void beginStreamOutput(const std::array<StreamOutputBuffer, 4>& buffers, int primitiveVertices, BackendObject query, BackendObject) override {
        std::string line = "beginStreamOutput " + std::to_string(primitiveVertices) + " query " + std::to_string(query);
        for (const auto& b : buffers)
            line += " " + std::to_string(b.buffer) + "@" + std::to_string(b.offset) + "+" + std::to_string(b.bytes);
        calls.push_back(line);
    }
    void endStreamOutput() override { calls.push_back("endStreamOutput"); }
    void setRasterizerDiscard(bool discard) override { calls.push_back(std::string("setRasterizerDiscard ") + (discard ? "on" : "off")); }
    void dispatch(int x, int y, int z) override {
        calls.push_back("dispatch " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z));
    }

    BackendObject createQuery(QueryKind) override { return make("createQuery"); }
    void deleteQuery(BackendObject query) override { release("deleteQuery", query); }
    void beginSamplesPassed(BackendObject query) override { calls.push_back("beginSamplesPassed " + std::to_string(query)); }
    void endSamplesPassed() override { calls.push_back("endSamplesPassed"); }
    void writeTimestamp(BackendObject query) override { calls.push_back("writeTimestamp " + std::to_string(query)); }
    bool hasPipelineStatistics() override { return true; }
    void beginStatistic(BackendObject query, QueryKind kind) override {
        calls.push_back("beginStatistic " + std::to_string(query) + " " + std::to_string(int(kind)));
    }
    void endStatistic(QueryKind kind) override { calls.push_back("endStatistic " + std::to_string(int(kind))); }
    bool queryReady(BackendObject) override { return true; }
    std::uint64_t queryResult(BackendObject) override { return 0; }

    // The objects made and not deleted; deletions of objects this backend never made (or deleted
    // twice), which a correct core never sends. Shared, so a test can read them after the device
    // (which owns its backend) is gone.
    struct Objects {
        std::set<BackendObject> live;
        std::vector<std::string> badDeletes;
    };
    std::shared_ptr<Objects> objects = std::make_shared<Objects>();
    bool rejectFramebuffers = false;
    std::map<BackendObject, std::pair<int, int>> textureSizes;

    // The calls starting with `prefix`, in order.
    std::vector<std::string> matching(const std::string& prefix) const {
        std::vector<std::string> found;
        for (const std::string& c : calls)
            if (c.rfind(prefix, 0) == 0) found.push_back(c);
        return found;
    }

    // The calls so far, and forgets them.
    std::vector<std::string> take() {
        std::vector<std::string> taken;
        taken.swap(calls);
        return taken;
    }

private:
    BackendObject make(const std::string& line) {
        const BackendObject object = nextObject++;
        calls.push_back(line + " -> " + std::to_string(object));
        objects->live.insert(object);
        return object;
    }
    void release(const char* what, BackendObject object) {
        calls.push_back(std::string(what) + " " + std::to_string(object));
        if (objects->live.erase(object) == 0) objects->badDeletes.push_back(std::string(what) + " " + std::to_string(object));
    }
    // "whole": every field to be set (the shadow did not know); "changed": only what differs from `had`.
    template <typename State>
    void note(const char* what, const State* had) {
        calls.push_back(std::string(what) + (had ? " changed" : " whole"));
    }
};

}  // namespace fxport::test
