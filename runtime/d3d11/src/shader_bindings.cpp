// D3D's slot allocation and cbuffer packing for one compiled shader (shader_bindings.h).
#include "shader_bindings.h"

#include <algorithm>
#include <map>
#include <set>

namespace fxport::d3d11 {

namespace {

using xlate::ParameterClass;
using RK = xlate::ResourceDeclaration::Kind;

// Registers one element of `p` takes, and the floats used in its last register.
void registerShape(const xlate::Parameter& p, int& registers, int& lastComponents) {
    if (p.parameterClass == ParameterClass::Matrix) {
        registers = p.rowMajor ? p.rows : p.columns;
        lastComponents = p.rowMajor ? p.columns : p.rows;
    } else {
        registers = 1;
        lastComponents = p.columns * p.rows;
    }
}

bool startsRegister(const xlate::Parameter& p) {
    return p.elements > 0 || p.parameterClass == ParameterClass::Matrix || p.parameterClass == ParameterClass::Struct;
}

// Lowest slot not in `taken`; marks it taken.
int lowestFree(std::set<int>& taken) {
    int slot = 0;
    while (taken.count(slot)) ++slot;
    taken.insert(slot);
    return slot;
}

int explicitRegister(const xlate::CompiledEffect& e, RK kind, const std::string& name) {
    for (const auto& r : e.resources)
        if (r.kind == kind && r.name == name) return r.explicitRegister;
    return -1;
}
int declarationOrder(const xlate::CompiledEffect& e, RK kind, const std::string& name) {
    for (std::size_t i = 0; i < e.resources.size(); ++i)
        if (e.resources[i].kind == kind && e.resources[i].name == name) return int(i);
    return int(e.resources.size());
}

// Allocates slots for `names` (used by the shader) of one kind: explicit registers first, then
// the lowest free ones in declaration order; `taken` holds slots other resources already use.
std::map<std::string, int> allocate(const xlate::CompiledEffect& e, RK kind, std::vector<std::string> names,
                                    const std::string& first = {}, std::set<int> taken = {}) {
    std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
        if (a == first || b == first) return a == first && b != first;
        return declarationOrder(e, kind, a) < declarationOrder(e, kind, b);
    });
    std::map<std::string, int> slots;
    // fxc keeps a register(xN) reservation even for a resource the shader never uses.
    for (const auto& r : e.resources)
        if (r.kind == kind && r.explicitRegister >= 0) taken.insert(r.explicitRegister);
    for (const auto& n : names)
        if (int r = explicitRegister(e, kind, n); r >= 0) {
            slots[n] = r;
            taken.insert(r);
        }
    for (const auto& n : names)
        if (!slots.count(n)) slots[n] = lowestFree(taken);
    return slots;
}

// The shader's samplers with the t#/s# registers this front end binds by: xlate's (fxc's) for a
// D3D10+ shader. An SM 1-3 shader's are D3D9 sampler registers (one s# per sampler and per combined
// `tex.Sample(sam, uv)`), not D3D11's separate t# and s#: such a shader keeps the slots allocated here.
std::vector<xlate::SamplerBinding> d3d10Registers(const xlate::CompiledShader& s) {
    std::vector<xlate::SamplerBinding> out = s.samplers;
    if (s.profile.major < 4)
        for (auto& sb : out) sb.textureRegister = sb.samplerRegister = -1;
    return out;
}

}  // namespace

int packedSize(const xlate::Parameter& p) {
    if (p.parameterClass == ParameterClass::Struct || p.parameterClass == ParameterClass::Object) return p.size;
    int registers = 1, last = 1;
    registerShape(p, registers, last);
    const int element = (registers - 1) * 16 + last * 4;
    const int count = std::max(p.elements, 1);
    return (count - 1) * registers * 16 + element;
}

// Where the translation laid the block out as D3D packs it (UniformBlock::d3dPacking: packoffset
// and register(cN) honoured), the reflection's offsets are D3D's; else D3D's rules in declaration
// order, which layoutMismatch compares with the GL layout.
std::vector<PackedVariable> packCbuffer(const xlate::CompiledEffect& effect, int block) {
    std::vector<PackedVariable> out;
    const bool d3dPacking = block >= 0 && std::size_t(block) < effect.uniformBlocks.size() && effect.uniformBlocks[std::size_t(block)].d3dPacking;
    int at = 0;
    for (std::size_t i = 0; i < effect.parameters.size(); ++i) {
        const xlate::Parameter& p = effect.parameters[i];
        if (p.block != block || p.isStatic || p.parameterClass == ParameterClass::Object) continue;
        const int size = packedSize(p);
        if (startsRegister(p) || (at % 16) + size > 16) at = (at + 15) / 16 * 16;
        out.push_back({int(i), d3dPacking && p.offset >= 0 ? p.offset : at, size});
        at += size;
    }
    return out;
}

ShaderBindings bindingsOf(const xlate::CompiledEffect& effect, int shader) {
    const xlate::CompiledShader& s = effect.shaders.at(std::size_t(shader));
    ShaderBindings b;
    b.shader = shader;

    // Constant buffers the shader reads ($Globals takes the first free slot, fxc's order).
    std::set<int> blocks;
    for (const auto& r : s.uniformRangesRead) blocks.insert(r.block);
    std::vector<std::string> names;
    for (int block : blocks) names.push_back(effect.uniformBlocks.at(std::size_t(block)).name);
    std::map<std::string, int> slots = allocate(effect, RK::ConstantBuffer, names, "$Global");
    for (int block : blocks) {
        const xlate::UniformBlock& u = effect.uniformBlocks[std::size_t(block)];
        CbufferBinding c;
        c.name = u.name == "$Global" ? "$Globals" : u.name;
        c.block = block;
        c.blockBinding = u.binding;
        c.slot = slots[u.name];
        int end = 0;
        for (const PackedVariable& v : packCbuffer(effect, block)) end = std::max(end, v.offset + v.size);
        c.size = (std::max(end, u.size) + 15) / 16 * 16;
        b.cbuffers.push_back(c);
    }
    std::sort(b.cbuffers.begin(), b.cbuffers.end(), [](const auto& x, const auto& y) { return x.slot < y.slot; });

    // Textures and samplers: DX10 pairs name both; a DX9 sampler (sampler2D) is its own s# and t#.
    const std::vector<xlate::SamplerBinding> shaderSamplers = d3d10Registers(s);
    std::vector<std::string> textures, samplers;
    std::map<std::string, xlate::TextureKind> kinds;
    for (const auto& sb : shaderSamplers) {
        const std::string t = sb.textureParameter.empty() ? sb.samplerName : sb.textureParameter;
        if (std::find(textures.begin(), textures.end(), t) == textures.end()) textures.push_back(t);
        kinds[t] = sb.kind;
        if (!sb.samplerName.empty() && std::find(samplers.begin(), samplers.end(), sb.samplerName) == samplers.end())
            samplers.push_back(sb.samplerName);
    }
    // Structured and raw buffers (StructuredBuffer<T>, ByteAddressBuffer) share the t# registers.
    std::set<int> bufferSlots;
    for (const xlate::StorageBinding& sb : s.storage)
        if (sb.registerClass == 't') bufferSlots.insert(sb.slot);
    std::map<std::string, int> tSlots = allocate(effect, RK::Texture, textures, {}, bufferSlots);
    std::map<std::string, int> sSlots = allocate(effect, RK::Sampler, samplers);
    // xlate's registers (fxc's, for SM4+ shaders) where it gives them.
    for (const auto& sb : shaderSamplers) {
        const std::string t = sb.textureParameter.empty() ? sb.samplerName : sb.textureParameter;
        if (sb.textureRegister >= 0) tSlots[t] = sb.textureRegister;
        if (sb.samplerRegister >= 0) sSlots[sb.samplerName] = sb.samplerRegister;
    }
    for (const auto& sb : shaderSamplers) {
        const std::string t = sb.textureParameter.empty() ? sb.samplerName : sb.textureParameter;
        SamplerUnit u;
        u.glUnit = sb.unit;
        u.textureSlot = sb.textureRegister >= 0                          ? sb.textureRegister
                        : sb.textureParameter.empty() && sb.unit >= 0 ? sb.unit  // DX9: register(sN) is both
                                                                      : tSlots[t];
        u.samplerSlot = sb.samplerName.empty()        ? -1
                        : sb.samplerRegister >= 0     ? sb.samplerRegister
                        : sb.textureParameter.empty() ? sb.unit
                                                      : sSlots[sb.samplerName];
        // An array of textures: element k on GL unit + k, from t# + k.
        for (int k = 0; k < std::max(sb.elements, 1); ++k) {
            SamplerUnit e = u;
            e.glUnit += k;
            if (e.textureSlot >= 0) e.textureSlot += k;
            b.units.push_back(e);
        }
    }
    for (const auto& [name, slot] : tSlots) b.textures.push_back({name, slot, kinds[name]});
    for (const auto& [name, slot] : sSlots) b.samplers.push_back({name, slot, xlate::TextureKind::Texture2D});
    auto bySlot = [](const ResourceBinding& x, const ResourceBinding& y) { return x.slot < y.slot; };
    std::sort(b.textures.begin(), b.textures.end(), bySlot);
    std::sort(b.samplers.begin(), b.samplers.end(), bySlot);
    return b;
}

std::string layoutMismatch(const xlate::CompiledEffect& effect, const ShaderBindings& bindings) {
    for (const CbufferBinding& c : bindings.cbuffers)
        for (const PackedVariable& v : packCbuffer(effect, c.block)) {
            if (effect.uniformBlocks.at(std::size_t(c.block)).d3dPacking) break;
            const xlate::Parameter& p = effect.parameters[std::size_t(v.parameter)];
            if (p.offset >= 0 && p.offset != v.offset)
                return "cbuffer '" + c.name + "' variable '" + p.name + "': D3D packs it at byte " + std::to_string(v.offset) +
                       ", fxport's GL layout at " + std::to_string(p.offset) +
                       " (fxport re-laid the block out with std140: its translation could not follow the shader's use of it); the bytes a host writes there "
                       "would be misread: start it on a 16-byte register (a float4, or packoffset)";
        }
    return {};
}

}  // namespace fxport::d3d11
