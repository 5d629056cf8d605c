// See one_component_types.h.
#include "one_component_types.h"

#include <string>

namespace fxport::xlate {

namespace {

bool isScalarName(const std::string& s) {
    static const char* const kScalars[] = {"float",      "half",       "double",    "int",      "uint",     "bool", "dword",
                                           "min16float", "min10float", "min16int",  "min12int", "min16uint"};
    for (const char* k : kScalars)
        if (s == k) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> respellOneComponentVectors(const std::vector<Token>& tokens) {
    std::vector<TextEdit> edits;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (!t.isIdent() || t.text.size() < 2 || t.text.back() != '1') continue;
        std::string scalar = t.text.substr(0, t.text.size() - 1);
        if (!isScalarName(scalar)) continue;
        if (i > 0 && tokens[i - 1].is(".")) continue;  // a member that happens to be named `float1`
        edits.push_back({t.offset, t.end, scalar});
    }
    return edits;
}

}  // namespace fxport::xlate
