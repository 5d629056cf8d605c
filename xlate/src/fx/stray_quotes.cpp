// See stray_quotes.h.
#include "fx/stray_quotes.h"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace fxport::xlate {

namespace {

constexpr char kHiddenApostrophe = '\x03', kHiddenDoubleQuote = '\x04';

// The length of the literal that starts at text[i] (a quote) and closes on its line, 0 if none.
// A ' literal is what glslang takes: one character or one escape between the quotes.
size_t literalLength(std::string_view text, size_t i) {
    const char quote = text[i];
    if (quote == '\'') {
        size_t k = i + 1;
        if (k < text.size() && text[k] == '\\') ++k;
        if (k >= text.size() || text[k] == '\n' || (text[k] == '\'' && text[k - 1] != '\\')) return 0;
        return k + 1 < text.size() && text[k + 1] == '\'' ? k + 2 - i : 0;
    }
    for (size_t k = i + 1; k < text.size() && text[k] != '\n'; ++k) {
        if (text[k] == '\\' && k + 1 < text.size() && text[k + 1] != '\n') ++k;
        else if (text[k] == '"') return k + 1 - i;
    }
    return 0;
}

// The directive's name when text[lineStart..] is a directive line ("" when it is not).
std::string_view directiveName(std::string_view text, size_t lineStart) {
    size_t hash = text.find_first_not_of(" \t", lineStart);
    if (hash == std::string_view::npos || text[hash] != '#') return {};
    size_t word = text.find_first_not_of(" \t", hash + 1);
    if (word == std::string_view::npos) return {};
    size_t end = word;
    while (end < text.size() && (std::isalpha(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
    return text.substr(word, end - word);
}

// `#error MESSAGE` with MESSAGE (up to a comment or the end of the line) as one string literal;
// `i` is the line's start, moved to where the rest of the line (a comment) continues.
void quoteErrorMessage(std::string_view text, size_t& i, std::string& out) {
    size_t name = text.find("error", text.find('#', i));
    size_t begin = text.find_first_not_of(" \t", name + 5);
    size_t end = text.find('\n', i);
    if (end == std::string_view::npos) end = text.size();
    size_t stop = std::min({end, text.substr(0, end).find("//", begin), text.substr(0, end).find("/*", begin)});
    size_t last = stop;
    while (last > begin && (text[last - 1] == ' ' || text[last - 1] == '\t' || text[last - 1] == '\r')) --last;
    std::string_view message = begin < last ? text.substr(begin, last - begin) : std::string_view();
    const bool continued = end > i && text[end - 1 - (end > 1 && text[end - 1] == '\r')] == '\\';
    const bool oneLiteral = message.size() >= 2 && message.front() == '"' && literalLength(text, begin) == message.size();
    if (message.empty() || continued || oneLiteral) return;  // left to the scan
    out.append(text.substr(i, begin - i));
    out += '"';
    for (char c : message) out += c == '"' ? kHiddenDoubleQuote : c;  // glslang reads no escapes in a directive
    out += '"';
    i = last;
}

}  // namespace

std::string hideStrayQuotes(const std::string& source) {
    std::string_view text = source;
    std::string out;
    out.reserve(text.size());
    bool inBlockComment = false, lineStart = true;
    for (size_t i = 0; i < text.size();) {
        if (lineStart && !inBlockComment) {
            std::string_view name = directiveName(text, i);
            if (name == "include") {  // its path is not a literal to judge
                size_t end = text.find('\n', i);
                end = end == std::string_view::npos ? text.size() : end;
                out.append(text.substr(i, end - i));
                i = end;
                continue;
            }
            if (name == "error") quoteErrorMessage(text, i, out);
        }
        lineStart = false;
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (inBlockComment) {
            if (c == '*' && next == '/') inBlockComment = false, out += "*/", i += 2;
            else out += c, lineStart = c == '\n', ++i;
            continue;
        }
        if (c == '\n') {
            const bool continued = i > 0 && (text[i - 1] == '\\' || (text[i - 1] == '\r' && i > 1 && text[i - 2] == '\\'));
            out += c, ++i;
            lineStart = !continued;
        } else if (c == '/' && next == '*') {
            inBlockComment = true, out += "/*", i += 2;
        } else if (c == '/' && next == '/') {
            size_t end = text.find('\n', i);  // a comment continued by a backslash keeps its quotes: glslang skips it too
            while (end != std::string_view::npos && end > 0 && text[end - 1 - (text[end - 1] == '\r')] == '\\') end = text.find('\n', end + 1);
            end = end == std::string_view::npos ? text.size() : end;
            out.append(text.substr(i, end - i));
            i = end;
        } else if (c == '\'' || c == '"') {
            size_t length = literalLength(text, i);
            if (length) out.append(text.substr(i, length)), i += length;
            else out += c == '\'' ? kHiddenApostrophe : kHiddenDoubleQuote, ++i;
        } else {
            out += c, ++i;
        }
    }
    return out;
}

void restoreStrayQuotes(std::string& text) {
    for (char& c : text)
        if (c == kHiddenApostrophe) c = '\'';
        else if (c == kHiddenDoubleQuote) c = '"';
}

}  // namespace fxport::xlate
