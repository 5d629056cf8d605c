// fxc's rules for the semantics of a vertex or pixel shader's entry that glslang does not check
// (vkd3d's entry-point-semantics pins them). Semantic names compare without case, `TEXCOORD` is
// `TEXCOORD0`, an array takes consecutive indices, struct members are flattened, a semantic on a
// struct cascades over its members (signature_layout.h):
//  - an output semantic names one value: two outputs (parameters, members, the result) on one
//    semantic and index are an error, so is an array of structs whose members carry semantics;
//  - at SM 4-5 two inputs on one semantic and index must have one layout: the same register
//    count and width and the same kind of register (float and half alike, int, uint, bool alike);
//    a row_major matrix's rows are not vectors there, though they take the registers a vector
//    would (`float2 a : TEXCOORD0, row_major float1x2 b : TEXCOORD0` is refused, vkd3d pins it),
//    while a column_major matrix's columns are (`float2x1` beside `float2` compiles);
//  - an output is no double (signature elements hold 32-bit components).
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"
#include "entry/signature_layout.h"

namespace fxport::xlate {

namespace {

// One flattened value of the signature.
struct Element {
    std::string semantic;  // upper case, with its index: TEXCOORD0
    std::string layout;    // "f:1x2" (kind: registers x width); empty when not judged
    size_t token;          // for the report
};

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// "TEXCOORD" + 2 -> "TEXCOORD2"; "sem1" + 1 -> "SEM2".
std::string withIndex(const std::string& semantic, int offset) {
    size_t digits = semantic.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(semantic[digits - 1]))) --digits;
    // 64-bit and capped: the digits come from the source.
    const long long index = digits < semantic.size() ? std::min(std::strtoll(semantic.c_str() + digits, nullptr, 10), 1LL << 40) : 0;
    return upper(semantic.substr(0, digits)) + std::to_string(index + offset);
}

class EntrySemantics : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage != ShaderStage::Vertex && e.profile.stage != ShaderStage::Pixel) continue;
            entry(*e.function, e.profile);
        }
    }

private:
    void entry(const FxFunction& f, const ShaderProfile& profile) {
        if (doubleOutput(f)) return;
        std::vector<Element> inputs, outputs;
        for (const auto& p : f.parameters) {
            auto has = [&](const char* m) { return std::find(p.modifiers.begin(), p.modifiers.end(), m) != p.modifiers.end(); };
            if (has("uniform")) continue;
            std::vector<Element> flat;
            if (!flatten(p.type, p.semantic, p.arrayDims, p.modifiers, p.typeToken, flat, 0)) continue;
            if (has("out") || has("inout")) outputs.insert(outputs.end(), flat.begin(), flat.end());
            if (!has("out")) inputs.insert(inputs.end(), flat.begin(), flat.end());
        }
        if (f.returnType != "void") flatten(f.returnType, f.returnSemantic, {}, entryReturnModifiers(syntax_, f), f.token, outputs, 0);
        std::map<std::string, const Element*> seen;
        for (const auto& o : outputs) {
            if (o.semantic.empty()) continue;
            auto [it, fresh] = seen.insert({o.semantic, &o});
            if (!fresh) {
                report("output semantic '" + o.semantic + "' is given to more than one value of '" + f.name + "'", o.token);
                return;
            }
        }
        if (profile.major < 4) return;  // SM 2-3 alias inputs of one semantic freely
        seen.clear();
        for (const auto& in : inputs) {
            if (in.semantic.empty()) continue;
            auto [it, fresh] = seen.insert({in.semantic, &in});
            if (!fresh && !in.layout.empty() && !it->second->layout.empty() && in.layout != it->second->layout) {
                report("input semantic '" + in.semantic + "' is given to two values of different layouts in '" + f.name + "'", in.token);
                return;
            }
        }
    }

    // A signature element holds 32-bit components: a double output (`double2 main() : sv_target`)
    // is refused (vkd3d's rt-format-mismatch), where glslang writes it to a dvec output.
    bool doubleOutput(const FxFunction& f) {
        auto isDouble = [&](const std::string& type) { return describeBasicType(syntax_.resolveType(type)).scalar == "double"; };
        if (f.returnType != "void" && isDouble(f.returnType)) {
            report("'" + f.name + "' returns a " + f.returnType + ": a shader output holds 32-bit values, no double", f.token);
            return true;
        }
        for (const auto& p : f.parameters)
            if (std::find(p.modifiers.begin(), p.modifiers.end(), "out") != p.modifiers.end() && isDouble(p.type)) {
                report("output '" + p.name + "' of '" + f.name + "' is a " + p.type + ": a shader output holds 32-bit values, no double", p.typeToken);
                return true;
            }
        return false;
    }

    // Appends the signature values of a `type name[dims] : semantic`; false when the type is not
    // understood (nothing judged then).
    bool flatten(const std::string& typeName, const std::string& semantic, const std::vector<int>& dims,
                 const std::vector<std::string>& modifiers, size_t token, std::vector<Element>& out, int depth,
                 SemanticCascade* cascade = nullptr) const {
        std::string type = syntax_.resolveType(typeName);
        long long count = 1;  // capped: sizes come from the source
        for (int d : dims) count = std::min(count * std::max(d, 1), 1LL << 20);
        if (count > 1024) return false;  // far past any stage's registers: not judged here
        BasicType b = describeBasicType(type);
        if (b.ok) {
            if (semantic.empty() && !cascade) return true;
            int registers = signatureRegisters(b, modifiers);
            int width = signatureWidth(b, modifiers);
            bool isFloat = b.scalar == "float" || b.scalar == "half" || b.scalar.rfind("min16float", 0) == 0 || b.scalar.rfind("min10float", 0) == 0;
            bool isInt = b.scalar == "int" || b.scalar == "uint" || b.scalar == "bool" || b.scalar == "dword" || b.scalar.rfind("min16", 0) == 0;
            std::string layout = isFloat || isInt ? std::string(isFloat ? "f:" : "i:") + std::to_string(registers) + "x" + std::to_string(width) : "";
            if (!layout.empty() && b.isMatrix && std::find(modifiers.begin(), modifiers.end(), "row_major") != modifiers.end()) layout += ":rows";
            if (cascade) {
                auto [base, first] = cascade->take(registers * int(count));
                for (int k = 0; k < registers * count; ++k) out.push_back({base + std::to_string(first + k), layout, token});
                return true;
            }
            for (int k = 0; k < count; ++k)
                for (int r = 0; r < registers; ++r)
                    out.push_back({withIndex(semantic, k * registers + r), layout, token});
            return true;
        }
        const FxStruct* s = syntax_.findStruct(type);
        if (!s || depth > 8) return false;
        // A semantic on the struct overrides its members' (signature_layout.h). Without one, each
        // element of an array of structs repeats the members' semantics: as outputs, a clash.
        SemanticCascade own = SemanticCascade::from(semantic);
        SemanticCascade* c = cascade ? cascade : (own.active ? &own : nullptr);
        for (int k = 0; k < count; ++k)
            for (const auto& m : s->members)
                if (!flatten(m.type, m.semantic, m.arrayDims, m.modifiers, token, out, depth + 1, c)) return false;
        return true;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findEntrySemanticErrors(const EffectSyntax& syntax, const SourceMap& map) {
    EntrySemantics check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
