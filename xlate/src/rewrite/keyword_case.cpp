// See keyword_case.h.
#include "rewrite/keyword_case.h"

#include <cctype>
#include <set>
#include <vector>

#include "fx/lexer.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// Spellings the source gives a meaning of its own: `struct Vector`, `class Matrix`, `typedef ... Matrix;`.
std::set<std::string> declaredNames(const std::vector<Token>& t) {
    std::set<std::string> names;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        if ((t[i].is("struct") || t[i].is("class") || t[i].is("interface")) && t[i + 1].isIdent()) names.insert(t[i + 1].text);
        if (t[i].isIdent() && t[i + 1].is(";") && i > 0 && t[i - 1].isIdent())
            for (size_t k = i; k-- > 0 && !t[k].is(";") && !t[k].is("{") && !t[k].is("}");)
                if (t[k].is("typedef")) names.insert(t[i].text);
    }
    return names;
}

}  // namespace

std::string typeKeywordsLowerCased(const std::string& text) {
    const std::vector<Token> t = tokenize(text);
    std::string out;
    std::set<std::string> declared;
    bool scanned = false;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        const std::string& w = t[i].text;
        if (!t[i].isIdent() || w == "matrix" || w == "vector" || w == "dword") continue;
        if (!(iequals(w, "matrix") || iequals(w, "vector") || iequals(w, "dword"))) continue;
        if (!t[i + 1].isIdent() || (i > 0 && t[i - 1].is("."))) continue;
        if (!scanned) declared = declaredNames(t), scanned = true;
        if (declared.count(w)) continue;
        if (out.empty()) out = text;
        for (size_t k = t[i].offset; k < t[i].end; ++k) out[k] = static_cast<char>(std::tolower(static_cast<unsigned char>(out[k])));
    }
    return out.empty() ? text : out;
}

std::string textureTemplatesSpelledAsObjects(const std::string& text) {
    static const char* const objects[] = {"Texture1D", "Texture2D", "Texture3D", "TextureCube"};
    const std::vector<Token> t = tokenize(text);
    std::string out;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        if (!t[i].isIdent() || !t[i + 1].is("<") || (i > 0 && t[i - 1].is("."))) continue;
        for (const char* object : objects)
            if (t[i].text != object && iequals(t[i].text, object)) {
                if (out.empty()) out = text;
                out.replace(t[i].offset, t[i].end - t[i].offset, object);
            }
    }
    return out.empty() ? text : out;
}

}  // namespace fxport::xlate
