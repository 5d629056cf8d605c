// See compare_store.h.
#include "rewrite/compare_store.h"

#include "hlsl/call_arguments.h"

namespace fxport::xlate {

std::vector<TextEdit> compareStoreAsExchange(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    if (syntax.findFunction("InterlockedCompareStore")) return edits;  // the effect's own function
    const char* kOld = "fxport_compare_store_old";
    bool declared = false;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].is("InterlockedCompareStore") || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.size() != 3) continue;
            if (!declared) {
                const size_t at = t[f.declaration.begin].offset;
                edits.push_back({at, at, std::string("static uint ") + kOld + "; "});
                declared = true;
            }
            edits.push_back({t[i].offset, t[i].end, "InterlockedCompareExchange"});
            const size_t close = t[spans[2].second - 1].end;
            edits.push_back({close, close, std::string(", ") + kOld});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
