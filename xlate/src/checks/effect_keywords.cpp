// The effect framework's keywords are reserved in every HLSL fxc compiles, loose shaders included
// (vkd3d's effect-technique-fx_2, _fx_4 and _fx_5 pin them):
//  - `technique` in any case, `technique10`, `technique11` and `fxgroup` exactly so, name nothing
//    else: a variable or typedef of that name is a syntax error;
//  - `String` is the string type (`sTring` is not: fxc's own quirk, vkd3d's strings): no typedef or
//    variable takes that name;
//  - `technique10` and `technique11` open a technique in lower case only: `tEchnique10 { }` is no
//    technique (fxc stops with a syntax error), while `Technique` and `TECHNIQUE` are;
//  - `VertexShader` and `PixelShader`, and D3D9's lower-case `vertexshader` and `pixelshader`, are
//    the shader object types and name no variable (`float4 VertexShader;` is refused, vkd3d's
//    effect-shader-objects-fx_2 and _fx_5; `vertexshadeR` and `geometryshader` are names);
//  - an `fxgroup` (fx_5_0's) holds versioned techniques only: a `technique` without 10 or 11
//    in it is a syntax error (vkd3d's fxgroup-syntax).
// The parser takes the keywords case-insensitively, so both are judged here on its tokens.
#include "checks/fxc_checks.h"

#include "hlsl/hlsl_types.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

bool isReserved(const std::string& s) {
    return iequals(s, "technique") || s == "technique10" || s == "technique11" || s == "fxgroup";
}

class EffectKeywords : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::vector<bool> keyword(t_.size(), false);
        for (const auto& tech : syntax_.techniques) {
            keyword[tech.token] = true;
            const std::string& k = tok(tech.token).text;
            if (!iequals(k, "technique") && k != "technique10" && k != "technique11")
                report("syntax error: unexpected token '" + k + "': the keywords technique10 and technique11 are lower case (fxc X3000)", tech.token);
        }
        for (size_t i = 0; i + 2 < t_.size(); ++i)
            if (t_[i].is("fxgroup") && t_[i + 1].isIdent() && (t_[i + 2].is("{") || t_[i + 2].is("<"))) keyword[i] = true;
        for (size_t i = 0; i < t_.size(); ++i)
            if (t_[i].isIdent() && !keyword[i] && isReserved(t_[i].text))
                report("syntax error: unexpected token '" + t_[i].text + "': '" + t_[i].text +
                           "' is a keyword of the effect framework and names no variable or type (fxc X3000)",
                       i);
        for (size_t i = 0; i + 2 < t_.size(); ++i)
            if (t_[i].is("fxgroup") && t_[i + 1].isIdent()) {
                const size_t open = t_[i + 2].is("<") ? closing(i + 2) + 1 : i + 2;  // after the annotations
                if (tok(open).is("{")) unversionedGroupTechniques(open);
            }
        for (size_t i = 1; i < t_.size(); ++i)
            if (t_[i].is("String") && (describeBasicType(syntax_.resolveType(t_[i - 1].text)).ok || syntax_.findStruct(t_[i - 1].text)))
                report("syntax error: unexpected token 'String': 'String' is the string type and names no variable or type (fxc X3000)", i);
        for (size_t i = 1; i + 1 < t_.size(); ++i)
            if (isShaderObjectKeyword(t_[i].text) && declares(i))
                report("syntax error: unexpected token '" + t_[i].text + "': '" + t_[i].text + "' is a shader object type and names no variable (fxc X3000)", i);
    }

private:
    static bool isShaderObjectKeyword(const std::string& s) {
        return s == "VertexShader" || s == "vertexshader" || s == "PixelShader" || s == "pixelshader";
    }
    // `T name` followed by what ends a declarator, with T a numeric type or a struct.
    bool declares(size_t i) const {
        const Token& next = t_[i + 1];
        if (!(next.is(";") || next.is("=") || next.is(":") || next.is("[") || next.is(","))) return false;
        return describeBasicType(syntax_.resolveType(t_[i - 1].text)).ok || syntax_.findStruct(t_[i - 1].text);
    }
    // The techniques directly inside the group's braces at `open`.
    void unversionedGroupTechniques(size_t open) {
        const size_t end = closing(open);
        for (size_t i = open + 1; i < end; ++i) {
            if (t_[i].is("{")) i = closing(i);
            else if (t_[i].isIdent() && iequals(t_[i].text, "technique"))
                report("syntax error: unexpected token '" + t_[i].text + "': an fxgroup holds technique10 or technique11 only (fxc X3000)", i);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findEffectKeywordErrors(const EffectSyntax& syntax, const SourceMap& map) {
    EffectKeywords check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
