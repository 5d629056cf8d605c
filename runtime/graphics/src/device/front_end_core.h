// INTERNAL, GL-free: what a front end other than XNA's (runtime/d3d11) needs of the device core
// beyond the public XNA API. The XNA GraphicsDevice keeps doing state shadowing, validation, target
// binding and draws; these functions only let a front end hand it objects XNA has no class for:
// byte buffers bound by slot, a shader without an effect, a depth buffer apart from its colour
// target, instanced and byte-offset draws. Nothing here changes what an XNA call does.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/graphics_resource.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/vertex_declaration.h"

#include "device/vertex_format.h"

namespace fxport::xlate {
struct CompiledEffect;
struct CompiledShader;
}

namespace fxport {
struct ShaderProgram;
}

namespace fxport::core {

// A GPU buffer of bytes: vertices, indices or constants, whichever slot it is bound to.
class ByteBuffer : public GraphicsResource {
public:
    // `initial` may be null (zero-filled). `dynamic`: rewritten often (a streaming hint).
    ByteBuffer(GraphicsDevice& device, std::size_t bytes, const void* initial, bool dynamic);
    ~ByteBuffer() override;
    std::size_t size() const { return size_; }
    // Throws ArgumentError when [offset, offset + bytes) is outside the buffer.
    void write(std::size_t offset, std::size_t bytes, const void* data);
    void read(std::size_t offset, std::size_t bytes, void* out) const;
    void copyFrom(const ByteBuffer& source);  // sizes must match
    // Bytes [sourceOffset, sourceOffset + bytes) of `source` to `destinationOffset` (both ranges inside).
    void copyFrom(const ByteBuffer& source, std::size_t sourceOffset, std::size_t destinationOffset, std::size_t bytes);
    std::uint32_t backendObject() const { return name_; }
    // D3D's BufferFilledSize: the bytes from the start to where stream output into it last stopped
    // (what DrawAuto draws and an append continues from).
    std::size_t streamOutputFilled() const { return streamFilled_; }
    void setStreamOutputFilled(std::size_t bytes) { streamFilled_ = bytes; }

protected:
    void releaseGpuObjects() override;

private:
    std::size_t size_;
    std::uint32_t name_ = 0;
    std::size_t streamFilled_ = 0;
};

// `count` elements of a ByteBuffer from element `first` read as texels of `format` (D3D11's typed
// buffer views: Buffer<T> at t#, RWBuffer<T> at u#). Throws ArgumentError for a format a buffer
// texture cannot hold (sRGB, packed, snorm, BGRA, depth), a range past the buffer, or a first
// element whose byte offset is not a multiple of bufferOffsetAlignment. `buffer` must outlive it.
bool isTexelBufferFormat(SurfaceFormat format);
// The multiple of bytes a view of part of a buffer starts at: a typed one (TexelBuffer, storage
// false) or a structured/raw one (setStorageBuffer's offset, storage true). The API's, not D3D's.
std::size_t bufferOffsetAlignment(GraphicsDevice& device, bool storage);
class TexelBuffer : public GraphicsResource {
public:
    TexelBuffer(GraphicsDevice& device, const ByteBuffer& buffer, SurfaceFormat format, std::size_t count, std::size_t first = 0);
    ~TexelBuffer() override;
    SurfaceFormat format() const { return format_; }
    std::uint32_t backendObject() const { return name_; }

protected:
    void releaseGpuObjects() override;

private:
    SurfaceFormat format_;
    std::uint32_t name_ = 0;
};
// Binds `buffer` (null: none) at register u`slot` (unorderedAccess: RWBuffer<T>) or t`slot` (Buffer<T>).
void setTexelBuffer(GraphicsDevice& device, bool unorderedAccess, int slot, const TexelBuffer* buffer);

// A depth/stencil buffer of its own (a D3D11 depth texture): made at the first draw that tests it
// (the device's lazy depth storage), cleared through clearDepthBuffer.
class DepthBuffer : public GraphicsResource {
public:
    // `samples` > 0: multisampled, for multisampled colour targets of that count (D3D11's
    // SampleDesc.Count); ArgumentError beyond the driver's count.
    DepthBuffer(GraphicsDevice& device, int width, int height, DepthFormat format, int samples = 0);
    // The depth buffer that is level 0 of `texture` (SurfaceFormat Depth32, Depth24Stencil8, Depth32Stencil8 or
    // Depth16): what draws write through it, shaders sample from the texture (a D3D11 shadow map's
    // DSV and SRV). Made at once; `texture` must outlive it.
    DepthBuffer(GraphicsDevice& device, Texture2D& texture);
    ~DepthBuffer() override;
    DepthStorage& storage() { return storage_; }
    int width() const { return storage_.width; }
    int height() const { return storage_.height; }

protected:
    void releaseGpuObjects() override;

private:
    DepthStorage storage_;
};

// One compiled shader made into a device program (what an effect pass binds, without the effect).
class ShaderCode : public GraphicsResource {
public:
    // Throws InvalidOperation when the driver rejects the GLSL.
    ShaderCode(GraphicsDevice& device, std::shared_ptr<const xlate::CompiledEffect> effect, int shaderIndex,
               const std::string& label);
    ~ShaderCode() override;
    const xlate::CompiledEffect& effect() const { return *effect_; }
    const xlate::CompiledShader& shader() const;
    const ShaderProgram& program() const { return *program_; }

protected:
    void releaseGpuObjects() override;

private:
    std::shared_ptr<const xlate::CompiledEffect> effect_;
    std::unique_ptr<ShaderProgram> program_;
};

// Binds the shaders of every draw stage (vertex, pixel, geometry, hull, domain; null: the stage
// is off -- vertex and pixel are required), as an effect pass with those stages would, with no D3D9
// pass emulation.
void setShaderStages(GraphicsDevice& device, const ShaderCode* const (&stages)[5]);
// After an effect pass whose pixel stage is NULL (xlate::Pass::nullPixelShader): binds `code` (a
// pixel shader that writes nothing) there and returns true; false when a pixel shader is bound.
bool fillEmptyPixelStage(GraphicsDevice& device, const ShaderCode& code);
// The compute shader GraphicsDevice::DispatchCompute runs (null: none).
void setComputeShader(GraphicsDevice& device, const ShaderCode* computeShader);
// Binds `buffer` (null: none) to uniform-block binding `blockBinding` of `stage` (0 vertex, 1 pixel,
// 2 geometry, 3 hull, 4 domain, 5 compute).
void setUniformBuffer(GraphicsDevice& device, int stage, int blockBinding, const ByteBuffer* buffer);
// Binds `buffer` (null: none) as the unordered-access view of register u`slot` (unorderedAccess)
// or the shader-resource buffer of register t`slot` (StructuredBuffer<T>), as
// GraphicsDevice::SetUnorderedAccess / SetShaderResource do for a StructuredBuffer. `bytes` > 0: only
// that many from byte `offset` (a multiple of bufferOffsetAlignment(device, true)), what the shader's
// runtime array then holds; throws ArgumentError for a range outside the buffer or misaligned.
void setStorageBuffer(GraphicsDevice& device, bool unorderedAccess, int slot, const ByteBuffer* buffer, std::size_t offset = 0,
                      std::size_t bytes = 0);
// D3D10/11's SOSetTargets: buffer `slot` (null: none) takes what the draws whose last stage before
// the rasteriser streams (xlate::StreamOutput) write, from byte offsets[slot], or with
// kStreamOutputAppend from its streamOutputFilled(). Each draw moves the write position on.
inline constexpr std::size_t kStreamOutputAppend = ~std::size_t(0);
void setStreamOutputTargets(GraphicsDevice& device, const std::array<ByteBuffer*, 4>& buffers, const std::array<std::size_t, 4>& offsets);
// The primitives stream output has written, and those it was given (written or not: a buffer
// without room drops them), since the device was made: D3D11's SO_STATISTICS queries are the
// difference between two readings. Stream 0 only (the one fxport captures); exact, since each
// streaming draw waits for its counts.
struct StreamOutputCounts {
    std::uint64_t written = 0, needed = 0;
};
StreamOutputCounts streamOutputCounts(GraphicsDevice& device);

// Binds colour targets and a depth buffer of their size (null: none); the targets' own depth
// buffers are not used. Resets the device's Viewport to the whole target (as SetRenderTargets).
void setTargets(GraphicsDevice& device, const std::vector<RenderTargetBinding>& colour, DepthBuffer* depth);

// D3D10/11's viewports and scissor rectangles 1.. (RSSetViewports / RSSetScissorRects with more
// than one; a pre-rasteriser stage's SV_ViewportArrayIndex picks one); the device's Viewport and
// ScissorRectangle are index 0. Kept until set again (empty: index 0 only, as for XNA). ArgumentError
// beyond D3D11's 16 in all.
void setMoreViewports(GraphicsDevice& device, const std::vector<Viewport>& viewports, const std::vector<Rectangle>& scissors);

// One attribute of a vertex stream: the vertex-shader input it feeds, matched by semantic whatever
// the name (D3D11 input layouts name any: "CASCADE0", "CLIP_DISTANCE0"), and how its bytes read.
struct StreamElement {
    std::string semantic;  // upper case with index (vertexSemantic): "POSITION0", "CASCADE2"
    int offset = 0;        // bytes from the vertex's start
    VertexFormat format;
};
// The elements of one vertex buffer and the bytes from one vertex to the next.
struct StreamLayout {
    int stride = 0;
    std::vector<StreamElement> elements;
};
// An XNA declaration as a stream layout (usage + index name the semantic).
StreamLayout streamLayoutOf(const VertexDeclaration& declaration);

struct VertexStream {
    const ByteBuffer* buffer = nullptr;
    std::size_t offset = 0;                 // bytes
    const StreamLayout* layout = nullptr;  // elements and stride
    std::uint32_t object = 0;               // the GPU buffer when `buffer` is null (an XNA VertexBuffer's)
};
struct DrawArguments {
    PrimitiveType type = PrimitiveType::TriangleList;
    int count = 0;       // vertices or indices
    int first = 0;       // first vertex, or first index when indexed
    int baseVertex = 0;  // indexed only
    int instances = 1;
    int firstInstance = 0;
    const ByteBuffer* indices = nullptr;  // indexed when set
    std::uint32_t indexObject = 0;        // indexed from this GPU buffer when `indices` is null (an XNA IndexBuffer's)
    int indexSize = 2;                    // 2 or 4 bytes
    int controlPoints = 0;                // > 0: patches of this many control points (type is ignored)
};
// One vertex buffer of a draw: stream i feeds the shader inputs its declaration's elements match
// (by semantic); with instanceStepRate > 0 it advances once per that many instances (D3D11's
// D3D11_INPUT_PER_INSTANCE_DATA), otherwise once per vertex.
struct InstancedStream {
    VertexStream vertices;
    int instanceStepRate = 0;
};
// Draws with the device's current state (BlendState, DepthStencilState, RasterizerState, Viewport,
// ScissorRectangle, Textures, SamplerStates), the shaders and buffers set above and the vertices of
// `streams`. Throws InvalidOperation / ArgumentError as the XNA draws do.
void drawStreams(GraphicsDevice& device, const std::vector<InstancedStream>& streams, const DrawArguments& arguments);

// Fills level 0 of a colour texture with `color` (whatever is bound, no viewport or scissor).
void clearTexture(Texture& texture, const Vector4& color);
// Clears the depth and/or stencil of `buffer` (whether bound or not).
void clearDepthBuffer(GraphicsDevice& device, DepthBuffer& buffer, bool depth, bool stencil, float depthValue,
                      int stencilValue);
// Makes levels 1.. of `texture` from level 0 (D3D11's GenerateMips).
void generateMips(Texture& texture);
// Copies every level of `source` into `destination` (same size, format and level count).
void copyTexture(Texture& destination, const Texture& source);
// Copies `area` of level `sourceLevel` of `source` to (x, y) of level `destinationLevel` of
// `destination` (same format; both rectangles inside their levels).
void copyTextureRegion(Texture& destination, int destinationLevel, int x, int y, const Texture& source, int sourceLevel,
                       const Rectangle& area);

}  // namespace fxport::core
