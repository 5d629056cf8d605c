// See effect_profile_rules.h: what fxc's effect profiles allow.
#include "checks/effect_profile_rules.h"

#include "fxport/xlate/effect_compiler.h"
#include "hlsl/hlsl_types.h"
#include "fx/text_util.h"

namespace fxport::xlate {

bool allowsTechniqueless(const std::string& effectProfile, const std::string& displayPath) {
    if (effectProfile.empty() || effectProfile == "fx_2_0") return false;
    if (effectProfile == "fx_4_0" || effectProfile == "fx_4_1" || effectProfile == "fx_5_0") return true;
    Diagnostic d;
    d.id = diag::kBadProfile;
    d.message = "unknown effect profile '" + effectProfile + "' (CompileOptions::effectProfile): fx_2_0, fx_4_0, fx_4_1 or fx_5_0";
    d.location = {displayPath, 0, 0};
    throw CompileError({d});
}

std::vector<Diagnostic> checkEffectProfile(const EffectSyntax& syntax, const SourceMap& map, const std::string& effectProfile) {
    std::vector<Diagnostic> errors;
    if (effectProfile.empty() || effectProfile == "fx_2_0") return errors;
    for (const auto& g : syntax.globals) {
        const FxStruct* s = syntax.findStruct(syntax.resolveType(g.type));
        if (!s) continue;
        for (const auto& m : s->members) {
            std::string type = syntax.resolveType(m.type);
            if (describeBasicType(type).ok || syntax.findStruct(type)) continue;
            const Token& t = syntax.tokens[g.token];
            errors.push_back(map.make(Severity::Error, diag::kHlsl,
                                      "variable '" + g.name + "' is a struct '" + s->name + "' holding the object '" + m.name + "' (" + m.type +
                                          "); " + effectProfile + " effects refuse such a variable (fxc)",
                                      t.line, t.column, t.text));
            break;
        }
    }
    // D3D10's BlendState has one blend per target only for BlendEnable and RenderTargetWriteMask;
    // D3D10.1 (fx_4_1) and D3D11 index every blend state (SrcBlend[2]).
    if (effectProfile != "fx_4_0") return errors;
    for (const auto& object : syntax.stateObjects) {
        if (!iequals(object.type, "BlendState")) continue;
        for (const auto& a : object.assignments) {
            if (a.index < 0 || iequals(a.name, "BlendEnable") || iequals(a.name, "RenderTargetWriteMask")) continue;
            const Token& t = syntax.tokens[a.nameToken];
            errors.push_back(map.make(Severity::Error, diag::kHlsl,
                                      "'" + a.name + "[" + std::to_string(a.index) + "]' in BlendState '" + object.name +
                                          "': fx_4_0 has one " + a.name + " for every target (only BlendEnable and RenderTargetWriteMask are "
                                          "per target; fx_4_1 and fx_5_0 index the others)",
                                      t.line, t.column, t.text));
        }
    }
    return errors;
}

}  // namespace fxport::xlate
