// Scans of raw and preprocessed source text for the limits in input_limits.h.
#include "fx/input_limits.h"

#include <algorithm>
#include <climits>
#include <vector>

namespace fxport::xlate {

namespace {

// Walks `text` outside comments, string and character literals, calling `onCode(i, line, column)`
// for every code character and `onLineStart(i, line)` at the first character of every line.
template <typename OnCode, typename OnLineStart>
void walkCode(std::string_view text, OnCode onCode, OnLineStart onLineStart) {
    enum class In { Code, LineComment, BlockComment, String, Char } state = In::Code;
    int line = 1;
    size_t lineStart = 0;
    onLineStart(size_t{0}, 1);
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (c == '\n') {
            bool continued = i > lineStart && text[i - 1] == '\\';
            if ((state == In::LineComment && !continued) || state == In::String || state == In::Char) state = In::Code;
            ++line;
            lineStart = i + 1;
            if (!onLineStart(i + 1, line)) return;
            continue;
        }
        switch (state) {
        case In::Code:
            if (c == '/' && next == '/') state = In::LineComment, ++i;
            else if (c == '/' && next == '*') state = In::BlockComment, ++i;
            else if (c == '"') state = In::String;
            else if (c == '\'') state = In::Char;
            else if (!onCode(i, line, static_cast<int>(i - lineStart) + 1)) return;
            break;
        case In::LineComment: break;
        case In::BlockComment:
            if (c == '*' && next == '/') state = In::Code, ++i;
            break;
        case In::String:
        case In::Char:
            if (c == '\\' && next != '\n') ++i;
            else if (c == (state == In::String ? '"' : '\'')) state = In::Code;
            break;
        }
    }
}


}  // namespace

std::string lineOf(std::string_view text, int line) {
    size_t pos = 0;
    for (int l = 1; l < line && pos != std::string_view::npos; ++l) {
        pos = text.find('\n', pos);
        if (pos != std::string_view::npos) ++pos;
    }
    if (pos == std::string_view::npos) return {};
    size_t end = text.find('\n', pos);
    std::string s(text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos));
    if (s.size() > 200) s.resize(200);  // enough to recognise the line; a megabyte line helps nobody
    while (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
}

std::optional<TextPosition> findNestingPastLimit(std::string_view text) {
    int depth = 0;
    std::optional<TextPosition> found;
    walkCode(
        text,
        [&](size_t i, int line, int column) {
            char c = text[i];
            if (c == '(' || c == '[' || c == '{') {
                if (++depth > limits::kMaxNesting) {
                    found = TextPosition{line, column};
                    return false;
                }
            } else if ((c == ')' || c == ']' || c == '}') && depth > 0) {
                --depth;
            }
            return true;
        },
        [](size_t, int) { return true; });
    return found;
}

std::optional<Diagnostic> checkSourceText(std::string_view text, const std::string& displayPath) {
    auto make = [&](const char* id, std::string message, int line, int column) {
        Diagnostic d;
        d.id = id;
        d.message = std::move(message);
        d.location = {displayPath, line, column};
        d.sourceLine = line > 0 ? lineOf(text, line) : std::string();
        return d;
    };
    if (text.size() > limits::kMaxFileBytes)
        return make(diag::kInputTooLarge, "the file has " + std::to_string(text.size()) + " bytes; fxport compiles source files of at most " +
                                              std::to_string(limits::kMaxFileBytes >> 20) + " MiB",
                    0, 0);
    if (auto p = findNestingPastLimit(text))
        return make(diag::kNestingTooDeep, "brackets are nested more than " + std::to_string(limits::kMaxNesting) + " levels deep here, the most fxport accepts",
                    p->line, p->column);
    // `#line N`: the lines after it are numbered N, N+1, ... and must stay representable.
    const long long totalLines = static_cast<long long>(std::count(text.begin(), text.end(), '\n')) + 1;
    std::optional<Diagnostic> lineProblem;
    walkCode(
        text, [](size_t, int, int) { return true; },
        [&](size_t i, int line) {
            size_t k = i;
            auto skipBlanks = [&] {
                while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
            };
            skipBlanks();
            if (k >= text.size() || text[k] != '#') return true;
            ++k;
            skipBlanks();
            if (text.compare(k, 4, "line") != 0 || k + 4 >= text.size() || (text[k + 4] != ' ' && text[k + 4] != '\t')) return true;
            k += 4;
            skipBlanks();
            size_t digitsStart = k;
            long long value = 0;
            while (k < text.size() && text[k] >= '0' && text[k] <= '9') {
                value = std::min<long long>(value * 10 + (text[k] - '0'), LLONG_MAX / 100);
                ++k;
            }
            if (k == digitsStart) return true;  // a macro or garbage: glslang's preprocessor judges it
            long long last = value + (totalLines - line);
            if (last > INT_MAX) {
                lineProblem = make(diag::kPreprocessor, "#line " + std::string(text.substr(digitsStart, k - digitsStart)) +
                                                            " numbers the lines that follow past " + std::to_string(INT_MAX) + ", the largest line number",
                                   line, static_cast<int>(digitsStart - i) + 1);
                return false;
            }
            return true;
        });
    return lineProblem;
}

long long arrayElementCount(const std::vector<int>& dims) {
    long long n = 1;
    for (int d : dims) {
        if (d <= 0) continue;
        if (__builtin_mul_overflow(n, static_cast<long long>(d), &n)) return LLONG_MAX;
    }
    return n;
}

}  // namespace fxport::xlate
