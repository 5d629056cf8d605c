#include "fx/lexer.h"

#include <cctype>

#include "fx/string_escapes.h"
#include "fx/text_util.h"

namespace fxport::xlate {

std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    size_t i = 0;
    int line = 1;
    size_t lineStart = 0;
    auto isIdentStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    auto isIdentChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    while (i < text.size()) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            lineStart = ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        Token t;
        t.offset = i;
        t.line = line;
        t.column = static_cast<int>(i - lineStart) + 1;
        if (isIdentStart(c)) {
            size_t j = i + 1;
            while (j < text.size() && isIdentChar(text[j])) ++j;
            t.kind = Token::Kind::Identifier;
            t.text = text.substr(i, j - i);
            i = j;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            size_t j = i;
            if (c == '0' && j + 1 < text.size() && (text[j + 1] == 'x' || text[j + 1] == 'X')) {
                j += 2;
                while (j < text.size() && std::isxdigit(static_cast<unsigned char>(text[j]))) ++j;
            } else {
                while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) ++j;
                if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
                    size_t k = j + 1;
                    if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
                    if (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) {
                        j = k;
                        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
                    }
                }
            }
            while (j < text.size() && (text[j] == 'f' || text[j] == 'F' || text[j] == 'h' || text[j] == 'H' ||
                                       text[j] == 'u' || text[j] == 'U' || text[j] == 'l' || text[j] == 'L'))
                ++j;
            t.kind = Token::Kind::Number;
            t.text = text.substr(i, j - i);
            i = j;
        } else if (c == '"') {
            size_t j = i + 1;
            while (j < text.size() && text[j] != '"' && text[j] != '\n') {
                if (text[j] == '\\' && j + 1 < text.size()) ++j;
                ++j;
            }
            t.kind = Token::Kind::String;
            // Strings are annotation and parameter metadata; old effects wrote them in a local
            // code page (checkIsText lets that through), but everything downstream is UTF-8.
            t.text = toValidUtf8(decodeStringEscapes(std::string_view(text).substr(i + 1, (j < text.size() ? j : text.size()) - i - 1)));
            i = j < text.size() && text[j] == '"' ? j + 1 : j;
        } else {
            static const char* const kMulti[] = {"<<=", ">>=", "::", "==", "!=", "<=", ">=", "&&", "||", "++", "--",
                                                  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>"};
            t.kind = Token::Kind::Punct;
            t.text = std::string(1, c);
            for (const char* m : kMulti) {
                std::string_view mv(m);
                if (text.compare(i, mv.size(), mv) == 0) {
                    // `<<`/`>>` must stay single characters: they close annotations and templates.
                    if (mv == "<<" || mv == ">>" || mv == "<=" || mv == ">=" || mv == "<<=" || mv == ">>=") continue;
                    t.text = std::string(mv);
                    break;
                }
            }
            i += t.text.size();
        }
        t.end = i;
        tokens.push_back(std::move(t));
    }
    Token end;
    end.kind = Token::Kind::End;
    end.offset = end.end = text.size();
    end.line = line;
    end.column = static_cast<int>(text.size() - lineStart) + 1;
    tokens.push_back(end);
    return tokens;
}

}  // namespace fxport::xlate
