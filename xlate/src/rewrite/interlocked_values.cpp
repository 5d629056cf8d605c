// See interlocked_values.h.
#include "rewrite/interlocked_values.h"

#include <map>
#include <string>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

// D3D's saturating conversions (D3D11 functional spec, 3.2.3: float -> integer conversions).
const char* kFtoi =
    "int fxport_ftoi(float v) { return isnan(v) ? 0 : v >= 2147483648.0 ? 2147483647 : v <= -2147483648.0 ? (-2147483647 - 1) : int(v); } ";
const char* kFtou = "uint fxport_ftou(float v) { return isnan(v) ? 0u : v >= 4294967296.0 ? 4294967295u : v <= 0.0 ? 0u : uint(v); } ";

// The value operands of each intrinsic (argument positions), and whether they become int.
struct ValueOperands {
    std::vector<size_t> positions;
    bool signedValue;
};

const std::map<std::string, ValueOperands>& intrinsics() {
    static const std::map<std::string, ValueOperands> table = {
        {"InterlockedMax", {{1}, true}},         {"InterlockedMin", {{1}, true}},          {"InterlockedAdd", {{1}, false}},
        {"InterlockedAnd", {{1}, false}},        {"InterlockedOr", {{1}, false}},          {"InterlockedXor", {{1}, false}},
        {"InterlockedExchange", {{1}, false}},   {"InterlockedCompareExchange", {{1, 2}, false}},
        {"InterlockedCompareStore", {{1, 2}, false}},
    };
    return table;
}

bool isFloatingPoint(const std::string& s) { return s == "float" || s == "half" || s == "double" || s == "min16float" || s == "min10float"; }

}  // namespace

std::vector<TextEdit> interlockedValueConversions(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    bool declared = false;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            auto it = intrinsics().find(t[i].text);
            if (it == intrinsics().end() || !t[i].isIdent() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is(".")) || syntax.findFunction(t[i].text))
                continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            for (size_t k : it->second.positions) {
                if (k >= spans.size()) continue;
                auto type = expressionType(syntax, f, spans[k].first, spans[k].second);
                if (!type || !type->isNumeric() || type->basic.isMatrix || type->basic.columns != 1 || !isFloatingPoint(type->basic.scalar)) continue;
                if (!declared) {
                    const size_t at = t[f.declaration.begin].offset;
                    edits.push_back({at, at, std::string(kFtoi) + kFtou});
                    declared = true;
                }
                // Insertions, so that rewrites inside the operand keep their edits; the closing one
                // comes before compare_store's `, old` at the same place (applyEdits keeps order).
                edits.push_back({t[spans[k].first].offset, t[spans[k].first].offset, it->second.signedValue ? "fxport_ftoi(" : "fxport_ftou("});
                edits.push_back({t[spans[k].second - 1].end, t[spans[k].second - 1].end, ")"});
            }
        }
    }
    return edits;
}

}  // namespace fxport::xlate
