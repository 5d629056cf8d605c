// Tokens of the preprocessed effect text. Only what the effect-framework parser needs: identifiers,
// numbers, strings, and punctuation; comments are already gone (the preprocessor removed them).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fxport::xlate {

struct Token {
    enum class Kind { Identifier, Number, String, Punct, End } kind = Kind::End;
    std::string text;
    size_t offset = 0;  // byte offset in the preprocessed text
    size_t end = 0;     // one past the token's last byte there (quotes included; `text` may differ)
    int line = 1;       // preprocessed line (1-based)
    int column = 1;

    bool is(std::string_view s) const { return kind != Kind::String && text == s; }
    bool isIdent() const { return kind == Kind::Identifier; }
};

// The last token is always Kind::End (at the end of the text).
std::vector<Token> tokenize(const std::string& text);

}  // namespace fxport::xlate
