// See byte_address_stores.h.
#include "rewrite/byte_address_stores.h"

#include "hlsl/call_arguments.h"

namespace fxport::xlate {

std::vector<TextEdit> byteAddressStoreValues(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin + 1; i + 1 < f.body.end; ++i) {
            // Only byte-address buffers have StoreN methods.
            const bool store = t[i].is("Store2") || t[i].is("Store3") || t[i].is("Store4");
            if (!store || !t[i - 1].is(".") || !t[i + 1].is("(")) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.size() != 2 || spans[1].first >= spans[1].second) continue;
            const std::string width = t[i].text.substr(5);
            edits.push_back({t[spans[1].first].offset, t[spans[1].first].offset, "(uint" + width + ")("});
            const size_t close = t[spans[1].second - 1].end;
            edits.push_back({close, close, ")"});
        }
    return edits;
}

}  // namespace fxport::xlate
