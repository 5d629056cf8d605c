// See literal_suffixes.h.
#include "rewrite/literal_suffixes.h"

#include <cctype>
#include <string>
#include <vector>

#include "fx/lexer.h"

namespace fxport::xlate {

std::string longLiteralSuffixesDropped(const std::string& text) {
    const std::vector<Token> tokens = tokenize(text);
    std::string out;
    size_t at = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (t.kind != Token::Kind::Number) continue;
        // glslang's preprocessor hands `3lu` on as `3 u` (its own long literal, then the rest): a
        // number followed by an identifier of suffix letters on its line is never anything else.
        const bool split = i + 1 < tokens.size() && tokens[i + 1].isIdent() && tokens[i + 1].line == t.line &&
                           tokens[i + 1].text.find_first_not_of("uUlL") == std::string::npos;
        const std::string s = split ? t.text + tokens[i + 1].text : t.text;
        const size_t end = split ? tokens[i + 1].end : t.end;
        const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
        size_t digits = hex ? 2 : 0;
        while (digits < s.size() && (hex ? std::isxdigit(static_cast<unsigned char>(s[digits])) : std::isdigit(static_cast<unsigned char>(s[digits]))))
            ++digits;
        if (digits == 0 || digits == s.size() || (hex && digits == 2)) continue;
        std::string suffix = s.substr(digits), kept;
        bool longSuffix = false, valid = true;
        for (char c : suffix) {
            if (c == 'l' || c == 'L') longSuffix = true;
            else if (c == 'u' || c == 'U') kept += c;
            else valid = false;
        }
        if (!valid || (!longSuffix && !split) || kept.size() > 1 || suffix.size() > 2) continue;
        out.append(text, at, t.offset - at);
        // `3l` is an int to fxc, where an unsuffixed `3` is a literal that fits int and uint alike
        // (an overload of each ties for it: overload_ties.cpp), so the type is spelled out.
        out += kept.empty() ? "int(" + s.substr(0, digits) + ")" : s.substr(0, digits) + kept;
        at = end;
    }
    if (at == 0) return text;
    out.append(text, at, std::string::npos);
    return out;
}

std::string halfLiteralSuffixesDropped(const std::string& text) {
    std::string out;
    size_t at = 0;
    for (const Token& t : tokenize(text)) {
        if (t.kind != Token::Kind::Number || t.text.size() < 2) continue;
        const char last = t.text.back();
        if (last != 'h' && last != 'H') continue;
        const std::string number = t.text.substr(0, t.text.size() - 1);
        // A floating literal only (`0.1h`, `1.h`, `1e3h`): digits with a point or an exponent.
        if (number.find_first_not_of("0123456789.eE+-") != std::string::npos) continue;
        if (number.find_first_of(".eE") == std::string::npos) continue;
        out.append(text, at, t.offset - at);
        out += number;
        at = t.end;
    }
    if (at == 0) return text;
    out.append(text, at, std::string::npos);
    return out;
}

}  // namespace fxport::xlate
