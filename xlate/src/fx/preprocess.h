// Step 1 of the compiler: glslang's HLSL preprocessor, with `#include` confined to the effect's own
// folder and the caller's include folders (case-insensitive fallback, as effects written on Windows
// expect; searched in fxc's order: the including file's folder, the other open files' folders, the
// include folders), cycles reported, and user `#define`s applied.
#pragma once

#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "fx/source_map.h"

namespace fxport::xlate {

// A file the result depends on: an include that was read (with its content hash), or a path the
// include search looked at and found empty (a file appearing there later would change the result).
struct IncludeDependency {
    std::string path;  // absolute
    std::string hash;  // contentHash() of the file; empty = the path must not exist
};

struct PreprocessedEffect {
    std::string text;        // preprocessed, `#line` markers blanked; line k maps through `map`
    SourceMap map;
    std::vector<IncludeDependency> dependencies;  // for the compile cache, in the order found
    std::vector<Diagnostic> warnings;             // malformed `#line` directives (ignored)
};

// `displayPath` is how diagnostics name the root file; `absolutePath` is where it lives (its folder
// is the include root). Throws CompileError on preprocessor errors.
PreprocessedEffect preprocessEffect(const std::string& source, const std::string& displayPath,
                                    const std::string& absolutePath, const CompileOptions& options);

// Rejects input that is not text (NUL or control bytes; bytes that are not UTF-8 outside comments and
// string literals) with a diagnostic naming the line.
// Prepares a file's decoded text for glslang: every `#line` directive the effect wrote is blanked
// (diagnostics then name the file and line a person can open, never a line 0 or a file that does
// not exist), a malformed one is reported in `warnings`; a missing final newline is added (glslang
// rejects `#include "x"` as the last bytes of a file).
void prepareSourceText(std::string& text, const std::string& displayPath, std::vector<Diagnostic>& warnings);

void checkIsText(const std::string& source, const std::string& displayPath);

}  // namespace fxport::xlate
