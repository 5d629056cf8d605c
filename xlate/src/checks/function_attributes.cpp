// fxc's rules for attributes at file scope (`[numthreads(8, 8, 1)]`, `[maxvertexcount(3)]`;
// vkd3d's attributes pins them), which fxport's parser only collects:
//  - an attribute list belongs to a function: before a variable it is an error;
//  - one attribute name appears once per function;
//  - a constructor in an attribute's arguments has its full component count (`float2(1)` is none).
// Statement attributes ([unroll], [branch]) are fxc_rejections.cpp's.
#include <set>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

class FunctionAttributes : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 0; i + 2 < t_.size(); ++i) {
            if (!t_[i].is("[") || !t_[i + 1].isIdent() || inFunctionBody(i)) continue;
            if (i > 0 && !(t_[i - 1].is(";") || t_[i - 1].is("}"))) continue;
            i = attributeList(i);
        }
    }

private:
    bool inFunctionBody(size_t at) const {
        const FxFunction* f = functionAt(at);
        return (f && at >= f->body.begin) || syntax_.inMemberFunctionBody(at);
    }

    // `[a][b(1)] declaration`: returns the index of the declaration's first token.
    size_t attributeList(size_t at) {
        std::set<std::string> names;
        size_t i = at;
        while (tok(i).is("[") && tok(i + 1).isIdent()) {
            const Token& name = t_[i + 1];
            if (!names.insert(name.text).second) report("attribute '" + name.text + "' is given twice on one function", i + 1);
            size_t close = closing(i);
            if (tok(i + 2).is("(")) constructors(i + 3, closing(i + 2));
            i = close + 1;
        }
        if (!declaresFunction(i))
            report("attributes apply to functions; '" + tok(i).text + "' starts no function declaration", at + 1);
        return i;
    }
    // `type name (` (modifiers and a template argument list allowed before the name).
    bool declaresFunction(size_t i) const {
        while (tok(i).isIdent() && (tok(i).is("inline") || tok(i).is("static") || tok(i).is("precise"))) ++i;
        if (!tok(i).isIdent()) return false;
        ++i;
        if (tok(i).is("<")) i = closing(i) + 1;
        return tok(i).isIdent() && tok(i + 1).is("(");
    }
    // `float2(1)` among [begin, end): a numeric constructor of plain numbers with too few or too
    // many of them.
    void constructors(size_t begin, size_t end) {
        for (size_t k = begin; k + 1 < end; ++k) {
            if (!t_[k].isIdent() || !t_[k + 1].is("(")) continue;
            BasicType b = describeBasicType(t_[k].text);
            if (!b.ok || (b.rows * b.columns) == 1) continue;
            size_t close = closing(k + 1);
            int numbers = 0;
            bool plain = true;
            for (size_t a = k + 2; a < close; ++a) {
                if (t_[a].is(",") || t_[a].is("-")) continue;
                plain &= t_[a].kind == Token::Kind::Number;
                ++numbers;
            }
            if (plain && numbers != b.rows * b.columns)
                report("'" + t_[k].text + "' is built from " + std::to_string(b.rows * b.columns) + " components, not " + std::to_string(numbers), k);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findFunctionAttributeErrors(const EffectSyntax& syntax, const SourceMap& map) {
    FunctionAttributes check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
