// Maps lines of the preprocessed text back to the original files, using the `#line N "file"`
// markers glslang's preprocessor emits at include boundaries. Every diagnostic goes through here,
// so errors always point into the file the user wrote, never into our rewritten text.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"

namespace fxport::xlate {

class SourceMap {
public:
    // Takes the preprocessed text, records where each of its lines came from, and returns the text
    // with the `#line` markers blanked (so line k of the result is line k of the input).
    std::string build(const std::string& preprocessed, const std::string& rootFile);

    // Remembers a file's original text (for printing the offending line and finding columns).
    void addFileText(const std::string& file, std::string text);

    // Location of preprocessed line `line` (1-based). `token`, when given, is searched for in the
    // original line to recover the column (the preprocessor re-spaces tokens).
    SourceLocation locate(int line, int column = 0, const std::string& token = {}) const;
    std::string originalLine(const std::string& file, int line) const;
    Diagnostic make(Severity severity, const char* id, std::string message, int line, int column = 0,
                    const std::string& token = {}) const;
    // Diagnostic at a known original location (file:line), with its source line filled in.
    Diagnostic makeAt(Severity severity, const char* id, std::string message, SourceLocation where) const;

    const std::vector<std::string>& files() const { return fileOrder_; }

private:
    struct LineOrigin {
        int fileIndex = 0;
        int line = 0;
    };
    std::vector<LineOrigin> lines_;   // index = preprocessed line - 1
    std::vector<std::string> fileOrder_;
    std::map<std::string, std::vector<std::string>> fileLines_;
    int fileIndex(const std::string& file);
};

}  // namespace fxport::xlate
