// fxc's t# and s# registers for one D3D10+ shader, and the s# of an SM 1-3 one (d3d_registers.h).
#include "effect/d3d_registers.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>

#include "rewrite/texture_registers.h"

namespace fxport::xlate {

namespace {

constexpr int kD3d9SamplerRegisters = 16;  // s0-s15

// `sam_fxport_3` -> {"sam", 3}: an element of a DX9 sampler array (sampler_array_elements.h);
// other names are {name, -1}.
std::pair<std::string, int> arrayElement(const std::string& name) {
    const std::string marker = "_fxport_";
    const size_t at = name.rfind(marker);
    if (at == std::string::npos || at == 0) return {name, -1};
    const std::string digits = name.substr(at + marker.size());
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return {name, -1};
    return {name.substr(0, at), std::stoi(digits)};
}

// `sam_fxport_texture2D` -> "sam": the texture fxport declared for a DX9 sampler that is also a
// sampler state (sampler_textures.h); empty for other names.
std::string samplerOfMadeTexture(const std::string& texture) {
    for (const char* suffix : {"_fxport_texture1d", "_fxport_texture2d", "_fxport_texture3d", "_fxport_texturecube"}) {
        const std::string s = suffix;
        if (texture.size() > s.size() && texture.compare(texture.size() - s.size(), s.size(), s) == 0)
            return texture.substr(0, texture.size() - s.size());
    }
    return {};
}

// The lowest first register of a free run of `count`; marks the run taken.
int takeRun(std::set<int>& taken, int count) {
    int first = 0;
    auto free = [&](int f) {
        for (int k = 0; k < count; ++k)
            if (taken.count(f + k)) return false;
        return true;
    };
    while (!free(first)) ++first;
    for (int k = 0; k < count; ++k) taken.insert(first + k);
    return first;
}

// One texture or sampler fxc allocates: a declared object, or (textures) one made for a DX9
// sampler (array). `width`: the registers it takes.
struct Object {
    std::string name;
    int width = 1;
    int explicitRegister = -1;
    bool madeForSampler = false;
    bool isArray = false;
    std::size_t declared = 0;  // declaration order
    std::uint32_t firstUse = 0;
    int first = -1;  // the register given
};

int samplerDeclaration(const EffectSyntax& syntax, const std::string& name) {
    for (std::size_t i = 0; i < syntax.samplers.size(); ++i)
        if (syntax.samplers[i].name == name || arrayElement(syntax.samplers[i].name).first == name) return int(i);
    return int(syntax.samplers.size());
}

int samplerExplicit(const EffectSyntax& syntax, const std::string& name, const ShaderProfile& target) {
    for (const auto& s : syntax.samplers)
        if (s.name == name) return reservedRegister(s.registers, 's', target);
    return -1;
}

// The texture a binding samples: {object, element}; made-for-sampler objects are keyed by the
// sampler's (array's) name with a '%' in front, which no HLSL name has.
std::pair<std::string, int> textureOf(const SamplerBinding& b) {
    if (b.textureParameter.empty()) {
        auto [base, element] = arrayElement(b.samplerName);
        return {"%" + base, std::max(element, 0)};
    }
    if (std::string s = samplerOfMadeTexture(b.textureParameter); !s.empty()) {
        auto [base, element] = arrayElement(s);
        return {"%" + base, std::max(element, 0)};
    }
    return {b.textureParameter, 0};
}

void assignTextures(std::vector<SamplerBinding>& bindings, const std::vector<std::uint32_t>& firstUse, const EffectSyntax& syntax,
                    const std::vector<int>& bufferRegisters, const ShaderProfile& target) {
    std::map<std::string, Object> objects;
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        auto [name, element] = textureOf(bindings[i]);
        Object& o = objects[name];
        const bool first = o.name.empty();
        o.name = name;
        o.madeForSampler = name[0] == '%';
        const std::uint32_t use = i < firstUse.size() ? firstUse[i] : 0;
        o.firstUse = first ? use : std::min(o.firstUse, use);
        if (o.madeForSampler) {
            o.width = std::max(o.width, element + 1);  // the bind count
            o.declared = std::size_t(samplerDeclaration(syntax, name.substr(1)));
            continue;
        }
        o.declared = syntax.textures.size();
        for (std::size_t k = 0; k < syntax.textures.size(); ++k)
            if (syntax.textures[k].name == name) {
                o.declared = k;
                o.width = textureElements(syntax, syntax.textures[k]);
                o.explicitRegister = reservedRegister(syntax.textures[k].registers, 't', target);
            }
    }
    std::set<int> taken(bufferRegisters.begin(), bufferRegisters.end());
    for (const auto& t : syntax.textures)  // fxc keeps a reservation even where it is unused
        if (int r = reservedRegister(t.registers, 't', target); !t.dx9Object && r >= 0)
            for (int k = 0; k < textureElements(syntax, t); ++k) taken.insert(r + k);
    std::vector<Object*> order;
    for (auto& [name, o] : objects)
        if (o.explicitRegister >= 0) o.first = o.explicitRegister;
        else order.push_back(&o);
    std::stable_sort(order.begin(), order.end(), [](const Object* a, const Object* b) {
        if (a->madeForSampler != b->madeForSampler) return a->madeForSampler;
        if (a->madeForSampler && a->width != b->width) return a->width > b->width;
        if (a->madeForSampler) return a->firstUse < b->firstUse;
        return a->declared < b->declared;
    });
    for (Object* o : order) o->first = takeRun(taken, o->width);
    for (auto& b : bindings) {
        auto [name, element] = textureOf(b);
        b.textureRegister = objects[name].first + element;
    }
}

void assignSamplers(std::vector<SamplerBinding>& bindings, const EffectSyntax& syntax, const ShaderProfile& target) {
    std::map<std::string, Object> objects;
    for (const auto& b : bindings) {
        if (b.samplerName.empty()) continue;
        auto [base, element] = arrayElement(b.samplerName);
        Object& o = objects[base];
        o.name = base;
        o.isArray = element >= 0;
        o.width = std::max(o.width, element + 1);
        o.declared = std::size_t(samplerDeclaration(syntax, base));
        // An array's register(sN) is on each element (sampler_array_elements.h): element 0's.
        o.explicitRegister = samplerExplicit(syntax, o.isArray ? base + "_fxport_0" : base, target);
    }
    std::set<int> taken;
    for (const auto& s : syntax.samplers)
        if (int r = reservedRegister(s.registers, 's', target); r >= 0) taken.insert(r);
    std::vector<Object*> order;
    for (auto& [name, o] : objects)
        if (o.explicitRegister >= 0) o.first = o.explicitRegister;
        else order.push_back(&o);
    std::stable_sort(order.begin(), order.end(), [](const Object* a, const Object* b) {
        if (a->isArray != b->isArray) return a->isArray;
        return a->declared < b->declared;
    });
    for (Object* o : order) o->first = takeRun(taken, o->width);
    for (auto& b : bindings) {
        if (b.samplerName.empty()) continue;
        auto [base, element] = arrayElement(b.samplerName);
        b.samplerRegister = objects[base].first + std::max(element, 0);
    }
}

// Whether DX9 sampler `name` names its texture itself (`Texture = <T>` in its sampler_state).
bool namesItsTexture(const EffectSyntax& syntax, const std::string& name) {
    for (const auto& s : syntax.samplers)
        if (s.name == name)
            for (const auto& a : s.states)
                if (a.name.size() == 7 && std::equal(a.name.begin(), a.name.end(), "texture",
                                                     [](char x, char y) { return std::tolower(static_cast<unsigned char>(x)) == y; }))
                    return true;
    return false;
}

// The D3D9 sampler object binding `b` uses, added to `objects` (widened as needed): a DX9 sampler
// (array), or the combined sampler `tex.Sample(sam, uv)` makes, as wide as the texture (array).
// Returns its key and the element `b` uses.
std::pair<std::string, int> addD3d9Object(std::map<std::string, Object>& objects, const SamplerBinding& b, const EffectSyntax& syntax,
                                          const ShaderProfile& target) {
    auto [base, element] = arrayElement(b.samplerName);
    const bool combined = !b.samplerName.empty() && !b.textureParameter.empty() && samplerOfMadeTexture(b.textureParameter).empty() &&
                          !namesItsTexture(syntax, b.samplerName);
    const std::string key = combined ? base + "+" + b.textureParameter : base;
    Object& o = objects[key];
    o.name = key;
    o.declared = std::size_t(samplerDeclaration(syntax, base));
    o.madeForSampler = combined;
    if (combined) {
        for (const auto& t : syntax.textures)
            if (t.name == b.textureParameter) o.width = std::max(o.width, textureElements(syntax, t));
        return {key, 0};
    }
    o.isArray = element >= 0;
    o.width = std::max(o.width, element + 1);  // the bind count
    o.explicitRegister = samplerExplicit(syntax, o.isArray ? base + "_fxport_0" : base, target);
    return {key, std::max(element, 0)};
}

// combined-samplers' order: register(sN) holds; the rest take the lowest free run by decreasing
// width, ties the combined samplers first, each kind in its samplers' declaration order.
void placeD3d9Objects(std::map<std::string, Object>& objects) {
    std::set<int> taken;
    std::vector<Object*> order;
    for (auto& [name, o] : objects)
        if (o.explicitRegister >= 0) {
            o.first = o.explicitRegister;
            for (int k = 0; k < o.width; ++k) taken.insert(o.first + k);
        } else {
            order.push_back(&o);
        }
    std::stable_sort(order.begin(), order.end(), [](const Object* a, const Object* b) {
        if (a->width != b->width) return a->width > b->width;
        if (a->madeForSampler != b->madeForSampler) return a->madeForSampler;
        return a->declared < b->declared;
    });
    for (Object* o : order) o->first = takeRun(taken, o->width);
}

}  // namespace

void assignD3d9SamplerRegisters(std::vector<SamplerBinding>& bindings, const EffectSyntax& syntax, const ShaderProfile& target) {
    // Keyed by sampler (array) name, or "sampler+texture" for a combined one (no HLSL name has '+').
    std::map<std::string, Object> objects;
    std::vector<std::pair<std::string, int>> keys;  // per binding: object and element
    for (const auto& b : bindings)  // a texture read without sampler has no s#
        keys.push_back(b.samplerName.empty() ? std::pair<std::string, int>{"", -1} : addD3d9Object(objects, b, syntax, target));
    placeD3d9Objects(objects);
    std::vector<int> registers;
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        registers.push_back(keys[i].second < 0 ? -1 : objects[keys[i].first].first + keys[i].second);
        // D3D9 has s0-s15, which fxc refuses to pass; fxport's units go further. Such a shader keeps
        // no registers (-1) and binds by `unit` alone, as every SM 1-3 shader did before.
        if (registers.back() + std::max(bindings[i].elements, 1) > kD3d9SamplerRegisters) return;
    }
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        bindings[i].samplerRegister = registers[i];
        bindings[i].textureRegister = registers[i];  // D3D9's texture stage is the sampler's
    }
}

int reservedRegister(const std::vector<FxRegister>& registers, char registerClass, const ShaderProfile& target) {
    const std::string stage = target.name.substr(0, 2);
    int found = -1;
    for (const FxRegister& r : registers) {
        if (r.registerClass != registerClass || r.profile.find('[') != std::string::npos) continue;
        const bool applies = r.profile.empty() || r.profile == stage || r.profile == target.name ||
                             (r.profile == stage + "_4_0" && target.major >= 4 && target.major <= 5);
        if (applies) found = r.index;
    }
    return found;
}

void assignD3dRegisters(std::vector<SamplerBinding>& bindings, const std::vector<std::uint32_t>& firstUse, const EffectSyntax& syntax,
                        const std::vector<int>& bufferRegisters, const ShaderProfile& target) {
    assignTextures(bindings, firstUse, syntax, bufferRegisters, target);
    assignSamplers(bindings, syntax, target);
}

}  // namespace fxport::xlate
