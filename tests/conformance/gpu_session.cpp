// GPU work of one (file, shader model) run through fxport's public runtime API (see gpu_session.h).
#include "gpu_session.h"

#include <cstring>

#include "fxport/graphics.h"
#include "fxport/xlate/compiled_effect.h"
#include "register_binding.h"

namespace conformance {

namespace {

fxport::CompareFunction alphaFunction(const std::string& name) {
    using C = fxport::CompareFunction;
    if (name == "never") return C::Never;
    if (name == "less") return C::Less;
    if (name == "equal") return C::Equal;
    if (name == "less equal") return C::LessEqual;
    if (name == "greater") return C::Greater;
    if (name == "not equal") return C::NotEqual;
    if (name == "greater equal") return C::GreaterEqual;
    return C::Always;
}

// vkd3d's test states as fxport's D3D9 states. The alpha reference is D3D9's 8-bit value, as
// vkd3d's d3d9 runner passes it (reference * 255).
fxport::FixedFunctionState fixedFunctionState(const FixedFunctionDesc& d) {
    fxport::FixedFunctionState s;
    s.FogEnable = d.fog;
    s.FogTableMode = fxport::FogMode(d.fogMode);
    s.FogFromW = d.fogFromW;
    s.FogStart = d.fogStart, s.FogEnd = d.fogEnd, s.FogDensity = d.fogDensity;
    s.FogColor = fxport::Vector4(d.fogColour[0], d.fogColour[1], d.fogColour[2], d.fogColour[3]);
    s.PointSize = d.pointSize, s.PointSizeMin = d.pointSizeMin, s.PointSizeMax = d.pointSizeMax;
    s.PointSpriteEnable = d.pointSprite;
    s.ClipPlaneEnable = d.clipPlaneMask & 0x3F;
    for (std::size_t i = 0; i < s.ClipPlanes.size(); ++i)
        s.ClipPlanes[i] = fxport::Vector4(d.clipPlanes[i][0], d.clipPlanes[i][1], d.clipPlanes[i][2], d.clipPlanes[i][3]);
    s.AlphaTestEnable = d.alphaTest;
    s.AlphaFunction = alphaFunction(d.alphaFunction);
    s.ReferenceAlpha = int(d.alphaReference * 255.0f + 0.5f);
    s.ShadeMode = d.flatShading ? fxport::ShadeMode::Flat : fxport::ShadeMode::Gouraud;
    return s;
}

using fxport::SurfaceFormat;

constexpr int kDefaultWidth = 640;   // vkd3d's RENDER_TARGET_WIDTH
constexpr int kDefaultHeight = 480;  // RENDER_TARGET_HEIGHT
constexpr int kDepthSlot = -1;       // the [dsv] in the maps of unsupported targets

// The XNA surface format of a float format with n components; Unsupported for the rest.
SurfaceFormat floatSurfaceFormat(const Format& f, const char* what) {
    if (f.type != 'f' || f.shadow)
        throw Unsupported(std::string(what) + " format " + f.name + " (XNA's SurfaceFormat has no integer or typeless formats)");
    if (f.components == 4) return SurfaceFormat::Vector4;
    if (f.components == 2) return SurfaceFormat::Vector2;
    if (f.components == 1) return SurfaceFormat::Single;
    throw Unsupported(std::string(what) + " format " + f.name);
}

fxport::TextureFilter textureFilter(const SamplerDesc& s) {
    using F = fxport::TextureFilter;
    bool minL = s.min == Filter::Linear, magL = s.mag == Filter::Linear, mipL = s.mip == Filter::Linear;
    if (minL && magL) return mipL ? F::Linear : F::LinearMipPoint;
    if (!minL && !magL) return mipL ? F::PointMipLinear : F::Point;
    if (minL) return mipL ? F::MinLinearMagPointMipLinear : F::MinLinearMagPointMipPoint;
    return mipL ? F::MinPointMagLinearMipLinear : F::MinPointMagLinearMipPoint;
}

fxport::TextureAddressMode addressMode(Address a) {
    switch (a) {
    case Address::Wrap: return fxport::TextureAddressMode::Wrap;
    case Address::Mirror: return fxport::TextureAddressMode::Mirror;
    case Address::Clamp: return fxport::TextureAddressMode::Clamp;
    case Address::Border: return fxport::TextureAddressMode::Border;
    case Address::MirrorOnce: break;
    }
    throw Unsupported("sampler address mode mirror_once (XNA's TextureAddressMode has none)");
}

fxport::SamplerState samplerState(const SamplerDesc& s) {
    if (s.comparison) throw Unsupported("comparison sampler from [sampler N] (the device's SamplerState takes it only from an effect)");
    fxport::SamplerState out;
    out.Filter = textureFilter(s);
    out.AddressU = addressMode(s.u);
    out.AddressV = addressMode(s.v);
    out.AddressW = addressMode(s.w);
    return out;
}

// The device's sampler where the test declares none: D3D10+ default (linear, clamp), D3D9's
// (point, no mip filter, wrap).
fxport::SamplerState defaultSampler(int model) {
    fxport::SamplerState out;
    if (model >= 40) {
        out.Filter = fxport::TextureFilter::Linear;
        out.AddressU = out.AddressV = out.AddressW = fxport::TextureAddressMode::Clamp;
    } else {
        out.Filter = fxport::TextureFilter::Point;
        out.UseMipMaps = false;
        out.AddressU = out.AddressV = out.AddressW = fxport::TextureAddressMode::Wrap;
    }
    return out;
}

bool isTexture(const fxport::xlate::Parameter& p) {
    using T = fxport::xlate::ParameterType;
    return p.type == T::Texture || p.type == T::Texture1D || p.type == T::Texture2D || p.type == T::Texture3D ||
           p.type == T::TextureCube;
}

bool isSampler(const fxport::xlate::Parameter& p) {
    using T = fxport::xlate::ParameterType;
    return p.type == T::Sampler || p.type == T::Sampler1D || p.type == T::Sampler2D || p.type == T::Sampler3D ||
           p.type == T::SamplerCube || p.type == T::SamplerState;
}

// Register slots of texture (or sampler) parameters: explicit ones, the rest in declaration order.
std::map<std::string, int> registerSlots(const fxport::xlate::CompiledEffect& compiled, const std::string& source,
                                         bool textures) {
    std::map<std::string, int> out;
    int next = 0;
    for (const auto& p : compiled.parameters) {
        if (textures ? !isTexture(p) : !isSampler(p)) continue;
        int reg = explicitRegister(source, p.name, textures ? 't' : 's');
        out[p.name] = reg >= 0 ? reg : next++;
    }
    return out;
}

fxport::VertexElementUsage usageOf(const std::string& semantic) {
    static const struct { const char* name; fxport::VertexElementUsage usage; } kUsages[] = {
        {"POSITION", fxport::VertexElementUsage::Position},
        {"TEXCOORD", fxport::VertexElementUsage::TextureCoordinate}, {"COLOR", fxport::VertexElementUsage::Color},
        {"NORMAL", fxport::VertexElementUsage::Normal}, {"BINORMAL", fxport::VertexElementUsage::Binormal},
        {"TANGENT", fxport::VertexElementUsage::Tangent}, {"BLENDINDICES", fxport::VertexElementUsage::BlendIndices},
        {"BLENDWEIGHT", fxport::VertexElementUsage::BlendWeight}, {"PSIZE", fxport::VertexElementUsage::PointSize},
        {"FOG", fxport::VertexElementUsage::Fog}, {"DEPTH", fxport::VertexElementUsage::Depth},
    };
    std::string upper;
    for (char c : semantic) upper += char(std::toupper(static_cast<unsigned char>(c)));
    for (const auto& u : kUsages)
        if (upper == u.name) return u.usage;
    // D3D10 input layouts may name system values; XNA's usages cannot, and the runtime does not
    // feed an SV_POSITION input from a POSITION element.
    if (upper.rfind("SV_", 0) == 0)
        throw Unsupported("vertex input semantic '" + semantic + "' (XNA's VertexElementUsage has no SV_ names)");
    throw Unsupported("vertex input semantic '" + semantic + "' (no XNA VertexElementUsage)");
}

fxport::VertexElementFormat elementFormat(const Format& f) {
    if (f.type != 'f') throw Unsupported("integer vertex attribute " + f.name + " (no XNA VertexElementFormat)");
    if (f.components == 1) return fxport::VertexElementFormat::Single;
    if (f.components == 2) return fxport::VertexElementFormat::Vector2;
    return fxport::VertexElementFormat::Vector4;
}

}  // namespace

GpuSession::GpuSession() = default;
GpuSession::~GpuSession() {
    textures_.clear();
    targets_.clear();
}

fxport::GraphicsDevice& GpuSession::device() {
    if (!device_) device_ = std::make_unique<fxport::GraphicsDevice>(fxport::PresentationParameters{});
    return *device_;
}

void GpuSession::setResource(const ResourceDesc& r) {
    switch (r.kind) {
    case BlockKind::Rtv: makeTarget(r); break;
    case BlockKind::Dsv: unsupportedTargets_[kDepthSlot] = "depth-stencil view [dsv] (no depth readback or depth test setup)"; break;
    case BlockKind::Srv:
        if (r.dimension == "buffer" || r.dimension == "raw_buffer") makeBufferSrv(r);
        else makeTexture(r);
        break;
    case BlockKind::VertexBuffer: vertexBuffers_[r.slot] = r; break;
    case BlockKind::Uav: makeUav(r); break;
    default: throw Unsupported("resource kind of this block");
    }
}

void GpuSession::makeTarget(const ResourceDesc& r) {
    targets_.erase(r.slot);
    unsupportedTargets_.erase(r.slot);
    readback_.clear();
    try {
        if (r.dimension != "2d") throw Unsupported("render target dimension " + r.dimension);
        SurfaceFormat format = floatSurfaceFormat(r.format, "render target");
        targets_[r.slot] = std::make_unique<fxport::RenderTarget2D>(device(), r.width, r.height, false, format,
                                                                    fxport::DepthFormat::None, 0,
                                                                    fxport::RenderTargetUsage::PreserveContents);
        float zero[4] = {0, 0, 0, 0};
        clearTarget(r.slot, zero);
    } catch (const Unsupported& e) {
        unsupportedTargets_[r.slot] = e.what();
    }
}

void GpuSession::makeTexture(const ResourceDesc& r) {
    textures_.erase(r.slot);
    unsupportedTextures_.erase(r.slot);
    try {
        if (r.dimension == "cube") return makeCube(r);
        if (r.dimension == "3d") return makeVolume(r);
        if (r.dimension != "2d") throw Unsupported("texture dimension " + r.dimension + " from [srv N]");
        SurfaceFormat format = floatSurfaceFormat(r.format, "texture");
        auto texture = std::make_unique<fxport::Texture2D>(device(), r.width, r.height, r.levels > 1, format);
        std::size_t at = 0;
        for (int level = 0; level < r.levels; ++level) {
            int w = std::max(1, r.width >> level), h = std::max(1, r.height >> level);
            std::vector<std::uint32_t> words(std::size_t(w * h * r.format.components), 0);
            for (std::size_t k = 0; k < words.size() && at < r.data.size(); ++k) words[k] = r.data[at++];
            texture->SetData(level, nullptr, reinterpret_cast<const float*>(words.data()), words.size());
        }
        textures_[r.slot] = std::move(texture);
    } catch (const Unsupported& e) {
        unsupportedTextures_[r.slot] = e.what();
    }
}

// A cube of one level: its faces' texels in D3D's face order (XNA's CubeMapFace order).
void GpuSession::makeCube(const ResourceDesc& r) {
    if (r.levels != 1) throw Unsupported("a cube texture of " + std::to_string(r.levels) + " levels");
    SurfaceFormat format = floatSurfaceFormat(r.format, "texture");
    auto cube = std::make_unique<fxport::TextureCube>(device(), r.width, false, format);
    const std::size_t faceWords = std::size_t(r.width) * std::size_t(r.width) * std::size_t(r.format.components);
    for (int face = 0; face < 6; ++face) {
        std::vector<std::uint32_t> words(faceWords, 0);
        for (std::size_t k = 0; k < faceWords && face * faceWords + k < r.data.size(); ++k) words[k] = r.data[face * faceWords + k];
        cube->SetData(fxport::CubeMapFace(face), reinterpret_cast<const float*>(words.data()), words.size());
    }
    textures_[r.slot] = std::move(cube);
}

// A volume: each level's slices front to back, as vkd3d lists the data.
void GpuSession::makeVolume(const ResourceDesc& r) {
    SurfaceFormat format = floatSurfaceFormat(r.format, "texture");
    auto volume = std::make_unique<fxport::Texture3D>(device(), r.width, r.height, r.depth, r.levels > 1, format);
    std::size_t at = 0;
    for (int level = 0; level < volume->LevelCount(); ++level) {
        std::vector<std::uint32_t> words(volume->levelBytes(level) / 4, 0);
        for (std::size_t k = 0; k < words.size() && at < r.data.size(); ++k) words[k] = r.data[at++];
        volume->SetData(level, reinterpret_cast<const float*>(words.data()), words.size());
    }
    textures_[r.slot] = std::move(volume);
}

namespace {

// A structured ("stride N") or raw ("raw_buffer", 32-bit words) buffer from its description, its
// data words in order; typed buffers (RWBuffer<float4>: a format and "buffer") have no
// StructuredBuffer counterpart.
std::unique_ptr<fxport::StructuredBuffer> makeStorageBuffer(fxport::GraphicsDevice& device, const ResourceDesc& r, const char* what) {
    int stride = r.dimension == "raw_buffer" ? 4 : r.stride;
    if (stride <= 0)
        throw Unsupported(std::string("typed buffer ") + what + " (format " + r.format.name +
                          "; RWBuffer<T>/Buffer<T> are D3D11 typed views: the XNA API's StructuredBuffer is structured or raw)");
    if (r.width <= 0) throw Unsupported(std::string(what) + " of no elements");
    auto buffer = std::make_unique<fxport::StructuredBuffer>(device, stride, r.width);
    std::vector<std::uint32_t> words(buffer->SizeInBytes() / 4, 0);
    for (std::size_t k = 0; k < words.size() && k < r.data.size(); ++k) words[k] = r.data[k];
    buffer->SetData(words);
    return buffer;
}

}  // namespace

void GpuSession::makeUav(const ResourceDesc& r) {
    uavs_.erase(r.slot);
    unsupportedUavs_.erase(r.slot);
    try {
        Uav uav;
        uav.desc = r;
        if (r.dimension == "buffer" || r.dimension == "raw_buffer") {
            uav.buffer = makeStorageBuffer(device(), r, "UAV");
        } else if (r.dimension == "2d") {
            SurfaceFormat format = floatSurfaceFormat(r.format, "UAV texture");
            uav.texture = std::make_unique<fxport::RenderTarget2D>(device(), r.width, r.height, false, format, fxport::DepthFormat::None, 0,
                                                                   fxport::RenderTargetUsage::PreserveContents);
            std::vector<std::uint32_t> words(std::size_t(r.width * r.height * r.format.components), 0);
            for (std::size_t k = 0; k < words.size() && k < r.data.size(); ++k) words[k] = r.data[k];
            uav.texture->SetData(0, nullptr, reinterpret_cast<const float*>(words.data()), words.size());
        } else {
            throw Unsupported("UAV dimension " + r.dimension);
        }
        uavs_[r.slot] = std::move(uav);
    } catch (const Unsupported& e) {
        unsupportedUavs_[r.slot] = e.what();
    }
}

void GpuSession::makeBufferSrv(const ResourceDesc& r) {
    srvBuffers_.erase(r.slot);
    unsupportedTextures_.erase(r.slot);
    try {
        srvBuffers_[r.slot] = makeStorageBuffer(device(), r, "shader resource");
    } catch (const Unsupported& e) {
        unsupportedTextures_[r.slot] = e.what();
    }
}

void GpuSession::bindStorage() {
    if (!unsupportedUavs_.empty()) throw Unsupported(unsupportedUavs_.begin()->second);
    for (int slot = 0; slot < fxport::kMaxUnorderedAccessSlots; ++slot) {
        auto it = uavs_.find(slot);
        if (it != uavs_.end() && it->second.buffer) device().SetUnorderedAccess(slot, it->second.buffer.get());
        else if (it != uavs_.end()) device().SetUnorderedAccess(slot, static_cast<fxport::Texture2D*>(it->second.texture.get()));
        else device().SetUnorderedAccess(slot, static_cast<fxport::StructuredBuffer*>(nullptr));
    }
    for (int slot = 0; slot < fxport::kMaxShaderResourceBuffers; ++slot) {
        auto it = srvBuffers_.find(slot);
        device().SetShaderResource(slot, it != srvBuffers_.end() ? it->second.get() : nullptr);
    }
    for (const auto& [slot, uav] : uavs_)
        if (slot >= fxport::kMaxUnorderedAccessSlots) throw Unsupported("UAV slot " + std::to_string(slot) + " (fxport has u0..u7)");
}

void GpuSession::dispatch(fxport::Effect& effect, const std::string& source, int model, int x, int y, int z) {
    bindTextures(effect, source, model);
    bindStorage();
    effect.CurrentTechnique = effect.Techniques[0];
    effect.CurrentTechnique->Passes[0].Apply();
    device().DispatchCompute(x, y, z);
    readback_.clear();
}

Texel GpuSession::readUav(int slot, int x, int y) {
    auto it = uavs_.find(slot);
    if (it == uavs_.end()) {
        auto bad = unsupportedUavs_.find(slot);
        throw Unsupported(bad != unsupportedUavs_.end() ? bad->second : "probe of an undeclared UAV");
    }
    Texel t;
    if (it->second.buffer) {
        const fxport::StructuredBuffer& b = *it->second.buffer;
        std::size_t wordsPerElement = std::size_t(b.ElementStride() / 4);
        if (x < 0 || x >= b.ElementCount()) throw std::runtime_error("probe outside the UAV buffer");
        std::vector<std::uint32_t> words = b.GetData<std::uint32_t>();
        for (std::size_t k = 0; k < 4 && std::size_t(x) * wordsPerElement + k < words.size(); ++k)
            t.bits[k] = words[std::size_t(x) * wordsPerElement + k];
        return t;
    }
    fxport::RenderTarget2D& texture = *it->second.texture;
    int w = texture.Width(), h = texture.Height();
    if (x < 0 || y < 0 || x >= w || y >= h) throw std::runtime_error("probe outside the UAV texture");
    std::vector<fxport::Vector4> texels = texture.GetDataAsVector4();
    const fxport::Vector4& v = texels[std::size_t(y * w + x)];
    const float f[4] = {v.X, v.Y, v.Z, v.W};
    std::memcpy(t.bits.data(), f, 16);
    return t;
}

void GpuSession::ensureDefaultTarget() {
    if (targets_.count(0) || unsupportedTargets_.count(0) || unsupportedTargets_.count(kDepthSlot)) return;
    ResourceDesc r;
    r.kind = BlockKind::Rtv;
    r.width = kDefaultWidth;
    r.height = kDefaultHeight;
    makeTarget(r);
}

bool GpuSession::hasTarget(int slot) const { return targets_.count(slot) > 0; }

void GpuSession::clearTarget(int slot, const float rgba[4]) {
    ensureDefaultTarget();
    auto it = targets_.find(slot);
    if (it == targets_.end()) {
        auto bad = unsupportedTargets_.find(slot);
        throw Unsupported(bad != unsupportedTargets_.end() ? bad->second : "clear of an undeclared render target");
    }
    device().SetRenderTarget(it->second.get());
    device().Clear(fxport::ClearOptions::Target, fxport::Vector4(rgba[0], rgba[1], rgba[2], rgba[3]), 1.0f, 0);
    readback_.clear();
}

void GpuSession::bindTargets() {
    ensureDefaultTarget();
    for (const auto& [slot, why] : unsupportedTargets_) throw Unsupported(why);
    std::vector<fxport::RenderTargetBinding> bindings;
    int expected = 0;
    for (auto& [slot, target] : targets_) {
        if (slot != expected++) throw Unsupported("render targets not numbered from 0 without gaps");
        bindings.emplace_back(target.get());
    }
    device().SetRenderTargets(bindings);
}

void GpuSession::bindTextures(fxport::Effect& effect, const std::string& source, int model) {
    const fxport::xlate::CompiledEffect& compiled = effect.compiled();
    std::map<std::string, int> textureSlots = registerSlots(compiled, source, true);
    std::map<std::string, int> samplerSlots = registerSlots(compiled, source, false);
    // Buffers and other views the reflection does not list as parameters cannot be matched to
    // their [srv N]: any view the session could not make skips the draw.
    if (!unsupportedTextures_.empty()) throw Unsupported(unsupportedTextures_.begin()->second);
    for (const auto& [name, slot] : textureSlots) {
        if (unsupportedTextures_.count(slot)) throw Unsupported(unsupportedTextures_[slot]);
        auto it = textures_.find(slot);
        effect.Parameters[name].SetValue(it == textures_.end() ? nullptr : it->second.get());
    }
    for (const auto& shader : compiled.shaders) {
        for (const auto& binding : shader.samplers) {
            if (model < 40 && binding.samplerRegister >= 0) {
                bindD3d9Sampler(binding, model, false);
                continue;
            }
            int slot = samplerSlots.count(binding.samplerName) ? samplerSlots[binding.samplerName] : binding.unit;
            auto s = samplers_.find(slot);
            device().SamplerStates[binding.unit] = s != samplers_.end() ? samplerState(s->second) : defaultSampler(model);
            if (!binding.textureParameter.empty()) continue;
            // D3D9 style: the texture bound at the sampler's register feeds it.
            if (unsupportedTextures_.count(slot)) throw Unsupported(unsupportedTextures_[slot]);
            auto t = textures_.find(slot);
            device().Textures[binding.unit] = t == textures_.end() ? nullptr : t->second.get();
        }
    }
}

// SM 1-3: [sampler N] and [srv N] are D3D9's sampler register N, which xlate's reflection gives
// each binding (a combined `tex.Sample(sam, uv)` has its own). The sampler state goes before
// Apply(), which merges the effect's sampler_state over it; the texture after, over the one
// Apply() binds from a texture parameter, as D3D9's SetTexture(N) feeds the register whatever
// texture object the shader names.
void GpuSession::bindD3d9Sampler(const fxport::xlate::SamplerBinding& binding, int model, bool texture) {
    for (int k = 0; k < binding.elements; ++k) {
        const int reg = binding.samplerRegister + k, unit = binding.unit + k;
        if (!texture) {
            auto s = samplers_.find(reg);
            device().SamplerStates[unit] = s != samplers_.end() ? samplerState(s->second) : defaultSampler(model);
            continue;
        }
        if (unsupportedTextures_.count(reg)) throw Unsupported(unsupportedTextures_[reg]);
        auto t = textures_.find(reg);
        device().Textures[unit] = t == textures_.end() ? nullptr : t->second.get();
    }
}

void GpuSession::bindD3d9Textures(fxport::Effect& effect, int model) {
    if (model >= 40) return;
    for (const auto& shader : effect.compiled().shaders)
        for (const auto& binding : shader.samplers)
            if (binding.samplerRegister >= 0) bindD3d9Sampler(binding, model, true);
}

void GpuSession::draw(fxport::Effect& effect, const std::string& source, int model, const DrawCall& call) {
    bindTargets();
    bindTextures(effect, source, model);
    bindStorage();
    effect.CurrentTechnique = effect.Techniques[0];
    effect.CurrentTechnique->Passes[0].Apply();
    bindD3d9Textures(effect, model);
    // D3D's defaults for a runner that sets no states: no culling, no blending, no depth test.
    device().RasterizerState = fxport::RasterizerState::CullNone;
    device().BlendState = fxport::BlendState::Opaque;
    device().BlendState.MultiSampleMask = int(sampleMask_);
    device().DepthStencilState = fxport::DepthStencilState::None;
    device().FixedFunction = fixedFunctionState(fixedFunction_);
    drawVertices(call);
    readback_.clear();
}

void GpuSession::drawVertices(const DrawCall& call) {
    if (call.instances != 1) throw Unsupported("instanced draw (XNA's DrawPrimitives has no instance count)");
    std::vector<fxport::VertexElement> elements;
    std::vector<std::uint32_t> words;
    int count = call.vertexCount;
    if (call.quad) {
        elements.emplace_back(0, fxport::VertexElementFormat::Vector2, fxport::VertexElementUsage::Position, 0);
        const float quad[6] = {-2.0f, -2.0f, -2.0f, 4.0f, 4.0f, -2.0f};
        words.resize(6);
        std::memcpy(words.data(), quad, sizeof quad);
    } else {
        int offset = 0;
        for (const InputElement& e : inputLayout_) {
            if (e.slot != 0) throw Unsupported("vertex buffers in several slots");
            elements.emplace_back(offset, elementFormat(e.format), usageOf(e.semantic), e.index);
            offset += 4 * e.format.components;
        }
        // No [input layout]: the vertex shader reads only system values (SV_VertexID ...); GL
        // still wants an attribute, which no input reads.
        if (elements.empty()) elements.emplace_back(0, fxport::VertexElementFormat::Vector4, fxport::VertexElementUsage::Position, 0);
        auto vb = vertexBuffers_.find(0);
        if (vb != vertexBuffers_.end()) words = vb->second.data;
    }
    fxport::VertexDeclaration declaration(elements);
    words.resize(std::size_t(count * declaration.VertexStride() / 4), 0);
    fxport::VertexBuffer buffer(device(), declaration, count);
    buffer.SetData(words.data(), words.size());
    device().SetVertexBuffer(buffer);
    if (call.topology == "triangle list") device().DrawPrimitives(fxport::PrimitiveType::TriangleList, 0, count / 3);
    else if (call.topology == "triangle strip") device().DrawPrimitives(fxport::PrimitiveType::TriangleStrip, 0, count - 2);
    else if (call.topology == "point list") device().DrawPrimitives(fxport::PrimitiveType::PointList, 0, count);
    else if (call.topology == "patch list") device().DrawPatches(call.controlPoints, 0, count / call.controlPoints);
    else throw Unsupported("primitive topology " + call.topology);
    device().SetVertexBuffer(nullptr);
}

Texel GpuSession::readTexel(int slot, int x, int y) {
    auto it = targets_.find(slot);
    if (it == targets_.end()) {
        auto bad = unsupportedTargets_.find(slot);
        throw Unsupported(bad != unsupportedTargets_.end() ? bad->second : "probe of an undeclared render target");
    }
    auto& cached = readback_[slot];
    if (cached.empty()) cached = it->second->GetDataAsVector4();  // once per target after each draw
    int w = it->second->Width(), h = it->second->Height();
    if (x < 0 || y < 0 || x >= w || y >= h) throw std::runtime_error("probe outside the render target");
    Texel t;
    const fxport::Vector4& v = cached[std::size_t(y * w + x)];
    const float f[4] = {v.X, v.Y, v.Z, v.W};
    std::memcpy(t.bits.data(), f, 16);
    return t;
}

}  // namespace conformance
