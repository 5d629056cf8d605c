// fxc's rules for row_major / column_major beyond a plain matrix type (vkd3d's majority-syntax
// pins them; fxc_rejections.cpp judges modifiers on built-in types): the modifier applies to a
// matrix type only, so it is an error
//  - on a struct (`column_major struct apple a;`, `typedef column_major struct apple apple_t;`),
//  - on a typedef of an array (`typedef float4x4 arr_t[2]; row_major arr_t a;`),
//  - on a typedef that already has the other majority (`typedef row_major float4x4 m_t; column_major m_t x;`),
//    its own or the one the latest `#pragma pack_matrix` named when it was declared (vkd3d's
//    majority-pragma: the typedef keeps that latent majority).
#include <map>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

bool isMajority(const Token& t) { return t.is("row_major") || t.is("column_major"); }

class MajorityModifiers : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        collectTypedefs();
        for (size_t i = 0; i + 1 < t_.size(); ++i)
            if (isMajority(t_[i])) modifier(i);
    }

private:
    struct Typedef {
        std::string majority;  // the one it was declared with, if any
        bool array = false;
        bool structure = false;
    };
    std::map<std::string, Typedef> typedefs_;

    // `typedef [modifiers] Type[<...>] Name[dims], ...;`
    void collectTypedefs() {
        std::string latent;  // the latest `#pragma pack_matrix(...)`'s majority
        for (size_t i = 0; i + 2 < t_.size(); ++i) {
            if (t_[i].is("#") && t_[i + 1].is("pragma") && tok(i + 2).is("pack_matrix") && tok(i + 3).is("(") && isMajority(tok(i + 4)))
                latent = tok(i + 4).text;
            if (!t_[i].is("typedef")) continue;
            Typedef d;
            size_t k = i + 1;
            for (; t_[k].is("const") || isMajority(t_[k]); ++k)
                if (isMajority(t_[k])) d.majority = t_[k].text;
            if (t_[k].is("struct")) {
                d.structure = true;
                ++k;
                if (t_[k].is("{")) k = closing(k);
            }
            if (!t_[k].isIdent() && !t_[k].is("}")) continue;
            if (auto it = typedefs_.find(t_[k].text); it != typedefs_.end() && d.majority.empty()) d = it->second;  // a typedef of a typedef
            else if (d.majority.empty() && !d.structure && describeBasicType(syntax_.resolveType(t_[k].text)).isMatrix) d.majority = latent;
            ++k;
            if (t_[k].is("<")) k = closing(k) + 1;
            while (t_[k].isIdent()) {
                Typedef one = d;
                size_t name = k++;
                one.array |= t_[k].is("[");
                while (t_[k].is("[")) k = closing(k) + 1;
                typedefs_[t_[name].text] = one;
                if (!t_[k].is(",")) break;
                ++k;
            }
        }
    }

    void modifier(size_t at) {
        size_t k = at + 1;
        while (t_[k].isIdent() && (isMajority(t_[k]) || t_[k].is("const") || t_[k].is("static") || t_[k].is("uniform") ||
                                   t_[k].is("extern") || t_[k].is("typedef") || t_[k].is("in") || t_[k].is("out") || t_[k].is("inout")))
            ++k;
        const std::string& m = t_[at].text;
        if (t_[k].is("struct")) {
            report("'" + m + "' applies to matrices only, not to struct" + (t_[k + 1].isIdent() ? " '" + t_[k + 1].text + "'" : std::string()) + " (fxc X3025)", at);
            return;
        }
        auto it = typedefs_.find(t_[k].text);
        if (it == typedefs_.end()) return;
        if (it->second.structure) report("'" + m + "' applies to matrices only, not to struct type '" + t_[k].text + "' (fxc X3025)", at);
        else if (it->second.array) report("'" + m + "' applies to matrices only, not to array type '" + t_[k].text + "' (fxc X3025)", at);
        else if (!it->second.majority.empty() && it->second.majority != m)
            report("'" + t_[k].text + "' is already declared " + it->second.majority + "; '" + m + "' cannot change it (fxc X3048)", at);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findMajorityModifierErrors(const EffectSyntax& syntax, const SourceMap& map) {
    MajorityModifiers check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
