// Direct3D 11's interfaces with D3D's names and signatures: IUnknown reference counting, the device
// (resources, views, shaders, state objects), the immediate context and D3D11CreateDevice. Objects
// are made by the device with a reference count of 1 and freed by their last Release(); ComPtr
// (com_ptr.h) does that for you. Calls fxport does not implement yet return E_NOTIMPL (and void
// ones do nothing) with GetLastErrorMessage() saying so.
#pragma once

#include "fxport/d3d11/com_identity.h"
#include "fxport/d3d11/d3d11_types.h"

namespace fxport::d3d11 {

class ID3D11Device;
class ID3D11ClassLinkage;
class ID3D11ClassInstance;

class IUnknown {
public:
    // Another interface of the same object, with a reference (E_NOINTERFACE and *ppvObject null
    // when it has none). Every object answers IID_IUnknown; the device answers IID_ID3D11Device and
    // IID_IDXGIDevice (dxgi.h), the DXGI objects their own interfaces.
    virtual HRESULT QueryInterface(REFIID riid, void** ppvObject);
    virtual ULONG AddRef() = 0;
    virtual ULONG Release() = 0;

protected:
    virtual ~IUnknown() = default;
};

class ID3D11DeviceChild : public IUnknown {
public:
    // Adds a reference to the device, as D3D does.
    virtual void GetDevice(ID3D11Device** ppDevice) = 0;
};

// Queries: Begin/End on the context bracket what an occlusion query counts (samples passing the
// depth and stencil tests) or a disjoint query's interval; End alone marks an event or timestamp.
// GetData returns S_FALSE until the GPU has the result, then S_OK with it in pData (DataSize must
// be GetDataSize() or 0 to ask only whether it is ready).
class ID3D11Asynchronous : public ID3D11DeviceChild {
public:
    virtual UINT GetDataSize() = 0;
};
class ID3D11Query : public ID3D11Asynchronous {
public:
    virtual void GetDesc(D3D11_QUERY_DESC* pDesc) = 0;
};
// An OCCLUSION_PREDICATE query made by CreatePredicate, for SetPredication.
class ID3D11Predicate : public ID3D11Query {};

// A deferred context's recorded commands (FinishCommandList), run by the immediate context's
// ExecuteCommandList.
class ID3D11CommandList : public ID3D11DeviceChild {
public:
    virtual UINT GetContextFlags() = 0;
};

class ID3D11Resource : public ID3D11DeviceChild {
public:
    virtual void GetType(D3D11_RESOURCE_DIMENSION* pResourceDimension) = 0;
};
class ID3D11Buffer : public ID3D11Resource {
public:
    virtual void GetDesc(D3D11_BUFFER_DESC* pDesc) = 0;
    // D3D10's spelling (fxport/d3d10.h: ID3D10Buffer is this interface): Map and Unmap on the buffer
    // itself, as ID3D10Buffer::Map(MapType, MapFlags, &data) -- the device's immediate context's
    // Map/Unmap of subresource 0, with its rules (WRITE_DISCARD on a DYNAMIC buffer, READ on a
    // STAGING one ...). D3D11 code maps through the context.
    virtual HRESULT Map(D3D11_MAP MapType, UINT MapFlags, void** ppData) = 0;
    virtual void Unmap() = 0;
};
class ID3D11Texture1D : public ID3D11Resource {
public:
    virtual void GetDesc(D3D11_TEXTURE1D_DESC* pDesc) = 0;
};
class ID3D11Texture2D : public ID3D11Resource {
public:
    virtual void GetDesc(D3D11_TEXTURE2D_DESC* pDesc) = 0;
};
class ID3D11Texture3D : public ID3D11Resource {
public:
    virtual void GetDesc(D3D11_TEXTURE3D_DESC* pDesc) = 0;
};

class ID3D11View : public ID3D11DeviceChild {
public:
    virtual void GetResource(ID3D11Resource** ppResource) = 0;
};
class ID3D11ShaderResourceView : public ID3D11View {
public:
    virtual void GetDesc(D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc) = 0;
};
class ID3D11RenderTargetView : public ID3D11View {
public:
    virtual void GetDesc(D3D11_RENDER_TARGET_VIEW_DESC* pDesc) = 0;
};
class ID3D11DepthStencilView : public ID3D11View {
public:
    virtual void GetDesc(D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc) = 0;
};
class ID3D11UnorderedAccessView : public ID3D11View {
public:
    virtual void GetDesc(D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc) = 0;
};

class ID3D11InputLayout : public ID3D11DeviceChild {};
class ID3D11VertexShader : public ID3D11DeviceChild {};
class ID3D11PixelShader : public ID3D11DeviceChild {};
class ID3D11GeometryShader : public ID3D11DeviceChild {};
class ID3D11HullShader : public ID3D11DeviceChild {};
class ID3D11DomainShader : public ID3D11DeviceChild {};
class ID3D11ComputeShader : public ID3D11DeviceChild {};

class ID3D11SamplerState : public ID3D11DeviceChild {
public:
    virtual void GetDesc(D3D11_SAMPLER_DESC* pDesc) = 0;
};
class ID3D11BlendState : public ID3D11DeviceChild {
public:
    virtual void GetDesc(D3D11_BLEND_DESC* pDesc) = 0;
};
class ID3D11RasterizerState : public ID3D11DeviceChild {
public:
    virtual void GetDesc(D3D11_RASTERIZER_DESC* pDesc) = 0;
};
class ID3D11DepthStencilState : public ID3D11DeviceChild {
public:
    virtual void GetDesc(D3D11_DEPTH_STENCIL_DESC* pDesc) = 0;
};

class ID3D11DeviceContext : public ID3D11DeviceChild {
public:
    // --- input assembler
    virtual void IASetInputLayout(ID3D11InputLayout* pInputLayout) = 0;
    virtual void IASetVertexBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppVertexBuffers,
                                    const UINT* pStrides, const UINT* pOffsets) = 0;
    virtual void IASetIndexBuffer(ID3D11Buffer* pIndexBuffer, DXGI_FORMAT Format, UINT Offset) = 0;
    virtual void IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY Topology) = 0;
    // --- shader stages
    virtual void VSSetShader(ID3D11VertexShader* pVertexShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void PSSetShader(ID3D11PixelShader* pPixelShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void GSSetShader(ID3D11GeometryShader* pShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void HSSetShader(ID3D11HullShader* pShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void DSSetShader(ID3D11DomainShader* pShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void CSSetShader(ID3D11ComputeShader* pShader, ID3D11ClassInstance* const* ppClassInstances,
                             UINT NumClassInstances) = 0;
    virtual void VSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void PSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void VSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void PSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void VSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    virtual void PSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    // The geometry, hull, domain and compute stages have their own slots, as in D3D.
    virtual void GSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void GSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void GSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    virtual void HSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void HSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void HSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    virtual void DSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void DSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void DSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    virtual void CSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) = 0;
    virtual void CSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void CSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) = 0;
    // pUAVInitialCounts (append/consume counters) is ignored: fxport has no UAV counters.
    virtual void CSSetUnorderedAccessViews(UINT StartSlot, UINT NumUAVs, ID3D11UnorderedAccessView* const* ppUnorderedAccessViews,
                                           const UINT* pUAVInitialCounts) = 0;
    // --- rasterizer and output merger
    virtual void RSSetViewports(UINT NumViewports, const D3D11_VIEWPORT* pViewports) = 0;
    virtual void RSSetScissorRects(UINT NumRects, const D3D11_RECT* pRects) = 0;
    virtual void RSSetState(ID3D11RasterizerState* pRasterizerState) = 0;
    virtual void OMSetRenderTargets(UINT NumViews, ID3D11RenderTargetView* const* ppRenderTargetViews,
                                    ID3D11DepthStencilView* pDepthStencilView) = 0;
    // Render targets and the pixel shader's UAVs, which share its output slots: the UAVs take
    // u[UAVStartSlot .. UAVStartSlot + NumUAVs), at or after the last RTV. NumRTVs =
    // D3D11_KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL keeps the targets, NumUAVs =
    // D3D11_KEEP_UNORDERED_ACCESS_VIEWS the UAVs. pUAVInitialCounts is ignored (no counters).
    virtual void OMSetRenderTargetsAndUnorderedAccessViews(UINT NumRTVs, ID3D11RenderTargetView* const* ppRenderTargetViews,
                                                           ID3D11DepthStencilView* pDepthStencilView, UINT UAVStartSlot, UINT NumUAVs,
                                                           ID3D11UnorderedAccessView* const* ppUnorderedAccessViews,
                                                           const UINT* pUAVInitialCounts) = 0;
    virtual void OMSetBlendState(ID3D11BlendState* pBlendState, const FLOAT BlendFactor[4], UINT SampleMask) = 0;
    virtual void OMSetDepthStencilState(ID3D11DepthStencilState* pDepthStencilState, UINT StencilRef) = 0;
    // --- draws
    virtual void Draw(UINT VertexCount, UINT StartVertexLocation) = 0;
    virtual void DrawIndexed(UINT IndexCount, UINT StartIndexLocation, INT BaseVertexLocation) = 0;
    virtual void DrawInstanced(UINT VertexCountPerInstance, UINT InstanceCount, UINT StartVertexLocation,
                               UINT StartInstanceLocation) = 0;
    virtual void DrawIndexedInstanced(UINT IndexCountPerInstance, UINT InstanceCount, UINT StartIndexLocation,
                                      INT BaseVertexLocation, UINT StartInstanceLocation) = 0;
    virtual void Dispatch(UINT ThreadGroupCountX, UINT ThreadGroupCountY, UINT ThreadGroupCountZ) = 0;
    // Draws the vertices stream output last wrote into the vertex buffer at slot 0 (its filled size
    // from the bound offset, divided by the bound stride).
    virtual void DrawAuto() = 0;
    // --- stream output: buffers written by a geometry shader made with stream output; an offset of
    // -1 (0xffffffff) appends where the buffer's last stream output ended.
    virtual void SOSetTargets(UINT NumBuffers, ID3D11Buffer* const* ppSOTargets, const UINT* pOffsets) = 0;
    virtual void SOGetTargets(UINT NumBuffers, ID3D11Buffer** ppSOTargets) = 0;
    // --- resources
    virtual HRESULT Map(ID3D11Resource* pResource, UINT Subresource, D3D11_MAP MapType, UINT MapFlags,
                        D3D11_MAPPED_SUBRESOURCE* pMappedResource) = 0;
    virtual void Unmap(ID3D11Resource* pResource, UINT Subresource) = 0;
    virtual void UpdateSubresource(ID3D11Resource* pDstResource, UINT DstSubresource, const D3D11_BOX* pDstBox,
                                   const void* pSrcData, UINT SrcRowPitch, UINT SrcDepthPitch) = 0;
    virtual void CopyResource(ID3D11Resource* pDstResource, ID3D11Resource* pSrcResource) = 0;
    // A region of one subresource (a byte range of a buffer: pSrcBox left..right; a rectangle of a
    // texture level) into another at (DstX, DstY, DstZ); pSrcBox null: the whole subresource.
    virtual void CopySubresourceRegion(ID3D11Resource* pDstResource, UINT DstSubresource, UINT DstX, UINT DstY, UINT DstZ,
                                       ID3D11Resource* pSrcResource, UINT SrcSubresource, const D3D11_BOX* pSrcBox) = 0;
    virtual void ClearRenderTargetView(ID3D11RenderTargetView* pRenderTargetView, const FLOAT ColorRGBA[4]) = 0;
    virtual void ClearDepthStencilView(ID3D11DepthStencilView* pDepthStencilView, UINT ClearFlags, FLOAT Depth,
                                       UINT8 Stencil) = 0;
    virtual void GenerateMips(ID3D11ShaderResourceView* pShaderResourceView) = 0;
    // A multisampled texture's pixels (each the average of its samples) into a single-sample one.
    virtual void ResolveSubresource(ID3D11Resource* pDstResource, UINT DstSubresource, ID3D11Resource* pSrcResource, UINT SrcSubresource,
                                    DXGI_FORMAT Format) = 0;
    virtual void Begin(ID3D11Asynchronous* pAsync) = 0;
    virtual void End(ID3D11Asynchronous* pAsync) = 0;
    virtual HRESULT GetData(ID3D11Asynchronous* pAsync, void* pData, UINT DataSize, UINT GetDataFlags) = 0;
    // Later draws, dispatches, clears, copies, UpdateSubresource and GenerateMips are skipped while
    // the predicate's result (any sample passed) equals PredicateValue; null: none. fxport waits for
    // the result at each such call (D3D may, too: its predicates can be hints).
    virtual void SetPredication(ID3D11Predicate* pPredicate, BOOL PredicateValue) = 0;
    virtual void GetPredication(ID3D11Predicate** ppPredicate, BOOL* pPredicateValue) = 0;
    // Unbinds everything and returns every state to D3D's default.
    virtual void ClearState() = 0;
    virtual void Flush() = 0;
    // Deferred contexts (ID3D11Device::CreateDeferredContext) record every call but GetData and
    // Flush; FinishCommandList hands the recording over (the context then starts again from D3D's
    // default state, or with RestoreDeferredContextState from the state it had); the immediate
    // context's ExecuteCommandList runs a list from the default state, then clears its state or,
    // with RestoreContextState, puts back what it had. On a deferred context, Map takes
    // WRITE_DISCARD of a DYNAMIC buffer only (the bytes are written when the list runs).
    virtual D3D11_DEVICE_CONTEXT_TYPE GetType() = 0;
    virtual void ExecuteCommandList(ID3D11CommandList* pCommandList, BOOL RestoreContextState) = 0;
    virtual HRESULT FinishCommandList(BOOL RestoreDeferredContextState, ID3D11CommandList** ppCommandList) = 0;
};

class ID3D11Device : public IUnknown {
public:
    virtual HRESULT CreateBuffer(const D3D11_BUFFER_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                                 ID3D11Buffer** ppBuffer) = 0;
    virtual HRESULT CreateTexture1D(const D3D11_TEXTURE1D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                                    ID3D11Texture1D** ppTexture1D) = 0;
    virtual HRESULT CreateTexture2D(const D3D11_TEXTURE2D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                                    ID3D11Texture2D** ppTexture2D) = 0;
    virtual HRESULT CreateTexture3D(const D3D11_TEXTURE3D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                                    ID3D11Texture3D** ppTexture3D) = 0;
    virtual HRESULT CreateShaderResourceView(ID3D11Resource* pResource, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc,
                                             ID3D11ShaderResourceView** ppSRView) = 0;
    virtual HRESULT CreateRenderTargetView(ID3D11Resource* pResource, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc,
                                           ID3D11RenderTargetView** ppRTView) = 0;
    virtual HRESULT CreateDepthStencilView(ID3D11Resource* pResource, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc,
                                           ID3D11DepthStencilView** ppDepthStencilView) = 0;
    virtual HRESULT CreateUnorderedAccessView(ID3D11Resource* pResource, const D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc,
                                              ID3D11UnorderedAccessView** ppUAView) = 0;
    virtual HRESULT CreateInputLayout(const D3D11_INPUT_ELEMENT_DESC* pInputElementDescs, UINT NumElements,
                                      const void* pShaderBytecodeWithInputSignature, SIZE_T BytecodeLength,
                                      ID3D11InputLayout** ppInputLayout) = 0;
    virtual HRESULT CreateVertexShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                       ID3D11VertexShader** ppVertexShader) = 0;
    virtual HRESULT CreatePixelShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                      ID3D11PixelShader** ppPixelShader) = 0;
    virtual HRESULT CreateGeometryShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                         ID3D11GeometryShader** ppGeometryShader) = 0;
    // A geometry shader (or, from vertex-shader bytecode, D3D's "null" geometry shader) whose output
    // vertices are written to the stream-output targets, as the declaration says.
    virtual HRESULT CreateGeometryShaderWithStreamOutput(const void* pShaderBytecode, SIZE_T BytecodeLength,
                                                         const D3D11_SO_DECLARATION_ENTRY* pSODeclaration, UINT NumEntries,
                                                         const UINT* pBufferStrides, UINT NumStrides, UINT RasterizedStream,
                                                         ID3D11ClassLinkage* pClassLinkage, ID3D11GeometryShader** ppGeometryShader) = 0;
    virtual HRESULT CreateHullShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                     ID3D11HullShader** ppHullShader) = 0;
    virtual HRESULT CreateDomainShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                       ID3D11DomainShader** ppDomainShader) = 0;
    virtual HRESULT CreateComputeShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D11ClassLinkage* pClassLinkage,
                                        ID3D11ComputeShader** ppComputeShader) = 0;
    virtual HRESULT CreateSamplerState(const D3D11_SAMPLER_DESC* pSamplerDesc, ID3D11SamplerState** ppSamplerState) = 0;
    virtual HRESULT CreateBlendState(const D3D11_BLEND_DESC* pBlendStateDesc, ID3D11BlendState** ppBlendState) = 0;
    virtual HRESULT CreateRasterizerState(const D3D11_RASTERIZER_DESC* pRasterizerDesc,
                                          ID3D11RasterizerState** ppRasterizerState) = 0;
    virtual HRESULT CreateDepthStencilState(const D3D11_DEPTH_STENCIL_DESC* pDepthStencilDesc,
                                            ID3D11DepthStencilState** ppDepthStencilState) = 0;
    virtual HRESULT CreateQuery(const D3D11_QUERY_DESC* pQueryDesc, ID3D11Query** ppQuery) = 0;
    virtual HRESULT CreatePredicate(const D3D11_QUERY_DESC* pPredicateDesc, ID3D11Predicate** ppPredicate) = 0;
    virtual HRESULT CreateDeferredContext(UINT ContextFlags, ID3D11DeviceContext** ppDeferredContext) = 0;
    virtual void GetImmediateContext(ID3D11DeviceContext** ppImmediateContext) = 0;
    virtual D3D_FEATURE_LEVEL GetFeatureLevel() = 0;
    // What the GL driver underneath can make of a format (D3D11_FORMAT_SUPPORT bits) and with how
    // many samples (1 quality level, or 0 when not); the features of a feature level 11_0 device.
    virtual HRESULT CheckFormatSupport(DXGI_FORMAT Format, UINT* pFormatSupport) = 0;
    virtual HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT Format, UINT SampleCount, UINT* pNumQualityLevels) = 0;
    virtual HRESULT CheckFeatureSupport(D3D11_FEATURE Feature, void* pFeatureSupportData, UINT FeatureSupportDataSize) = 0;
    virtual UINT GetCreationFlags() = 0;
    virtual HRESULT GetDeviceRemovedReason() = 0;  // S_OK: a GL device is never removed under the program
};

// The identifiers QueryInterface and IDXGISwapChain::GetBuffer answer (the DXGI ones are in dxgi.h).
FXPORT_INTERFACE_ID(IUnknown, 0x00000000, 0x0000, 0x0000, 0xc0, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x46)
FXPORT_INTERFACE_ID(ID3D11Device, 0xdb6f6ddb, 0xac77, 0x4e88, 0x82, 0x53, 0x81, 0x9d, 0xf9, 0xbb, 0xf1, 0x40)
FXPORT_INTERFACE_ID(ID3D11Texture2D, 0x6f15aaf2, 0xd208, 0x4e89, 0x9a, 0xb4, 0x48, 0x95, 0x35, 0xd3, 0x4f, 0x9c)

// Makes a device and its immediate context. Headless: the device draws into textures on the
// platform $FXPORT_PLATFORM names (OSMesa by default, "egl" for a GPU). pAdapter is null or the
// one adapter IDXGIFactory::EnumAdapters gives (then DriverType must be UNKNOWN, as D3D's rule);
// Software must be null; DriverType HARDWARE, UNKNOWN, WARP or REFERENCE all mean the same GL driver. The
// feature level is 11_0 (the first of pFeatureLevels it must be at most).
HRESULT D3D11CreateDevice(void* pAdapter, D3D_DRIVER_TYPE DriverType, void* Software, UINT Flags,
                          const D3D_FEATURE_LEVEL* pFeatureLevels, UINT FeatureLevels, UINT SDKVersion,
                          ID3D11Device** ppDevice, D3D_FEATURE_LEVEL* pFeatureLevel,
                          ID3D11DeviceContext** ppImmediateContext);

}  // namespace fxport::d3d11
