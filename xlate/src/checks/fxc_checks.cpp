// See fxc_checks.h.
#include "checks/fxc_checks.h"

#include <algorithm>

#include "checks/fxc_rejections.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

using Family = std::vector<std::pair<size_t, Diagnostic>> (*)(const EffectSyntax&, const SourceMap&);

// One line per family.
constexpr Family kFamilies[] = {
    findRegisterReservationErrors,
    findGeometryEntryErrors,
    findGeometryInputErrors,
    findLocalDeclarationErrors,
    findImplicitSizeArrayErrors,
    findEntrySemanticErrors,
    findMajorityModifierErrors,
    findStateBlockErrors,
    findFunctionAttributeErrors,
    findStaticSamplerErrors,
    findFunctionSignatureErrors,
    findComputeOnlyIntrinsicErrors,
    findTextureShaderIntrinsicErrors,
    findSm4ObjectMethodErrors,
    findMatrixShapeConversionErrors,
    findLvalueCastErrors,
    findEffectKeywordErrors,
    findPatchObjectErrors,
    findOverloadAmbiguityErrors,
    findTernaryShapeErrors,
    findUniformInitializerErrors,
    findUavRuleErrors,
    findEffectObjectValueErrors,
    findCbufferReservationErrors,
    findResourceArrayIndexingErrors,
    findIndexTypeErrors,
    findLengthPropertyErrors,
    findSwitchSelectorErrors,
    findOperandTypeErrors,
    findDeclarationLimitErrors,
    findOverloadTieErrors,
    findDeclarationFormErrors,
    findMatrixSubscriptErrors,
    findOutArgumentShapeErrors,
    findVectorElementWriteErrors,
    findNegativeUintConstantErrors,
    findTexelOffsetErrors,
    findTextureSubscriptErrors,
    findGroupSharedCs4Errors,
    findStaticMixedStructErrors,
    findConstantBufferSlotErrors,
};

bool isShaderState(const std::string& name) {
    for (const char* n : {"VertexShader", "PixelShader", "GeometryShader", "HullShader", "DomainShader", "ComputeShader", "SetVertexShader",
                          "SetPixelShader", "SetGeometryShader", "SetHullShader", "SetDomainShader", "SetComputeShader"})
        if (iequals(name, n)) return true;
    return false;
}

}  // namespace

void FxcCheck::report(const std::string& message, size_t token) { report(diag::kHlsl, message, token); }

void FxcCheck::report(const char* id, const std::string& message, size_t token) {
    const Token& t = tok(token);
    found_.push_back({token, map_.make(Severity::Error, id, message, t.line, t.column, t.text)});
}

size_t FxcCheck::closing(size_t open) const {
    const std::string o = t_[open].text, c = o == "(" ? ")" : o == "[" ? "]" : o == "<" ? ">" : "}";
    int depth = 0;
    for (size_t i = open; i < t_.size(); ++i) {
        if (t_[i].is(o)) ++depth;
        else if (t_[i].is(c) && --depth == 0) return i;
    }
    return t_.size() - 1;
}

const FxFunction* FxcCheck::functionAt(size_t at) const {
    for (const auto& f : syntax_.functions)
        if (at >= f.declaration.begin && at < f.declaration.end) return &f;
    return nullptr;
}

bool FxcCheck::inFunction(size_t at) const { return functionAt(at) != nullptr || syntax_.inMemberFunctionBody(at); }

std::vector<FxcCheck::CompiledEntry> FxcCheck::compiledEntries() const {
    // A loose-shader compile (fxc /T ps_4_0 /E main) compiles its entry points only: the technique
    // fxport appends, last; the file's own techniques and shader variables are not compiled.
    std::vector<FxShaderExpr> compiles;
    size_t first = syntax_.looseShaders && !syntax_.techniques.empty() ? syntax_.techniques.size() - 1 : 0;
    for (size_t k = first; k < syntax_.techniques.size(); ++k)
        for (const auto& p : syntax_.techniques[k].passes)
            for (const auto& a : p.assignments)
                if (isShaderState(a.name)) compiles.push_back(parseShaderExpr(syntax_, a.value));
    if (!syntax_.looseShaders)
        for (const auto& v : syntax_.shaderVariables) compiles.insert(compiles.end(), v.elements.begin(), v.elements.end());
    std::vector<CompiledEntry> out;
    for (const auto& e : compiles) {
        if (e.kind != FxShaderExpr::Kind::Compile) continue;
        auto profile = parseShaderProfile(e.profile);
        const FxFunction* f = syntax_.findEntry(e.entry, e.arguments);
        if (profile && f) out.push_back({*profile, f});
    }
    return out;
}

std::vector<const FxFunction*> FxcCheck::reachableFrom(const FxFunction& entry) const {
    std::vector<const FxFunction*> out{&entry};
    for (size_t k = 0; k < out.size(); ++k)
        for (size_t i = out[k]->body.begin; i + 1 < out[k]->body.end; ++i) {
            if (!t_[i].isIdent() || !t_[i + 1].is("(")) continue;
            for (const auto& f : syntax_.functions)  // every overload of the name
                if (f.name == t_[i].text && std::find(out.begin(), out.end(), &f) == out.end()) out.push_back(&f);
        }
    return out;
}

bool FxcCheck::mentionedIn(const std::vector<const FxFunction*>& functions, const std::string& name) const {
    for (const FxFunction* f : functions)
        for (size_t i = f->body.begin; i < f->body.end; ++i)
            if (t_[i].isIdent() && t_[i].text == name && !(i > 0 && t_[i - 1].is("."))) return true;
    return false;
}

std::vector<Diagnostic> runFxcChecks(const EffectSyntax& syntax, const SourceMap& map) {
    std::vector<Diagnostic> out = findFxcRejections(syntax, map);
    std::vector<std::pair<size_t, Diagnostic>> found;
    for (Family family : kFamilies)
        for (auto& f : family(syntax, map)) found.push_back(std::move(f));
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    size_t last = size_t(-1);
    for (auto& [token, d] : found)
        if (token != last) out.push_back(std::move(d)), last = token;  // one error per place
    return out;
}

}  // namespace fxport::xlate
