// See builtin_type_typedefs.h.
#include "rewrite/builtin_type_typedefs.h"

#include <map>
#include <regex>
#include <vector>

#include "fx/fx_syntax.h"
#include "fx/lexer.h"

namespace fxport::xlate {

namespace {

// float, uint3, half4x4, dword, min16float2 ...: a built-in numeric type name (not matrix/vector,
// which fxc refuses as a local typedef's name).
bool isBuiltinTypeName(const std::string& s) {
    static const std::regex name("(bool|int|uint|dword|half|float|double|min16float|min10float|min16int|min12int|min16uint)([1-4](x[1-4])?)?");
    return std::regex_match(s, name);
}

// `typedef T... NAME ;` starting at `i` (the `typedef` token): NAME's index, or 0 when it is not
// that shape or NAME is no built-in type name.
size_t shadowingTypedef(const std::vector<Token>& t, size_t i) {
    size_t k = i + 1;
    for (int depth = 0; k < t.size() && t[k].kind != Token::Kind::End; ++k) {
        if (t[k].is("<")) ++depth;
        if (t[k].is(">")) --depth;
        if (depth == 0 && (t[k].is(";") || t[k].is("{") || t[k].is("}"))) break;
    }
    if (k >= t.size() || !t[k].is(";") || k < i + 3) return 0;
    return t[k - 1].isIdent() && isBuiltinTypeName(t[k - 1].text) ? k - 1 : 0;
}

}  // namespace

std::string builtinTypeTypedefsResolved(const std::string& text) {
    if (text.find("typedef") == std::string::npos) return text;
    const std::vector<Token> t = tokenize(text);
    std::vector<TextEdit> edits;
    // The aliases of each open block, innermost last; the file's scope holds none (fxc refuses a
    // global typedef of a built-in name, and so does glslang).
    std::vector<std::map<std::string, std::string>> scopes(1);
    auto resolved = [&](const std::string& name) -> const std::string* {
        for (auto s = scopes.rbegin(); s != scopes.rend(); ++s)
            if (auto it = s->find(name); it != s->end()) return &it->second;
        return nullptr;
    };
    for (size_t i = 0; i < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) scopes.emplace_back();
        if (t[i].is("}") && scopes.size() > 1) scopes.pop_back();
        if (t[i].is("typedef") && scopes.size() > 1) {
            if (size_t name = shadowingTypedef(t, i)) {
                std::string alias;
                for (size_t k = i + 1; k < name; ++k) {
                    const std::string* a = t[k].isIdent() ? resolved(t[k].text) : nullptr;
                    alias += (alias.empty() ? "" : " ") + (a ? *a : t[k].text);
                }
                scopes.back()[t[name].text] = alias;
                edits.push_back({t[i].offset, t[name + 1].end, {}});
                i = name + 1;
                continue;
            }
        }
        if (!t[i].isIdent() || (i > 0 && t[i - 1].is("."))) continue;
        if (const std::string* a = resolved(t[i].text); a && *a != t[i].text) edits.push_back({t[i].offset, t[i].end, *a});
    }
    if (edits.empty()) return text;
    std::string out;
    size_t at = 0;
    for (const auto& e : edits) {  // in text order, none overlapping
        out.append(text, at, e.begin - at);
        if (e.replacement.empty()) {
            for (size_t k = e.begin; k < e.end; ++k) out += text[k] == '\n' ? '\n' : ' ';
        } else {
            out += e.replacement;
        }
        at = e.end;
    }
    out.append(text, at, std::string::npos);
    return out;
}

}  // namespace fxport::xlate
