// See attribute_case.h.
#include "rewrite/attribute_case.h"

#include <cctype>
#include <vector>

#include "fx/lexer.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// fxc's entry attributes other than numthreads (see the header for why it is left out).
bool caseFreeAttribute(const std::string& w) {
    static const char* const kNames[] = {"maxvertexcount",      "instance",          "domain",       "partitioning",
                                         "outputtopology",      "outputcontrolpoints", "patchconstantfunc", "maxtessfactor",
                                         "earlydepthstencil"};
    for (const char* n : kNames)
        if (iequals(w, n)) return true;
    return false;
}

}  // namespace

std::string entryAttributeNamesLowerCased(const std::string& text) {
    const std::vector<Token> t = tokenize(text);
    std::string out;
    int depth = 0;  // braces: attributes inside a body are statement attributes, left alone
    for (size_t i = 0; i + 2 < t.size(); ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}") && depth > 0) --depth;
        if (depth > 0 || !t[i].is("[") || !t[i + 1].isIdent()) continue;
        const Token& name = t[i + 1];
        if (!caseFreeAttribute(name.text) || !(t[i + 2].is("(") || t[i + 2].is("]"))) continue;
        // An attribute starts a declaration; `a[MaxVertexCount]` is an array size.
        if (i > 0 && !(t[i - 1].is(";") || t[i - 1].is("}") || t[i - 1].is("]"))) continue;
        if (out.empty()) out = text;
        for (size_t k = name.offset; k < name.end; ++k) out[k] = static_cast<char>(std::tolower(static_cast<unsigned char>(out[k])));
    }
    return out.empty() ? text : out;
}

}  // namespace fxport::xlate
