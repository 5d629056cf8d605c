// The XNA session's device objects (xna_session.h draws with them), through fxport's public XNA API only: a
// headless GraphicsDevice (OSMesa), render targets for [rtv N] (or vkd3d's default 640x480
// r32g32b32a32-float one), textures for [srv N], sampler states for [sampler N], vertex buffers and
// draws. What the API cannot express throws Unsupported with the reason, which the run reports as
// a skip; runtime errors (a shader that will not compile or link) surface as other exceptions.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fxport/math.h"
#include "fxport/xlate/compiled_effect.h"
#include "gpu_backend.h"
#include "probe.h"
#include "resource_desc.h"

namespace fxport {
class Effect;
class GraphicsDevice;
class RenderTarget2D;
class StructuredBuffer;
class Texture;
class Texture2D;
}

namespace conformance {

class GpuSession {
public:
    GpuSession();
    ~GpuSession();

    void setResource(const ResourceDesc& resource);  // srv/rtv/dsv/vb/uav (what cannot be made throws Unsupported)
    void setSampler(const SamplerDesc& sampler) { samplers_[sampler.slot] = sampler; }
    void setInputLayout(std::vector<InputElement> layout) { inputLayout_ = std::move(layout); }
    void setFixedFunction(const FixedFunctionDesc& states) { fixedFunction_ = states; }
    void setSampleMask(unsigned mask) { sampleMask_ = mask; }
    void clearTarget(int slot, const float rgba[4]);
    // Binds textures and samplers for `effect` (texture and sampler parameters in declaration order
    // = registers t/s; explicit register(tN)/register(sN) in `source` win) and draws.
    void draw(fxport::Effect& effect, const std::string& source, int model, const DrawCall& call);
    // Binds what `effect` needs and runs its compute shader over x*y*z groups.
    void dispatch(fxport::Effect& effect, const std::string& source, int model, int x, int y, int z);
    // Reads one texel of render target `slot` as 32-bit words.
    Texel readTexel(int slot, int x, int y);
    // One element of UAV `slot`: a texel of a texture (x, y) or element x of a buffer (its first
    // four words), as 32-bit words.
    Texel readUav(int slot, int x, int y);
    bool hasTarget(int slot) const;

    fxport::GraphicsDevice& device();

private:
    FixedFunctionDesc fixedFunction_;
    unsigned sampleMask_ = 0xffffffffu;  // BlendState::MultiSampleMask for the draws
    void ensureDefaultTarget();
    void makeTarget(const ResourceDesc& r);
    void makeTexture(const ResourceDesc& r);
    void makeCube(const ResourceDesc& r);
    void makeVolume(const ResourceDesc& r);
    void bindTargets();
    void bindTextures(fxport::Effect& effect, const std::string& source, int model);
    void bindD3d9Sampler(const fxport::xlate::SamplerBinding& binding, int model, bool texture);
    void bindD3d9Textures(fxport::Effect& effect, int model);  // after Apply(): SM 1-3 textures by register
    void drawVertices(const DrawCall& call);
    void makeUav(const ResourceDesc& r);
    void makeBufferSrv(const ResourceDesc& r);
    void bindStorage();  // [uav N] and buffer [srv N] into the device's slots (UAVs it could not make: Unsupported)

    std::unique_ptr<fxport::GraphicsDevice> device_;
    std::map<int, std::unique_ptr<fxport::RenderTarget2D>> targets_;
    std::map<int, std::unique_ptr<fxport::Texture>> textures_;  // 2D, cube and 3D
    std::map<int, std::string> unsupportedTextures_;  // slot -> why it could not be made
    std::map<int, std::string> unsupportedTargets_;
    std::map<int, SamplerDesc> samplers_;
    std::map<int, ResourceDesc> vertexBuffers_;
    std::vector<InputElement> inputLayout_;
    std::map<int, std::vector<fxport::Vector4>> readback_;  // per target, since the last draw or clear
    struct Uav {
        ResourceDesc desc;
        std::unique_ptr<fxport::RenderTarget2D> texture;    // 2d float formats
        std::unique_ptr<fxport::StructuredBuffer> buffer;   // structured and raw buffers
    };
    std::map<int, Uav> uavs_;
    std::map<int, std::string> unsupportedUavs_;  // slot -> why it could not be made
    std::map<int, std::unique_ptr<fxport::StructuredBuffer>> srvBuffers_;  // structured/raw [srv N]
};

}  // namespace conformance
