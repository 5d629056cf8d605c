#include "fxport/xlate/diagnostics.h"

namespace fxport::xlate {

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
        if (first != std::string::npos) out += "\n    " + sourceLine.substr(first);
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

CompileError::CompileError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(joinMessages(diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace fxport::xlate
