// Direct3D 10's device with D3D10's names. D3D10 has no device context: the device itself takes
// the pipeline calls (IASetInputLayout, DrawIndexed ...), which D3D11 moved to its immediate
// context. fxport's ID3D10Device is a thin adapter over one D3D11 device and its immediate
// context -- one implementation underneath -- and D3D10's resources, views, shaders and state
// objects are D3D11's (ID3D10Texture2D is ID3D11Texture2D ...), so either API's calls take them.
// ID3D10Buffer::Map/Unmap map on the buffer (through the immediate context underneath); queries
// and predicates are D3D10's own objects (Begin, End and GetData on the query) over D3D11's.
// Missing here: ID3D10Texture2D::Map (use fxport's D3D11 context: GetD3D11Context()).
#pragma once

#include "fxport/d3d10/d3d10_types.h"
#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d10 {

using ID3D10DeviceChild = ID3D11DeviceChild;
using ID3D10Resource = ID3D11Resource;
using ID3D10Buffer = ID3D11Buffer;
using ID3D10Texture1D = ID3D11Texture1D;
using ID3D10Texture2D = ID3D11Texture2D;
using ID3D10View = ID3D11View;
using ID3D10ShaderResourceView = ID3D11ShaderResourceView;
using ID3D10RenderTargetView = ID3D11RenderTargetView;
using ID3D10DepthStencilView = ID3D11DepthStencilView;
using ID3D10InputLayout = ID3D11InputLayout;
using ID3D10VertexShader = ID3D11VertexShader;
using ID3D10PixelShader = ID3D11PixelShader;
using ID3D10GeometryShader = ID3D11GeometryShader;
using ID3D10SamplerState = ID3D11SamplerState;
using ID3D10RasterizerState = ID3D11RasterizerState;
using ID3D10DepthStencilState = ID3D11DepthStencilState;

// D3D10's queries: Begin, End and GetData are the query's own calls (D3D11 moved them to the
// context). GetData answers S_FALSE until the result is there, then S_OK with it in pData.
class ID3D10Asynchronous : public ID3D10DeviceChild {
public:
    virtual void Begin() = 0;
    virtual void End() = 0;
    virtual HRESULT GetData(void* pData, UINT DataSize, UINT GetDataFlags) = 0;
    virtual UINT GetDataSize() = 0;
};
class ID3D10Query : public ID3D10Asynchronous {
public:
    virtual void GetDesc(D3D10_QUERY_DESC* pDesc) = 0;
};
class ID3D10Predicate : public ID3D10Query {};

// D3D10's blend state keeps its own description (D3D10_BLEND_DESC); it binds as the D3D11 one
// made from it.
class ID3D10BlendState : public ID3D10DeviceChild {
public:
    virtual void GetDesc(D3D10_BLEND_DESC* pDesc) = 0;
};

class ID3D10Device : public IUnknown {
public:
    // --- resources, views, shaders and states (D3D11's checks and messages)
    virtual HRESULT CreateBuffer(const D3D10_BUFFER_DESC* pDesc, const D3D10_SUBRESOURCE_DATA* pInitialData, ID3D10Buffer** ppBuffer) = 0;
    virtual HRESULT CreateTexture1D(const D3D10_TEXTURE1D_DESC* pDesc, const D3D10_SUBRESOURCE_DATA* pInitialData,
                                    ID3D10Texture1D** ppTexture1D) = 0;
    virtual HRESULT CreateTexture2D(const D3D10_TEXTURE2D_DESC* pDesc, const D3D10_SUBRESOURCE_DATA* pInitialData,
                                    ID3D10Texture2D** ppTexture2D) = 0;
    virtual HRESULT CreateShaderResourceView(ID3D10Resource* pResource, const D3D10_SHADER_RESOURCE_VIEW_DESC* pDesc,
                                             ID3D10ShaderResourceView** ppSRView) = 0;
    virtual HRESULT CreateRenderTargetView(ID3D10Resource* pResource, const D3D10_RENDER_TARGET_VIEW_DESC* pDesc,
                                           ID3D10RenderTargetView** ppRTView) = 0;
    virtual HRESULT CreateDepthStencilView(ID3D10Resource* pResource, const D3D10_DEPTH_STENCIL_VIEW_DESC* pDesc,
                                           ID3D10DepthStencilView** ppDepthStencilView) = 0;
    virtual HRESULT CreateInputLayout(const D3D10_INPUT_ELEMENT_DESC* pInputElementDescs, UINT NumElements,
                                      const void* pShaderBytecodeWithInputSignature, SIZE_T BytecodeLength,
                                      ID3D10InputLayout** ppInputLayout) = 0;
    virtual HRESULT CreateVertexShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D10VertexShader** ppVertexShader) = 0;
    virtual HRESULT CreatePixelShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D10PixelShader** ppPixelShader) = 0;
    virtual HRESULT CreateGeometryShader(const void* pShaderBytecode, SIZE_T BytecodeLength, ID3D10GeometryShader** ppGeometryShader) = 0;
    virtual HRESULT CreateGeometryShaderWithStreamOutput(const void* pShaderBytecode, SIZE_T BytecodeLength,
                                                         const D3D10_SO_DECLARATION_ENTRY* pSODeclaration, UINT NumEntries,
                                                         UINT OutputStreamStride, ID3D10GeometryShader** ppGeometryShader) = 0;
    virtual HRESULT CreateBlendState(const D3D10_BLEND_DESC* pBlendStateDesc, ID3D10BlendState** ppBlendState) = 0;
    virtual HRESULT CreateDepthStencilState(const D3D10_DEPTH_STENCIL_DESC* pDepthStencilDesc,
                                            ID3D10DepthStencilState** ppDepthStencilState) = 0;
    virtual HRESULT CreateRasterizerState(const D3D10_RASTERIZER_DESC* pRasterizerDesc, ID3D10RasterizerState** ppRasterizerState) = 0;
    virtual HRESULT CreateSamplerState(const D3D10_SAMPLER_DESC* pSamplerDesc, ID3D10SamplerState** ppSamplerState) = 0;

    // --- the pipeline (D3D11's immediate-context calls, without class instances)
    virtual void IASetInputLayout(ID3D10InputLayout* pInputLayout) = 0;
    virtual void IASetVertexBuffers(UINT StartSlot, UINT NumBuffers, ID3D10Buffer* const* ppVertexBuffers, const UINT* pStrides,
                                    const UINT* pOffsets) = 0;
    virtual void IASetIndexBuffer(ID3D10Buffer* pIndexBuffer, DXGI_FORMAT Format, UINT Offset) = 0;
    virtual void IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY Topology) = 0;
    virtual void VSSetShader(ID3D10VertexShader* pVertexShader) = 0;
    virtual void PSSetShader(ID3D10PixelShader* pPixelShader) = 0;
    virtual void GSSetShader(ID3D10GeometryShader* pShader) = 0;
    virtual void VSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D10Buffer* const* ppConstantBuffers) = 0;
    virtual void PSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D10Buffer* const* ppConstantBuffers) = 0;
    virtual void GSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D10Buffer* const* ppConstantBuffers) = 0;
    virtual void VSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D10ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void PSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D10ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void GSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D10ShaderResourceView* const* ppShaderResourceViews) = 0;
    virtual void VSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D10SamplerState* const* ppSamplers) = 0;
    virtual void PSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D10SamplerState* const* ppSamplers) = 0;
    virtual void GSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D10SamplerState* const* ppSamplers) = 0;
    virtual void RSSetViewports(UINT NumViewports, const D3D10_VIEWPORT* pViewports) = 0;
    virtual void RSSetScissorRects(UINT NumRects, const D3D10_RECT* pRects) = 0;
    virtual void RSSetState(ID3D10RasterizerState* pRasterizerState) = 0;
    virtual void OMSetRenderTargets(UINT NumViews, ID3D10RenderTargetView* const* ppRenderTargetViews,
                                    ID3D10DepthStencilView* pDepthStencilView) = 0;
    virtual void OMSetBlendState(ID3D10BlendState* pBlendState, const FLOAT BlendFactor[4], UINT SampleMask) = 0;
    virtual void OMSetDepthStencilState(ID3D10DepthStencilState* pDepthStencilState, UINT StencilRef) = 0;
    virtual void Draw(UINT VertexCount, UINT StartVertexLocation) = 0;
    virtual void DrawIndexed(UINT IndexCount, UINT StartIndexLocation, INT BaseVertexLocation) = 0;
    virtual void DrawInstanced(UINT VertexCountPerInstance, UINT InstanceCount, UINT StartVertexLocation, UINT StartInstanceLocation) = 0;
    virtual void DrawIndexedInstanced(UINT IndexCountPerInstance, UINT InstanceCount, UINT StartIndexLocation, INT BaseVertexLocation,
                                      UINT StartInstanceLocation) = 0;
    virtual void DrawAuto() = 0;
    virtual void SOSetTargets(UINT NumBuffers, ID3D10Buffer* const* ppSOTargets, const UINT* pOffsets) = 0;
    virtual void SOGetTargets(UINT NumBuffers, ID3D10Buffer** ppSOTargets, UINT* pOffsets) = 0;
    virtual void ClearRenderTargetView(ID3D10RenderTargetView* pRenderTargetView, const FLOAT ColorRGBA[4]) = 0;
    virtual void ClearDepthStencilView(ID3D10DepthStencilView* pDepthStencilView, UINT ClearFlags, FLOAT Depth, UINT8 Stencil) = 0;
    virtual void UpdateSubresource(ID3D10Resource* pDstResource, UINT DstSubresource, const D3D10_BOX* pDstBox, const void* pSrcData,
                                   UINT SrcRowPitch, UINT SrcDepthPitch) = 0;
    virtual void CopyResource(ID3D10Resource* pDstResource, ID3D10Resource* pSrcResource) = 0;
    virtual void CopySubresourceRegion(ID3D10Resource* pDstResource, UINT DstSubresource, UINT DstX, UINT DstY, UINT DstZ,
                                       ID3D10Resource* pSrcResource, UINT SrcSubresource, const D3D10_BOX* pSrcBox) = 0;
    virtual void GenerateMips(ID3D10ShaderResourceView* pShaderResourceView) = 0;
    virtual void ClearState() = 0;
    virtual void Flush() = 0;
    virtual HRESULT CreateQuery(const D3D10_QUERY_DESC* pQueryDesc, ID3D10Query** ppQuery) = 0;
    virtual HRESULT CreatePredicate(const D3D10_QUERY_DESC* pPredicateDesc, ID3D10Predicate** ppPredicate) = 0;
    virtual void SetPredication(ID3D10Predicate* pPredicate, BOOL PredicateValue) = 0;
    virtual void GetPredication(ID3D10Predicate** ppPredicate, BOOL* pPredicateValue) = 0;
    // As ID3D11Device's (D3D10_FORMAT_SUPPORT has D3D11_FORMAT_SUPPORT's bits).
    virtual HRESULT CheckFormatSupport(DXGI_FORMAT Format, UINT* pFormatSupport) = 0;
    virtual HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT Format, UINT SampleCount, UINT* pNumQualityLevels) = 0;
    virtual UINT GetCreationFlags() = 0;
    virtual HRESULT GetDeviceRemovedReason() = 0;

    // fxport: the D3D11 device and immediate context underneath (no reference added), for what
    // D3D10 does on resources (Map) and for mixing the two APIs.
    virtual ID3D11Device* GetD3D11Device() = 0;
    virtual ID3D11DeviceContext* GetD3D11Context() = 0;
};

// A headless device (as D3D11CreateDevice). pAdapter and Software must be null; DriverType
// HARDWARE, REFERENCE or WARP all mean the same GL driver.
HRESULT D3D10CreateDevice(void* pAdapter, D3D10_DRIVER_TYPE DriverType, void* Software, UINT Flags, UINT SDKVersion, ID3D10Device** ppDevice);
// The same, and a headless swap chain (dxgi.h) of pSwapChainDesc->BufferDesc's size and format.
HRESULT D3D10CreateDeviceAndSwapChain(void* pAdapter, D3D10_DRIVER_TYPE DriverType, void* Software, UINT Flags, UINT SDKVersion,
                                      const DXGI_SWAP_CHAIN_DESC* pSwapChainDesc, IDXGISwapChain** ppSwapChain, ID3D10Device** ppDevice);

}  // namespace fxport::d3d10
