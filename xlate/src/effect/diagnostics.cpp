#include "fxport/xlate/diagnostics.h"

#include <algorithm>
#include <set>

namespace fxport::xlate {

namespace {

// The source line from its first non-blank character; a line longer than kMaxQuoted (a minified
// or generated file: one line of megabytes) is quoted only around the column, marked with "...".
std::string quotedPart(const std::string& line, size_t first, int column) {
    constexpr size_t kMaxQuoted = 160;
    if (line.size() - first <= kMaxQuoted) return line.substr(first);
    size_t at = column > 0 ? static_cast<size_t>(column - 1) : first;
    size_t begin = std::max(first, at > kMaxQuoted / 2 ? at - kMaxQuoted / 2 : first);
    begin = std::min(begin, line.size() - kMaxQuoted);
    return (begin > first ? "..." : "") + line.substr(begin, kMaxQuoted) + (begin + kMaxQuoted < line.size() ? "..." : "");
}

}  // namespace

std::string Diagnostic::format() const {
    std::string out = location.file.empty() ? std::string("<effect>") : location.file;
    if (location.line > 0) {
        out += "(" + std::to_string(location.line);
        if (location.column > 0) out += "," + std::to_string(location.column);
        out += ")";
    }
    out += severity == Severity::Error ? ": error " : ": warning ";
    out += id + ": " + message;
    if (!sourceLine.empty()) {
        size_t first = sourceLine.find_first_not_of(" \t");
        if (first != std::string::npos) out += "\n    " + quotedPart(sourceLine, first, location.column);
    }
    return out;
}

static std::string joinMessages(const std::vector<Diagnostic>& diagnostics) {
    std::string all;
    for (const auto& d : diagnostics) {
        if (!all.empty()) all += "\n";
        all += d.format();
    }
    return all.empty() ? std::string("effect compilation failed") : all;
}

// glslang compiles the whole effect for each of its shaders, so an error in a function every
// shader includes comes back once per shader, word for word: it is reported once.
static std::vector<Diagnostic> withoutRepeats(std::vector<Diagnostic> diagnostics) {
    std::vector<Diagnostic> out;
    std::set<std::string> seen;
    for (auto& d : diagnostics)
        if (seen.insert(d.format()).second) out.push_back(std::move(d));
    return out;
}

CompileError::CompileError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(joinMessages(withoutRepeats(diagnostics))), diagnostics_(withoutRepeats(std::move(diagnostics))) {}

}  // namespace fxport::xlate
