// Effect construction (programs, uniform buffers, defaults) and the technique/pass/parameter
// collections. Apply() is in effect_pass.cpp, SetValue/GetValue in effect_parameter.cpp.
#include "fxport/graphics/effect.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "effect_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fxport {

namespace {

std::vector<EffectAnnotation> annotationsOf(const std::vector<xlate::Annotation>& in) {
    std::vector<EffectAnnotation> out;
    for (const xlate::Annotation& a : in) out.push_back({a.name, a.type, a.value});
    return out;
}

GLenum glStage(xlate::ShaderStage stage) {
    switch (stage) {
    case xlate::ShaderStage::Vertex: return GL_VERTEX_SHADER;
    case xlate::ShaderStage::Pixel: return GL_FRAGMENT_SHADER;
    case xlate::ShaderStage::Geometry: return GL_GEOMETRY_SHADER;
    }
    return GL_VERTEX_SHADER;
}

int stageIndex(xlate::ShaderStage stage) {
    switch (stage) {
    case xlate::ShaderStage::Vertex: return 0;
    case xlate::ShaderStage::Pixel: return 1;
    case xlate::ShaderStage::Geometry: return 2;
    }
    return 0;
}

xlate::CompiledEffect compileFile(const std::string& path, const EffectOptions& options) {
    xlate::CompileOptions o;
    o.includeDirs = options.includeDirs;
    o.defines = options.defines;
    o.techniques = options.techniques;
    o.useCache = options.useCache;
    o.cacheDir = options.cacheDir;
    return xlate::compileEffectFile(path, o);
}

}  // namespace

std::string Effect::Impl::hlslTypeName(const xlate::Parameter& p) {
    std::string base;
    switch (p.type) {
    case xlate::ParameterType::Void: base = "void"; break;
    case xlate::ParameterType::Bool: base = "bool"; break;
    case xlate::ParameterType::Int: base = "int"; break;
    case xlate::ParameterType::UInt: base = "uint"; break;
    case xlate::ParameterType::Float: base = "float"; break;
    case xlate::ParameterType::String: base = "string"; break;
    case xlate::ParameterType::Texture: base = "texture"; break;
    case xlate::ParameterType::Texture1D: base = "texture1D"; break;
    case xlate::ParameterType::Texture2D: base = "texture2D"; break;
    case xlate::ParameterType::Texture3D: base = "texture3D"; break;
    case xlate::ParameterType::TextureCube: base = "textureCUBE"; break;
    case xlate::ParameterType::Sampler: base = "sampler"; break;
    case xlate::ParameterType::Sampler1D: base = "sampler1D"; break;
    case xlate::ParameterType::Sampler2D: base = "sampler2D"; break;
    case xlate::ParameterType::Sampler3D: base = "sampler3D"; break;
    case xlate::ParameterType::SamplerCube: base = "samplerCUBE"; break;
    case xlate::ParameterType::SamplerState: base = "SamplerState"; break;
    }
    if (p.parameterClass == xlate::ParameterClass::Struct) base = "struct";
    if (p.parameterClass == xlate::ParameterClass::Vector) base += std::to_string(p.columns);
    if (p.parameterClass == xlate::ParameterClass::Matrix) base += std::to_string(p.rows) + "x" + std::to_string(p.columns);
    if (p.elements > 0) base += "[" + std::to_string(p.elements) + "]";
    return base;
}

Effect::Effect(fxport::GraphicsDevice& device, const std::string& fxPath, const EffectOptions& options)
    : GraphicsResource(device, "Effect"), impl_(std::make_unique<Impl>()) {
    impl_->compiled = compileFile(fxPath, options);
    build();
}

Effect::Effect(fxport::GraphicsDevice& device, const xlate::CompiledEffect& compiled)
    : GraphicsResource(device, "Effect"), impl_(std::make_unique<Impl>()) {
    impl_->compiled = compiled;
    build();
}

std::unique_ptr<Effect> Effect::FromCompiledFile(fxport::GraphicsDevice& device, const std::string& path) {
    return std::make_unique<Effect>(device, xlate::loadEffectFile(path));
}

Effect::~Effect() { disposeFromDestructor(); }

const xlate::CompiledEffect& Effect::compiled() const { return impl_->compiled; }
const std::string& Effect::sourcePath() const { return impl_->compiled.sourcePath; }

void Effect::build() {
    Impl& e = *impl_;
    GraphicsDevice::Impl& d = device().impl();
    const xlate::CompiledEffect& c = e.compiled;
    e.displayName = std::filesystem::path(c.sourcePath).filename().string();
    if (e.displayName.empty()) e.displayName = "<effect>";
    Name = e.displayName;

    // Uniform blocks with their CPU shadows.
    for (const xlate::UniformBlock& ub : c.uniformBlocks) {
        Impl::Block block;
        block.binding = ub.binding;
        block.shadow.assign(std::size_t(std::max(ub.size, 0)), 0);
        if (ub.size > 0) {
            block.buffer = d.createBuffer();
            glNamedBufferStorage(block.buffer, ub.size, nullptr, GL_DYNAMIC_STORAGE_BIT);
            block.dirtyBegin = 0;
            block.dirtyEnd = ub.size;
        }
        e.blocks.push_back(std::move(block));
    }

    // Programs (the device moves each uniform block to its stage's range of binding points).
    try {
        for (const xlate::CompiledShader& shader : c.shaders) {
            ShaderProgram p;
            p.stage = stageIndex(shader.profile.stage);
            p.shader = &shader;
            p.label = e.displayName + ": " + shader.entryPoint + " (" + shader.profile.name + ")";
            p.program = d.createProgram(glStage(shader.profile.stage), shader.glsl, p.label);
            e.programs.push_back(p);
        }
    } catch (...) {
        releaseGpuObjects();
        throw;
    }

    // Parameters and their defaults.
    Parameters.effect_ = this;
    e.textures.assign(c.parameters.size(), nullptr);
    for (std::size_t i = 0; i < c.parameters.size(); ++i) {
        Parameters.items_.push_back(EffectParameter(this, int(i)));
        e.parameterIndex.emplace(c.parameters[i].name, int(i));
        const xlate::Parameter& p = c.parameters[i];
        if (p.offset < 0 || p.defaultValue.empty() || p.block < 0 || std::size_t(p.block) >= e.blocks.size()) continue;
        Impl::Block& block = e.blocks[std::size_t(p.block)];
        std::size_t k = 0;
        for (int el = 0; el < std::max(1, p.elements); ++el)
            for (int r = 0; r < p.rows; ++r)
                for (int col = 0; col < p.columns && k < p.defaultValue.size(); ++col, ++k) {
                    int at = Impl::byteOffset(p, el, r, col);
                    if (at < 0 || std::size_t(at) + 4 > block.shadow.size()) continue;
                    double v = p.defaultValue[k];
                    if (p.type == xlate::ParameterType::Float) {
                        float f = float(v);
                        std::memcpy(&block.shadow[std::size_t(at)], &f, 4);
                    } else if (p.type == xlate::ParameterType::Int) {
                        std::int32_t n = std::int32_t(v);
                        std::memcpy(&block.shadow[std::size_t(at)], &n, 4);
                    } else {
                        std::uint32_t n = v != 0 ? (p.type == xlate::ParameterType::Bool ? 1u : std::uint32_t(v)) : 0u;
                        std::memcpy(&block.shadow[std::size_t(at)], &n, 4);
                    }
                }
    }

    // Techniques and passes.
    Techniques.owner_ = e.displayName;
    for (std::size_t t = 0; t < c.techniques.size(); ++t) {
        auto technique = std::make_unique<EffectTechnique>();
        technique->name_ = c.techniques[t].name;
        technique->annotations_ = annotationsOf(c.techniques[t].annotations);
        technique->Passes.owner_ = e.displayName + " technique '" + technique->name_ + "'";
        for (std::size_t p = 0; p < c.techniques[t].passes.size(); ++p) {
            const xlate::Pass& pass = c.techniques[t].passes[p];
            technique->Passes.items_.push_back(
                EffectPass(this, int(t), int(p), pass.name, annotationsOf(pass.annotations)));
        }
        Techniques.items_.push_back(std::move(technique));
    }
    CurrentTechnique = Techniques.items_.empty() ? nullptr : Techniques.items_[0].get();
    d.effects.push_back(this);
}

void Effect::releaseGpuObjects() {
    GraphicsDevice::Impl& d = device().impl();
    for (ShaderProgram& p : impl_->programs) {
        // The device may still point at this effect's ShaderProgram records (the GL program
        // itself can outlive them when another effect shares it).
        for (const ShaderProgram*& bound : d.shaders)
            if (bound == &p) bound = nullptr;
        d.deleteProgram(p.program);
    }
    for (Impl::Block& b : impl_->blocks) d.deleteBuffer(b.buffer);
    d.effects.erase(std::remove(d.effects.begin(), d.effects.end(), this), d.effects.end());
}

// --- collections

EffectParameter& EffectParameterCollection::operator[](const std::string& name) {
    if (EffectParameter* p = find(name)) return *p;
    std::string known;
    for (const EffectParameter& p : items_) known += (known.empty() ? "" : ", ") + p.Name();
    throw ArgumentError("Effect '" + (effect_ ? effect_->impl().displayName : std::string("?")) +
                        "' has no parameter named '" + name + "' (its parameters: " +
                        (known.empty() ? "none" : known) + ")");
}

EffectParameter& EffectParameterCollection::operator[](int index) {
    if (index < 0 || index >= Count())
        throw ArgumentError("Effect '" + (effect_ ? effect_->impl().displayName : std::string("?")) + "': parameter index " +
                            std::to_string(index) + " is outside 0.." + std::to_string(Count() - 1));
    return items_[std::size_t(index)];
}

EffectParameter* EffectParameterCollection::find(const std::string& name) {
    if (!effect_) return nullptr;
    auto& index = effect_->impl().parameterIndex;
    auto it = index.find(name);
    return it == index.end() ? nullptr : &items_[std::size_t(it->second)];
}

EffectPass& EffectPassCollection::operator[](int index) {
    if (index < 0 || index >= Count())
        throw ArgumentError(owner_ + ": pass index " + std::to_string(index) + " is outside 0.." + std::to_string(Count() - 1));
    return items_[std::size_t(index)];
}

EffectPass& EffectPassCollection::operator[](const std::string& name) {
    for (EffectPass& p : items_)
        if (p.Name() == name) return p;
    throw ArgumentError(owner_ + " has no pass named '" + name + "'");
}

EffectTechnique* EffectTechniqueCollection::operator[](int index) {
    if (index < 0 || index >= Count())
        throw ArgumentError("Effect '" + owner_ + "': technique index " + std::to_string(index) + " is outside 0.." +
                            std::to_string(Count() - 1));
    return items_[std::size_t(index)].get();
}

EffectTechnique* EffectTechniqueCollection::operator[](const std::string& name) {
    for (auto& t : items_)
        if (t->Name() == name) return t.get();
    std::string known;
    for (auto& t : items_) known += (known.empty() ? "" : ", ") + t->Name();
    throw ArgumentError("Effect '" + owner_ + "' has no technique named '" + name + "' (its techniques: " + known + ")");
}

}  // namespace fxport
