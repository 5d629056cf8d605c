// What a model run asks of the GPU, whichever public API does it: the XNA session (fxport's Effect
// API, for SM 2.0/3.0: D3D9's constant registers) or the D3D11 session (fxport's D3D11 API, for
// SM 4.0/5.0: the uniform words are constant buffer 0, as vkd3d's own runner writes them). Both
// make what the resource blocks describe, draw or dispatch the stages' HLSL as given, and read
// texels back. What a session cannot express throws Unsupported with the reason, which the run
// reports as a skip; real errors (a shader that will not compile or link) are other exceptions.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixed_function_states.h"
#include "probe.h"
#include "resource_desc.h"
#include "shader_test_file.h"

namespace conformance {

class SectionCompiler;

// Something the runtime cannot do (yet): a skip with this reason, never a pass or a failure.
struct Unsupported : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct DrawCall {
    std::string topology = "triangle list";  // triangle list, triangle strip, point list
    int vertexCount = 3;
    int instances = 1;
    bool quad = false;  // vkd3d's "draw quad": one big triangle from float2 positions
    int controlPoints = 0;  // "draw N control point patch list M": patches of N (topology "patch list")
};

// The HLSL of each stage a draw or dispatch runs (entry `main`), and the [require] it runs under.
struct StageSource {
    Stage stage = Stage::Pixel;
    std::string source;
    int line = 0;  // of its section (0: the runner's own quad vertex shader)
};
struct ShaderSet {
    std::vector<StageSource> stages;
    RequireDesc require;
    std::string allSource() const;  // every stage's text, for register() lookups
};

class GpuBackend {
public:
    virtual ~GpuBackend() = default;
    virtual void setResource(const ResourceDesc& resource) = 0;  // what cannot be made is remembered, not thrown
    virtual void setSampler(const SamplerDesc& sampler) = 0;
    virtual void setInputLayout(std::vector<InputElement> layout) = 0;
    virtual void clearTarget(int slot, const float rgba[4]) = 0;
    // D3D9's fixed-function states for the draws that follow (the XNA session sets them; the
    // D3D11 session skips a draw that needs any, D3D11 having none).
    virtual void setFixedFunction(const FixedFunctionDesc& states) = 0;
    // vkd3d's `sample mask N`: the blend state's sample mask for the draws that follow.
    virtual void setSampleMask(unsigned mask) = 0;
    // vkd3d's `copy rtv 0 srv 0`: the whole of one resource into another ("rtv" or "srv", slot).
    virtual void copyResource(const std::string& fromKind, int fromSlot, const std::string& toKind, int toSlot) = 0;
    // Both return "" or why the uniforms' placement was a guess (UniformLayout::guess).
    virtual std::string draw(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, const DrawCall& call) = 0;
    virtual std::string dispatch(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, int x, int y, int z) = 0;
    virtual Texel readTexel(int slot, int x, int y) = 0;  // render target `slot`, as 32-bit words
    // One element of UAV `slot`: a texel of a texture (x, y) or element x of a buffer (its first
    // four words), as 32-bit words.
    virtual Texel readUav(int slot, int x, int y) = 0;
};

enum class SessionKind { Xna, D3d11 };
// A session of `kind` for `model` (D3D11 only from SM 4.0). `compiler` writes the sources the XNA
// session's effects are made from; `cacheDir` is the compile cache ("" for none).
std::unique_ptr<GpuBackend> makeBackend(SessionKind kind, int model, SectionCompiler& compiler, const std::string& cacheDir);

}  // namespace conformance
