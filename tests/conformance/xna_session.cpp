// The XNA session (see xna_session.h).
#include "xna_session.h"

#include <cstring>
#include <span>

#include "fxport/graphics.h"
#include "fxport/xlate/compiled_effect.h"
#include "section_compiler.h"
#include "uniform_layout.h"

namespace conformance {

namespace {

// The value of one parameter scalar from vkd3d's uniform words. SM4+ constant buffers hold ints as
// ints; D3D9's float registers hold every numeric constant as a float.
double scalarValue(const fxport::xlate::Parameter& p, std::uint32_t word, int model) {
    float f;
    std::memcpy(&f, &word, 4);
    if (p.type == fxport::xlate::ParameterType::Float) return double(f);
    if (model < 40) return p.type == fxport::xlate::ParameterType::Bool ? (f != 0.0f ? 1.0 : 0.0) : double(int(f));
    if (p.type == fxport::xlate::ParameterType::Bool) return word != 0 ? 1.0 : 0.0;
    if (p.type == fxport::xlate::ParameterType::UInt) return double(word);
    return double(std::int32_t(word));
}

}  // namespace

std::string ShaderSet::allSource() const {
    std::string all;
    for (const StageSource& s : stages) all += s.source;
    return all;
}

XnaSession::XnaSession(int model, SectionCompiler& compiler, std::string cacheDir)
    : model_(model), compiler_(compiler), cacheDir_(std::move(cacheDir)) {}

XnaSession::~XnaSession() = default;

fxport::Effect& XnaSession::effectOf(const ShaderSet& shaders) {
    std::string key = shaders.require.matrixPacking;
    for (const StageSource& s : shaders.stages) key += "\x01" + std::to_string(int(s.stage)) + "\x01" + s.source;
    auto known = effects_.find(key);
    if (known != effects_.end()) return *known->second;
    std::vector<fxport::Effect::ShaderFile> files;
    for (const StageSource& s : shaders.stages)
        files.push_back({compiler_.writeSource(s.source, s.line, shaders.require, ".hlsl"), "main", shaderProfile(s.stage, model_)});
    fxport::EffectOptions options;
    options.cacheDir = cacheDir_;
    options.useCache = !cacheDir_.empty();
    std::unique_ptr<fxport::Effect> effect = fxport::Effect::FromShaderFiles(gpu_.device(), files, options);
    effect->Precompile();
    return *(effects_[key] = std::move(effect));
}

std::string XnaSession::applyUniforms(fxport::Effect& effect, const std::string& source, const std::vector<std::uint32_t>& uniforms) {
    const fxport::xlate::CompiledEffect& compiled = effect.compiled();
    std::string uncovered = uncoveredUniformRead(compiled);
    if (!uncovered.empty()) throw Unsupported(uncovered);
    UniformLayout layout = computeUniformLayout(compiled, source, model_);
    for (const ParameterPlacement& placement : layout.placements) {
        const fxport::xlate::Parameter& top = compiled.parameters[std::size_t(placement.parameter)];
        if (!placement.settable) throw Unsupported(placement.why);
        if (top.offset < 0) continue;  // no shader reads it
        const fxport::xlate::Parameter& p = placement.leaf ? *placement.leaf : top;
        // D3D reads 0 past the end of the constant data bound (and ignores HLSL initializers of
        // loose shaders' globals), so every parameter is written, unset ones as 0.
        std::vector<float> floats;
        std::vector<int> ints;
        for (int off : placement.scalarOffsets) {
            std::uint32_t word = std::size_t(off) < uniforms.size() ? uniforms[std::size_t(off)] : 0u;
            double v = scalarValue(p, word, model_);
            if (p.type == fxport::xlate::ParameterType::Float) floats.push_back(float(v));
            else ints.push_back(int(std::int64_t(v)));
        }
        fxport::EffectParameter* parameter = &effect.Parameters[top.name];
        for (const auto& [isMember, k] : placement.path) parameter = isMember ? &parameter->StructureMembers()[k] : &parameter->Elements()[k];
        if (p.type == fxport::xlate::ParameterType::Float) parameter->SetValue(std::span<const float>(floats));
        else parameter->SetValue(std::span<const int>(ints));
    }
    return layout.guess;
}

std::string XnaSession::draw(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, const DrawCall& call) {
    fxport::Effect& effect = effectOf(shaders);
    const std::string all = shaders.allSource();
    std::string guess = applyUniforms(effect, all, uniforms);
    gpu_.draw(effect, all, model_, call);
    return guess;
}

std::string XnaSession::dispatch(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, int x, int y, int z) {
    fxport::Effect& effect = effectOf(shaders);
    const std::string all = shaders.allSource();
    std::string guess = applyUniforms(effect, all, uniforms);
    gpu_.dispatch(effect, all, model_, x, y, z);
    return guess;
}

}  // namespace conformance
