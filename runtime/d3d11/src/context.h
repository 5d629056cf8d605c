// INTERNAL: the immediate context: D3D's pipeline bindings, held (with a reference each) until a
// draw copies them into the device core (context.cpp).
#pragma once

#include <array>

#include "d3d11_impl.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/vertex_declaration.h"

namespace fxport::d3d11 {

// `object` as this front end's T when `device` made it; null otherwise (D3D ignores foreign objects).
template <class T, class I>
T* own(I* object, Device* device) {
    auto* t = dynamic_cast<T*>(object);
    return t && &t->device() == device ? t : nullptr;
}

class Context final : public ID3D11DeviceContext {
public:
    explicit Context(Device* device);
    ULONG AddRef() override { return device_->AddRef(); }  // lives as long as its device
    ULONG Release() override { return device_->Release(); }
    void GetDevice(ID3D11Device** ppDevice) override {
        if (!ppDevice) return;
        device_->AddRef();
        *ppDevice = device_;
    }

    void IASetInputLayout(ID3D11InputLayout* pInputLayout) override;
    void IASetVertexBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppVertexBuffers, const UINT* pStrides,
                            const UINT* pOffsets) override;
    void IASetIndexBuffer(ID3D11Buffer* pIndexBuffer, DXGI_FORMAT Format, UINT Offset) override;
    void IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY Topology) override;
    void VSSetShader(ID3D11VertexShader* pVertexShader, ID3D11ClassInstance* const*, UINT) override;
    void PSSetShader(ID3D11PixelShader* pPixelShader, ID3D11ClassInstance* const*, UINT) override;
    void GSSetShader(ID3D11GeometryShader* pShader, ID3D11ClassInstance* const*, UINT) override;
    void HSSetShader(ID3D11HullShader* pShader, ID3D11ClassInstance* const*, UINT) override;
    void DSSetShader(ID3D11DomainShader* pShader, ID3D11ClassInstance* const*, UINT) override;
    void CSSetShader(ID3D11ComputeShader* pShader, ID3D11ClassInstance* const*, UINT) override;
    void VSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void PSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void VSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void PSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void VSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void PSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void GSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void GSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void GSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void HSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void HSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void HSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void DSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void DSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void DSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void CSSetConstantBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* ppConstantBuffers) override;
    void CSSetShaderResources(UINT StartSlot, UINT NumViews, ID3D11ShaderResourceView* const* ppViews) override;
    void CSSetSamplers(UINT StartSlot, UINT NumSamplers, ID3D11SamplerState* const* ppSamplers) override;
    void CSSetUnorderedAccessViews(UINT StartSlot, UINT NumUAVs, ID3D11UnorderedAccessView* const* ppUnorderedAccessViews,
                                   const UINT* pUAVInitialCounts) override;
    void RSSetViewports(UINT NumViewports, const D3D11_VIEWPORT* pViewports) override;
    void RSSetScissorRects(UINT NumRects, const D3D11_RECT* pRects) override;
    void RSSetState(ID3D11RasterizerState* pRasterizerState) override;
    void OMSetRenderTargetsAndUnorderedAccessViews(UINT NumRTVs, ID3D11RenderTargetView* const* ppRenderTargetViews,
                                                   ID3D11DepthStencilView* pDepthStencilView, UINT UAVStartSlot, UINT NumUAVs,
                                                   ID3D11UnorderedAccessView* const* ppUnorderedAccessViews,
                                                   const UINT* pUAVInitialCounts) override;
    void OMSetRenderTargets(UINT NumViews, ID3D11RenderTargetView* const* ppRenderTargetViews,
                            ID3D11DepthStencilView* pDepthStencilView) override;
    void OMSetBlendState(ID3D11BlendState* pBlendState, const FLOAT BlendFactor[4], UINT SampleMask) override;
    void OMSetDepthStencilState(ID3D11DepthStencilState* pDepthStencilState, UINT StencilRef) override;
    void Draw(UINT VertexCount, UINT StartVertexLocation) override;
    void DrawIndexed(UINT IndexCount, UINT StartIndexLocation, INT BaseVertexLocation) override;
    void DrawInstanced(UINT VertexCountPerInstance, UINT InstanceCount, UINT StartVertexLocation, UINT StartInstanceLocation) override;
    void DrawIndexedInstanced(UINT IndexCountPerInstance, UINT InstanceCount, UINT StartIndexLocation, INT BaseVertexLocation,
                              UINT StartInstanceLocation) override;
    void Dispatch(UINT ThreadGroupCountX, UINT ThreadGroupCountY, UINT ThreadGroupCountZ) override;
    void DrawAuto() override;  // stream_output.cpp
    void SOSetTargets(UINT NumBuffers, ID3D11Buffer* const* ppSOTargets, const UINT* pOffsets) override;
    void SOGetTargets(UINT NumBuffers, ID3D11Buffer** ppSOTargets) override;
    HRESULT Map(ID3D11Resource* pResource, UINT Subresource, D3D11_MAP MapType, UINT MapFlags,
                D3D11_MAPPED_SUBRESOURCE* pMappedResource) override;
    void Unmap(ID3D11Resource* pResource, UINT Subresource) override;
    void UpdateSubresource(ID3D11Resource* pDstResource, UINT DstSubresource, const D3D11_BOX* pDstBox, const void* pSrcData,
                           UINT SrcRowPitch, UINT SrcDepthPitch) override;
    void CopyResource(ID3D11Resource* pDstResource, ID3D11Resource* pSrcResource) override;
    void CopySubresourceRegion(ID3D11Resource* pDstResource, UINT DstSubresource, UINT DstX, UINT DstY, UINT DstZ,
                               ID3D11Resource* pSrcResource, UINT SrcSubresource, const D3D11_BOX* pSrcBox) override;
    void ClearRenderTargetView(ID3D11RenderTargetView* pRenderTargetView, const FLOAT ColorRGBA[4]) override;
    void ClearDepthStencilView(ID3D11DepthStencilView* pDepthStencilView, UINT ClearFlags, FLOAT Depth, UINT8 Stencil) override;
    void GenerateMips(ID3D11ShaderResourceView* pShaderResourceView) override;
    void ResolveSubresource(ID3D11Resource* pDstResource, UINT DstSubresource, ID3D11Resource* pSrcResource, UINT SrcSubresource,
                            DXGI_FORMAT Format) override;  // resources_multisample.cpp
    void ClearState() override;
    void Flush() override;
    // Queries (queries.cpp).
    void Begin(ID3D11Asynchronous* pAsync) override;
    void End(ID3D11Asynchronous* pAsync) override;
    HRESULT GetData(ID3D11Asynchronous* pAsync, void* pData, UINT DataSize, UINT GetDataFlags) override;
    void SetPredication(ID3D11Predicate* pPredicate, BOOL PredicateValue) override;
    void GetPredication(ID3D11Predicate** ppPredicate, BOOL* pPredicateValue) override;
    // Whether SetPredication's predicate skips a predicated call now (it waits for the result).
    bool predicatedAway();
    // Command lists (deferred_context.cpp).
    D3D11_DEVICE_CONTEXT_TYPE GetType() override { return D3D11_DEVICE_CONTEXT_IMMEDIATE; }
    void ExecuteCommandList(ID3D11CommandList* pCommandList, BOOL RestoreContextState) override;
    HRESULT FinishCommandList(BOOL RestoreDeferredContextState, ID3D11CommandList** ppCommandList) override;

    // The effects framework (effect11.cpp): a pass applied on this context runs at the next draws,
    // until VSSetShader/PSSetShader, ClearState or another Apply; `owner` is its ID3DX11Effect,
    // which forgets itself here when released.
    void applyEffectPass(EffectPass* pass, const void* owner) {
        effectPass_ = pass;
        effectOwner_ = owner;
    }
    void forgetEffect(const void* owner) {
        if (effectOwner_ == owner) effectPass_ = nullptr, effectOwner_ = nullptr;
    }

private:
    // What ExecuteCommandList's RestoreContextState puts back: every binding (deferred_context.cpp).
    struct Bindings;
    Bindings bindings() const;
    void rebind(const Bindings& saved);
    // The occlusion query between Begin and End (GL counts one at a time); held, so that it counts
    // until End even if its last other reference goes.
    ComPtr<Query> counting_;
    ComPtr<Query> statistics_;  // the pipeline-statistics query between Begin and End (one at a time too)
    ComPtr<Query> predicate_;   // SetPredication's
    BOOL predicateValue_ = FALSE;
    // One shader stage's slots (each stage has its own, as in D3D).
    struct Stage {
        std::array<ComPtr<Buffer>, D3D11_COMMONSHADER_CONSTANT_BUFFER_API_SLOT_COUNT> constantBuffers;
        std::array<ComPtr<ShaderResourceView>, D3D11_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT> views;  // t0..t127; a shader's GL units are its own (SamplerBinding::unit)
        std::array<ComPtr<SamplerState>, D3D11_COMMONSHADER_SAMPLER_SLOT_COUNT> samplers;
    };
    using UavSlots = std::array<ComPtr<UnorderedAccessView>, D3D11_PS_CS_UAV_REGISTER_COUNT>;
    // Copies the bindings into the device core; false (with the reason noted) when D3D would draw
    // nothing or the draw cannot be made.
    bool prepare(const char* call);
    void bindStage(int stage, const ShaderBindings& bindings, const Stage& s);
    // The buffers and textures `code` reads and writes through t# (buffer SRVs) and u# (UAVs):
    // throws InvalidOperation naming the register when its slot holds no view of the right kind.
    void bindStorage(const char* call, const core::ShaderCode& code, const Stage& s, const UavSlots* uavs);
    void draw(const char* call, core::DrawArguments arguments, bool indexed);
    bool streams(const char* call, std::vector<core::InstancedStream>& out);

    Device* device_;
    ComPtr<InputLayout> layout_;
    struct VertexSlot {
        ComPtr<Buffer> buffer;
        UINT stride = 0, offset = 0;
    };
    std::array<VertexSlot, D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT> vertexSlots_;
    ComPtr<Buffer> indexBuffer_;
    std::array<ComPtr<Buffer>, D3D11_SO_BUFFER_SLOT_COUNT> soTargets_;  // SOSetTargets
    DXGI_FORMAT indexFormat_ = DXGI_FORMAT_UNKNOWN;
    UINT indexOffset_ = 0;
    D3D11_PRIMITIVE_TOPOLOGY topology_ = D3D11_PRIMITIVE_TOPOLOGY_UNDEFINED;
    ComPtr<VertexShader> vertexShader_;
    ComPtr<PixelShader> pixelShader_;
    ComPtr<GeometryShader> geometryShader_;
    ComPtr<HullShader> hullShader_;
    ComPtr<DomainShader> domainShader_;
    ComPtr<ComputeShader> computeShader_;
    Stage vs_, ps_, gs_, hs_, ds_, cs_;
    UavSlots csUavs_;
    UavSlots psUavs_;  // OMSetRenderTargetsAndUnorderedAccessViews: the pixel shader's u#
    // RSSetViewports / RSSetScissorRects, as the core's (index 0 first; no viewport: the whole target).
    std::vector<Viewport> viewports_;
    std::vector<Rectangle> scissors_;
    void setViewports(GraphicsDevice& core) const;  // context_draw.cpp
    ComPtr<RasterizerState> rasterizer_;
    ComPtr<BlendState> blend_;
    FLOAT blendFactor_[4] = {1, 1, 1, 1};
    UINT sampleMask_ = 0xffffffffu;
    ComPtr<DepthStencilState> depthStencil_;
    UINT stencilRef_ = 0;
    std::array<ComPtr<RenderTargetView>, D3D11_SIMULTANEOUS_RENDER_TARGET_COUNT> targets_;
    ComPtr<DepthStencilView> depthView_;
    // Device-core states for the D3D defaults (a null state object), decoded once.
    fxport::BlendState defaultBlend_;
    fxport::RasterizerState defaultRasterizer_;
    fxport::DepthStencilState defaultDepthStencil_;
    fxport::SamplerState defaultSampler_;
    std::vector<core::StreamLayout> declarations_;  // each input slot's elements and stride, made at each draw
    EffectPass* effectPass_ = nullptr;  // fxport::EffectPass (applied at each draw instead of VS/PS)
    const void* effectOwner_ = nullptr;

    // Depth-only draws (depth_only_draws.cpp): the device core draws into at least one colour
    // target and runs a pixel shader, D3D needs neither.
    RenderTarget2D& scratchTarget(int width, int height);
    const PixelShader& emptyPixelShader();
    std::unique_ptr<RenderTarget2D> scratch_;
    ComPtr<PixelShader> emptyPixelShader_;
};

}  // namespace fxport::d3d11
