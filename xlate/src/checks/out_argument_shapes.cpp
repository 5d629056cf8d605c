// A vector or matrix passed for a scalar `out`/`inout` parameter (`void fun(out float f)` called
// as `fun(p)` with a float4 p): fxc refuses the call, as it would have to write one value back
// into several components (vkd3d's function-cast pins it); glslang took it. Judged where the
// function has one definition and the argument's type is evident (expression_types.h); a
// one-component vector is a scalar here too.
#include <map>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool writesBack(const FxParameter& p) {
    for (const auto& m : p.modifiers)
        if (m == "out" || m == "inout") return true;
    return false;
}

class OutArgumentShapes : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::map<std::string, int> definitions;
        for (const auto& f : syntax_.functions) ++definitions[f.name];
        for (const auto& caller : syntax_.functions)
            for (size_t i = caller.body.begin; i + 1 < caller.body.end; ++i) {
                if (!t_[i].isIdent() || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
                auto d = definitions.find(t_[i].text);
                if (d == definitions.end() || d->second != 1) continue;
                for (const auto& callee : syntax_.functions)
                    if (callee.name == t_[i].text) check(caller, callee, i);
            }
    }

private:
    void check(const FxFunction& caller, const FxFunction& callee, size_t at) {
        auto args = callArgumentSpans(t_, at + 1, caller.body.end);
        if (args.size() != callee.parameters.size()) return;
        for (size_t k = 0; k < args.size(); ++k) {
            const FxParameter& p = callee.parameters[k];
            if (!writesBack(p) || !p.arrayDims.empty()) continue;
            BasicType param = describeBasicType(syntax_.resolveType(p.type));
            if (!param.ok || param.isMatrix || param.columns != 1) continue;
            auto arg = expressionType(syntax_, caller, args[k].first, args[k].second);
            if (!arg || !arg->isNumeric() || arg->vector1 || arg->basic.rows * arg->basic.columns < 2) continue;
            report("argument " + std::to_string(k + 1) + " of '" + callee.name + "' is an out parameter of type '" + p.type +
                       "': fxc does not write one value back into the " + std::to_string(arg->basic.rows * arg->basic.columns) +
                       " components of '" + spellType(arg->basic) + "'",
                   args[k].first);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findOutArgumentShapeErrors(const EffectSyntax& syntax, const SourceMap& map) {
    OutArgumentShapes check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
