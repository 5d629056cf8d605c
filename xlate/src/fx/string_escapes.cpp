// See string_escapes.h.
#include "fx/string_escapes.h"

#include <cctype>

namespace fxport::xlate {

namespace {

constexpr char kHiddenBackslash = '\x01', kHiddenQuote = '\x02';

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::string protectStringEscapes(const std::string& text) {
    std::string out = text;
    enum class In { Code, LineComment, BlockComment, String, Directive } state = In::Code;
    bool lineStart = true;  // only blanks since the line began
    for (size_t i = 0; i < out.size(); ++i) {
        const char c = out[i], next = i + 1 < out.size() ? out[i + 1] : '\0';
        if (c == '\n') {
            const bool continued = i > 0 && (out[i - 1] == '\\' || (out[i - 1] == '\r' && i > 1 && out[i - 2] == '\\'));
            if (state != In::BlockComment && !continued) state = In::Code;
            lineStart = true;
            continue;
        }
        switch (state) {
        case In::Code:
            if (c == '#' && lineStart) state = In::Directive;
            else if (c == '/' && next == '/') state = In::LineComment;
            else if (c == '/' && next == '*') state = In::BlockComment, ++i;
            else if (c == '"') state = In::String;
            break;
        case In::BlockComment:
            if (c == '*' && next == '/') state = In::Code, ++i;
            break;
        case In::String:
            if (c == '"') state = In::Code;
            else if (c == '\\' && next != '\n' && next != '\r' && next != '\0') {
                out[i] = kHiddenBackslash;
                if (next == '"') out[i + 1] = kHiddenQuote;  // would end the literal for glslang
                if (next == '\\') out[i + 1] = kHiddenBackslash;  // would escape what follows
                ++i;  // the escaped character belongs to the string
            }
            break;
        case In::LineComment:
        case In::Directive: break;
        }
        if (c != ' ' && c != '\t' && c != '\r') lineStart = false;
    }
    return out;
}

void restoreStringEscapes(std::string& text) {
    for (char& c : text)
        if (c == kHiddenBackslash) c = '\\';
        else if (c == kHiddenQuote) c = '"';
}

std::string decodeStringEscapes(std::string_view raw) {
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 == raw.size()) {
            out += raw[i];
            continue;
        }
        const char e = raw[++i];
        switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'f': out += '\f'; break;
        case 'v': out += '\v'; break;
        case 'a': out += '\a'; break;
        case 'b': out += '\b'; break;
        case 'x': {
            unsigned value = 0;
            size_t digits = 0;
            for (; i + 1 < raw.size() && hexValue(raw[i + 1]) >= 0; ++i, ++digits) value = (value << 4 | unsigned(hexValue(raw[i + 1]))) & 0xFFu;
            out += digits ? char(value) : 'x';
            break;
        }
        default:
            if (e >= '0' && e <= '7') {
                unsigned value = unsigned(e - '0');
                for (int k = 0; k < 2 && i + 1 < raw.size() && raw[i + 1] >= '0' && raw[i + 1] <= '7'; ++k) value = value * 8 + unsigned(raw[++i] - '0');
                out += char(value & 0xFFu);
            } else {
                out += e;  // \\ \" \' \? and the escapes fxc only warns about
            }
        }
    }
    return out;
}

}  // namespace fxport::xlate
