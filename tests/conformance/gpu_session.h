// The GPU side of one (file, shader model) run, through fxport's public runtime API only: a
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
#include "probe.h"
#include "resource_desc.h"

namespace fxport {
class Effect;
class GraphicsDevice;
class RenderTarget2D;
class Texture2D;
}

namespace conformance {

// Something the runtime cannot do (yet): a skip with this reason, never a pass or a failure.
struct Unsupported : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct DrawCall {
    std::string topology = "triangle list";  // triangle list, triangle strip, point list
    int vertexCount = 3;
    bool quad = false;  // vkd3d's "draw quad": one big triangle from float2 positions
};

class GpuSession {
public:
    GpuSession();
    ~GpuSession();

    void setResource(const ResourceDesc& resource);  // srv/rtv/dsv/vb (uav throws Unsupported)
    void setSampler(const SamplerDesc& sampler) { samplers_[sampler.slot] = sampler; }
    void setInputLayout(std::vector<InputElement> layout) { inputLayout_ = std::move(layout); }
    void clearTarget(int slot, const float rgba[4]);
    // Binds textures and samplers for `effect` (texture and sampler parameters in declaration order
    // = registers t/s; explicit register(tN)/register(sN) in `source` win) and draws.
    void draw(fxport::Effect& effect, const std::string& source, int model, const DrawCall& call);
    // Reads one texel of render target `slot` as 32-bit words.
    Texel readTexel(int slot, int x, int y);
    bool hasTarget(int slot) const;

    fxport::GraphicsDevice& device();

private:
    void ensureDefaultTarget();
    void makeTarget(const ResourceDesc& r);
    void makeTexture(const ResourceDesc& r);
    void bindTargets();
    void bindTextures(fxport::Effect& effect, const std::string& source, int model);
    void drawVertices(const DrawCall& call);

    std::unique_ptr<fxport::GraphicsDevice> device_;
    std::map<int, std::unique_ptr<fxport::RenderTarget2D>> targets_;
    std::map<int, std::unique_ptr<fxport::Texture2D>> textures_;
    std::map<int, std::string> unsupportedTextures_;  // slot -> why it could not be made
    std::map<int, std::string> unsupportedTargets_;
    std::map<int, SamplerDesc> samplers_;
    std::map<int, ResourceDesc> vertexBuffers_;
    std::vector<InputElement> inputLayout_;
    std::map<int, std::vector<fxport::Vector4>> readback_;  // per target, since the last draw or clear
};

}  // namespace conformance
