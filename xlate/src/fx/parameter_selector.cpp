#include "fx/parameter_selector.h"

#include <cstdlib>

namespace fxport::xlate {

std::optional<SelectorError> appendSelector(const std::vector<Token>& t, TokenSpan span,
                                          const std::function<int(const std::string&)>& parameterIndex,
                                          std::vector<SelectorOp>& ops) {
    // index := NUMBER | NAME | NAME '[' index ']'
    if (span.empty()) return SelectorError{"the index is empty"};
    if (span.end == span.begin + 1) {
        const Token& only = t[span.begin];
        if (only.kind == Token::Kind::Number) {
            ops.push_back({SelectorOp::Kind::PushConstant, std::atoi(only.text.c_str())});
            return std::nullopt;
        }
        int p = only.isIdent() ? parameterIndex(only.text) : -1;
        if (p < 0) return SelectorError{"'" + only.text + "' is not a parameter of this effect"};
        ops.push_back({SelectorOp::Kind::PushParameter, p});
        return std::nullopt;
    }
    if (t[span.begin].isIdent() && t[span.begin + 1].is("[") && t[span.end - 1].is("]")) {
        int p = parameterIndex(t[span.begin].text);
        if (p < 0) return SelectorError{"array '" + t[span.begin].text + "' is not a parameter of this effect"};
        if (auto error = appendSelector(t, {span.begin + 2, span.end - 1}, parameterIndex, ops)) return error;
        ops.push_back({SelectorOp::Kind::IndexParameter, p});
        return std::nullopt;
    }
    std::string text;
    for (size_t i = span.begin; i < span.end; ++i) text += (text.empty() ? "" : " ") + t[i].text;
    return SelectorError{"index expression '" + text + "' is too complex (use a parameter, a literal or array[parameter])", true};
}

}  // namespace fxport::xlate
