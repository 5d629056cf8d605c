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

#include "fxport/graphics/adapter_identity.h"
#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/device_optimizations.h"
#include "fxport/graphics/device_statistics.h"
#include "fxport/graphics/fixed_function_state.h"
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
class Texture1D;

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
    // fxport: the passes the device may run between these calls and the GPU, each leaving the pixels
    // as XNA draws them (fxport/graphics/device_optimizations.h; DeviceOptimizations::None() for none).
    DeviceOptimizations Optimizations;
    std::string windowTitle;     // GLFW only
};

// Number of sampler/texture slots (D3D9 has 16 pixel samplers).
inline constexpr int kMaxTextureSlots = 16;
inline constexpr int kMaxRenderTargets = 4;
inline constexpr int kMaxVertexBufferBindings = 16;  // XNA HiDef's vertex streams
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
    // D3D9 states XNA 4 has no API for (fog, points, clip planes, alpha test, shade mode): set by an
    // effect pass's D3D9 states at Apply(), or assigned here after Apply() (fixed_function_state.h).
    fxport::FixedFunctionState FixedFunction;
    TextureCollection Textures;
    SamplerStateCollection SamplerStates;
    // XNA 4's vertex textures (HiDef): what an SM 1-3 vertex shader's samplers read (tex2Dlod;
    // D3D9's vertex texture samplers, indexed by the sampler's s#, 0-3), apart from the pixel
    // samplers' Textures[] and SamplerStates[]. An effect pass sets them for its vertex shader's
    // samplers, as XNA's effects do. SM 4+ shaders (D3D10/11) use Textures[] for every stage.
    TextureCollection VertexTextures;
    SamplerStateCollection VertexSamplerStates;
    IndexBuffer* Indices = nullptr;
    Rectangle ScissorRectangle;
    // Reset to the whole target by SetRenderTarget(s), as in XNA.
    fxport::Viewport Viewport;

    void SetVertexBuffer(VertexBuffer* buffer, int vertexOffset = 0);
    void SetVertexBuffer(VertexBuffer& buffer, int vertexOffset = 0) { SetVertexBuffer(&buffer, vertexOffset); }
    // XNA's SetVertexBuffers: up to kMaxVertexBufferBindings buffers at once (several streams, or
    // per-instance data for DrawInstancedPrimitives); the bindings are ordered as given.
    void SetVertexBuffers(const std::vector<VertexBufferBinding>& bindings);
    template <class... More>
    void SetVertexBuffers(const VertexBufferBinding& first, const More&... more) {
        SetVertexBuffers(std::vector<VertexBufferBinding>{first, VertexBufferBinding(more)...});
    }
    std::vector<VertexBufferBinding> GetVertexBuffers() const;

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
    // next draws do not cover are undefined, as in D3D. DeviceOptimizations::HonourDiscards.
    void DiscardContents(ClearOptions options);

    // XNA 4 signatures. baseVertex is added to every index; minVertexIndex/numVertices are hints.
    void DrawIndexedPrimitives(PrimitiveType primitiveType, int baseVertex, int minVertexIndex, int numVertices,
                               int startIndex, int primitiveCount);
    void DrawPrimitives(PrimitiveType primitiveType, int vertexStart, int primitiveCount);
    // XNA's hardware instancing: `instanceCount` copies of the indexed primitives, the bindings
    // with an InstanceFrequency advancing once per that many instances.
    void DrawInstancedPrimitives(PrimitiveType primitiveType, int baseVertex, int minVertexIndex, int numVertices,
                                 int startIndex, int primitiveCount, int instanceCount);

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
    // fxport: level 0 of a 1D texture (RWTexture1D), or every layer of a 1D array (RWTexture1DArray).
    void SetUnorderedAccess(int slot, Texture1D* texture);
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
    // The GPU's name, vendor and video memory as the driver reports them (DXGI's adapter description).
    AdapterIdentity adapterIdentity() const;
    int maxTextureSize() const;
    // fxport: what the driver can make, for D3D's CheckFormatSupport / CheckMultisampleQualityLevels:
    // textures of `format` (the compressed ones are GL extensions), render targets of it, and the
    // most samples a multisampled target has.
    bool supportsTextureFormat(SurfaceFormat format) const;
    bool supportsRenderTargetFormat(SurfaceFormat format) const;
    int maxSampleCount() const;
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
