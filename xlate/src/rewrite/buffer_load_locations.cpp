// See buffer_load_locations.h.
#include "rewrite/buffer_load_locations.h"

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "hlsl/method_receivers.h"

namespace fxport::xlate {

namespace {

// Buffer, Buffer<float4>, RWBuffer<uint> (typedefs resolved by methodReceiver).
bool isTypedBuffer(const std::string& type) {
    const std::string name = type.substr(0, type.find('<'));
    return name == "Buffer" || name == "RWBuffer" || name == "Buffer " || name == "RWBuffer ";
}

}  // namespace

std::vector<TextEdit> bufferLoadLocationsAsScalars(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin + 1; i + 1 < f.body.end; ++i) {
            if (!t[i].is("Load") || !t[i - 1].is(".") || !t[i + 1].is("(")) continue;
            auto receiver = methodReceiver(syntax, f, i - 1);
            if (!receiver || !isTypedBuffer(receiver->type)) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.empty() || spans[0].first >= spans[0].second) continue;
            auto type = expressionType(syntax, f, spans[0].first, spans[0].second);
            if (!type || !type->isNumeric() || (type->basic.rows == 1 && type->basic.columns == 1)) continue;
            // A one-row or one-column matrix is a vector to glslang unless it was kept a matrix.
            const bool matrix = type->basic.isMatrix && ((type->basic.rows > 1 && type->basic.columns > 1) || type->keptMatrix);
            edits.push_back({t[spans[0].first].offset, t[spans[0].first].offset, "("});
            const size_t close = t[spans[0].second - 1].end;
            edits.push_back({close, close, matrix ? ")._m00" : ").x"});
        }
    return edits;
}

}  // namespace fxport::xlate
