// The XNA session (SM 2.0/3.0): each draw's stages become an fxport Effect of loose shaders
// (Effect::FromShaderFiles), the `uniform` words reach its parameters by the D3D9/D3D10 packing
// guess of uniform_layout.h, and GpuSession's render targets, textures and buffers feed it.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "gpu_backend.h"
#include "gpu_session.h"

namespace fxport {
class Effect;
}

namespace conformance {

class XnaSession : public GpuBackend {
public:
    XnaSession(int model, SectionCompiler& compiler, std::string cacheDir);
    ~XnaSession() override;

    void setResource(const ResourceDesc& resource) override { gpu_.setResource(resource); }
    void setSampler(const SamplerDesc& sampler) override { gpu_.setSampler(sampler); }
    void setInputLayout(std::vector<InputElement> layout) override { gpu_.setInputLayout(std::move(layout)); }
    void clearTarget(int slot, const float rgba[4]) override { gpu_.clearTarget(slot, rgba); }
    void setFixedFunction(const FixedFunctionDesc& states) override { gpu_.setFixedFunction(states); }
    void setSampleMask(unsigned mask) override { gpu_.setSampleMask(mask); }
    void copyResource(const std::string&, int, const std::string&, int) override {
        throw Unsupported("copy between resources (the XNA session's targets and textures are not copied)");
    }
    std::string draw(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, const DrawCall& call) override;
    std::string dispatch(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, int x, int y, int z) override;
    Texel readTexel(int slot, int x, int y) override { return gpu_.readTexel(slot, x, y); }
    Texel readUav(int slot, int x, int y) override { return gpu_.readUav(slot, x, y); }

private:
    // An effect of loose shaders, one per stage, cached by stages and sources.
    fxport::Effect& effectOf(const ShaderSet& shaders);
    std::string applyUniforms(fxport::Effect& effect, const std::string& source, const std::vector<std::uint32_t>& uniforms);

    int model_;
    SectionCompiler& compiler_;
    std::string cacheDir_;
    GpuSession gpu_;  // declared before the effects: destroyed after them
    std::map<std::string, std::unique_ptr<fxport::Effect>> effects_;
};

}  // namespace conformance
