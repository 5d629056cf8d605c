// What every draw does before the draw call: validate, then bring shaders, uniform buffers,
// textures, samplers, vertex layout and fixed-function state up to date, touching only what
// changed since the last draw. No GL here: the backend (device/backend.h) says it in GL's words.
#include <algorithm>
#include <array>
#include <cstring>
#include <iostream>
#include <optional>

#include "device/device_impl.h"
#include "device/optimization_passes.h"
#include "device/vertex_input.h"
#include "effect/effect_notices.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

namespace {

// D3D leaves a bound render target alone when the pixel shader writes nothing to it (a depth-only
// pass whose shader only clip()s); GL writes undefined values there (llvmpipe: whatever its output
// registers held, which ASan builds showed as garbage). So targets at and past the shader's outputs
// get their colour writes masked off.
fxport::BlendState blendForPixelShader(const fxport::BlendState& wanted, int outputTargets) {
    fxport::BlendState effective = wanted;
    fxport::ColorWriteChannels* channels[4] = {&effective.ColorWriteChannels, &effective.ColorWriteChannels1,
                                               &effective.ColorWriteChannels2, &effective.ColorWriteChannels3};
    for (int i = std::max(outputTargets, 0); i < 4; ++i) *channels[i] = fxport::ColorWriteChannels::None;
    return effective;
}

std::string textureName(const Texture* t) { return t->Name.empty() ? std::string("(unnamed)") : "'" + t->Name + "'"; }

}  // namespace

void GraphicsDevice::Impl::flush(const char* what) {
    checkDrawable(what);
    syncFixedFunction();
    storageBarrier();  // what an earlier dispatch or draw wrote through images or SSBOs, before this draw uses it
    if (boundFramebuffer == 0) bindTargets();
    const fxport::DepthStencilState& depthStencil = applyClearPasses();
    applyBlend();
    noteDrawnTargets();
    shadow.setDepthStencil(depthStencil);
    shadow.setRasterizer(device.RasterizerState);
    applyViewport(device.Viewport);
    shadow.setScissor(device.ScissorRectangle, moreScissors);
    applyShaders();
    applyTextures();
    if (applyStorage(shaders.data(), shaders.size(), what)) storageDirty = true;  // the draw writes: barrier before what follows
    applyPassEmulation();
    tallyDraw();
    shadow.settle();
}

void GraphicsDevice::Impl::checkDrawable(const char* what) const {
    if (!passApplied || !shaders[0] || !shaders[1])
        throw InvalidOperation(std::string(what) +
                               ": no effect pass is applied (call effect.CurrentTechnique->Passes[i].Apply() first)");
    checkTessellation(patchDraw, what);
}

// The passes that know the bound targets' pending clear decide what the draw needs of it, in this
// order: the depth buffer made if this draw is the first to test it (lazy depth storage), a depth
// test that cannot fail against the known clear turned off, a blend onto a zero clear turned into
// a write (decided while the clear is still pending), then the clear executed for the channels the
// draw uses. Returns the depth/stencil state the draw has.
const fxport::DepthStencilState& GraphicsDevice::Impl::applyClearPasses() {
    const fxport::DepthStencilState& wanted = device.DepthStencilState;
    if constexpr (kLazyDepthBuilt) makeDepthStorageFor(wanted);  // a buffer nothing needed until now (depth_storage.cpp)
    const fxport::DepthStencilState& drawn = foldMootDepthTest(wanted) ? fxport::DepthStencilState::None : wanted;
    foldBlendOverZeroClear();
    resolvePendingClearBeforeDraw(drawn);
    return drawn;
}

// The draw's blend (drawBlend: the device's, or its fold into a write), colour writes masked past
// the pixel shader's outputs.
void GraphicsDevice::Impl::applyBlend() {
    shadow.setBlend(blendForPixelShader(drawBlend(), shaders[1]->shader->outputTargets));
    if (trackingBoundTargets && drawBlend().blendingEnabled()) blendedSinceMark = true;
}

// The D3D9 states the pass emulates beside the shaders: sRGB write, clip planes, point size.
void GraphicsDevice::Impl::applyPassEmulation() {
    shadow.setSrgbWrite(emulation.srgbWrite);
    const int shaderPlanes = clipPlanesOfShaders();  // a shader's own SV_ClipDistance, else D3D9's user planes
    shadow.setClipPlanes(shaderPlanes > 0 ? shaderPlanes : userClipPlanes());
    applyPointSize(*shaders[shaders[2] ? 2 : shaders[std::size_t(kDomainStage)] ? kDomainStage : 0]);
    if (emulation.srgbWrite) reportUnencodedSrgbWrite();
}

// A depth test that cannot fail against the known clear and writes nothing (DepthRead against
// the far clear: the deferred G-buffer's clear quad) needs neither the clear nor the test: it
// draws as with the test off and the clear waits for a draw that reads or writes depth (so a
// compute pass can take such a draw; compute_pass.cpp). A buffer not made yet is not attached
// (GL passes the test) and its clear already waits on the target (depth_storage.cpp). Returns
// whether the draw turns the test off.
bool GraphicsDevice::Impl::foldMootDepthTest(const fxport::DepthStencilState& wanted) {
    drawDepthTestMoot = wanted.DepthBufferEnable && depthTestIsMoot(wanted);
    return drawDepthTestMoot && boundDepthStorage()->renderbuffer != 0;
}

// A blend onto the zero clear it reads draws as a write (blendOverZeroClearIsWrite): drawBlend().
void GraphicsDevice::Impl::foldBlendOverZeroClear() {
    if constexpr (kPendingClearsBuilt) drawBlendIsWrite = blendOverZeroClearIsWrite();
    if (!drawBlendIsWrite) return;
    drawWriteBlend = device.BlendState;
    drawWriteBlend.ColorSourceBlend = drawWriteBlend.AlphaSourceBlend = fxport::Blend::One;
    drawWriteBlend.ColorDestinationBlend = drawWriteBlend.AlphaDestinationBlend = fxport::Blend::Zero;
    drawWriteBlend.ColorBlendFunction = drawWriteBlend.AlphaBlendFunction = fxport::BlendFunction::Add;
    ++clearStats.blendsAsWrites;
}

// The clip distances the last stage before the rasteriser writes (geometry, else domain, else vertex).
int GraphicsDevice::Impl::clipPlanesOfShaders() const {
    for (int stage : {2, kDomainStage, 0})
        if (shaders[std::size_t(stage)]) return shaders[std::size_t(stage)]->shader->clipDistances;
    return 0;
}

void GraphicsDevice::Impl::reportUnencodedSrgbWrite() {
    // D3D9 encodes into 8-bit colour targets only: float and packed formats are written as they
    // are there too, and an sRGB-encoded target (SurfaceFormat::ColorSRgb) is converted by GL.
    const Texture* target = targets.empty() ? nullptr : targets[0].RenderTarget;
    const SurfaceFormat format = target ? target->Format() : device.PresentationParameters().BackBufferFormat;
    if (format != SurfaceFormat::Color || !emulation.srgbWriteAt || !emulation.srgbWriteReported || *emulation.srgbWriteReported) return;
    *emulation.srgbWriteReported = true;
    const xlate::SourceLocation& at = *emulation.srgbWriteAt;
    xlate::Diagnostic d;
    d.severity = xlate::Severity::Warning;
    d.id = xlate::diag::kUnhonouredState;
    d.location = at;
    d.message = "state 'SRGBWriteEnable' is not honoured drawing into " +
                (!target ? std::string("the back buffer")
                         : target->Name.empty() ? std::string("a render target") : "render target '" + target->Name + "'") +
                " (SurfaceFormat::Color): GL encodes sRGB only into SurfaceFormat::ColorSRgb targets, so the colours are "
                "written unconverted";
    reportEffectWarning(d.format());
}

void GraphicsDevice::Impl::applyShaders() {
    // Each stage reads what the stage before it in the pipeline (vertex, hull, domain, geometry,
    // pixel) writes, linked by semantic.
    std::array<const ShaderProgram*, kStageCount> linked = shaders;
    const ShaderProgram* writer = shaders[0];
    const ShaderProgram* pixelWriter = writer;
    for (int stage : {kHullStage, kDomainStage, 2, 1}) {
        if (!shaders[std::size_t(stage)]) continue;
        linked[std::size_t(stage)] = &linkedReader(*shaders[std::size_t(stage)], *writer);
        if (stage == 1) pixelWriter = writer;
        writer = shaders[std::size_t(stage)];
    }
    BackendObject vs = vertexProgramFor(*linked[0]), ps = pixelProgramFor(*linked[1], *pixelWriter);
    boundVertexProgram = vs;
    BackendObject gs = linked[2] ? linked[2]->program : 0;
    BackendObject hs = linked[kHullStage] ? linked[kHullStage]->program : 0, ds = linked[kDomainStage] ? linked[kDomainStage]->program : 0;
    auto key = std::make_tuple(vs, ps, gs, hs, ds);
    auto it = pipelines.find(key);
    BackendObject pipeline = 0;
    if (it != pipelines.end()) {
        pipeline = it->second;
    } else {
        pipeline = backend->createPipeline({vs, ps, gs, hs, ds});
        ++live.pipelines;
        pipelines.emplace(key, pipeline);
    }
    if (pipeline != boundPipeline) {
        backend->bindPipeline(pipeline);
        boundPipeline = pipeline;
    }
    for (std::size_t i = 0; i < wantedUniformBuffers.size(); ++i) {
        if (wantedUniformBuffers[i] == boundUniformBuffers[i]) continue;
        backend->bindUniformBuffer(int(i), wantedUniformBuffers[i]);
        boundUniformBuffers[i] = wantedUniformBuffers[i];
    }
}

namespace {

// Integer texels are never filtered (D3D10 has no filtered reads of them; GL leaves an integer
// texture with a linear filter incomplete, reading 0): the nearest texel of the nearest level.
SamplerState unfiltered(const SamplerState& s) {
    SamplerState out = s;
    out.Filter = TextureFilter::Point;
    return out;
}

// How a shader's sampler names the texture it reads, for the mismatch message.
const char* shapeName(xlate::TextureKind kind) {
    switch (kind) {
    case xlate::TextureKind::TextureCube: return "cube";
    case xlate::TextureKind::Texture3D: return "3D";
    case xlate::TextureKind::Texture1D: return "1D";
    default: return "2D";
    }
}

// The shader-side dimension a texture of `kind` is sampled as (arrays as their elements: xlate's
// kinds do not mark arrays).
xlate::TextureKind shapeOf(Texture::Kind kind) {
    switch (kind) {
    case Texture::Kind::TextureCube:
    case Texture::Kind::TextureCubeArray: return xlate::TextureKind::TextureCube;
    case Texture::Kind::Texture3D: return xlate::TextureKind::Texture3D;
    case Texture::Kind::Texture1D:
    case Texture::Kind::Texture1DArray: return xlate::TextureKind::Texture1D;
    default: return xlate::TextureKind::Texture2D;
    }
}

}  // namespace

void GraphicsDevice::Impl::applyTextures() { applyTexturesOf(shaders.data(), shaders.size()); }

void GraphicsDevice::Impl::applyTexturesOf(const ShaderProgram* const* programs, std::size_t count) {
    for (std::size_t p = 0; p < count; ++p) {
        const ShaderProgram* program = programs[p];
        if (!program) continue;
        if (!program->multisampledUnits) program->multisampledUnits = program->program ? backend->multisampledUnits(program->program) : 0u;
        // XNA: an SM 1-3 vertex shader's samplers read VertexTextures[] and VertexSamplerStates[]
        // by their s# (D3D9's vertex texture samplers); every other sampler Textures[unit].
        const bool vertexTextures = program->stage == 0 && program->shader->profile.isD3D9();
        const char* const collection = vertexTextures ? "VertexTextures" : "Textures";
        // An array of samplers (`Texture2D t[3]`) takes a unit per element, from sampler.unit on.
        for (const xlate::SamplerBinding& sampler : program->shader->samplers) {
            for (int element = 0; element < std::max(sampler.elements, 1); ++element) {
                int unit = sampler.unit + element;
                if (unit < 0 || unit >= kMaxTextureSlots) continue;
                const int slot = vertexTextures ? sampler.samplerRegister + element : unit;
                if (slot < 0 || slot >= kMaxTextureSlots) continue;
                Texture* texture = (vertexTextures ? device.VertexTextures : device.Textures)[slot].get();
                BackendObject name = texture ? texture->backendObject() : 0;
                const bool readsSamples = ((*program->multisampledUnits >> unit) & 1u) != 0;
                if (texture) {
                    if (&texture->device() != &device)  // its GL name means nothing in this device's context
                        throw InvalidOperation("Draw: texture " + textureName(texture) + " in " + collection + "[" + std::to_string(slot) +
                                               "] was made by another GraphicsDevice; make it with this one");
                    for (const RenderTargetBinding& b : targets)
                        if (b.RenderTarget == texture)
                            throw InvalidOperation("Draw: texture " + textureName(texture) + " in " + collection + "[" +
                                                   std::to_string(slot) + "] is also the current render target; " +
                                                   "set another render target (or clear the slot) before sampling it");
                    // GL reads a texture of another dimension than the sampler's as black: a D3D debug-layer error instead.
                    if (shapeOf(texture->kind()) != sampler.kind)
                        throw InvalidOperation(std::string("Draw: ") + program->label + " samples a " + shapeName(sampler.kind) +
                                               " texture at unit " + std::to_string(unit) + " but " + collection + "[" + std::to_string(slot) +
                                               "] holds a " + shapeName(shapeOf(texture->kind())) + " texture " + textureName(texture));
                    if (texture->sampleCount() > 0 && !readsSamples)
                        throw InvalidOperation(std::string("Draw: ") + program->label + " samples unit " + std::to_string(unit) + " as a Texture2D but Textures[" +
                                               std::to_string(unit) + "] holds the multisampled texture " + textureName(texture) +
                                               " (declare it Texture2DMS, or resolve it first)");
                    if (readsSamples && texture->sampleCount() == 0) name = sampleCopyOf(*texture);
                }
                if (shadow.unknown() || boundTextures[std::size_t(unit)] != name) {
                    backend->bindTexture(unit, name);
                    boundTextures[std::size_t(unit)] = name;
                }
                // The sampler-object lookup (a map keyed by the state's bytes) runs only when the
                // slot's state differs from what is bound, not on every draw.
                const SamplerState& given = (vertexTextures ? device.VertexSamplerStates : device.SamplerStates)[slot];
                const SamplerState& wanted = texture && isIntegerFormat(texture->Format()) ? unfiltered(given) : given;
                std::size_t u = std::size_t(unit);
                if (shadow.unknown() || boundSamplers[u] == 0 || !(boundSamplerStates[u] == wanted)) {
                    BackendObject object = samplerFor(wanted);
                    if (shadow.unknown() || boundSamplers[u] != object) backend->bindSampler(unit, object);
                    boundSamplers[u] = object;
                    boundSamplerStates[u] = wanted;
                }
            }
        }
    }
}

void GraphicsDevice::Impl::applyViewport(const fxport::Viewport& w) {
    // D3D9 pixel centres: an SM1-3 vertex shader's geometry moves right by half a pixel and down by
    // (half a pixel - 1/256), through the viewport's origin, where both are exact. Half a pixel
    // puts D3D9's integer pixel centres on GL's, so attributes interpolate at D3D9's positions (a
    // shift in clip space rounded: 0.5 px became 0.49999237 at 640 wide, and llvmpipe's 1/256 grid
    // made that 127/256). Columns need nothing more: GL's rasterisers include a left edge that
    // falls on a centre, as D3D's top-left rule does. Rows do: under GL_UPPER_LEFT llvmpipe treats a
    // top edge on a centre as a bottom one and drops the row, so the 1/256 (one step of the
    // sub-pixel grid) keeps such an edge just above the centre. Its price is an attribute bias of
    // 1/256 pixel down the rows (docs/DESIGN.md).
    const ShaderProgram* vertex = shaders[0];
    const bool d3d9 = vertex && vertex->shader && vertex->shader->needsD3D9PixelOffset;
    shadow.setViewport(w, d3d9 ? ViewportShift{0.5f, 0.5f - 1.0f / 256.0f} : ViewportShift{}, moreViewports);
}

BackendObject GraphicsDevice::Impl::samplerFor(const SamplerState& s) {
    std::array<std::uint8_t, sizeof(SamplerState)> key{};
    // SamplerState is a plain aggregate of enums, ints, floats and a Vector4: compare by fields
    // through a canonical byte image (padding zeroed by value-initialising a copy).
    SamplerState canonical{};
    canonical = s;
    std::memcpy(key.data(), &canonical, sizeof canonical);
    auto it = samplerObjects.find(key);
    if (it != samplerObjects.end()) return it->second;
    const BackendObject sampler = backend->createSampler(s);
    samplerObjects.emplace(std::move(key), sampler);
    return sampler;
}

GraphicsDevice::Impl::VertexArray& GraphicsDevice::Impl::vertexArrayFor(const VertexDeclaration& declaration) {
    BackendObject vs = shaders[0]->program;
    LastVertexArray& last = lastVertexArray;
    if (last.array && last.program == vs && last.declaration == &declaration && last.copy == declaration) {
        if (boundVertexArray != last.array->vao) {
            backend->bindVertexArray(last.array->vao);
            boundVertexArray = last.array->vao;
        }
        return *last.array;
    }
    std::string key;
    key += std::to_string(declaration.VertexStride());
    for (const VertexElement& e : declaration.GetVertexElements())
        key += ";" + std::to_string(e.Offset) + "," + std::to_string(int(e.VertexElementFormat)) + "," +
               std::to_string(int(e.VertexElementUsage)) + "," + std::to_string(e.UsageIndex);
    key += "|" + std::to_string(vs);
    auto it = vertexArrays.find(key);
    if (it == vertexArrays.end()) {
        const std::vector<const VertexElement*> elements =
            vertexElementsFor(declaration, shaders[0]->shader->inputs, "'" + shaders[0]->shader->entryPoint + "'");
        std::vector<VertexAttribute> attributes;
        for (std::size_t i = 0; i < elements.size(); ++i) {
            const xlate::VertexInput& input = shaders[0]->shader->inputs[i];
            attributes.push_back({input.location, vertexFormatOf(elements[i]->VertexElementFormat), elements[i]->Offset, input.isInteger});
        }
        VertexArray va;
        va.vao = backend->createVertexArray(attributes, {});
        ++live.vertexArrays;
        it = vertexArrays.emplace(key, va).first;
    }
    last.array = &it->second;
    last.program = vs;
    last.declaration = &declaration;
    last.copy = declaration;
    if (boundVertexArray != it->second.vao) {
        backend->bindVertexArray(it->second.vao);
        boundVertexArray = it->second.vao;
    }
    return it->second;
}

}  // namespace fxport
