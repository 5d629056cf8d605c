// INTERNAL: the D3D11 front end's objects. Each D3D object holds the device-core object it stands
// for (a Texture2D or RenderTarget2D, a core::ByteBuffer, a core::ShaderCode ...) or a description
// decoded once into the XNA device's state structs; the context copies its bindings into the
// device core at each draw. No GL here (tests/layering checks it).
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "device/front_end_core.h"
#include "device/gpu_query.h"
#include "fxport/d3d11.h"
#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_1d.h"
#include "fxport/graphics/texture_2d_array.h"
#include "fxport/graphics/texture_3d.h"
#include "fxport/xlate/compiled_effect.h"
#include "shader_bindings.h"

namespace fxport::d3d11 {

class Device;
class DxgiDevice;  // dxgi_impl.h

// --- results (errors.cpp)
HRESULT fail(HRESULT code, const std::string& message);  // records the message, returns code
HRESULT succeed();                                         // clears the message, returns S_OK
void note(const std::string& message);                     // a void call's problem
// guarded(call, body) (guarded.h) turns the device core's exceptions into HRESULTs.

// --- reference counting: every object starts at 1 and deletes itself at 0.
template <class Interface>
class Object : public Interface {
public:
    explicit Object(Device* device) : device_(device) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    void GetDevice(ID3D11Device** ppDevice) override;
    Device& device() const { return *device_; }

protected:
    Device* device_;

private:
    std::atomic<ULONG> references_{1};
};

// --- resources
class Buffer final : public Object<ID3D11Buffer> {
public:
    Buffer(Device* device, const D3D11_BUFFER_DESC& desc, const void* initial);
    void GetType(D3D11_RESOURCE_DIMENSION* d) override { if (d) *d = D3D11_RESOURCE_DIMENSION_BUFFER; }
    void GetDesc(D3D11_BUFFER_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    HRESULT Map(D3D11_MAP MapType, UINT MapFlags, void** ppData) override;  // D3D10's (d3d10_buffer_map.cpp)
    void Unmap() override;
    D3D11_BUFFER_DESC desc;
    std::unique_ptr<core::ByteBuffer> gpu;  // null for staging buffers
    std::vector<std::uint8_t> cpu;          // staging buffers, and what Map hands out
    bool mapped = false;
};

class Texture final : public Object<ID3D11Texture2D> {
public:
    Texture(Device* device, const D3D11_TEXTURE2D_DESC& desc);
    void GetType(D3D11_RESOURCE_DIMENSION* d) override { if (d) *d = D3D11_RESOURCE_DIMENSION_TEXTURE2D; }
    void GetDesc(D3D11_TEXTURE2D_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_TEXTURE2D_DESC desc;
    SurfaceFormat format = SurfaceFormat::Color;
    std::unique_ptr<fxport::Texture2D> colour;      // a RenderTarget2D when BIND_RENDER_TARGET
    std::unique_ptr<fxport::TextureCube> cube;      // MISC_TEXTURECUBE (shader resource only)
    std::unique_ptr<fxport::Texture2DArray> array;  // ArraySize > 1 without TEXTURECUBE (resources_array.cpp)
    std::unique_ptr<core::DepthBuffer> depth;       // BIND_DEPTH_STENCIL (over `colour` for a typeless depth texture: declared after it, released first)
    std::vector<std::vector<std::uint8_t>> staging;  // USAGE_STAGING: each subresource's texels, tightly packed
    int levels = 1;
    int mappedLevel = -1;
    fxport::Texture* sampled() const {  // what an SRV of the whole texture reads
        return colour ? static_cast<fxport::Texture*>(colour.get()) : cube ? static_cast<fxport::Texture*>(cube.get()) : array.get();
    }
    // D3D's subresources: level + slice * levels, over the array's slices (a cube's faces aside).
    int slices() const { return cube ? 1 : int(desc.ArraySize); }
    int subresources() const { return levels * slices(); }
    int levelWidth(int level) const { return std::max(1, int(desc.Width) >> level); }
    int levelHeight(int level) const { return std::max(1, int(desc.Height) >> level); }
    std::size_t levelBytes(int level) const;
};

// A 3D texture (texture_3d.cpp): a volume shader resource, sampled through a TEXTURE3D view.
class Volume final : public Object<ID3D11Texture3D> {
public:
    Volume(Device* device, const D3D11_TEXTURE3D_DESC& d) : Object(device), desc(d) {}
    void GetType(D3D11_RESOURCE_DIMENSION* d) override { if (d) *d = D3D11_RESOURCE_DIMENSION_TEXTURE3D; }
    void GetDesc(D3D11_TEXTURE3D_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_TEXTURE3D_DESC desc;
    std::unique_ptr<fxport::Texture3D> texels;
};

// A 1D texture or 1D array (resources_1d.cpp): a device-core Texture1D (GL's 1D or 1D array
// texture, by ArraySize), or CPU memory for USAGE_STAGING; a DYNAMIC one keeps what Map hands out
// in `staging` too and uploads it at Unmap. Subresources are D3D's level + slice * MipLevels.
class LineTexture final : public Object<ID3D11Texture1D> {
public:
    LineTexture(Device* device, const D3D11_TEXTURE1D_DESC& d) : Object(device), desc(d) {}
    void GetType(D3D11_RESOURCE_DIMENSION* d) override { if (d) *d = D3D11_RESOURCE_DIMENSION_TEXTURE1D; }
    void GetDesc(D3D11_TEXTURE1D_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_TEXTURE1D_DESC desc;
    SurfaceFormat format = SurfaceFormat::Color;
    std::unique_ptr<fxport::Texture1D> texels;       // null for USAGE_STAGING
    std::vector<std::vector<std::uint8_t>> staging;  // STAGING (and a mapped DYNAMIC): each subresource's row
    int levels = 1;
    int mapped = -1;  // the mapped subresource
    int subresources() const { return levels * int(desc.ArraySize); }
    int levelWidth(int level) const { return std::max(1, int(desc.Width) >> level); }
    std::size_t rowBytes(int level) const { return regionBytes(format, levelWidth(level), 1); }
};

// The elements of a buffer a view sees: [first, first + count), bound as bytes [offset, offset +
// bytes) for a structured or raw view (bytes 0: the whole buffer).
struct BufferRange {
    UINT first = 0, count = 0;
    std::size_t offset = 0, bytes = 0;
};

// A view of a texture (texture set), of a 3D texture (volume set) or of a buffer (buffer set); it
// holds a reference.
class ShaderResourceView final : public Object<ID3D11ShaderResourceView> {
public:
    ShaderResourceView(Device* device, Texture* viewed, const D3D11_SHADER_RESOURCE_VIEW_DESC& d)
        : Object(device), texture(viewed), desc(d) { texture->AddRef(); }
    ShaderResourceView(Device* device, Buffer* viewed, const D3D11_SHADER_RESOURCE_VIEW_DESC& d)
        : Object(device), buffer(viewed), desc(d) { buffer->AddRef(); }
    ShaderResourceView(Device* device, Volume* viewed, const D3D11_SHADER_RESOURCE_VIEW_DESC& d)
        : Object(device), volume(viewed), desc(d) { volume->AddRef(); }
    ShaderResourceView(Device* device, LineTexture* viewed, const D3D11_SHADER_RESOURCE_VIEW_DESC& d)
        : Object(device), line(viewed), desc(d) { line->AddRef(); }
    ~ShaderResourceView() override {
        typed.reset();  // before the buffer it reads may go
        formatView.reset();
        arrayRange.reset();
        cubeRange.reset();
        lineRange.reset();
        resource()->Release();
    }
    void GetResource(ID3D11Resource** r) override { resource()->AddRef(); *r = resource(); }
    void GetDesc(D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    ID3D11Resource* resource() const {
        if (line) return line;
        return texture ? static_cast<ID3D11Resource*>(texture) : volume ? static_cast<ID3D11Resource*>(volume) : buffer;
    }
    // What a shader samples through the view; null for a view of a buffer.
    fxport::Texture* sampled() const {
        if (formatView) return formatView.get();
        if (arrayRange) return arrayRange.get();
        if (cubeRange) return cubeRange.get();
        if (line) return lineRange ? lineRange.get() : line->texels.get();
        return texture ? texture->sampled() : volume ? volume->texels.get() : nullptr;
    }
    Texture* texture = nullptr;
    Volume* volume = nullptr;
    LineTexture* line = nullptr;
    Buffer* buffer = nullptr;
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    BufferRange range;                         // buffer views
    std::unique_ptr<core::TexelBuffer> typed;  // a typed buffer view (Buffer<T>)
    std::unique_ptr<fxport::Texture2D> formatView;       // a typeless colour texture read in another format of its family
    std::unique_ptr<fxport::Texture2DArray> arrayRange;  // a view of part of an array texture's levels or slices
    std::unique_ptr<fxport::TextureCube> cubeRange;      // a TEXTURECUBE view of a cube array (its first cube)
    std::unique_ptr<fxport::Texture1D> lineRange;        // a 1D texture seen as another dimension or in part
};
// An unordered-access view of a structured or raw buffer, of level 0 of a 2D texture, or of level
// 0 of a 1D texture (`image`: every slice of a 1D array).
class UnorderedAccessView final : public Object<ID3D11UnorderedAccessView> {
public:
    UnorderedAccessView(Device* device, ID3D11Resource* viewed, Buffer* b, Texture* t, const D3D11_UNORDERED_ACCESS_VIEW_DESC& d)
        : Object(device), resource(viewed), buffer(b), texture(t), desc(d) { resource->AddRef(); }
    ~UnorderedAccessView() override {
        typed.reset();
        image.reset();
        formatView.reset();
        resource->Release();
    }
    void GetResource(ID3D11Resource** r) override { resource->AddRef(); *r = resource; }
    void GetDesc(D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    ID3D11Resource* resource;
    Buffer* buffer;
    Texture* texture;
    D3D11_UNORDERED_ACCESS_VIEW_DESC desc;
    BufferRange range;                         // buffer views
    std::unique_ptr<core::TexelBuffer> typed;  // a typed buffer view (RWBuffer<T>)
    std::unique_ptr<fxport::Texture1D> image;  // a 1D texture's view (resources_1d.cpp)
    std::unique_ptr<fxport::Texture2D> formatView;  // a typeless colour texture written in another format of its family
};
// A render-target view of a 2D texture (texture set) or of rows of a 1D texture (line set, and
// `slice` the target over them).
class RenderTargetView final : public Object<ID3D11RenderTargetView> {
public:
    RenderTargetView(Device* device, Texture* viewed, const D3D11_RENDER_TARGET_VIEW_DESC& d)
        : Object(device), texture(viewed), desc(d) { texture->AddRef(); }
    RenderTargetView(Device* device, LineTexture* viewed, const D3D11_RENDER_TARGET_VIEW_DESC& d)
        : Object(device), line(viewed), desc(d) { line->AddRef(); }
    ~RenderTargetView() override {
        slice.reset();  // before the array it draws into may go
        resource()->Release();
    }
    ID3D11Resource* resource() const { return line ? static_cast<ID3D11Resource*>(line) : texture; }
    void GetResource(ID3D11Resource** r) override { resource()->AddRef(); *r = resource(); }
    void GetDesc(D3D11_RENDER_TARGET_VIEW_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    RenderTarget2D& target() const { return slice ? *slice : static_cast<RenderTarget2D&>(*texture->colour); }
    Texture* texture = nullptr;
    LineTexture* line = nullptr;
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    std::unique_ptr<RenderTarget2D> slice;  // a view of slices of an array texture (layered for several), or in another format
};
class DepthStencilView final : public Object<ID3D11DepthStencilView> {
public:
    DepthStencilView(Device* device, Texture* viewed, const D3D11_DEPTH_STENCIL_VIEW_DESC& d)
        : Object(device), texture(viewed), desc(d) { texture->AddRef(); }
    DepthStencilView(Device* device, LineTexture* viewed, const D3D11_DEPTH_STENCIL_VIEW_DESC& d)
        : Object(device), line(viewed), desc(d) { line->AddRef(); }
    ~DepthStencilView() override {
        slice.reset();  // before the texture it is made over
        sliceTexture.reset();
        resource()->Release();
    }
    ID3D11Resource* resource() const { return line ? static_cast<ID3D11Resource*>(line) : texture; }
    void GetResource(ID3D11Resource** r) override { resource()->AddRef(); *r = resource(); }
    void GetDesc(D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    Texture* texture = nullptr;
    LineTexture* line = nullptr;  // a 1D view: slice is the depth buffer over sliceTexture's rows
    D3D11_DEPTH_STENCIL_VIEW_DESC desc;
    std::unique_ptr<fxport::Texture2D> sliceTexture;  // slices of an array texture (one: a 2D texture)
    std::unique_ptr<core::DepthBuffer> slice;          // the depth buffer over it
    core::DepthBuffer& buffer() const { return slice ? *slice : *texture->depth; }
};

// --- shaders
class VertexShader final : public Object<ID3D11VertexShader> {
public:
    VertexShader(Device* device, std::unique_ptr<core::ShaderCode> shaderCode, ShaderBindings slots)
        : Object(device), code(std::move(shaderCode)), bindings(std::move(slots)) {}
    std::unique_ptr<core::ShaderCode> code;
    ShaderBindings bindings;
};
class PixelShader final : public Object<ID3D11PixelShader> {
public:
    PixelShader(Device* device, std::unique_ptr<core::ShaderCode> shaderCode, ShaderBindings slots)
        : Object(device), code(std::move(shaderCode)), bindings(std::move(slots)) {}
    std::unique_ptr<core::ShaderCode> code;
    ShaderBindings bindings;
};
// The geometry, hull, domain and compute shaders: a device program and D3D's slots for it.
template <class Interface>
class StageShader final : public Object<Interface> {
public:
    StageShader(Device* device, std::unique_ptr<core::ShaderCode> shaderCode, ShaderBindings slots)
        : Object<Interface>(device), code(std::move(shaderCode)), bindings(std::move(slots)) {}
    std::unique_ptr<core::ShaderCode> code;
    ShaderBindings bindings;
};
using GeometryShader = StageShader<ID3D11GeometryShader>;
using HullShader = StageShader<ID3D11HullShader>;
using DomainShader = StageShader<ID3D11DomainShader>;
using ComputeShader = StageShader<ID3D11ComputeShader>;

// The elements of each input slot that the layout reads (offsets within that slot's vertex), and
// whether the slot steps per instance.
class InputLayout final : public Object<ID3D11InputLayout> {
public:
    struct Slot {
        std::vector<core::StreamElement> elements;
        UINT instanceStepRate = 0;  // 0: per vertex
    };
    InputLayout(Device* device, std::vector<Slot> layoutSlots) : Object(device), slots(std::move(layoutSlots)) {}
    std::vector<Slot> slots;  // index = InputSlot, up to the highest one used
    bool empty() const {
        for (const Slot& s : slots)
            if (!s.elements.empty()) return false;
        return true;
    }
};

// --- state objects, decoded once into the device core's descriptions (states.cpp)
class SamplerState final : public Object<ID3D11SamplerState> {
public:
    SamplerState(Device* device, const D3D11_SAMPLER_DESC& d, const fxport::SamplerState& s) : Object(device), desc(d), state(s) {}
    void GetDesc(D3D11_SAMPLER_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_SAMPLER_DESC desc;
    fxport::SamplerState state;
};
class BlendState final : public Object<ID3D11BlendState> {
public:
    BlendState(Device* device, const D3D11_BLEND_DESC& d, const fxport::BlendState& s) : Object(device), desc(d), state(s) {}
    void GetDesc(D3D11_BLEND_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_BLEND_DESC desc;
    fxport::BlendState state;
};
class RasterizerState final : public Object<ID3D11RasterizerState> {
public:
    RasterizerState(Device* device, const D3D11_RASTERIZER_DESC& d, const fxport::RasterizerState& s) : Object(device), desc(d), state(s) {}
    void GetDesc(D3D11_RASTERIZER_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_RASTERIZER_DESC desc;
    fxport::RasterizerState state;
};
class DepthStencilState final : public Object<ID3D11DepthStencilState> {
public:
    DepthStencilState(Device* device, const D3D11_DEPTH_STENCIL_DESC& d, const fxport::DepthStencilState& s) : Object(device), desc(d), state(s) {}
    void GetDesc(D3D11_DEPTH_STENCIL_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_DEPTH_STENCIL_DESC desc;
    fxport::DepthStencilState state;
};
// Descriptions -> device-core states; E_INVALIDARG naming the field and value (states.cpp).
HRESULT decodeSampler(const D3D11_SAMPLER_DESC& d, fxport::SamplerState& out);
HRESULT decodeBlend(const D3D11_BLEND_DESC& d, fxport::BlendState& out);
HRESULT decodeRasterizer(const D3D11_RASTERIZER_DESC& d, fxport::RasterizerState& out);
HRESULT decodeDepthStencil(const D3D11_DEPTH_STENCIL_DESC& d, fxport::DepthStencilState& out);
D3D11_SAMPLER_DESC defaultSamplerDesc();

// --- formats (formats.cpp)
const char* formatName(DXGI_FORMAT format);
bool textureFormat(DXGI_FORMAT format, SurfaceFormat& out);
// D3D's limits on a block-compressed texture (BC1-BC7): sampled only -- no render-target,
// depth-stencil or unordered-access binding, one sample, no generated mips. S_OK for other formats.
HRESULT checkCompressedUse(const std::string& at, const D3D11_TEXTURE2D_DESC& d, SurfaceFormat format);
bool depthFormat(DXGI_FORMAT format, DepthFormat& out);
// --- vertex formats (vertex_formats.cpp)
bool vertexFormat(DXGI_FORMAT format, VertexFormat& out);
// D3D10+'s input assembler converts nothing between an element's integers and a float input: the
// shader's register holds the integer's bits, where GL would convert the value. A 32-bit integer
// element feeding a float input is therefore read as Float32; 8- and 16-bit ones are E_NOTIMPL
// (message starting `at`).
HRESULT readAsInputReads(VertexFormat& format, bool integerInput, DXGI_FORMAT dxgi, const std::string& at);

// --- typeless depth textures (typeless_formats.cpp): R32/R24G8/R16_TYPELESS, with their depth and
// shader-resource view formats and what the device core makes of them.
struct DepthFamily {
    DXGI_FORMAT typeless, depthView, sampledView;
    DepthFormat depth;      // a depth buffer's format (DSV only)
    SurfaceFormat sampled;  // the depth texture's (SRV, or SRV and DSV)
    DXGI_FORMAT stencilView = DXGI_FORMAT_UNKNOWN;  // an SRV of the stencil (R24G8 / R32G8X24 only)
    SurfaceFormat stencil = SurfaceFormat::Depth32;  // what that view reads (StencilOf...)
};
const DepthFamily* depthFamilyOf(DXGI_FORMAT textureFormat);  // null: not one of them
const DepthFamily* depthFamilyOfView(DXGI_FORMAT depthView);   // the family whose DSV format this is (D32_FLOAT ...)
// The format a typeless colour texture is stored in (R8G8B8A8_TYPELESS: R8G8B8A8_UNORM's; BC1-7,
// B8G8R8A8/X8); false for any other format.
bool typelessColourStorage(DXGI_FORMAT typeless, SurfaceFormat& out);
// What a view of `viewFormat` reads `t` as: the view's format for a typeless colour texture, the
// stencil for a typeless depth-stencil texture's stencil view, the texture's own otherwise.
SurfaceFormat viewSurface(DXGI_FORMAT viewFormat, const Texture& t);
// A view's Format for texture `t`: its own (or UNKNOWN), a typed member of a typeless colour
// texture's family, or the typeless depth family's view of that kind; E_NOTIMPL/E_INVALIDARG
// naming `desc`.Format otherwise.
HRESULT checkViewFormat(const char* call, const char* desc, DXGI_FORMAT viewFormat, const Texture& t, bool depthView);
// D3D11_DEPTH_STENCIL_VIEW_DESC.Flags for a view of `viewFormat`: read-only depth, and read-only
// stencil where the format has stencil; E_INVALIDARG naming the field (`at` ends with "DESC.").
HRESULT checkDepthViewFlags(const std::string& at, UINT flags, DXGI_FORMAT viewFormat);
// CreateTexture2D's checks of a multisampled description (resources_multisample.cpp).
HRESULT checkMultisampleDesc(const D3D11_TEXTURE2D_DESC& d, bool hasData);
// CreateTexture2D's usage rules (resources.cpp) and its full mip chain.
HRESULT checkUsage(const char* call, const char* desc, D3D11_USAGE usage, UINT bind, UINT cpu, bool hasData);
int fullMipCount(UINT width, UINT height);
// Array textures (resources_array.cpp): CreateTexture2D with ArraySize > 1 (no TEXTURECUBE), and
// the TEXTURE2DARRAY shader-resource and render-target views of them.
HRESULT createTextureArray(Device* device, const D3D11_TEXTURE2D_DESC& d, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Texture2D** pp);
HRESULT arrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp);
HRESULT arrayRenderTargetView(Device* device, Texture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp);
HRESULT arrayDepthStencilView(Device* device, Texture* t, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc, ID3D11DepthStencilView** pp);
// The slices [first, first + count) a view names, inside the texture's `slices`: E_INVALIDARG
// naming `at`FirstArraySlice + ArraySize otherwise.
HRESULT checkSlices(const std::string& at, UINT first, UINT count, int slices);
// TEXTURE2DMSARRAY views of a multisampled array (resources_multisample_array.cpp).
HRESULT multisampleArrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp);
HRESULT multisampleArrayRenderTargetView(Device* device, Texture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp);
// One subresource of a 2D texture or array (texture_subresources.cpp): which level and slice D3D's
// index names, and its texels, tightly packed, from wherever the texture keeps them (GPU or staging).
struct Subresource {
    int level = 0, slice = 0;
};
bool splitSubresource(const Texture& t, UINT index, Subresource& out);  // false: past the last
std::vector<std::uint8_t> readSubresource(Texture& t, Subresource s);
// The same into `texels` (resized; its memory reused when it has the room).
void readSubresourceInto(Texture& t, Subresource s, std::vector<std::uint8_t>& texels);
// `area` (null: the whole level) of subresource `s` from tightly packed texels.
void writeSubresource(Texture& t, Subresource s, const Rectangle* area, const std::vector<std::uint8_t>& packed);
// CreateShaderResourceView of a 3D texture (resources_3d.cpp).
HRESULT volumeShaderResourceView(Device* device, Volume* v, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp);

// 1D textures (resources_1d.cpp, line_subresources.cpp): their views, and the context's Map,
// UpdateSubresource and copies of them (D3D's checks of the call done by the caller).
HRESULT lineShaderResourceView(Device* device, LineTexture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp);
HRESULT lineUnorderedAccessView(Device* device, LineTexture* t, const D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc, ID3D11UnorderedAccessView** pp);
// Render-target and depth-stencil views of rows of a 1D texture (line_targets.cpp).
HRESULT lineRenderTargetView(Device* device, LineTexture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp);
HRESULT lineDepthStencilView(Device* device, LineTexture* t, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc, ID3D11DepthStencilView** pp);
std::vector<std::uint8_t> readLine(LineTexture& t, int subresource);
void writeLine(LineTexture& t, int subresource, int x, const std::uint8_t* texels, int count);
HRESULT mapLine(LineTexture& t, UINT subresource, D3D11_MAPPED_SUBRESOURCE& out);
HRESULT unmapLine(LineTexture& t, UINT subresource);
HRESULT updateLine(LineTexture& t, UINT subresource, const D3D11_BOX* box, const void* data);
HRESULT copyLines(LineTexture& destination, LineTexture& source);
HRESULT copyLineRegion(LineTexture& destination, UINT destinationSub, UINT x, LineTexture& source, UINT sourceSub, const D3D11_BOX* box);

// --- a compiled-shader blob's content (compile.cpp)
std::string narrowPath(const wchar_t* path);  // UTF-8; null gives ""
// A blob starts with one line saying what D3DCompile made: a shader (vs_*, ps_* ... targets) or a
// whole effect (fx_* targets); the compiled effect's text follows.
enum class BlobKind { Shader, Effect };
std::shared_ptr<const xlate::CompiledEffect> effectFromBytecode(const void* bytecode, SIZE_T length, std::string& error,
                                                                BlobKind* kind = nullptr);
std::string shaderBlob(const xlate::CompiledEffect& shader);  // the bytes of a shader blob

class Context;

// An ID3D11Query or ID3D11Predicate (queries.cpp): the GPU query behind it (none for TIMESTAMP_DISJOINT).
class Query final : public Object<ID3D11Predicate> {
public:
    Query(Device* device, const D3D11_QUERY_DESC& desc);
    UINT GetDataSize() override;
    void GetDesc(D3D11_QUERY_DESC* pDesc) override { if (pDesc) *pDesc = desc; }
    D3D11_QUERY_DESC desc;
    std::unique_ptr<core::GpuQuery> gpu;
    bool begun = false;  // between Begin and End (occlusion and disjoint queries)
    bool ended = false;  // End has been called since the last Begin
    core::StreamOutputCounts atBegin, atEnd;  // a stream-output query's readings of the core's counts
};

class Device final : public ID3D11Device {
public:
    Device();
    ~Device() override;
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override;
    // ID3D11Device, and IDXGIDevice(1) through dxgi() (dxgi_device.cpp).
    HRESULT QueryInterface(REFIID riid, void** ppvObject) override;

    HRESULT CreateBuffer(const D3D11_BUFFER_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Buffer** ppBuffer) override;
    HRESULT CreateTexture1D(const D3D11_TEXTURE1D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                            ID3D11Texture1D** ppTexture1D) override;  // resources_1d.cpp
    HRESULT CreateTexture2D(const D3D11_TEXTURE2D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                            ID3D11Texture2D** ppTexture2D) override;
    HRESULT CreateTexture3D(const D3D11_TEXTURE3D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                            ID3D11Texture3D** ppTexture3D) override;
    HRESULT CreateShaderResourceView(ID3D11Resource* pResource, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc,
                                     ID3D11ShaderResourceView** ppSRView) override;
    HRESULT CreateRenderTargetView(ID3D11Resource* pResource, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc,
                                   ID3D11RenderTargetView** ppRTView) override;
    HRESULT CreateDepthStencilView(ID3D11Resource* pResource, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc,
                                   ID3D11DepthStencilView** ppDepthStencilView) override;
    HRESULT CreateUnorderedAccessView(ID3D11Resource* pResource, const D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc,
                                      ID3D11UnorderedAccessView** ppUAView) override;
    HRESULT CreateInputLayout(const D3D11_INPUT_ELEMENT_DESC* pInputElementDescs, UINT NumElements,
                              const void* pShaderBytecodeWithInputSignature, SIZE_T BytecodeLength,
                              ID3D11InputLayout** ppInputLayout) override;
    HRESULT CreateVertexShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                               ID3D11VertexShader** ppVertexShader) override;
    HRESULT CreatePixelShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                              ID3D11PixelShader** ppPixelShader) override;
    HRESULT CreateGeometryShader(const void*, SIZE_T, ID3D11ClassLinkage*, ID3D11GeometryShader** pp) override;
    HRESULT CreateGeometryShaderWithStreamOutput(const void*, SIZE_T, const D3D11_SO_DECLARATION_ENTRY*, UINT, const UINT*, UINT, UINT,
                                                 ID3D11ClassLinkage*, ID3D11GeometryShader** pp) override;  // stream_output.cpp
    HRESULT CreateHullShader(const void*, SIZE_T, ID3D11ClassLinkage*, ID3D11HullShader** pp) override;
    HRESULT CreateDomainShader(const void*, SIZE_T, ID3D11ClassLinkage*, ID3D11DomainShader** pp) override;
    HRESULT CreateComputeShader(const void*, SIZE_T, ID3D11ClassLinkage*, ID3D11ComputeShader** pp) override;
    HRESULT CreateSamplerState(const D3D11_SAMPLER_DESC* pSamplerDesc, ID3D11SamplerState** ppSamplerState) override;
    HRESULT CreateBlendState(const D3D11_BLEND_DESC* pBlendStateDesc, ID3D11BlendState** ppBlendState) override;
    HRESULT CreateRasterizerState(const D3D11_RASTERIZER_DESC* pRasterizerDesc, ID3D11RasterizerState** ppRasterizerState) override;
    HRESULT CreateDepthStencilState(const D3D11_DEPTH_STENCIL_DESC* pDepthStencilDesc,
                                    ID3D11DepthStencilState** ppDepthStencilState) override;
    HRESULT CreateQuery(const D3D11_QUERY_DESC* pQueryDesc, ID3D11Query** ppQuery) override;
    HRESULT CreatePredicate(const D3D11_QUERY_DESC* pPredicateDesc, ID3D11Predicate** ppPredicate) override;
    HRESULT CreateDeferredContext(UINT ContextFlags, ID3D11DeviceContext** ppDeferredContext) override;
    void GetImmediateContext(ID3D11DeviceContext** ppImmediateContext) override;
    D3D_FEATURE_LEVEL GetFeatureLevel() override { return D3D_FEATURE_LEVEL_11_0; }
    HRESULT CheckFormatSupport(DXGI_FORMAT Format, UINT* pFormatSupport) override;  // format_support.cpp
    HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT Format, UINT SampleCount, UINT* pNumQualityLevels) override;
    HRESULT CheckFeatureSupport(D3D11_FEATURE Feature, void* pFeatureSupportData, UINT FeatureSupportDataSize) override;
    UINT GetCreationFlags() override { return creationFlags; }
    HRESULT GetDeviceRemovedReason() override { return S_OK; }
    UINT creationFlags = 0;  // D3D11CreateDevice's Flags

    GraphicsDevice& core() { return *core_; }
    Context& context() { return *context_; }
    DxgiDevice& dxgi();  // the device's IDXGIDevice (dxgi_device.cpp)

private:
    std::atomic<ULONG> references_{1};
    std::unique_ptr<GraphicsDevice> core_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<DxgiDevice> dxgi_;
};

template <class Interface>
void Object<Interface>::GetDevice(ID3D11Device** ppDevice) {
    if (!ppDevice) return;
    device_->AddRef();
    *ppDevice = device_;
}

}  // namespace fxport::d3d11
