// What a draw does for GraphicsDevice::FixedFunction (fixed_function_state.h): the D3D9 states GL
// core lacks run as variants of the draw's shaders (xlate/fixed_function.h), made once per shader
// and set of stages they emulate, whose uniforms each draw sets; the point size and the clip
// distances GL enables are the backend's. No GL here.
#include <algorithm>
#include <functional>
#include <iostream>
#include <optional>
#include <string>

#include "device/device_impl.h"
#include "fxport/xlate/fixed_function.h"

namespace fxport {

namespace {

// Uniforms of a variant, in FixedFunctionVariant::locations.
enum FixedFunctionUniform { kAlphaFunc, kAlphaRef, kFogColor, kFogMode, kFogParams, kClipPlanes, kPointSize, kUniformCount };
const char* const kUniformNames[kUniformCount] = {"fxport_AlphaFunc", "fxport_AlphaRef", xlate::kFogColorUniform, xlate::kFogModeUniform,
                                                  xlate::kFogParamsUniform, xlate::kClipPlanesUniform, xlate::kPointSizeUniform};

int d3d9CompareCode(CompareFunction f) {
    switch (f) {
    case CompareFunction::Never: return 1;
    case CompareFunction::Less: return 2;
    case CompareFunction::Equal: return 3;
    case CompareFunction::LessEqual: return 4;
    case CompareFunction::Greater: return 5;
    case CompareFunction::NotEqual: return 6;
    case CompareFunction::GreaterEqual: return 7;
    case CompareFunction::Always: return 8;
    }
    return 8;
}

// The semantic's location among a shader's outputs, -1 when it writes none.
int outputLocation(const xlate::CompiledShader& shader, const char* semantic) {
    for (const xlate::Varying& v : shader.varyingOutputs)
        if (v.semantic == semantic) return v.location;
    return -1;
}

// Where a D3D9 vertex shader (vs_1_1..vs_3_0) writes PSIZE, -1 when it does not: D3D10+ points
// are one pixel, whatever a shader calls PSIZE.
int pointSizeOutput(const xlate::CompiledShader& shader) {
    return shader.profile.stage == xlate::ShaderStage::Vertex && shader.profile.isD3D9() ? outputLocation(shader, "PSIZE0") : -1;
}

xlate::PixelFixedFunction pixelStages(const FixedFunctionState& s, const xlate::CompiledShader& writer, bool points) {
    xlate::PixelFixedFunction p;
    p.alphaTest = s.AlphaTestEnable;
    p.fog = s.FogEnable;
    if (p.fog && s.FogTableMode == FogMode::None) {
        // Vertex fog: the factor the vertex shader wrote to FOG, else (D3D9 hardware keeps it there)
        // the specular colour's alpha.
        p.fogInput.location = outputLocation(writer, "FOG0");
        if (p.fogInput.location < 0) {
            p.fogInput.location = outputLocation(writer, "COLOR1");
            p.fogInput.component = 3;
        }
    }
    p.pointSprite = s.PointSpriteEnable && points;  // D3D9's sprites are points only
    p.flatColors = s.ShadeMode == ShadeMode::Flat;
    return p;
}

int pixelKey(const xlate::PixelFixedFunction& p) {
    return int(p.alphaTest) | int(p.fog) << 1 | int(p.pointSprite) << 2 | int(p.flatColors) << 3 |
           (p.fogInput.location + 1) << 8 | p.fogInput.component << 16;
}

int enabledClipPlanes(const FixedFunctionState& s) {
    int n = 0;
    for (int i = 0; i < xlate::kMaxUserClipPlanes; ++i) n += (s.ClipPlaneEnable >> i) & 1;
    return n;
}

}  // namespace

void GraphicsDevice::Impl::syncFixedFunction() {
    const FixedFunctionState& s = device.FixedFunction;
    emulation.alphaTest = s.AlphaTestEnable;
    emulation.fixedFunction = s.FogEnable || s.PointSpriteEnable || s.ShadeMode == ShadeMode::Flat || enabledClipPlanes(s) > 0;
}

// Makes (once) the variant of `program` for `key`; warns once when the shader cannot have it.
static const FixedFunctionVariant& variantFor(GraphicsDevice::Impl& d, const ShaderProgram& program, int key,
                                              const std::function<std::optional<std::string>(std::string&)>& make,
                                              const std::string& what) {
    auto it = program.fixedFunctionVariants.find(key);
    if (it != program.fixedFunctionVariants.end()) return it->second;
    FixedFunctionVariant v;
    std::string why;
    std::optional<std::string> glsl = make(why);
    if (!glsl) {
        std::cerr << "fxport: " << program.label << ": " << what << " cannot be emulated (" << why << "); drawing without it\n";
    } else {
        v.program = d.createProgram(program.stage, *program.shader, *glsl, program.label + " [" + what + "]");
        for (int u = 0; u < kUniformCount; ++u) v.locations[std::size_t(u)] = d.backend->uniformLocation(v.program, kUniformNames[u]);
    }
    return program.fixedFunctionVariants.emplace(key, v).first->second;
}

BackendObject GraphicsDevice::Impl::pixelProgramFor(const ShaderProgram& program, const ShaderProgram& writer) {
    const FixedFunctionState& s = device.FixedFunction;
    const xlate::PixelFixedFunction wanted = pixelStages(s, *writer.shader, drawingPoints);
    if (!wanted.any()) return program.program;
    const FixedFunctionVariant& v = variantFor(
        *this, program, pixelKey(wanted), [&](std::string& why) { return xlate::pixelFixedFunctionVariant(program.shader->glsl, wanted, why); },
        "D3D9 fixed-function pixel states");
    if (!v.program) return program.program;
    const auto at = [&](FixedFunctionUniform u) { return v.locations[std::size_t(u)]; };
    if (wanted.alphaTest) {
        backend->setUniform(v.program, at(kAlphaFunc), d3d9CompareCode(s.AlphaFunction));
        backend->setUniform(v.program, at(kAlphaRef), float(s.ReferenceAlpha & 0xFF) / 255.0f);
    }
    if (wanted.fog) {
        const float color[4] = {s.FogColor.X, s.FogColor.Y, s.FogColor.Z, s.FogColor.W};
        // D3D9 fogs everything when FogStart == FogEnd (a scale of 0: f = 0).
        const float scale = s.FogEnd != s.FogStart ? 1.0f / (s.FogEnd - s.FogStart) : 0.0f;
        const float params[4] = {s.FogEnd, scale, s.FogDensity, s.FogFromW ? 1.0f : 0.0f};
        backend->setUniform(v.program, at(kFogColor), color, 1);
        backend->setUniform(v.program, at(kFogMode), int(s.FogTableMode));
        backend->setUniform(v.program, at(kFogParams), params, 1);
    }
    return v.program;
}

int GraphicsDevice::Impl::userClipPlanes() const {
    return shaders[2] || shaders[std::size_t(kDomainStage)] ? 0 : enabledClipPlanes(device.FixedFunction);
}

BackendObject GraphicsDevice::Impl::vertexProgramFor(const ShaderProgram& program) {
    const FixedFunctionState& s = device.FixedFunction;
    xlate::VertexFixedFunction wanted;
    const bool lastBeforeRasteriser = !shaders[2] && !shaders[std::size_t(kDomainStage)];
    if (lastBeforeRasteriser) {
        wanted.clipPlanes = userClipPlanes();
        wanted.pointSizeLocation = pointSizeOutput(*program.shader);
    } else if (enabledClipPlanes(s) > 0) {
        std::cerr << "fxport: " << program.label << ": D3D9 clip planes are not applied to draws with geometry or domain shaders\n";
    }
    if (!wanted.any()) return program.program;
    const FixedFunctionVariant& v = variantFor(
        *this, program, wanted.clipPlanes | (wanted.pointSizeLocation + 1) << 8,
        [&](std::string& why) { return xlate::vertexFixedFunctionVariant(program.shader->glsl, wanted, why); },
        "D3D9 clip planes / point size");
    if (!v.program) return program.program;
    if (wanted.clipPlanes > 0) {
        float planes[4 * xlate::kMaxUserClipPlanes] = {};
        int n = 0;
        for (int i = 0; i < xlate::kMaxUserClipPlanes; ++i) {
            if (!((s.ClipPlaneEnable >> i) & 1)) continue;
            const Vector4& p = s.ClipPlanes[std::size_t(i)];
            planes[4 * n] = p.X, planes[4 * n + 1] = p.Y, planes[4 * n + 2] = p.Z, planes[4 * n + 3] = p.W;
            ++n;
        }
        backend->setUniform(v.program, v.locations[kClipPlanes], planes, xlate::kMaxUserClipPlanes);
    }
    if (wanted.pointSizeLocation >= 0) {
        const float size[4] = {s.PointSize, s.PointSizeMin, s.PointSizeMax, 0};
        backend->setUniform(v.program, v.locations[kPointSize], size, 1);
    }
    return v.program;
}

void GraphicsDevice::Impl::applyPointSize(const ShaderProgram& last) {
    const FixedFunctionState& s = device.FixedFunction;
    const bool fromShader = last.stage == 0 && pointSizeOutput(*last.shader) >= 0;
    // D3D9 clamps D3DRS_POINTSIZE to [POINTSIZE_MIN, POINTSIZE_MAX] (max first: a min above the max
    // wins, as D3D9's clamp does); GL's own range limits what is left.
    shadow.setPointSize(std::max(std::min(s.PointSize, s.PointSizeMax), s.PointSizeMin), fromShader);
}

void GraphicsDevice::Impl::releaseFixedFunctionVariants(const ShaderProgram& program) {
    for (auto& [key, v] : program.fixedFunctionVariants) deleteProgram(v.program);
    program.fixedFunctionVariants.clear();
}

}  // namespace fxport
