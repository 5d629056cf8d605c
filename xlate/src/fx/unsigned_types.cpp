// `unsigned T` as the uint type fxc means (unsigned_types.h).
#include "fx/unsigned_types.h"

#include <map>

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Typedef {
    std::string type;
    bool array = false;
};

// `typedef int2 Int2;` and `typedef int Int[2];`, in the order written (a typedef names one
// declared before it).
std::map<std::string, Typedef> simpleTypedefs(const std::vector<Token>& t) {
    std::map<std::string, Typedef> out;
    for (size_t i = 0; i + 3 < t.size(); ++i) {
        if (!t[i].is("typedef") || !t[i + 1].isIdent() || !t[i + 2].isIdent()) continue;
        if (t[i + 3].is(";")) out[t[i + 2].text] = {t[i + 1].text, false};
        else if (t[i + 3].is("[")) out[t[i + 2].text] = {t[i + 1].text, true};
    }
    return out;
}

}  // namespace

std::optional<std::pair<size_t, std::string>> mergeUnsignedTypes(std::vector<Token>& tokens, std::vector<TextEdit>& edits) {
    std::map<std::string, Typedef> typedefs;
    bool scanned = false;
    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
        if (!tokens[i].is("unsigned") || !tokens[i + 1].isIdent()) continue;
        if (!scanned) typedefs = simpleTypedefs(tokens), scanned = true;
        std::string type = tokens[i + 1].text;
        bool array = false;
        for (int depth = 0; typedefs.count(type) && depth < 16; ++depth) {
            array |= typedefs[type].array;
            type = typedefs[type].type;
        }
        BasicType b = describeBasicType(type);
        if (array || !b.ok || b.scalar != "int")
            return std::pair<size_t, std::string>(i, "'unsigned' applies to int types; '" + tokens[i + 1].text + "' is not one");
        std::string spelled = b.isMatrix ? "uint" + std::to_string(b.rows) + "x" + std::to_string(b.columns)
                              : type.rfind("int", 0) == 0 ? "u" + type
                              : b.columns > 1 ? "uint" + std::to_string(b.columns) : "uint";
        edits.push_back({tokens[i].offset, tokens[i + 1].end, spelled});
        tokens[i].text = spelled;
        tokens[i].end = tokens[i + 1].end;
        tokens.erase(tokens.begin() + long(i) + 1);
    }
    return std::nullopt;
}

}  // namespace fxport::xlate
