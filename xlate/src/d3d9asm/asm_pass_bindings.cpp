// Pass states -> register contents of shader-assembly shaders (see asm_pass_bindings.h).
#include "d3d9asm/asm_pass_bindings.h"

#include <algorithm>
#include <sstream>

#include "fx/constant_eval.h"
#include "hlsl/hlsl_types.h"
#include "fx/source_map.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// "vertexshaderconstant4" -> Vertex; "pixelshaderconstantf" -> Pixel; B/I (bool/int registers)
// and anything else -> none.
std::optional<ShaderStage> constantStateStage(const std::string& lower) {
    for (const auto& [prefix, stage] : {std::pair{"vertexshaderconstant", ShaderStage::Vertex}, std::pair{"pixelshaderconstant", ShaderStage::Pixel}}) {
        if (lower.rfind(prefix, 0) != 0) continue;
        std::string rest = lower.substr(std::string_view(prefix).size());
        if (rest.empty() || rest == "f" || rest == "1" || rest == "2" || rest == "3" || rest == "4") return stage;
    }
    return std::nullopt;
}

std::string padded(const std::vector<std::string>& components) {
    std::string out = "float4(";
    for (size_t i = 0; i < 4; ++i) out += (i ? ", " : "") + (i < components.size() ? components[i] : std::string("0"));
    return out + ")";
}

class Collector {
public:
    Collector(const RewrittenEffect& rewritten, StateContext& ctx) : rewritten_(rewritten), ctx_(ctx) {}

    // The registers parameter `name` fills from register `first` on; false after a diagnostic.
    bool bindParameter(const FxAssignment& a, const std::string& name, AsmBindings& out, std::string& signature) {
        const FxGlobal* g = nullptr;
        for (const auto& x : ctx_.syntax.globals)
            if (x.name == name) g = &x;
        if (!g) return bad(a, "'" + name + "' is not a numeric parameter of this effect");
        BasicType b = describeBasicType(ctx_.syntax.resolveType(g->type));
        if (!b.ok) return bad(a, "parameter '" + name + "' has type '" + g->type + "', which cannot fill constant registers");
        bool rowMajor = false;
        for (const auto& m : g->modifiers) rowMajor |= m == "row_major";
        int elements = g->arrayDims.empty() ? 1 : g->arrayDims[0];
        int reg = a.index < 0 ? 0 : a.index;
        for (int e = 0; e < elements; ++e) {
            std::string p = g->arrayDims.empty() ? name : name + "[" + std::to_string(e) + "]";
            if (!b.isMatrix) {
                std::vector<std::string> c;
                if (b.columns == 1) c.push_back("(float)" + p);
                else
                    for (int k = 0; k < b.columns; ++k) c.push_back(p + "[" + std::to_string(k) + "]");
                out.constants[reg++] = padded(c);
                continue;
            }
            int registers = rowMajor ? b.rows : b.columns;
            for (int i = 0; i < registers; ++i) {
                std::vector<std::string> c;
                int n = rowMajor ? b.columns : b.rows;
                for (int k = 0; k < n; ++k)
                    c.push_back(p + "[" + std::to_string(rowMajor ? i : k) + "][" + std::to_string(rowMajor ? k : i) + "]");
                out.constants[reg++] = padded(c);
            }
        }
        signature += "c" + std::to_string(a.index) + "=" + name + ";";
        return true;
    }

    bool bindLiteral(const FxAssignment& a, AsmBindings& out, std::string& signature) {
        // {1, 0, 0, 1}, float4(1, 0, 0, 1), or the effect framework's (1, 0, 0, 1).
        TokenSpan s = a.value;
        const auto& t = ctx_.syntax.tokens;
        std::vector<double> values;
        if (s.end > s.begin + 2 && t[s.begin].is("(") && t[s.end - 1].is(")")) {
            size_t start = s.begin + 1;
            int depth = 0;
            for (size_t i = s.begin + 1; i < s.end; ++i) {
                bool last = i == s.end - 1;
                if (t[i].is("(")) ++depth;
                else if (t[i].is(")") && !last) --depth;
                else if ((t[i].is(",") && depth == 0) || last) {
                    auto v = evaluateConstant(ctx_.syntax, {start, i}, {});
                    if (!v) return bad(a, "the value of " + a.name + " is neither a parameter (<Name>) nor numbers");
                    values.insert(values.end(), v->begin(), v->end());
                    start = i + 1;
                }
            }
        } else if (auto v = evaluateConstant(ctx_.syntax, s, {})) {
            values = *v;
        } else {
            return bad(a, "the value of " + a.name + " is neither a parameter (<Name>) nor numbers");
        }
        int reg = a.index < 0 ? 0 : a.index;
        for (size_t i = 0; i < values.size(); i += 4) {
            std::vector<std::string> c;
            for (size_t k = i; k < i + 4 && k < values.size(); ++k) {
                std::ostringstream n;
                n.precision(9);
                n << values[k];
                c.push_back(n.str());
            }
            out.constants[reg++] = padded(c);
        }
        signature += "c" + std::to_string(a.index) + "=" + ctx_.syntax.text(s) + ";";
        return true;
    }

    bool bindBumpEnvironment(const FxAssignment& a, const std::string& lower, std::map<std::string, std::string>& out, std::string& signature) {
        static const char* const k[] = {"bumpenvmat00", "bumpenvmat01", "bumpenvmat10", "bumpenvmat11", "bumpenvlscale", "bumpenvloffset"};
        if (std::find(std::begin(k), std::end(k), lower) == std::end(k)) return bad(a, "unknown texture-stage state '" + a.name + "'");
        TokenSpan s = a.value;
        const auto& t = ctx_.syntax.tokens;
        std::string name = s.end == s.begin + 3 && t[s.begin + 1].isIdent() ? t[s.begin + 1].text : s.end == s.begin + 1 && t[s.begin].isIdent() ? t[s.begin].text : "";
        bool isParameter = false;
        for (const auto& g : ctx_.syntax.globals) isParameter |= !name.empty() && g.name == name;
        if (isParameter) {
            out[lower] = "((float)" + name + ")";
        } else if (auto v = evaluateConstant(ctx_.syntax, s, {}); v && v->size() == 1) {
            std::ostringstream n;
            n.precision(9);
            n << (*v)[0];
            out[lower] = "(" + n.str() + ")";
        } else {
            return bad(a, a.name + " takes a number or a float parameter (<Name>)");
        }
        signature += lower + std::to_string(a.index) + "=" + out[lower] + ";";
        return true;
    }

    bool bindSamplerStage(const FxAssignment& a, AsmTextureStage& stage) {
        std::string lower = toLower(a.name);
        stage.signature += lower + "=" + ctx_.syntax.text(a.value) + ";";
        if (lower == "sampler") {
            TokenSpan s = a.value;
            const auto& t = ctx_.syntax.tokens;
            std::string name = s.end == s.begin + 3 ? t[s.begin + 1].text : s.end == s.begin + 1 ? t[s.begin].text : std::string();
            for (const auto& es : rewritten_.samplers)
                if (es.name == name && !es.dx10) {
                    stage.textureParameter = es.textureParameter;
                    stage.state = es.state;
                    stage.kind = es.kind;
                    return true;
                }
            return bad(a, "Sampler[" + std::to_string(a.index) + "] names '" + name + "', which is not a DX9 sampler of this effect");
        }
        std::string texture;
        if (!translateSamplerAssignment(a, ctx_, stage.state, texture)) return false;
        if (lower == "texture") {
            stage.textureParameter = texture;
            for (const auto& t : ctx_.syntax.textures)
                if (t.name == texture && !iequals(t.type, "texture")) stage.kind = textureKindOfType(t.type);
        }
        return true;
    }

private:
    const RewrittenEffect& rewritten_;
    StateContext& ctx_;

    bool bad(const FxAssignment& a, const std::string& message) {
        const Token& t = ctx_.syntax.tokens[a.nameToken];
        ctx_.diagnostics.push_back(ctx_.map.make(Severity::Error, diag::kBadStateValue, message, t.line, t.column, t.text));
        return false;
    }
};

}  // namespace

AsmPassBindings collectAsmPassBindings(const FxPass& pass, bool vertexIsAsm, bool pixelIsAsm, const RewrittenEffect& rewritten,
                                       StateContext& context, std::vector<bool>& consumed) {
    AsmPassBindings out;
    Collector c(rewritten, context);
    consumed.assign(pass.assignments.size(), false);
    for (size_t i = 0; i < pass.assignments.size(); ++i) {
        const FxAssignment& a = pass.assignments[i];
        if (a.isCall) continue;
        std::string lower = toLower(a.name);
        if (auto stage = constantStateStage(lower)) {
            bool isAsm = *stage == ShaderStage::Vertex ? vertexIsAsm : pixelIsAsm;
            if (!isAsm) continue;
            consumed[i] = true;
            AsmBindings& b = *stage == ShaderStage::Vertex ? out.vertex : out.pixel;
            std::string& sig = *stage == ShaderStage::Vertex ? out.vertexSignature : out.pixelSignature;
            TokenSpan s = a.value;
            const auto& t = context.syntax.tokens;
            bool isName = (s.end == s.begin + 3 && ((t[s.begin].is("<") && t[s.end - 1].is(">")) || (t[s.begin].is("(") && t[s.end - 1].is(")"))) &&
                           t[s.begin + 1].isIdent()) ||
                          (s.end == s.begin + 1 && t[s.begin].isIdent());
            if (isName) c.bindParameter(a, s.end == s.begin + 1 ? t[s.begin].text : t[s.begin + 1].text, b, sig);
            else c.bindLiteral(a, b, sig);
            continue;
        }
        if (!pixelIsAsm) continue;
        if (lower.rfind("bumpenv", 0) == 0 && a.index >= 0) {  // texbem's 2x2 matrix, texbeml's luminance scale/offset
            consumed[i] = true;
            c.bindBumpEnvironment(a, lower, out.pixel.bumpEnvironment[a.index], out.pixelSignature);
            continue;
        }
        if (lower == "texture" || lower == "sampler" || (a.index >= 0 && isTextureStageSamplerState(lower))) {
            consumed[i] = true;
            c.bindSamplerStage(a, out.stages[a.index < 0 ? 0 : a.index]);
        }
    }
    for (const auto& [n, stage] : out.stages)
        if (stage.kind) out.pixel.stageKinds[n] = *stage.kind;
    return out;
}

std::map<int, PassSamplerStage> collectPassSamplerStages(const FxPass& pass, const RewrittenEffect& rewritten, StateContext& context,
                                                         std::vector<bool>& consumed) {
    std::map<int, PassSamplerStage> out;
    Collector c(rewritten, context);
    for (size_t i = 0; i < pass.assignments.size(); ++i) {
        const FxAssignment& a = pass.assignments[i];
        const std::string lower = toLower(a.name);
        if (a.isCall || consumed[i] || !(lower == "texture" || lower == "sampler" || (a.index >= 0 && isTextureStageSamplerState(lower)))) continue;
        consumed[i] = true;
        auto [it, first] = out.try_emplace(a.index < 0 ? 0 : a.index);
        if (first) it->second.token = a.nameToken;
        c.bindSamplerStage(a, it->second.stage);
    }
    return out;
}

}  // namespace fxport::xlate
