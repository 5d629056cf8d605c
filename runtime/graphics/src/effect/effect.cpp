// Effect construction (programs, uniform buffers, defaults) and the technique/pass/parameter
// collections. Apply() is in effect_pass.cpp, SetValue/GetValue in effect_parameter.cpp.
#include "fxport/graphics/effect.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "device/effect_programs.h"
#include "effect/effect_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/file_reading.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fxport {

namespace {

std::vector<EffectAnnotation> annotationsOf(const std::vector<xlate::Annotation>& in) {
    std::vector<EffectAnnotation> out;
    for (const xlate::Annotation& a : in) out.push_back({a.name, a.type, a.value});
    return out;
}


int stageIndex(xlate::ShaderStage stage) {
    switch (stage) {
    case xlate::ShaderStage::Vertex: return 0;
    case xlate::ShaderStage::Pixel: return 1;
    case xlate::ShaderStage::Geometry: return 2;
    case xlate::ShaderStage::Hull: return kHullStage;
    case xlate::ShaderStage::Domain: return kDomainStage;
    case xlate::ShaderStage::Compute: return kComputeStage;
    }
    return 0;
}

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

xlate::CompileOptions compileOptions(const EffectOptions& options, std::vector<std::string> techniques) {
    xlate::CompileOptions o;
    o.includeDirs = options.includeDirs;
    o.includeRoot = options.includeRoot;
    o.defines = options.defines;
    o.techniques = techniques.empty() ? options.techniques : std::move(techniques);
    o.useCache = options.useCache;
    o.cacheDir = options.cacheDir;
    return o;
}

// The effect's bytes, read once at load: techniques compiled later compile the same text as the
// outline (include files are read when compiling, as the cache key assumes).
std::string readEffectSource(const std::string& path) {
    // xlate compiles at most 4 MiB per source file; anything larger is refused before reading.
    platform::FileBytes file = platform::readUntrustedFile(path, std::size_t{4} << 20);
    if (!file.ok()) {
        xlate::Diagnostic d;
        d.id = file.tooLarge ? xlate::diag::kInputTooLarge : xlate::diag::kFileUnreadable;
        d.message = file.error;
        d.location = {path, 0, 0};
        throw xlate::CompileError({d});
    }
    return std::string(file.bytes.begin(), file.bytes.end());
}

// Compiles the effect's kept source: `techniques` only, or every technique when empty.
xlate::CompiledEffect compileSource(const Effect::Impl& e, std::vector<std::string> techniques) {
    if (!e.fromSource)
        throw InvalidOperation("Effect '" + e.displayName + "' was built from compiled code and has no source to compile");
    return xlate::compileEffectSource(e.source, e.sourcePath, compileOptions(e.options, std::move(techniques)));
}

// The byte ranges of each uniform block a shader reads, sorted and merged.
std::vector<Effect::Impl::BlockReads> blockReadsOf(const xlate::CompiledShader& shader, std::size_t blockCount) {
    std::vector<Effect::Impl::BlockReads> out;
    for (const xlate::UniformRange& r : shader.uniformRangesRead) {
        if (r.size <= 0 || r.block < 0 || std::size_t(r.block) >= blockCount) continue;
        auto it = std::find_if(out.begin(), out.end(), [&](const auto& b) { return b.block == r.block; });
        if (it == out.end()) it = out.insert(out.end(), Effect::Impl::BlockReads{r.block, {}});
        it->ranges.push_back({r.offset, r.offset + r.size});
    }
    for (auto& b : out) {
        std::sort(b.ranges.begin(), b.ranges.end());
        std::vector<std::pair<int, int>> merged;
        for (const auto& r : b.ranges) {
            if (!merged.empty() && r.first <= merged.back().second) merged.back().second = std::max(merged.back().second, r.second);
            else merged.push_back(r);
        }
        b.ranges = std::move(merged);
    }
    return out;
}

// The texture units a shader samples, with texture parameters resolved to indices and the
// effect's sampler_state decoded.
std::vector<SamplerSlot> samplerSlotsOf(const xlate::CompiledShader& shader, const Effect::Impl& e) {
    std::vector<SamplerSlot> out;
    for (const xlate::SamplerBinding& sampler : shader.samplers) {
        if (sampler.unit < 0 || sampler.unit >= kMaxTextureSlots) continue;
        SamplerSlot slot;
        slot.unit = sampler.unit;
        if (shader.profile.stage == xlate::ShaderStage::Vertex && shader.profile.isD3D9()) slot.vertexRegister = sampler.samplerRegister;
        if (!sampler.textureParameter.empty()) {
            auto it = e.parameterIndex.find(sampler.textureParameter);
            if (it != e.parameterIndex.end()) slot.textureParameter = it->second;
        }
        slot.state = decodeSamplerState(sampler.state);
        if (!sampler.stateParameters.empty()) slot.literal = sampler.state;  // decoded again with them at Apply()
        for (const xlate::SamplerStateParameter& p : sampler.stateParameters) {
            SamplerStateFromParameter from{p.field, p.element};  // leaves the element index on the stack (none: 0)
            from.read.push_back({xlate::SelectorOp::Kind::IndexParameter, p.parameter});
            slot.fromParameters.push_back(std::move(from));
        }
        out.push_back(slot);
        // An array of textures (`Texture2D t[3]`): its other elements sample the units after it,
        // fed by GraphicsDevice.Textures (a texture parameter feeds element 0).
        for (int k = 1; k < sampler.elements && sampler.unit + k < kMaxTextureSlots; ++k) {
            SamplerSlot element = slot;
            element.unit = sampler.unit + k;
            if (slot.vertexRegister >= 0) element.vertexRegister = slot.vertexRegister + k;
            element.textureParameter = SamplerSlot{}.textureParameter;
            out.push_back(element);
        }
    }
    return out;
}

// A D3D9 texture stage a pass sets for later passes (xlate::Pass::textureStages) as a slot.
SamplerSlot textureStageSlot(const xlate::TextureStage& stage, const Effect::Impl& e) {
    SamplerSlot slot;
    slot.unit = stage.stage;
    if (auto it = e.parameterIndex.find(stage.textureParameter); !stage.textureParameter.empty() && it != e.parameterIndex.end())
        slot.textureParameter = it->second;
    slot.state = decodeSamplerState(stage.state);
    return slot;
}

EffectWarningHandler& warningHandler() {
    static EffectWarningHandler handler = [](const std::string& warning) { std::cerr << "fxport: " << warning << "\n"; };
    return handler;
}

}  // namespace

void reportEffectWarning(const std::string& warning) {
    if (const EffectWarningHandler& report = warningHandler()) report(warning);
}

void forgetTexture(Effect& effect, const Texture* texture) { effectImpl(effect).forgetTexture(texture); }

EffectWarningHandler SetEffectWarningHandler(EffectWarningHandler handler) {
    EffectWarningHandler old = std::move(warningHandler());
    warningHandler() = std::move(handler);
    return old;
}

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
    Impl& e = *impl_;
    e.fromSource = true;
    e.sourcePath = fxPath;
    e.options = options;
    auto started = Clock::now();
    e.source = readEffectSource(fxPath);
    if (options.precompile) {
        e.outline = compileSource(e, {});
    } else {
        xlate::CompileOptions o = compileOptions(options, {});
        o.skipShaders = true;
        e.outline = xlate::compileEffectSource(e.source, fxPath, o);
    }
    e.loadMilliseconds = millisecondsSince(started);
    build();
    if (options.precompile) linkWhole(std::make_shared<const xlate::CompiledEffect>(e.outline));
}

Effect::Effect(fxport::GraphicsDevice& device, const EffectSource& source, const EffectOptions& options)
    : GraphicsResource(device, "Effect"), impl_(std::make_unique<Impl>()) {
    Impl& e = *impl_;
    e.fromSource = true;
    e.sourcePath = source.virtualPath;
    e.options = options;
    auto started = Clock::now();
    e.source = source.text;
    xlate::CompileOptions o = compileOptions(options, {});
    o.skipShaders = !options.precompile;
    e.outline = options.precompile ? compileSource(e, {}) : xlate::compileEffectSource(e.source, e.sourcePath, o);
    e.loadMilliseconds = millisecondsSince(started);
    build();
    if (options.precompile) linkWhole(std::make_shared<const xlate::CompiledEffect>(e.outline));
}

Effect::Effect(fxport::GraphicsDevice& device, const xlate::CompiledEffect& compiled)
    : GraphicsResource(device, "Effect"), impl_(std::make_unique<Impl>()) {
    Impl& e = *impl_;
    e.outline = compiled;
    build();
    // Already compiled: link now (SpriteBatch's and Model's built-in effects come this way).
    linkWhole(std::make_shared<const xlate::CompiledEffect>(compiled));
}

void Effect::linkWhole(std::shared_ptr<const xlate::CompiledEffect> whole) {
    Impl& e = *impl_;
    try {
        Impl::Code& code = e.addCode(std::move(whole), device());
        e.whole = &code;
        for (std::size_t t = 0; t < e.techniqueCode.size(); ++t) e.techniqueCode[t] = {&code, int(t)};
    } catch (...) {
        releaseGpuObjects();  // the constructor fails: leave nothing registered with the device
        throw;
    }
}

std::unique_ptr<Effect> Effect::FromCompiledFile(fxport::GraphicsDevice& device, const std::string& path) {
    return std::make_unique<Effect>(device, xlate::loadEffectFile(path));
}

Effect::~Effect() { disposeFromDestructor(); }

std::unique_ptr<Effect> Effect::Clone() {
    if (IsDisposed()) throw InvalidOperation("Effect '" + impl_->displayName + "'.Clone(): the effect was disposed");
    // Both whole, so their blocks have the final layouts and the values copy byte for byte.
    auto clone = std::make_unique<Effect>(device(), compiled());
    copyValuesTo(*clone);
    return clone;
}

void Effect::copyValuesTo(Effect& clone) {
    // Blocks of one size are copied: after Clone's compiled() both effects have the final layouts;
    // a stock effect and its clone, built alike, have the same ones (and push their properties
    // into them at each Apply anyway). Compiling every permutation here would take seconds.
    Impl& from = *impl_;
    Impl& to = *clone.impl_;
    for (std::size_t b = 0; b < from.blocks.size() && b < to.blocks.size(); ++b) {
        ConstantBlock& target = to.blocks[b].constants;
        if (target.bytes.size() != from.blocks[b].constants.bytes.size()) continue;
        target.bytes = from.blocks[b].constants.bytes;
        target.dirtyBegin = 0;
        target.dirtyEnd = int(target.bytes.size());
    }
    to.textures = from.textures;
    to.unread = from.unread;
    clone.Name = Name;
    for (std::size_t t = 0; t < Techniques.items_.size(); ++t)
        if (CurrentTechnique == Techniques.items_[t].get() && t < clone.Techniques.items_.size()) clone.CurrentTechnique = clone.Techniques.items_[t].get();
}

const xlate::CompiledEffect& Effect::compiled() const {
    if (!impl_->whole) const_cast<Effect*>(this)->Precompile();
    return *impl_->whole->effect;
}

void Effect::Precompile() {
    if (IsDisposed()) throw InvalidOperation("Effect '" + impl_->displayName + "'.Precompile(): the effect was disposed");
    impl_->compileAll(device());
}

const std::string& Effect::sourcePath() const { return impl_->outline.sourcePath; }

EffectStatistics Effect::statistics() const {
    const Impl& e = *impl_;
    EffectStatistics s;
    s.techniqueCount = int(e.techniqueCode.size());
    for (std::size_t t = 0; t < e.techniqueCode.size(); ++t)
        if (e.techniqueCode[t].code) s.compiledTechniques.push_back(e.outline.techniques[t].name);
    s.loadMilliseconds = e.loadMilliseconds;
    s.compileMilliseconds = e.compileMilliseconds;
    s.linkMilliseconds = e.linkMilliseconds;
    s.constantBytesUploaded = e.constantBytesUploaded;
    s.constantUploads = e.constantUploads;
    return s;
}

bool EffectTechnique::IsCompiled() const {
    return effect_ && effectImpl(*effect_).techniqueCode[std::size_t(index_)].code != nullptr;
}

// --- layouts

void Effect::Impl::layOutProvisionally() {
    // Each block's numeric parameters packed one after another, row-major, 4 bytes a scalar: a
    // place to keep values until a compiled shader says where they really go.
    // A struct's members likewise, one element after another.
    std::vector<int> sizes(blocks.size(), 0);
    auto numeric = [](const xlate::Parameter& p) {
        return p.parameterClass == xlate::ParameterClass::Scalar || p.parameterClass == xlate::ParameterClass::Vector ||
               p.parameterClass == xlate::ParameterClass::Matrix;
    };
    auto place = [](xlate::Parameter& p, int at) {
        p.rowMajor = true;
        p.matrixStride = p.columns * 4;
        p.arrayStride = p.rows * p.columns * 4;
        p.size = p.arrayStride * std::max(1, p.elements);
        p.offset = at;
    };
    for (xlate::Parameter& p : outline.parameters) {
        bool isStruct = p.parameterClass == xlate::ParameterClass::Struct;
        if (p.isStatic || !(numeric(p) || isStruct) || p.block < 0 || std::size_t(p.block) >= blocks.size()) continue;
        if (!blocks[std::size_t(p.block)].provisional) continue;
        int& at = sizes[std::size_t(p.block)];
        if (isStruct) {
            int element = 0;
            for (xlate::Parameter& m : p.members) {
                m.block = p.block;
                if (!numeric(m)) continue;  // a struct inside: no place until compiled
                place(m, at + element);
                element += m.size;
            }
            p.offset = at;
            p.arrayStride = element;
            p.size = element * std::max(1, p.elements);
        } else {
            place(p, at);
        }
        at += p.size;
    }
    for (std::size_t b = 0; b < blocks.size(); ++b)
        if (blocks[b].provisional) blocks[b].constants.bytes.assign(std::size_t(sizes[b]), 0);
}

void Effect::Impl::keepUnreadValue(int index) {
    const xlate::Parameter& p = outline.parameters[std::size_t(index)];
    std::vector<double>& kept = unread[std::size_t(index)];
    kept.assign(std::size_t(p.rows * p.columns * std::max(1, p.elements)), 0.0);
    const ConstantBlock& from = blocks[std::size_t(p.block)].constants;
    from.forEachScalar(p, std::max(1, p.elements), [&](const ConstantBlock::Scalar& s) { kept[std::size_t(s.index)] = from.decode(p, s.offset); });
}

namespace {

// A struct parameter's member values from the provisional block to the compiled layout, element by
// element (member offsets are those inside element 0).
void moveStructValues(const xlate::Parameter& p, const xlate::Parameter& r, const ConstantBlock& from, ConstantBlock& to) {
    if (p.offset < 0 || r.offset < 0 || p.members.size() != r.members.size()) return;
    for (int e = 0; e < std::max(1, p.elements); ++e)
        for (std::size_t k = 0; k < p.members.size(); ++k) {
            xlate::Parameter pm = p.members[k], rm = r.members[k];
            if (pm.offset < 0 || rm.offset < 0 || pm.parameterClass == xlate::ParameterClass::Struct) continue;
            pm.offset += e * p.arrayStride;
            rm.offset += e * r.arrayStride;
            from.forEachScalar(pm, std::max(1, pm.elements), [&](const ConstantBlock::Scalar& s) {
                int at = ConstantBlock::offsetOf(rm, s.element, s.row, s.column);
                if (to.holds(at)) std::memcpy(&to.bytes[std::size_t(at)], &from.bytes[std::size_t(s.offset)], 4);
            });
        }
}

}  // namespace

void Effect::Impl::adoptLayouts(const xlate::CompiledEffect& code, GraphicsDevice& device) {
    if (code.parameters.size() != outline.parameters.size() || code.uniformBlocks.size() != blocks.size())
        throw InvalidOperation("Effect '" + displayName + "': a technique compiled with " + std::to_string(code.parameters.size()) +
                               " parameters and " + std::to_string(code.uniformBlocks.size()) + " uniform blocks, the effect loaded with " +
                               std::to_string(outline.parameters.size()) + " and " + std::to_string(blocks.size()) + " (internal error)");
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const xlate::UniformBlock& real = code.uniformBlocks[b];
        Block& block = blocks[b];
        if (real.size <= 0) continue;  // no shader of this code reads the block: nothing learnt
        if (!block.provisional) {
            if (int(block.constants.bytes.size()) != real.size)
                throw InvalidOperation("Effect '" + displayName + "': uniform block '" + real.name + "' has " + std::to_string(real.size) +
                                       " bytes in one technique and " + std::to_string(block.constants.bytes.size()) + " in another (internal error)");
            continue;
        }
        // Move each value from its provisional place to the real one.
        ConstantBlock moved;
        moved.bytes.assign(std::size_t(real.size), 0);
        for (std::size_t i = 0; i < outline.parameters.size(); ++i) {
            xlate::Parameter& p = outline.parameters[i];
            const xlate::Parameter& r = code.parameters[i];
            if (p.name != r.name)
                throw InvalidOperation("Effect '" + displayName + "': parameter " + std::to_string(i) + " is '" + r.name +
                                       "' in a compiled technique but '" + p.name + "' in the effect (internal error)");
            if (r.block != int(b)) continue;
            if (p.parameterClass == xlate::ParameterClass::Struct) {
                moveStructValues(p, r, block.constants, moved);
                p.offset = r.offset;
                p.size = r.size;
                p.arrayStride = r.arrayStride;
                p.members = r.members;
                continue;
            }
            if (p.offset >= 0 && r.offset < 0) keepUnreadValue(int(i));  // no shader reads it: its value stays the effect's
            if (p.offset >= 0 && r.offset >= 0)
                block.constants.forEachScalar(p, std::max(1, p.elements), [&](const ConstantBlock::Scalar& from) {
                    int to = ConstantBlock::offsetOf(r, from.element, from.row, from.column);
                    if (moved.holds(to))  // else trimmed by the optimiser
                        std::memcpy(&moved.bytes[std::size_t(to)], &block.constants.bytes[std::size_t(from.offset)], 4);
                });
            p.offset = r.offset;
            p.size = r.size;
            p.matrixStride = r.matrixStride;
            p.arrayStride = r.arrayStride;
            p.rowMajor = r.rowMajor;
        }
        block.constants = std::move(moved);
        block.provisional = false;
        block.buffer = effects::createConstantBuffer(device, std::size_t(real.size));
        block.constants.markDirty(0, real.size);
    }
    for (std::size_t b = 0; b < blocks.size(); ++b)
        if (!blocks[b].provisional) outline.uniformBlocks[b].size = int(blocks[b].constants.bytes.size());
}

// --- compiling

Effect::Impl::Code& Effect::Impl::addCode(std::shared_ptr<const xlate::CompiledEffect> effect, GraphicsDevice& device) {
    adoptLayouts(*effect, device);
    auto code = std::make_unique<Code>();
    code->effect = std::move(effect);
    auto started = Clock::now();
    try {
        for (const xlate::CompiledShader& shader : code->effect->shaders) {
            ShaderProgram p;
            p.stage = stageIndex(shader.profile.stage);
            p.shader = &shader;
            p.label = displayName + ": " + shader.entryPoint + " (" + shader.profile.name + ")";
            p.mayDiscard = shader.glsl.find("discard") != std::string::npos;
            p.program = effects::createProgram(device, int(shader.profile.stage), shader, shader.glsl, p.label);
            code->programs.push_back(p);
            code->reads.push_back(blockReadsOf(shader, blocks.size()));
            code->samplers.push_back(samplerSlotsOf(shader, *this));
        }
        for (const xlate::Technique& technique : code->effect->techniques) {
            std::vector<PassStates>& passes = code->passStates.emplace_back();
            for (const xlate::Pass& pass : technique.passes) {
                PassStates& states = passes.emplace_back(decodePassStates(pass));
                for (const xlate::TextureStage& stage : pass.textureStages) states.textureStages.push_back(textureStageSlot(stage, *this));
            }
        }
    } catch (...) {
        for (ShaderProgram& p : code->programs) effects::deleteProgram(device, p.program);
        throw;
    }
    linkMilliseconds += millisecondsSince(started);
    codes.push_back(std::move(code));
    return *codes.back();
}

const Effect::Impl::TechniqueCode& Effect::Impl::ensureCompiled(int technique, GraphicsDevice& device) {
    TechniqueCode& tc = techniqueCode[std::size_t(technique)];
    if (tc.code) return tc;
    const std::string& name = outline.techniques[std::size_t(technique)].name;
    auto started = Clock::now();
    auto effect = std::make_shared<const xlate::CompiledEffect>(compileSource(*this, {name}));
    compileMilliseconds += millisecondsSince(started);
    // The n-th technique of this name in the outline is the n-th in the code (names may repeat).
    int nth = 0;
    for (int t = 0; t < technique; ++t) nth += outline.techniques[std::size_t(t)].name == name;
    int index = -1;
    for (std::size_t t = 0; t < effect->techniques.size() && index < 0; ++t)
        if (effect->techniques[t].name == name && nth-- == 0) index = int(t);
    if (index < 0)
        throw InvalidOperation("Effect '" + displayName + "': compiling technique '" + name + "' produced no such technique (internal error)");
    Code& code = addCode(std::move(effect), device);
    tc = {&code, index};
    return tc;
}

void Effect::Impl::compileAll(GraphicsDevice& device) {
    if (whole) return;
    bool missing = false;
    for (const TechniqueCode& tc : techniqueCode) missing |= tc.code == nullptr;
    if (!missing && codes.size() == 1) {
        whole = codes.front().get();
        return;
    }
    auto started = Clock::now();
    auto effect = std::make_shared<const xlate::CompiledEffect>(compileSource(*this, options.techniques));
    compileMilliseconds += millisecondsSince(started);
    if (effect->techniques.size() != techniqueCode.size())
        throw InvalidOperation("Effect '" + displayName + "': the whole effect compiled to " + std::to_string(effect->techniques.size()) +
                               " techniques, it loaded with " + std::to_string(techniqueCode.size()) + " (internal error)");
    Code& code = addCode(std::move(effect), device);
    whole = &code;
    for (std::size_t t = 0; t < techniqueCode.size(); ++t)
        if (!techniqueCode[t].code) techniqueCode[t] = {&code, int(t)};
}

void Effect::Impl::releasePrograms(GraphicsDevice& device) {
    for (auto& code : codes)
        for (ShaderProgram& p : code->programs) effects::releaseProgram(device, p);
}

void Effect::build() {
    Impl& e = *impl_;
    const xlate::CompiledEffect& c = e.outline;
    e.displayName = std::filesystem::path(c.sourcePath).filename().string();
    if (e.displayName.empty()) e.displayName = "<effect>";
    Name = e.displayName;

    // No state dropped silently: what xlate could not honour is said once, here.
    if (const EffectWarningHandler& report = warningHandler())
        for (const xlate::Diagnostic& diag : c.diagnostics)
            if (diag.severity == xlate::Severity::Warning && diag.dropsState()) report(diag.format());

    // Uniform blocks: provisional shadows until compiled shaders give their layouts (an effect
    // built from compiled code adopts them right after this).
    for (const xlate::UniformBlock& ub : c.uniformBlocks) {
        Impl::Block block;
        block.binding = ub.binding;
        e.blocks.push_back(std::move(block));
    }
    e.layOutProvisionally();

    // Parameters and their defaults.
    Parameters.effect_ = this;
    e.textures.assign(c.parameters.size(), nullptr);
    e.unread.assign(c.parameters.size(), {});
    for (std::size_t i = 0; i < c.parameters.size(); ++i) {
        Parameters.items_.push_back(EffectParameter(this, int(i)));
        e.parameterIndex.emplace(c.parameters[i].name, int(i));
        const xlate::Parameter& p = c.parameters[i];
        if (p.offset < 0 || p.defaultValue.empty() || p.block < 0 || std::size_t(p.block) >= e.blocks.size()) continue;
        e.blocks[std::size_t(p.block)].constants.store(
            p, std::max(1, p.elements), [&](const ConstantBlock::Scalar& s) { return p.defaultValue[std::size_t(s.index)]; },
            [&](const ConstantBlock::Scalar& s) { return std::size_t(s.index) < p.defaultValue.size(); });
    }

    // Techniques and passes.
    Techniques.owner_ = e.displayName;
    e.techniqueCode.assign(c.techniques.size(), {});
    for (std::size_t t = 0; t < c.techniques.size(); ++t) {
        auto technique = std::make_unique<EffectTechnique>();
        technique->effect_ = this;
        technique->index_ = int(t);
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
    effects::add(device(), *this);
}

void Effect::releaseGpuObjects() {
    impl_->releasePrograms(device());
    for (Impl::Block& b : impl_->blocks) effects::deleteBuffer(device(), b.buffer);
    effects::remove(device(), *this, &impl_->reportedUnencodedSrgbWrite);
}

// --- collections

EffectParameter& EffectParameterCollection::operator[](const std::string& name) {
    if (EffectParameter* p = find(name)) return *p;
    std::string known;
    for (const EffectParameter& p : items_) known += (known.empty() ? "" : ", ") + p.Name();
    throw ArgumentError("Effect '" + (effect_ ? effectImpl(*effect_).displayName : std::string("?")) +
                        "' has no parameter named '" + name + "' (its parameters: " +
                        (known.empty() ? "none" : known) + ")");
}

EffectParameter& EffectParameterCollection::operator[](int index) {
    if (index < 0 || index >= Count())
        throw ArgumentError("Effect '" + (effect_ ? effectImpl(*effect_).displayName : std::string("?")) + "': parameter index " +
                            std::to_string(index) + " is outside 0.." + std::to_string(Count() - 1));
    return items_[std::size_t(index)];
}

EffectParameter* EffectParameterCollection::find(const std::string& name) {
    if (!effect_) return nullptr;
    if (nested_) {
        for (EffectParameter& p : items_)
            if (p.Name() == name) return &p;
        return nullptr;
    }
    auto& index = effectImpl(*effect_).parameterIndex;
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

EffectPass* EffectPassCollection::find(const std::string& name) {
    for (EffectPass& p : items_)
        if (p.Name() == name) return &p;
    return nullptr;
}

EffectTechnique* EffectTechniqueCollection::find(const std::string& name) {
    for (auto& t : items_)
        if (t->Name() == name) return t.get();
    return nullptr;
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
