// GraphicsDevice: XNA 4's device over OpenGL 4.5, with D3D's conventions (see docs/DESIGN.md,
// "D3D semantics on GL"): NDC depth [0,1], render targets stored top row first, D3D9 pixel centres
// for SM1-3 vertex shaders, XNA culling, Textures[]/SamplerStates[] slots by sampler register.
//
// State is set the XNA way, by assigning public members (device.BlendState = BlendState::Additive;
// device.Textures[0] = rt;). Setting only records the wish; the next draw compares each state with
// what GL has and calls GL only for what differs (FNA's model).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/surface_format.h"
#include "fxport/graphics/vertex_buffer.h"
#include "fxport/graphics/viewport.h"
#include "fxport/math.h"

namespace fxport::platform {
class GraphicsContext;
}

namespace fxport {

class Effect;
class StructuredBuffer;

enum class PrimitiveType : std::uint8_t { TriangleList, TriangleStrip, LineList, LineStrip, PointList };

enum class ClearOptions : std::uint8_t { Target = 1, DepthBuffer = 2, Stencil = 4 };
constexpr ClearOptions operator|(ClearOptions a, ClearOptions b) { return ClearOptions(std::uint8_t(a) | std::uint8_t(b)); }

struct PresentationParameters {
    int BackBufferWidth = 800;
    int BackBufferHeight = 480;
    SurfaceFormat BackBufferFormat = SurfaceFormat::Color;
    DepthFormat DepthStencilFormat = DepthFormat::Depth24Stencil8;
    // DiscardContents (XNA's default): the back buffer is cleared to DiscardColor when set.
    fxport::RenderTargetUsage RenderTargetUsage = fxport::RenderTargetUsage::DiscardContents;
    // fxport: where the GL context comes from: "osmesa" (CPU, headless; the default), "egl" (GPU,
    // headless), "glfw" (a window). Empty = $FXPORT_PLATFORM, else osmesa.
    std::string platform;
    bool debug = false;          // GL debug context; driver messages go to stderr
    // fxport: clears of a whole target are recorded and sent to GL only when a draw or read needs the
    // channel; a clear replaced by a later one, or a depth/stencil clear of a DiscardContents target
    // that no draw tested, never runs. The pixels are the same either way; false (or
    // $FXPORT_DEFER_CLEARS=0) executes every clear at once, as written.
    bool DeferClears = true;
    // fxport: GraphicsDevice::DiscardContents drops what it names (false, or
    // $FXPORT_HONOUR_DISCARDS=0: it does nothing, so every clear runs as written).
    bool HonourDiscards = true;
    // fxport: a render target's depth/stencil buffer (the back buffer's too) is made at the first draw
    // into it that tests depth or stencil, so a target never drawn with depth takes no memory
    // (DepthStorageStatistics); leaving a DiscardContents target tells GL its depth/stencil is no
    // longer needed (glInvalidateFramebuffer: XNA clears them at its next binding). DepthStencilFormat
    // reports the format asked for either way, and the pixels are the same; false (or
    // $FXPORT_LAZY_DEPTH=0) makes every buffer with its target.
    bool LazyDepthStorage = true;
    // fxport: a pending colour clear is dropped under a SpriteBatch sprite that provably writes every
    // pixel of the target (ClearStatistics::covered), and a draw that blends onto a zero colour clear
    // executed for it, on an unsigned-normalized target with source factor One and Add, Subtract or
    // Max, draws as the write it amounts to (ClearStatistics::blendsAsWrites; same bytes); false (or
    // $FXPORT_DROP_COVERED_CLEARS=0) does neither.
    bool DropCoveredClears = true;
    // fxport: a draw of at most two triangles (a FullscreenQuad, a one-sprite SpriteBatch batch)
    // whose state a compute dispatch honours exactly -- no depth or stencil test, no blending but
    // Min/Max (and One/One on 32-bit float targets), targets with an image format, a pixel shader
    // without derivatives -- runs as a compute shader generated from its pixel shader, fed the
    // values the rasteriser itself interpolated for an earlier draw with bit-identical vertices, so
    // the pixels are the fragment stage's (ComputePassStatistics). Unset (the default): on where
    // this GPU's compute shaders write images at least kComputePassesWhereFaster times as fast as
    // its fragment stage writes a Color target (GpuLimits, measured once per GPU and cached), never
    // on a software rasteriser; true/false force it. $FXPORT_COMPUTE_PASSES=1 or 0 overrides both.
    std::optional<bool> ComputePasses;
    std::string windowTitle;     // GLFW only
};

// PresentationParameters::ComputePasses left unset turns compute passes on where the GPU's compute
// image writes are at least this many times its fragment output (the H100 measured 393 against 56
// GB/s: x7; llvmpipe runs compute passes several times slower than its rasteriser).
inline constexpr double kComputePassesWhereFaster = 2.0;

// Number of sampler/texture slots (D3D9 has 16 pixel samplers).
inline constexpr int kMaxTextureSlots = 16;
inline constexpr int kMaxRenderTargets = 4;
inline constexpr int kMaxUnorderedAccessSlots = 8;   // D3D11's UAV slots u0..u7
inline constexpr int kMaxShaderResourceBuffers = 16;  // buffer SRVs t0..t15

// device.Textures[2] = texture; accepts Texture*, Texture&, unique_ptr and shared_ptr.
class TextureSlot {
public:
    TextureSlot& operator=(Texture* texture) { texture_ = texture; return *this; }
    TextureSlot& operator=(Texture& texture) { texture_ = &texture; return *this; }
    TextureSlot& operator=(std::nullptr_t) { texture_ = nullptr; return *this; }
    template <class T> TextureSlot& operator=(const std::unique_ptr<T>& t) { texture_ = t.get(); return *this; }
    template <class T> TextureSlot& operator=(const std::shared_ptr<T>& t) { texture_ = t.get(); return *this; }
    operator Texture*() const { return texture_; }
    Texture* get() const { return texture_; }

private:
    Texture* texture_ = nullptr;
};

class TextureCollection {
public:
    TextureSlot& operator[](int slot);
    const TextureSlot& operator[](int slot) const;

private:
    std::array<TextureSlot, kMaxTextureSlots> slots_{};
};

class SamplerStateCollection {
public:
    SamplerStateCollection();
    fxport::SamplerState& operator[](int slot);
    const fxport::SamplerState& operator[](int slot) const;

private:
    std::array<fxport::SamplerState, kMaxTextureSlots> slots_;
};

// Live GL objects made by this device (textures, renderbuffers, buffers, programs, pipelines,
// framebuffers, vertex arrays, queries): what the resource-lifetime test checks returns to zero.
struct GpuObjectCounts {
    int textures = 0, renderbuffers = 0, buffers = 0, programs = 0, pipelines = 0, framebuffers = 0,
        vertexArrays = 0, queries = 0;
    int total() const { return textures + renderbuffers + buffers + programs + pipelines + framebuffers + vertexArrays + queries; }
};

// Depth/stencil buffers over the device's life (PresentationParameters::LazyDepthStorage): bytes
// as drivers store them (Depth16 2 per pixel, Depth24 and Depth24Stencil8 4).
struct DepthStorageStatistics {
    long requested = 0;                // render targets and back buffers made with a DepthFormat
    long allocated = 0;                // their buffers made in GL (at a draw that needed one, or at once)
    std::int64_t requestedBytes = 0, allocatedBytes = 0;
    long invalidated = 0;              // depth/stencil contents given up on leaving a DiscardContents target
    long unallocated() const { return requested - allocated; }  // targets never drawn with depth or stencil
    std::int64_t savedBytes() const { return requestedBytes - allocatedBytes; }
};

// What the device did with the clears it was asked for (PresentationParameters::DeferClears).
struct ClearStatistics {
    long requested = 0;  // channel clears asked for (colour, depth, stencil each count; SetRenderTargets' too)
    long executed = 0;   // channel clears sent to GL
    long replaced = 0;   // pending channel clears overwritten by a later clear before any use
    long dropped = 0;    // depth/stencil clears of a DiscardContents target left before any draw tested them
    long discarded = 0;  // pending channel clears dropped by DiscardContents
    long covered = 0;    // pending colour clears dropped under a SpriteBatch sprite that writes every pixel
    long blendsAsWrites = 0;  // draws blending onto the zero clear executed for them, drawn as writes (same bits)
};

// What PresentationParameters::ComputePasses did: draws run as compute dispatches, and, for draws
// that were candidates (at most two triangles) but were drawn as usual, how many per reason. The
// GPU decides part of it (whether the vertices changed, w = 1, overlap); its counters are read
// without waiting, so draws it has not run yet are not counted (a read-back of a target waits).
struct ComputePassStatistics {
    long issued = 0;      // draws sent to the GPU as compute passes, counted at once (the GPU may still
                          // draw some as usual: fellBack's GPU reasons)
    long dispatched = 0;  // draws run as compute dispatches
    long replayed = 0;    // of those, from interpolants stored by an earlier draw (no fill)
    std::map<std::string, long> fellBack;
    long entries = 0;              // replay entries held now
    std::int64_t entryBytes = 0;   // their GPU memory (bounded by $FXPORT_COMPUTE_PASS_CACHE_MB, 512 by default)
    long evicted = 0;              // entries dropped to stay within the bound
};

class GraphicsDevice {
public:
    explicit GraphicsDevice(const fxport::PresentationParameters& parameters = {});
    ~GraphicsDevice();
    GraphicsDevice(const GraphicsDevice&) = delete;
    GraphicsDevice& operator=(const GraphicsDevice&) = delete;

    // --- state (recorded; applied at the next draw or clear). Member names are XNA's; the types
    // are spelled fxport:: because each member is named like its type.
    fxport::BlendState BlendState;
    fxport::DepthStencilState DepthStencilState;
    fxport::RasterizerState RasterizerState;
    TextureCollection Textures;
    SamplerStateCollection SamplerStates;
    IndexBuffer* Indices = nullptr;
    Rectangle ScissorRectangle;
    // Reset to the whole target by SetRenderTarget(s), as in XNA.
    fxport::Viewport Viewport;

    void SetVertexBuffer(VertexBuffer* buffer, int vertexOffset = 0);
    void SetVertexBuffer(VertexBuffer& buffer, int vertexOffset = 0) { SetVertexBuffer(&buffer, vertexOffset); }

    // nullptr = the back buffer. Targets must all have the same size (D3D9's rule); the depth buffer
    // is the first target's. Throws ArgumentError naming the target otherwise. As XNA 4 on Windows
    // does, a target whose RenderTargetUsage is DiscardContents is cleared when set: colour to
    // DiscardColor, depth to 1, stencil to 0 (PreserveContents keeps what it held).
    Color DiscardColor = Color(68, 34, 136, 255);
    void SetRenderTarget(RenderTarget2D* target);
    void SetRenderTarget(RenderTarget2D& target) { SetRenderTarget(&target); }
    void SetRenderTarget(RenderTargetCube* target, CubeMapFace face);
    void SetRenderTarget(RenderTargetCube& target, CubeMapFace face) { SetRenderTarget(&target, face); }
    void SetRenderTargets(const std::vector<RenderTargetBinding>& bindings);
    void SetRenderTargets(std::initializer_list<RenderTargetBinding> bindings) {
        SetRenderTargets(std::vector<RenderTargetBinding>(bindings));
    }
    std::vector<RenderTargetBinding> GetRenderTargets() const;

    // fxport, for checks of what a pass wrote (FiniteCheck, fxdemo --check-finite): markBoundTargets()
    // starts a list, targetsBoundSinceMark() returns every binding (a cube face is its own binding)
    // that was bound at the mark or set since, each once, in the order first bound. The back buffer
    // appears as backBufferTarget(). A disposed target drops out of the list.
    void markBoundTargets();
    std::vector<RenderTargetBinding> targetsBoundSinceMark() const;
    // Also since the mark (issue 16's per-pass bounds): the most colour bytes one fragment writes
    // (the sum over the targets one SetRenderTargets bound together, the widest such set), and
    // whether a draw blended.
    int colorBytesPerFragmentSinceMark() const;
    bool blendedSinceMark() const;
    // The targets that draws and executed clears wrote since the mark (each binding once, in the
    // order first written); a target only bound is not among them. color: a draw or a colour clear
    // wrote it; depthStencil: a draw tested or a clear wrote its depth/stencil buffer, which then
    // exists (lazy storage makes it on demand; MRT use the first target's). drawnPixels: the
    // largest area one draw could cover (its viewport, within the scissor when on); clearedPixels:
    // the largest area one clear covered.
    struct WrittenTarget {
        RenderTargetBinding binding;
        bool color = false;
        bool depthStencil = false;
        double drawnPixels = 0;
        double clearedPixels = 0;
        double colorClearedPixels = 0;  // of those, by clears of colour (depth clears are fast clears on GPUs)
    };
    std::vector<WrittenTarget> targetsWrittenSinceMark() const;

    // fxport, for the fetches in per-pass bounds (fxdemo --bounds): with tallyFragments(true) the
    // device counts fragments (GL_SAMPLES_PASSED) per run of consecutive draws whose pixel shaders
    // make the same texture fetches per fragment (xlate::countTextureFetches of their GLSL).
    // fragmentTallyMark() ends the current run and returns how many runs there are; between two
    // marks, fragmentTallies(from, to) gives those runs, waiting for the GPU's counts. Not with
    // GpuTimer::CountFragments at the same time: GL counts one GL_SAMPLES_PASSED query at a time.
    struct FragmentTally {
        double fragments = 0;
        int fetchesLeast = 0, fetchesMost = 0;  // per fragment (xlate::TextureFetches)
        bool fetchesUnbounded = false;
    };
    void tallyFragments(bool on);
    std::size_t fragmentTallyMark();
    std::vector<FragmentTally> fragmentTallies(std::size_t from, std::size_t to);
    RenderTarget2D& backBufferTarget();  // to read (GetDataAsVector4); SetRenderTarget(nullptr) binds it

    // Clears every bound target (colour, depth, stencil) inside the viewport, ignoring blend and
    // write masks the way D3D9 Clear does.
    void Clear(Color color);
    void Clear(ClearOptions options, Color color, float depth, int stencil);
    void Clear(ClearOptions options, Vector4 color, float depth, int stencil);
    // fxport addition (D3D11.1's DiscardView, GL's glInvalidateFramebuffer): the bound targets'
    // channels in `options` will be overwritten before anything reads them (a full-target quad with
    // blending off, say), so their contents are undefined from here: a clear of them still pending
    // (SetRenderTargets' clear of a DiscardContents target) is dropped and GL is told. Pixels the
    // next draws do not cover are undefined, as in D3D. PresentationParameters::HonourDiscards.
    void DiscardContents(ClearOptions options);

    // XNA 4 signatures. baseVertex is added to every index; minVertexIndex/numVertices are hints.
    void DrawIndexedPrimitives(PrimitiveType primitiveType, int baseVertex, int minVertexIndex, int numVertices,
                               int startIndex, int primitiveCount);
    void DrawPrimitives(PrimitiveType primitiveType, int vertexStart, int primitiveCount);

    // --- D3D11 stages (fxport additions; XNA has none of them)
    // Tessellated draws: patches of `controlPoints` (1..32) vertices each, through the hull and
    // domain shaders of the applied pass (D3D11's N_CONTROL_POINT_PATCHLIST topologies).
    void DrawPatches(int controlPoints, int vertexStart, int patchCount);
    void DrawIndexedPatches(int controlPoints, int baseVertex, int startIndex, int patchCount);
    // Runs the compute shader of the last applied pass that has one (SetComputeShader) over
    // groupsX * groupsY * groupsZ thread groups. Its constants, Textures[] and the buffers and
    // textures below are bound as for a draw. What it writes is visible to every later draw,
    // dispatch and GetData (the device places the memory barriers).
    void DispatchCompute(int groupsX, int groupsY, int groupsZ);
    // Unordered-access views (register uN, N < kMaxUnorderedAccessSlots) for RWStructuredBuffer /
    // RWByteAddressBuffer (a StructuredBuffer) and RWTexture2D (level 0 of a Texture2D or
    // RenderTarget2D whose format a shader can write: Single, Vector2, Vector4, HalfVector4, Color ...).
    // nullptr clears the slot. Bound at every draw and dispatch whose shaders declare the register.
    void SetUnorderedAccess(int slot, StructuredBuffer* buffer);
    void SetUnorderedAccess(int slot, StructuredBuffer& buffer) { SetUnorderedAccess(slot, &buffer); }
    void SetUnorderedAccess(int slot, Texture2D* texture);
    void SetUnorderedAccess(int slot, Texture2D& texture) { SetUnorderedAccess(slot, &texture); }
    // Shader-resource buffers (register tN) for StructuredBuffer<T> / ByteAddressBuffer.
    void SetShaderResource(int slot, StructuredBuffer* buffer);
    void SetShaderResource(int slot, StructuredBuffer& buffer) { SetShaderResource(slot, &buffer); }
    template <class T>
    void DrawUserPrimitives(PrimitiveType primitiveType, const T* vertexData, int vertexOffset, int primitiveCount) {
        drawUser(primitiveType, vertexData + vertexOffset, sizeof(T), T::VertexDeclaration, primitiveCount);
    }
    template <class T>
    void DrawUserPrimitives(PrimitiveType primitiveType, const T* vertexData, int vertexOffset, int primitiveCount,
                            const VertexDeclaration& declaration) {
        drawUser(primitiveType, vertexData + vertexOffset, sizeof(T), declaration, primitiveCount);
    }
    template <class T, class I>
    void DrawUserIndexedPrimitives(PrimitiveType primitiveType, const T* vertexData, int vertexOffset, int numVertices,
                                   const I* indexData, int indexOffset, int primitiveCount) {
        static_assert(sizeof(I) == 2 || sizeof(I) == 4, "indices are 16 or 32 bit");
        drawUserIndexed(primitiveType, vertexData + vertexOffset, sizeof(T), numVertices, T::VertexDeclaration,
                        indexData + indexOffset, int(sizeof(I)), primitiveCount);
    }
    template <class T, class I>
    void DrawUserIndexedPrimitives(PrimitiveType primitiveType, const T* vertexData, int vertexOffset, int numVertices,
                                   const I* indexData, int indexOffset, int primitiveCount,
                                   const VertexDeclaration& declaration) {
        static_assert(sizeof(I) == 2 || sizeof(I) == 4, "indices are 16 or 32 bit");
        drawUserIndexed(primitiveType, vertexData + vertexOffset, sizeof(T), numVertices, declaration,
                        indexData + indexOffset, int(sizeof(I)), primitiveCount);
    }

    // Shows the back buffer (GLFW: flips it into the window and swaps; headless: no-op).
    void Present();
    // The back buffer's pixels, top row first.
    std::vector<Color> GetBackBufferData() const;
    // The frame as a screen shows it: RGB of the back buffer, alpha written as 255 (RenderTarget2D's
    // SaveAsPng keeps alpha, as XNA's does).
    void SaveBackBufferAsPng(const std::string& path) const;

    const fxport::PresentationParameters& PresentationParameters() const { return parameters_; }
    // XNA's Reset(PresentationParameters): makes the back buffer again with the new size, formats and
    // usage (its contents are lost) and binds it. The platform, window and debug flag stay as they
    // were (a window keeps its size). Throws ArgumentError for a size that is not positive.
    void Reset(const fxport::PresentationParameters& parameters);
    platform::GraphicsContext& context() { return *context_; }
    std::string rendererName() const;
    int maxTextureSize() const;
    DepthStorageStatistics depthStorageStatistics() const;
    GpuObjectCounts liveGpuObjects() const;
    ClearStatistics clearStatistics() const;
    ComputePassStatistics computePassStatistics() const;
    // Waits until the GPU has finished everything submitted (for timing and tests).
    void finish();
    // fxport drives GL from one thread, and the device created last is the current one. With
    // several devices alive, call makeCurrent() before using another; destroying a device makes
    // the one created before it current again.
    void makeCurrent();
    // The device GL calls currently go to (the last created or made current); nullptr if none.
    static GraphicsDevice* current();

    struct Impl;  // the library's own state (not API)

private:
    friend struct ImplAccess;  // the library reaches Impl through it (src/device/impl_access.h)
    void drawUser(PrimitiveType type, const void* vertices, std::size_t stride, const VertexDeclaration& declaration,
                  int primitiveCount);
    void drawUserIndexed(PrimitiveType type, const void* vertices, std::size_t stride, int vertexCount,
                         const VertexDeclaration& declaration, const void* indices, int indexSize, int primitiveCount);

    fxport::PresentationParameters parameters_;
    std::unique_ptr<platform::GraphicsContext> context_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fxport
