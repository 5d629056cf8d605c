// The D3D11 session (SM 4.0/5.0), through fxport's public D3D11 API only, as vkd3d's own d3d11
// runner does it: each stage's section compiled with D3DCompile (entry `main`, the model's
// profile) and made with Create*Shader; the `uniform` words as constant buffer 0 of every stage;
// [rtv]/[srv]/[uav] as textures and buffers with their DXGI formats and views; [sampler] as sampler
// states; [vb] and [input layout] as vertex buffers in their slots and an input layout; probes read
// through staging copies and Map. What fxport's D3D11 front end refuses is remembered with its
// message (GetLastErrorMessage) and skips the draw or probe that needs it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "d3d11_descs.h"
#include "gpu_backend.h"

namespace conformance {

class D3d11Session : public GpuBackend {
public:
    explicit D3d11Session(int model);
    ~D3d11Session() override;

    void setResource(const ResourceDesc& resource) override;
    void setSampler(const SamplerDesc& sampler) override;
    void setInputLayout(std::vector<InputElement> layout) override { layout_ = std::move(layout); }
    void clearTarget(int slot, const float rgba[4]) override;
    void setFixedFunction(const FixedFunctionDesc& states) override { fixedFunction_ = states.firstSet(); }
    void setSampleMask(unsigned mask) override { sampleMask_ = mask; }
    void copyResource(const std::string& fromKind, int fromSlot, const std::string& toKind, int toSlot) override;
    std::string draw(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, const DrawCall& call) override;
    std::string dispatch(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, int x, int y, int z) override;
    Texel readTexel(int slot, int x, int y) override;
    Texel readUav(int slot, int x, int y) override;

private:
    std::string fixedFunction_;  // a D3D9 fixed-function state the next draw needs ("" none)
    unsigned sampleMask_ = 0xffffffffu;  // OMSetBlendState's SampleMask
    template <class T> using ComPtr = fxport::d3d11::ComPtr<T>;
    struct Texture {  // a render target, or a UAV's texture
        ResourceDesc desc;
        ComPtr<fxport::d3d11::ID3D11Texture2D> texture;
        ComPtr<fxport::d3d11::ID3D11RenderTargetView> rtv;
        std::vector<std::uint32_t> readback;  // level 0's words, since the last draw or clear
    };
    struct Uav {
        ResourceDesc desc;
        ComPtr<fxport::d3d11::ID3D11Resource> resource;
        ComPtr<fxport::d3d11::ID3D11UnorderedAccessView> view;
        std::vector<std::uint32_t> readback;
    };
    struct Shader {  // one compiled stage
        ComPtr<fxport::d3d11::ID3DBlob> code;
        ComPtr<fxport::d3d11::ID3D11DeviceChild> object;  // the ID3D11*Shader
    };

    // d3d11_session_resources.cpp
    void makeTarget(const ResourceDesc& r);
    void makeTexture(const ResourceDesc& r);
    void makeBufferSrv(const ResourceDesc& r);
    void makeUav(const ResourceDesc& r);
    ComPtr<fxport::d3d11::ID3D11Buffer> makeBuffer(const ResourceDesc& r, fxport::d3d11::UINT bind);
    void ensureDefaultTarget();
    ComPtr<fxport::d3d11::ID3D11Resource> resourceOf(const std::string& kind, int slot);
    ComPtr<fxport::d3d11::ID3D11Resource> resolved(fxport::d3d11::ID3D11Texture2D* texture);
    ComPtr<fxport::d3d11::ID3D11Resource> stagingFor(fxport::d3d11::ID3D11Resource* resource, const ResourceDesc& desc,
                                                     std::size_t& rowBytes, std::size_t& rows);
    // Level 0 (or the buffer) into `words`, whose memory is reused from one read-back to the next.
    void readBack(fxport::d3d11::ID3D11Resource* resource, const ResourceDesc& desc, std::vector<std::uint32_t>& words);
    void forgetReadbacks();

    // d3d11_session.cpp
    const Shader& shaderOf(const StageSource& stage, const RequireDesc& require);
    void setShaders(const ShaderSet& shaders);
    void bindStageResources(Stage stage);
    void setUniforms(const std::vector<std::uint32_t>& uniforms);
    void bindTargets();
    void setInputs(const ShaderSet& shaders, const DrawCall& call);
    void throwIfUnmade(const std::map<int, std::string>& unmade) const;

    int model_;
    ComPtr<fxport::d3d11::ID3D11Device> device_;
    ComPtr<fxport::d3d11::ID3D11DeviceContext> context_;
    std::map<int, Texture> targets_;
    std::map<int, ComPtr<fxport::d3d11::ID3D11ShaderResourceView>> srvs_;
    std::map<int, Uav> uavs_;
    std::map<int, ComPtr<fxport::d3d11::ID3D11SamplerState>> samplers_;
    std::map<int, std::string> unmadeTargets_, unmadeSrvs_, unmadeUavs_, unmadeSamplers_;  // slot -> why
    std::map<int, ResourceDesc> vertexBuffers_;
    std::vector<InputElement> layout_;
    std::map<std::string, Shader> shaders_;  // by stage, packing and source
    ComPtr<fxport::d3d11::ID3D11Buffer> constants_;
    std::vector<std::uint32_t> constantWords_;  // what constants_ holds
    struct StagingCopy {
        ComPtr<fxport::d3d11::ID3D11Resource> resource;  // held: its address keys the map
        ComPtr<fxport::d3d11::ID3D11Resource> staging;
        std::size_t rowBytes = 0, rows = 0;
    };
    std::map<fxport::d3d11::ID3D11Resource*, StagingCopy> stagingCopies_;  // readBack()'s, per resource
};

}  // namespace conformance
