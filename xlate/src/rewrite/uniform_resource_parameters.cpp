// See uniform_resource_parameters.h.
#include "rewrite/uniform_resource_parameters.h"

#include <algorithm>
#include <set>

#include "fx/text_util.h"
#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

bool isShaderState(const std::string& name) {
    for (const char* n : {"VertexShader", "PixelShader", "GeometryShader", "HullShader", "DomainShader", "ComputeShader",
                          "SetVertexShader", "SetPixelShader", "SetGeometryShader", "SetHullShader", "SetDomainShader", "SetComputeShader"})
        if (iequals(name, n)) return true;
    return false;
}

size_t literalCount(const std::string& arguments) {
    if (arguments.find_first_not_of(" \t") == std::string::npos) return 0;
    size_t n = 1;
    int depth = 0;
    for (char c : arguments) {
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') --depth;
        else if (c == ',' && depth == 0) ++n;
    }
    return n;
}

// ` : register(s0)` as written after the parameter, or "".
std::string registerOf(const EffectSyntax& syntax, const FxParameter& p) {
    const auto& t = syntax.tokens;
    for (size_t k = p.typeToken; k + 3 < t.size() && !t[k].is(",") && !t[k].is(")"); ++k)
        if (t[k].is("register") && t[k + 1].is("(") && t[k + 2].isIdent() && t[k + 3].is(")"))
            return " : register(" + t[k + 2].text + ")";
    return "";
}

bool declared(const EffectSyntax& syntax, const std::string& name) {
    return syntax.findSampler(name) || syntax.findTexture(name) ||
           std::any_of(syntax.globals.begin(), syntax.globals.end(), [&](const FxGlobal& g) { return g.name == name; });
}

}  // namespace

std::string uniformResourceParametersDeclared(const std::string& preprocessed, const EffectSyntax& syntax) {
    if (!syntax.looseShaders) return preprocessed;  // an effect's compile statement must give objects (FX1403 stays)
    std::vector<FxShaderExpr> compiles;
    for (const auto& technique : syntax.techniques)
        for (const auto& pass : technique.passes)
            for (const auto& a : pass.assignments)
                if (isShaderState(a.name)) compiles.push_back(parseShaderExpr(syntax, a.value));
    for (const auto& v : syntax.shaderVariables) compiles.insert(compiles.end(), v.elements.begin(), v.elements.end());
    std::string declarations;
    std::set<std::string> names;
    for (const auto& e : compiles) {
        if (e.kind != FxShaderExpr::Kind::Compile) continue;
        const FxFunction* f = syntax.findEntry(e.entry, e.arguments);
        if (!f) continue;
        size_t literals = literalCount(e.arguments), k = 0;
        for (const auto& p : f->parameters) {
            if (std::find(p.modifiers.begin(), p.modifiers.end(), "uniform") == p.modifiers.end()) continue;
            if (k++ < literals || !p.defaultValue.empty() || p.name.empty() || !p.arrayDims.empty() || !isResourceType(p.type)) continue;
            if (declared(syntax, p.name) || !names.insert(p.name).second) continue;
            declarations += " " + p.type + " " + p.name + registerOf(syntax, p) + ";";
        }
    }
    if (declarations.empty()) return preprocessed;
    std::string text = preprocessed;
    size_t at = !text.empty() && text.back() == '\n' ? text.size() - 1 : text.size();
    text.insert(at, declarations);
    return text;
}

}  // namespace fxport::xlate
