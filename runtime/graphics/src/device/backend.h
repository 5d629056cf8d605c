// INTERNAL, GL-free: the seam between the device core and a graphics API, in the manner of
// FNA3D's driver table. The core (device/: XNA's semantics, validation, the state shadow, resources,
// draws) decides *what* the GPU must have; a Backend only says it in its API's words. The OpenGL
// backend is gl/gl_backend.cpp; tests use a recording one (tests/runtime/recording_backend.h) and
// need no GL context.
//
// The seam carries what a draw sets up (fixed-function state, sampler objects, texture, sampler,
// uniform- and storage-buffer bindings, program pipelines, vertex arrays), the objects the core
// makes (buffers, textures, programs, framebuffers, queries), the draws and dispatches themselves,
// and the transfers (buffer and texel reads, writes and copies, clears of a texture or a depth
// buffer). The optimisation passes (gl/passes/) and the measurements (diagnostics/) that still call
// GL themselves are listed by tests/layering/check_graphics_seam.cmake.
#pragma once

#include <cstddef>
#include <cstdint>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/adapter_identity.h"
#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/gpu_limits.h"
#include "fxport/graphics/graphics_device.h"  // PrimitiveType
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/surface_format.h"
#include "fxport/graphics/vertex_declaration.h"
#include "fxport/graphics/viewport.h"
#include "fxport/math/rectangle.h"
#include "fxport/math/vector4.h"

#include "device/vertex_format.h"

namespace fxport {

// A backend object (a GL name today): 0 is "none".
using BackendObject = std::uint32_t;

// Uniform-buffer binding points per stage: D3D has separate constant slots per stage, so the same
// HLSL binding (b0 = $Global, b1 = fxport's internal block, b2.. user cbuffers) gets a range per
// stage. A pixel shader's $Global (its own effect's) never collides with the vertex shader's
// (SpriteBatch's, say). A backend's createProgram moves each block of a program there.
inline constexpr int kUniformBindingsPerStage = 8;
inline constexpr int kStageCount = 5;  // vertex, pixel, geometry, hull, domain (the draw pipeline)
inline constexpr int kHullStage = 3, kDomainStage = 4;
inline constexpr int kComputeStage = 5;  // dispatched alone; its own uniform-binding range
inline constexpr int kUniformStages = kStageCount + 1;
// Binding 1 of each stage is never a shader's: xlate numbers $Global 0 and user cbuffers from 2.
inline constexpr int kUnusedUniformBinding = 1;
inline int uniformBindingFor(int stage, int hlslBinding) { return stage * kUniformBindingsPerStage + hlslBinding; }

// One vertex-shader input fed from vertex-buffer binding `binding` at `offset` bytes.
struct VertexAttribute {
    int location = 0;
    VertexFormat format;
    int offset = 0;
    bool integer = false;  // the shader reads it as integers (no conversion to float)
    int binding = 0;
};

// One draw's parameters, as the device's draw entry points make it. Compute passes
// (gl/passes/compute_pass.h) issue the same draw again in other forms, so they get the parameters
// rather than an opaque call.
struct DrawCall {
    PrimitiveType type = PrimitiveType::TriangleList;
    int controlPoints = 0;   // > 0: patches of this many control points (type is ignored)
    int count = 0;           // vertices or indices
    int first = 0;           // first vertex, or first index when indexed
    bool indexed = false;
    int baseVertex = 0;      // indexed only
    int indexSize = 2;       // bytes per index, 2 or 4
    // A front end's instanced draw (front_end_core.h): `instances` from `firstInstance`.
    bool instanced = false;
    int instances = 1;
    int firstInstance = 0;
    // DrawUser(Indexed)Primitives of at most two triangles with compute passes on: a hash of the
    // vertex and index bytes (a hint that the vertices changed; exactness never depends on it). 0: unknown.
    std::uint64_t userDataHash = 0;
};

// FNV-1a over `bytes` bytes, continuing from `hash`.
inline std::uint64_t hashBytes(const void* data, std::size_t bytes, std::uint64_t hash = 1469598103934665603ull) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
    return hash;
}

// A colour attachment of a framebuffer: level 0 of a 2D texture, or one face of a cube or one
// layer of an array texture (face >= 0).
struct ColorAttachment {
    BackendObject texture = 0;
    int face = -1;
};

// A copy of `width` x `height` texels (of every face when `cube`) between two textures of one format.
struct TextureCopy {
    BackendObject source = 0, destination = 0;
    bool cube = false;
    bool multisampled = false;  // two multisampled textures of one sample count: every sample copied
    int sourceLevel = 0, destinationLevel = 0;
    int sourceX = 0, sourceY = 0, destinationX = 0, destinationY = 0;
    int width = 0, height = 0;
    // >= 0: that layer of an array texture (one layer is copied; `cube` is false).
    int sourceLayer = -1, destinationLayer = -1;
};

// A copySamples: level 0 of `source` (layer `sourceLayer` of an array, -1 for a 2D texture) into
// level `destinationLevel` of `destination` (layer `destinationLayer`, or -1), width x height texels.
struct SampleCopy {
    BackendObject source = 0, destination = 0;
    int sourceLayer = -1, destinationLayer = -1, destinationLevel = 0;
    int width = 0, height = 0;
};

// What a query measures: the samples passing the depth and stencil tests, a GPU timestamp, or one
// of the pipeline statistics (GL_ARB_pipeline_statistics_query's counters), those in the order of
// D3D11_QUERY_DATA_PIPELINE_STATISTICS's members (IAVertices ... CSInvocations).
enum class QueryKind {
    SamplesPassed, Timestamp,
    VerticesSubmitted, PrimitivesSubmitted, VertexShaderInvocations, GeometryShaderInvocations, GeometryShaderPrimitives,
    ClippingInputPrimitives, ClippingOutputPrimitives, FragmentShaderInvocations, TessControlPatches, TessEvaluationInvocations,
    ComputeShaderInvocations,
    PrimitivesWritten,    // by stream output (between beginStreamOutput and endStreamOutput)
    PrimitivesGenerated,  // for stream output, whether or not they fitted (D3D's PrimitivesStorageNeeded)
};
inline constexpr int kPipelineStatistics = 11;  // QueryKind::VerticesSubmitted + 0 .. 10
inline QueryKind pipelineStatistic(int i) { return QueryKind(int(QueryKind::VerticesSubmitted) + i); }

// Where a viewport's origin sits, in pixels right and down of its integer corner. D3D9's pixel
// centres lie on integer coordinates, half a pixel up and left of GL's (and D3D10's): SM1-3 shaders
// draw with the origin moved by that half (GraphicsDevice::Impl::applyViewport says how much).
struct ViewportShift {
    float x = 0;
    float y = 0;
    bool operator==(const ViewportShift&) const = default;
};

class Backend {
public:
    virtual ~Backend() = default;

    // Fixed-function state. `had` is the state this backend was last given (null when unknown: set
    // every field), so an implementation may touch only the fields that differ.
    virtual void setBlend(const BlendState& state, const BlendState* had) = 0;
    virtual void setDepthStencil(const DepthStencilState& state, const DepthStencilState* had) = 0;
    virtual void setRasterizer(const RasterizerState& state, const RasterizerState* had) = 0;
    // Viewport 0, and (unshifted) every other index of the viewport array too, so that an index
    // nothing set draws through viewport 0.
    virtual void setViewport(const Viewport& viewport, ViewportShift shift) = 0;
    // D3D10/11's viewports 1..more.size() (a pre-rasteriser stage's SV_ViewportArrayIndex picks
    // one), each with its own depth range; sent after setViewport.
    virtual void setMoreViewports(const std::vector<Viewport>& more, ViewportShift shift) = 0;
    // The rectangle of every viewport; RasterizerState switches the test.
    virtual void setScissor(const Rectangle& rectangle) = 0;
    virtual void setMoreScissors(const std::vector<Rectangle>& more) = 0;  // of viewports 1.., after setScissor
    virtual void setSrgbWrite(bool enabled) = 0;              // encode into sRGB-encoded targets (D3D9 SRGBWriteEnable)
    // Clip planes 0..count-1 on, the others off: the SV_ClipDistance values the last stage before
    // the rasteriser writes (D3D clips by every one a shader writes; GL only by those enabled).
    virtual void setClipPlanes(int count) = 0;
    // Points: `size` pixels wide, unless `fromShader` (the vertex shader writes the size).
    virtual void setPointSize(float size, bool fromShader) = 0;

    // Samplers and textures. A sampler object is made once per distinct SamplerState (the core caches it).
    virtual BackendObject createSampler(const SamplerState& state) = 0;
    virtual void deleteSampler(BackendObject sampler) = 0;
    virtual void bindTexture(int unit, BackendObject texture) = 0;
    virtual void bindSampler(int unit, BackendObject sampler) = 0;

    // Buffers.
    virtual void writeBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, const void* data) = 0;
    virtual void bindUniformBuffer(int binding, BackendObject buffer) = 0;

    // Programs and pipelines. A pipeline joins one program per draw stage (vertex, pixel, geometry,
    // hull, domain; 0 = none; vertex and pixel always set).
    virtual int uniformLocation(BackendObject program, const char* name) = 0;  // -1: none
    virtual void setUniform(BackendObject program, int location, int value) = 0;
    virtual void setUniform(BackendObject program, int location, float value) = 0;
    virtual void setUniform(BackendObject program, int location, const float* vec4s, int count) = 0;  // vec4 (array)
    virtual BackendObject createPipeline(const std::array<BackendObject, 5>& stagePrograms) = 0;
    virtual void bindPipeline(BackendObject pipeline) = 0;

    // Vertex input: a layout of attributes read from vertex-buffer bindings; `divisors[i]` > 0
    // advances binding i once per that many instances (empty: every binding per vertex).
    virtual BackendObject createVertexArray(const std::vector<VertexAttribute>& attributes, const std::vector<int>& divisors) = 0;
    virtual void deleteVertexArray(BackendObject vertexArray) = 0;
    virtual void bindVertexArray(BackendObject vertexArray) = 0;
    virtual void setVertexBuffer(BackendObject vertexArray, int binding, BackendObject buffer, std::size_t offset, int stride) = 0;
    virtual void setIndexBuffer(BackendObject vertexArray, BackendObject buffer) = 0;

    // The API's conventions made D3D's, once per device: NDC z in [0, 1], window y from the top row
    // (targets come out top-row-first), seamless cube filtering, flat values from a primitive's
    // first vertex.
    virtual void adoptD3DConventions() = 0;
    virtual int maxTextureSize() = 0;
    virtual int maxSamples() = 0;  // of a multisampled colour target
    virtual AdapterIdentity adapterIdentity() = 0;  // the driver's name, vendor and video memory
    virtual void finish() = 0;  // waits until the GPU has done everything submitted

    // Buffers. allocateBuffer fixes the size once, from `initial` (null: undefined); `streaming`
    // hints that it is rewritten often. orphanBuffer gives a buffer a fresh store of `bytes` (the
    // draws still reading the old one need not finish first).
    virtual BackendObject createBuffer() = 0;
    virtual void deleteBuffer(BackendObject buffer) = 0;
    virtual void allocateBuffer(BackendObject buffer, std::size_t bytes, const void* initial, bool streaming) = 0;
    virtual void orphanBuffer(BackendObject buffer, std::size_t bytes) = 0;
    virtual void readBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, void* out) = 0;
    virtual void copyBuffer(BackendObject source, BackendObject destination, std::size_t sourceOffset,
                            std::size_t destinationOffset, std::size_t bytes) = 0;

    // Textures: 2D or cube, `levels` levels of `format` (D3D9's reads of missing channels applied).
    // Texel transfers are in the format's own layout (rowBytes x rowCount: blocks for a compressed
    // format, whose areas lie on the 4-texel grid or reach the level's edge), face -1 for a 2D texture;
    // readTextureFloats reads RGBA floats.
    virtual bool isColorRenderable(SurfaceFormat format) = 0;
    // Whether textures of `format` can be made and sampled (the compressed families are extensions in GL).
    virtual bool isSampleable(SurfaceFormat format) = 0;
    // The image-unit format qualifier a shader declares for `format` ("rgba8"), "" when images cannot hold it.
    virtual const char* imageFormatName(SurfaceFormat format) = 0;
    virtual BackendObject createTexture(bool cube, SurfaceFormat format, int levels, int width, int height) = 0;
    // A buffer texture over `bytes` of `buffer` from byte `offset`, texels of `format` (deleted with
    // deleteTexture). `offset` is a multiple of bufferOffsetAlignment(false).
    virtual BackendObject createBufferTexture(BackendObject buffer, SurfaceFormat format, std::size_t offset, std::size_t bytes) = 0;
    // The multiple a range of a buffer must start at to be a buffer texture (storage false) or a
    // shader-storage binding (storage true).
    virtual std::size_t bufferOffsetAlignment(bool storage) = 0;
    virtual void deleteTexture(BackendObject texture) = 0;
    virtual void writeTexture(BackendObject texture, SurfaceFormat format, int face, int level, const Rectangle& area,
                              const void* data) = 0;
    virtual void readTexture(BackendObject texture, SurfaceFormat format, int face, int level, std::size_t bytes, void* out) = 0;
    virtual void readTextureFloats(BackendObject texture, int face, int level, std::size_t bytes, void* out) = 0;
    virtual Rectangle textureLevelSize(BackendObject texture, int level) = 0;  // Width x Height
    virtual void clearTexture(BackendObject texture, int level, const float (&rgba)[4]) = 0;
    virtual void generateMipmaps(BackendObject texture) = 0;
    virtual void copyTexture(const TextureCopy& copy) = 0;
    // Volume (3D) textures: `levels` levels of width x height x depth texels. writeVolume uploads a
    // whole level, slices front to back, rows top first; readTexture (face -1) reads one back so.
    virtual BackendObject createVolumeTexture(SurfaceFormat format, int levels, int width, int height, int depth) = 0;
    virtual void writeVolume(BackendObject texture, SurfaceFormat format, int level, int width, int height, int depth, const void* data) = 0;
    // 2D array textures: `layers` layers of `levels` levels of width x height texels. One layer of
    // one level is written (writeTexture) and read (readTexture, readTextureFloats) with the layer as
    // `face`; a colour attachment's `face` names the layer too.
    virtual BackendObject createArrayTexture(SurfaceFormat format, int levels, int width, int height, int layers) = 0;
    // 1D textures (D3D10+'s Texture1D): `layers` rows of `levels` levels of `width` texels, a 1D
    // array texture (`array`) or a plain 1D one (one layer). Transfers, copies and clears address
    // them as array textures of height 1 do: the layer as `face` (-1 for a plain 1D texture), Y and
    // the copy's Y 0, heights 1. textureLevelSize gives Height 1, or a 1D array's layer count (a copy
    // of that height copies every layer). No compressed formats (D3D has none in 1D).
    virtual BackendObject createLineTexture(SurfaceFormat format, int levels, int width, int layers, bool array) = 0;
    // A second texture over the texels of `source` (an array texture, 2D or 1D): levels [firstLevel,
    // firstLevel + levels) and layers [firstLayer, firstLayer + layers), seen as an array texture
    // (`array`) or, for one layer, as a single 2D (or 1D) texture. Writes through either are seen by
    // both; it is deleted with deleteTexture (the source's texels stay). 0 when the API cannot make views.
    virtual BackendObject createTextureView(BackendObject source, SurfaceFormat format, bool array, int firstLevel, int levels, int firstLayer,
                                            int layers) = 0;
    // The same over a 2D array's layers read as cubes (a cube map array: `layers` a multiple of 6,
    // square levels; D3D11's TEXTURECUBEARRAY view). 0 when the API cannot make it.
    virtual BackendObject createCubeArrayView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer, int layers) = 0;
    // The same over six layers from `firstLayer` read as one cube (D3D11's TEXTURECUBE view of a cube array).
    virtual BackendObject createCubeView(BackendObject source, SurfaceFormat format, int firstLevel, int levels, int firstLayer) = 0;
    // Multisampled 2D textures (D3D10+'s SampleDesc.Count > 1), fixed sample positions: render
    // targets a shader reads sample by sample. `given` is the count the driver made (it may round
    // up). copySamples copies between a multisampled texture (or layer) and a single-sample one of
    // one size and format: a resolve (each pixel the average of its samples, for non-integer formats)
    // or the other way (each sample the source's texel). multisampledUnits: the texture units a
    // program's sampler2DMS and sampler2DMSArray uniforms read, one bit each.
    virtual BackendObject createMultisampleTexture(SurfaceFormat format, int samples, int width, int height, int& given) = 0;
    // The same as an array of `layers` layers (D3D11's Texture2DMSArray). createTextureView of it
    // gives multisampled views; copySamples reads a layer of it named in the SampleCopy (not a view:
    // Mesa's blits read a multisampled view's first layer of the array, whatever the view's).
    virtual BackendObject createMultisampleArrayTexture(SurfaceFormat format, int samples, int width, int height, int layers, int& given) = 0;
    virtual void copySamples(const SampleCopy& copy) = 0;
    virtual unsigned multisampledUnits(BackendObject program) = 0;

    // Depth/stencil buffers (renderbuffers) and framebuffers. createFramebuffer returns 0 and says
    // why in `problem` when the API cannot draw to that combination. clearDepthStencil clears a
    // depth buffer whether bound or not; it changes the depth and stencil write masks and turns the
    // scissor test off (the core's shadow must forget them).
    virtual BackendObject createRenderbuffer() = 0;
    virtual void deleteRenderbuffer(BackendObject renderbuffer) = 0;
    // `depthIsTexture`: `depth` names a depth texture (DepthStorage::isTexture), not a renderbuffer.
    virtual BackendObject createFramebuffer(const std::vector<ColorAttachment>& colour, BackendObject depth, bool depthHasStencil,
                                            bool depthIsTexture, std::string& problem) = 0;
    virtual void deleteFramebuffer(BackendObject framebuffer) = 0;
    virtual void bindFramebuffer(BackendObject framebuffer) = 0;  // 0: the window's
    virtual void presentFlipped(BackendObject framebuffer, int width, int height) = 0;  // to the window, rows reversed
    virtual void clearDepthStencil(BackendObject renderbuffer, bool hasStencil, bool isTexture, bool depth, bool stencil, float depthValue,
                                   int stencilValue) = 0;
    // `samples` > 0: multisampled, exactly that many (InvalidOperation when the driver gives another count).
    virtual void allocateRenderbuffer(BackendObject renderbuffer, DepthFormat format, int width, int height, int samples) = 0;
    // Clears `area` of the bound framebuffer's first `colourTargets` colour attachments (when
    // `colour`) and of its depth and/or stencil, whatever the write masks and scissor were: it
    // leaves the scissor test on, the scissor at `area` and the cleared channels' masks open (the
    // core's shadow puts its state back).
    virtual void clearFramebuffer(BackendObject framebuffer, const Rectangle& area, int colourTargets, bool colour,
                                  const Vector4& color, bool depth, bool stencil, float depthValue, int stencilValue) = 0;
    // The bound framebuffer's contents that nothing will read: its first `colourTargets` colour
    // attachments, and its depth and/or stencil.
    virtual void invalidateFramebuffer(int colourTargets, bool depth, bool stencil) = 0;

    // Programs: one shader of `stage` (0 vertex .. 5 compute) made from `source`, its uniform blocks
    // moved to the stage's binding range; 0 with the API's log in `log` when rejected. `captured`:
    // the outputs stream output writes (xlate::capturedVaryings: names, gaps, buffer changes), for
    // the last stage before the rasteriser; empty for the others.
    virtual BackendObject createProgram(int stage, const std::string& source, const std::vector<std::string>& captured, std::string& log) = 0;
    virtual void deleteProgram(BackendObject program) = 0;
    virtual BackendObject createComputePipeline(BackendObject program) = 0;
    virtual void deletePipeline(BackendObject pipeline) = 0;

    // Storage: a buffer on a shader-storage binding, level 0 of a texture on an image unit (every
    // layer of a 1D array texture, which a shader's image1DArray indexes), and the barrier that
    // makes shader writes visible to whatever comes next.
    // `bytes` 0: the whole buffer; otherwise that many from `offset` (a multiple of bufferOffsetAlignment(true)).
    virtual void bindStorageBuffer(int binding, BackendObject buffer, std::size_t offset, std::size_t bytes) = 0;
    virtual void bindStorageImage(int unit, BackendObject texture, SurfaceFormat format, bool writes) = 0;
    virtual void storageBarrier() = 0;

    // Stream output: the draws between beginStreamOutput and endStreamOutput write the captured
    // outputs of primitives of `primitiveVertices` vertices (1 points, 2 lines, 3 triangles) to
    // `buffers` (one per slot, bytes 0: none), count the primitives written into `written` (a
    // PrimitivesWritten query) and those generated, written or not, into `generated` (a
    // PrimitivesGenerated query). Rasterizer discard drops every primitive after it (D3D11's
    // D3D11_SO_NO_RASTERIZED_STREAM).
    struct StreamOutputBuffer {
        BackendObject buffer = 0;
        std::size_t offset = 0, bytes = 0;
    };
    virtual void beginStreamOutput(const std::array<StreamOutputBuffer, 4>& buffers, int primitiveVertices, BackendObject written,
                                   BackendObject generated) = 0;
    virtual void endStreamOutput() = 0;
    virtual void setRasterizerDiscard(bool discard) = 0;

    // Work: a draw with the bound pipeline, vertex array and state; a compute dispatch.
    virtual void draw(const DrawCall& call) = 0;
    virtual void dispatch(int groupsX, int groupsY, int groupsZ) = 0;

    // Queries (the measurements of diagnostics/): the samples that pass between beginSamplesPassed
    // and endSamplesPassed (one open at a time), a GPU timestamp taken when the commands before it
    // have run. queryReady says whether a result can be read without waiting; queryResult waits.
    virtual BackendObject createQuery(QueryKind kind) = 0;
    virtual void deleteQuery(BackendObject query) = 0;
    virtual void beginSamplesPassed(BackendObject query) = 0;
    virtual void endSamplesPassed() = 0;
    virtual void writeTimestamp(BackendObject query) = 0;
    // The pipeline statistics: whether the API counts them, and the counting of one (each kind
    // counts into one query at a time; they count alongside each other and a samples query).
    virtual bool hasPipelineStatistics() = 0;
    virtual void beginStatistic(BackendObject query, QueryKind kind) = 0;
    virtual void endStatistic(QueryKind kind) = 0;
    virtual bool queryReady(BackendObject query) = 0;
    virtual std::uint64_t queryResult(BackendObject query) = 0;

    // The GPU's own rates (diagnostics/gpu_limits.cpp): each of `formats` filled, a clear, bilinear
    // fetches and compute image writes into size x size targets, `repeats` times each. It works outside
    // the state given above: afterwards the caller binds its objects again and sets every state.
    virtual GpuLimits measureLimits(const std::vector<SurfaceFormat>& formats, int size, int repeats) = 0;
};

// The backends there are (one registration each): OpenGL 4.5 core (gl/gl_backend.cpp).
std::unique_ptr<Backend> createGlBackend();

// A device whose every call reaches `backend`, with no GL context (GraphicsDevice's own constructor
// makes a context and the GL backend): the device core's tests use it with a recording backend
// (tests/runtime/recording_backend.h). The GL backend's own passes (compute passes) stay off.
std::unique_ptr<GraphicsDevice> createDeviceOver(std::unique_ptr<Backend> backend, const PresentationParameters& parameters);

}  // namespace fxport
