// INTERNAL: the device's private state: the backend and its shadow, the caches of backend objects made
// from immutable descriptions, the registry of live resources. device/ reaches it through deviceImpl()
// (device/impl_access.h); effects and GL passes only through device/effect_programs.h, compute_passes.h.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "device/backend.h"
#include "device/impl_access.h"
#include "device/pass_emulation.h"
#include "device/shader_program.h"
#include "device/state_shadow.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/xlate/compiled_effect.h"
#include "fxport/xlate/texture_fetches.h"

namespace fxport::xlate {
struct CompiledShader;
struct SourceLocation;
}

namespace fxport {

class GraphicsResource;
struct ComputeAnalysis;
class ComputePasses;  // compute_passes.h
class FragmentRuns;  // fragment_tally.h
namespace core {
class ByteBuffer;  // front_end_core.h
}


struct GraphicsDevice::Impl {
    Impl(GraphicsDevice& owner, std::unique_ptr<Backend> api) : device(owner), backend(std::move(api)) {}

    GraphicsDevice& device;
    GpuObjectCounts live;
    // The graphics API behind the seam (device/backend.h), and the fixed-function state it has.
    std::unique_ptr<Backend> backend;
    StateShadow shadow{*backend};

    // --- resource registry (so destroying a resource unbinds it everywhere)
    std::vector<GraphicsResource*> resources;
    std::vector<Effect*> effects;
    int nextSerial = 1;
    void forget(GraphicsResource* resource);

    // --- render targets
    std::vector<RenderTargetBinding> targets;   // empty = back buffer
    std::unique_ptr<RenderTarget2D> backBuffer;
    std::map<std::vector<std::uint64_t>, BackendObject> framebuffers;  // attachment key -> FBO
    BackendObject boundFramebuffer = 0;
    int targetWidth = 0, targetHeight = 0;
    void bindTargets();
    // What targetsBoundSinceMark() returns (after the first mark, the bindings of every SetRenderTargets).
    std::vector<RenderTargetBinding> boundSinceMark;
    bool trackingBoundTargets = false;  // set by the first markBoundTargets(): hosts that never check pay nothing
    int widestColorBytesSinceMark = 0;  // colorBytesPerFragmentSinceMark()
    bool blendedSinceMark = false;      // set by flush() while tracking
    std::vector<WrittenTarget> writtenSinceMark;  // targetsWrittenSinceMark(), noted by flush() and executeClear()
    void noteWrittenTargets(bool color, bool depthStencil, const Rectangle& area, bool cleared);  // area: what the draw or clear covers
    void noteDrawnTargets();  // flush(): what the draw may write (its viewport within the scissor; depth if tested)
    std::shared_ptr<FragmentRuns> fragmentTally;  // tallyFragments(true); null when off
    void tallyDraw();  // before a draw: its pixel shader's fetches to the tally (fragment_tally.cpp)
    void noteBoundTargets();
    // A depth/stencil buffer of its own that replaces the first target's (front_end_core.h: D3D11's
    // depth-stencil views are apart from render targets). Null for XNA, whose targets own theirs.
    DepthStorage* depthOverride = nullptr;
    // D3D10/11's viewports and scissor rectangles 1.. (setMoreViewports); index 0 is the device's
    // Viewport and ScissorRectangle. Empty for XNA.
    std::vector<fxport::Viewport> moreViewports;
    std::vector<Rectangle> moreScissors;
    void generateMipsOfUnboundTargets(const std::vector<RenderTargetBinding>& previous);

    // --- shaders set by EffectPass::Apply (a stage left null keeps what was there)
    std::array<const ShaderProgram*, kStageCount> shaders{};
    bool passApplied = false;
    PassEmulation emulation;         // wanted (set by Apply)
    // SRGBWriteEnable drawing into an 8-bit target that is not sRGB-encoded: GL writes unconverted
    // where D3D9 encoded. Reported once per effect, through the effect warning handler.
    void reportUnencodedSrgbWrite();
    int clipPlanesOfShaders() const;
    // D3D9 fixed-function emulation (fixed_function_draw.cpp): each draw reads
    // GraphicsDevice::FixedFunction, picks the shaders' own programs or their variants (made on
    // first use) and sets their uniforms, the clip planes and the point size.
    void syncFixedFunction();
    bool drawingPoints = false;  // the draw being flushed is of points (set by the Draw* calls)
    BackendObject pixelProgramFor(const ShaderProgram& program, const ShaderProgram& writer);
    BackendObject vertexProgramFor(const ShaderProgram& program);
    int userClipPlanes() const;  // enabled D3D9 clip planes the vertex shader's variant writes
    void applyPointSize(const ShaderProgram& lastBeforeRasteriser);
    void releaseFixedFunctionVariants(const ShaderProgram& program);
    std::map<std::tuple<BackendObject, BackendObject, BackendObject, BackendObject, BackendObject>, BackendObject> pipelines;  // vs, ps, gs, hs, ds
    // Stages compiled apart link by semantic (device/stage_links.cpp): a reader whose inputs sit at
    // other locations than its writer's outputs of the same semantics draws through a variant with
    // the writer's (xlate::inputsLinkedTo), made once per reader program and writer's outputs.
    struct LinkedReader {
        xlate::CompiledShader shader;  // the reader, its inputs moved
        ShaderProgram program;         // over `shader`
    };
    std::map<std::pair<BackendObject, std::string>, std::unique_ptr<LinkedReader>> linkedReaders;
    // (reader, writer) programs -> the reader's linked variant, null: the reader as it is.
    std::map<std::pair<BackendObject, BackendObject>, const ShaderProgram*> readerForWriter;
    const ShaderProgram& linkedReader(const ShaderProgram& reader, const ShaderProgram& writer);
    const ShaderProgram* makeLinkedReader(const ShaderProgram& reader, const ShaderProgram& writer);
    void dropLinkedReadersOf(BackendObject readerProgram);
    BackendObject boundPipeline = 0;

    // --- stream output (stream_output.cpp): D3D10/11's SO targets, where the next draw whose last
    // stage before the rasteriser streams writes in each (bytes from the buffer's start).
    struct StreamTarget {
        core::ByteBuffer* buffer = nullptr;
        std::size_t offset = 0;
    };
    std::array<StreamTarget, xlate::kStreamOutputSlots> streamTargets{};
    BackendObject primitivesWrittenQuery = 0;
    BackendObject primitivesGeneratedQuery = 0;
    std::uint64_t streamOutputWritten = 0, streamOutputNeeded = 0;  // since the device was made (core::streamOutputCounts)
    // Every draw goes through here: with stream output, wrapped in its capture.
    void issueDraw(const DrawCall& call);
    // The bound vertex program's xlate::kStartVertexUniform set to the draw's start vertex (a
    // vertex program that reads SV_VertexID has one; start_vertex.cpp), per program: its location
    // (-1: none) and the value it holds.
    struct StartVertexUniform {
        int location = -1;
        int value = 0;
    };
    std::map<BackendObject, StartVertexUniform> startVertexUniforms;
    BackendObject boundVertexProgram = 0;  // applyShaders: the vertex program of boundPipeline
    void setStartVertex(const DrawCall& call);
    void forgetStreamTarget(const core::ByteBuffer* buffer);

    // --- uniform buffers: wanted (set by Apply) and bound
    std::array<BackendObject, kUniformStages * kUniformBindingsPerStage> wantedUniformBuffers{};
    std::array<BackendObject, kUniformStages * kUniformBindingsPerStage> boundUniformBuffers{};

    // --- D3D11 stages (storage_bindings.cpp, compute_dispatch.cpp, tessellated_draw.cpp)
    const ShaderProgram* computeShader = nullptr;  // the last applied pass's SetComputeShader
    // What SetUnorderedAccess / SetShaderResource put in a slot: a buffer or a texture's level 0.
    struct StorageSlot {
        const GraphicsResource* resource = nullptr;
        BackendObject name = 0;
        bool image = false;
        SurfaceFormat format = SurfaceFormat::Color;  // images: the texture's format
        bool typedBuffer = false;  // a buffer texture (core::TexelBuffer): Buffer<T> at t#, RWBuffer<T> at u# (image set)
        std::size_t offset = 0, bytes = 0;  // a storage buffer's bound range (bytes 0: all of it)
    };
    std::array<StorageSlot, kMaxUnorderedAccessSlots> unorderedAccess{};
    std::array<StorageSlot, kMaxShaderResourceBuffers> resourceBuffers{};
    // Binds the storage `programs` declare (their StorageBinding lists) from the slots above; returns
    // whether one of them may write (so a barrier must follow). `what` names the call for errors.
    bool applyStorage(const ShaderProgram* const* programs, std::size_t count, const char* what);
    // Work that may write through images or SSBOs sets storageDirty; storageBarrier(), called
    // before every later draw, dispatch, buffer or texture transfer, places one barrier of all bits
    // so that access sees the writes (D3D11 orders UAV writes before any later use; GL does not).
    bool storageDirty = false;
    void storageBarrier();
    void forgetStorage(const GraphicsResource* resource);  // a disposed buffer or texture leaves its slots
    // A single-sample 2D texture a shader reads as Texture2DMS (sample_copies.cpp): D3D reads its
    // texels as sample 0, GL only through a multisampled texture, so a one-sample copy is made and
    // refreshed at each draw that binds it so; released with the texture.
    BackendObject sampleCopyOf(const Texture& texture);
    void forgetSampleCopy(const Texture* texture);
    std::map<const Texture*, BackendObject> sampleCopies;
    // Draws with the pipeline flush() set up, checking the tessellation stages agree with `patches`.
    void checkTessellation(bool patches, const char* what) const;
    bool patchDraw = false;  // set by DrawPatches around its flush
    std::map<BackendObject, BackendObject> computePipelines;  // compute program -> its pipeline
    void dispatch(int x, int y, int z);  // DispatchCompute after its checks
    void dropComputePipelinesUsing(BackendObject program);

    // --- vertex input
    VertexBuffer* vertexBuffer = nullptr;
    int vertexOffset = 0;
    // SetVertexBuffers' bindings (SetVertexBuffer's one); more than one: draws go through the
    // device core's streams (vertex_buffer_bindings.cpp).
    std::vector<VertexBufferBinding> vertexBindings;
    // A draw of the bound buffers as streams: `instances` copies, indexed by Indices when `indexed`.
    void drawBindings(const char* call, PrimitiveType type, int count, int first, int baseVertex, bool indexed, int instances);
    struct VertexArray {
        BackendObject vao = 0;
        BackendObject buffer = 0;
        std::int64_t offset = -1;
        int stride = 0;
        BackendObject elements = 0;
    };
    std::unordered_map<std::string, VertexArray> vertexArrays;  // key: declaration + VS program
    struct LastVertexArray {
        const VertexDeclaration* declaration = nullptr;
        VertexDeclaration copy;
        BackendObject program = 0;
        VertexArray* array = nullptr;
    } lastVertexArray;
    BackendObject boundVertexArray = 0;
    VertexArray& vertexArrayFor(const VertexDeclaration& declaration);
    // The VAO for the current vertex buffer and vertex shader, with the buffer attached at the
    // SetVertexBuffer offset.
    VertexArray& bindVertexBuffer();

    // Streaming buffers for DrawUser(Indexed)Primitives: written with orphaning.
    BackendObject userVertices = 0, userIndices = 0;
    std::size_t userVerticesSize = 0, userIndicesSize = 0;
    void streamUserData(BackendObject& buffer, std::size_t& capacity, const void* data, std::size_t bytes);

    // --- texture and sampler bindings (the fixed-function state is `shadow`'s)
    std::array<BackendObject, kMaxTextureSlots> boundTextures{};
    std::array<BackendObject, kMaxTextureSlots> boundSamplers{};
    std::array<SamplerState, kMaxTextureSlots> boundSamplerStates{};  // what boundSamplers were made from
    std::map<std::array<std::uint8_t, sizeof(SamplerState)>, BackendObject> samplerObjects;  // SamplerState bytes -> backend sampler
    BackendObject samplerFor(const SamplerState& state);

    void applyViewport(const fxport::Viewport& wanted);  // with the D3D9 pixel offset when the vertex shader is SM1-3
    void applyTextures();
    void applyTexturesOf(const ShaderProgram* const* programs, std::size_t count);  // for compute dispatches too
    void applyShaders();

    // Everything a draw needs, compared against the shadow. `what` names the draw call for errors.
    // A list of steps (draw_state.cpp): checkDrawable, the targets, applyClearPasses, applyBlend,
    // the depth/stencil, rasterizer, viewport and scissor state, applyShaders, applyTextures,
    // applyStorage, applyPassEmulation.
    void flush(const char* what);
    void checkDrawable(const char* what) const;  // a pass applied, tessellation stages agree with the draw
    const fxport::DepthStencilState& applyClearPasses();  // returns the depth/stencil state the draw has
    void applyBlend();
    void applyPassEmulation();

    // --- clears of the bound targets: executed, or pending (device/clears.cpp; recorded only by the pass
    // device/passes/pending_clear.cpp, FXPORT_PASS_PENDING_CLEARS, with the folds that know it). A clear of the whole
    // target (the one SetRenderTargets does for DiscardContents, and Clear over a full viewport) is
    // recorded per channel, a later clear of the same channel replaces it, and it reaches the backend when
    // something needs that channel: colour before any draw or read-back of a bound target, depth and
    // stencil before a draw that tests them. Leaving a DiscardContents target drops a depth/stencil
    // clear nothing used (its next binding clears them again and nothing can read them); colour is
    // always executed (the target may be sampled).
    struct PendingClear {
        unsigned options = 0;  // ClearOptions bits still to execute
        Vector4 color;
        float depth = 1;
        int stencil = 0;
    } pendingClear;
    bool deferClears = true;  // DeviceOptimizations::DeferClears and $FXPORT_DEFER_CLEARS
    bool honourDiscards = true;  // DeviceOptimizations::HonourDiscards and $FXPORT_HONOUR_DISCARDS
    bool dropCoveredClears = true;  // DeviceOptimizations::DropCoveredClears and $FXPORT_DROP_COVERED_CLEARS
    void discardContents(unsigned options);               // GraphicsDevice::DiscardContents
    // SpriteBatch, before drawing a batch with a sprite whose rectangle covers the whole viewport:
    // drops the pending colour clear if the draw must write every pixel (passes/pending_clear.cpp).
    void dropColorClearUnderCoveringSprite(const ShaderProgram* spriteVertexShader);
    ClearStatistics clearStats;
    // DeviceOptimizations::ComputePasses and $FXPORT_COMPUTE_PASSES: null when off (compute_passes.h).
    std::shared_ptr<ComputePasses> computePasses;
    void executeClear(const Rectangle& rect, unsigned options, const Vector4& color, float depth, int stencil);
    void recordClear(unsigned options, const Vector4& color, float depth, int stencil);  // the pass's
    void resolvePendingClear(unsigned options);           // executes the pending part within `options`
    void resolvePendingClearBeforeDraw(const fxport::DepthStencilState& state);
    void resolvePendingClearBeforeRead(const Texture* texture);
    void leaveBoundTargets();                               // before SetRenderTargets changes them
    fxport::RenderTargetUsage boundUsage() const;           // of the bound targets (the first one's, or the back buffer's)

    // --- depth/stencil storage (device/depth_buffers.cpp), made when a draw first needs it by the pass
    // device/passes/depth_storage.cpp (FXPORT_PASS_LAZY_DEPTH: makeDepthStorageFor, holdDepthClear,
    // discardWaitingDepthClear, leaveDiscardedDepth)
    bool lazyDepthStorage = true;  // DeviceOptimizations::LazyDepthStorage and $FXPORT_LAZY_DEPTH
    DepthStorageStatistics depthStats;
    void adoptDepthStorage(DepthStorage& storage);    // a target made with it: counted; made now unless lazy
    void releaseDepthStorage(DepthStorage& storage);  // the target is released
    DepthStorage* boundDepthStorage();                // the first bound target's (XNA: MRT use its buffer)
    // Before a draw: makes the bound depth/stencil buffer if the draw tests depth or stencil.
    void makeDepthStorageFor(const fxport::DepthStencilState& state);
    void makeDepthStorage(DepthStorage& storage);     // makes it, rebinds, runs its waiting clear
    bool depthTestPassesAll(const fxport::DepthStencilState& state, const DepthStorage& storage) const;
    // Writes neither depth nor stencil and its depth test cannot fail against the bound buffer's
    // known clear (depthTestPassesAll): such a draw draws what no test draws.
    bool depthTestIsMoot(const fxport::DepthStencilState& state);
    bool drawDepthTestMoot = false;  // flush's depthTestIsMoot for the draw it prepared (compute_pass.cpp reads it)
    bool foldMootDepthTest(const fxport::DepthStencilState& wanted);  // flush: sets drawDepthTestMoot; true: draw with the test off
    // A blend whose every destination is the zero clear executed for this draw, on unsigned-
    // normalized targets, with source factor One and Add, Subtract or Max: src * 1 + 0 * factor is
    // src (factors are finite there), so the draw writes (passes/pending_clear.cpp, blendOverZeroClearIsWrite).
    // flush decides it; compute_pass.cpp reads drawBlend, the blend the draw has.
    bool blendOverZeroClearIsWrite() const;
    bool drawBlendIsWrite = false;
    void foldBlendOverZeroClear();  // flush: sets drawBlendIsWrite and drawWriteBlend
    fxport::BlendState drawWriteBlend;  // the device's blend with blending off, when drawBlendIsWrite
    const fxport::BlendState& drawBlend() const { return drawBlendIsWrite ? drawWriteBlend : device.BlendState; }
    // executeClear's depth/stencil bits for a bound buffer not made yet: a whole-target clear waits
    // on the target (returned without those bits), a partial one makes the buffer first.
    unsigned holdDepthClear(const Rectangle& rect, unsigned options, float depth, int stencil);
    void discardWaitingDepthClear(unsigned options, long& counter);  // DiscardContents / leaving
    void leaveDiscardedDepth();  // leaving a DiscardContents target: its depth/stencil is not kept

    // Backend object bookkeeping: every create/delete goes through these so liveGpuObjects() is exact.
    // Texture creation first requires the format (ArgumentError naming it when the driver lacks it).
    void requireSampleable(SurfaceFormat format);
    bool isSampleable(SurfaceFormat format);  // asked of the backend once per format
    std::array<std::int8_t, kSurfaceFormatCount> sampleableFormats{};  // per SurfaceFormat: 0 not asked, 1 yes, -1 no
    BackendObject createTexture(bool cube, SurfaceFormat format, int levels, int width, int height);
    BackendObject createVolumeTexture(SurfaceFormat format, int levels, int width, int height, int depth);
    BackendObject createArrayTexture(SurfaceFormat format, int levels, int width, int height, int layers);
    BackendObject createLineTexture(SurfaceFormat format, int levels, int width, int layers, bool array);
    // A view of `source` (Backend::createTextureView); throws InvalidOperation naming `who` when the backend cannot make it.
    BackendObject createTextureView(const std::string& who, BackendObject source, SurfaceFormat format, bool array, int firstLevel, int levels,
                                    int firstLayer, int layers);
    BackendObject createMultisampleTexture(SurfaceFormat format, int samples, int width, int height, int& given);
    BackendObject createMultisampleArrayTexture(SurfaceFormat format, int samples, int width, int height, int layers, int& given);
    void deleteTexture(BackendObject& name);
    BackendObject createBuffer();
    void deleteBuffer(BackendObject& name);
    BackendObject createRenderbuffer();
    void deleteRenderbuffer(BackendObject& name);
    // Programs are shared by (stage, GLSL text) and reference-counted. `stage`: 0 vertex .. 5 compute.
    // The program of `shader` at `stage` from `glsl` (the shader's own, or a variant of it): what
    // stream output writes comes from the shader (Backend::createProgram).
    BackendObject createProgram(int stage, const xlate::CompiledShader& shader, const std::string& glsl, const std::string& label);
    struct CachedProgram {
        BackendObject program = 0;
        int references = 0;
    };
    std::map<std::pair<int, std::string>, CachedProgram> programCache;
    void deleteProgram(BackendObject& name);
    BackendObject createQuery(QueryKind kind);
    void deleteQuery(BackendObject& name);
    // Forgets FBOs, pipelines and VAOs that mention a deleted texture / program / buffer.
    void dropFramebuffersUsing(BackendObject texture);
    void dropPipelinesUsing(BackendObject program);
    void dropVertexArraysUsing(BackendObject program);
    void releaseAll();
};

}  // namespace fxport
