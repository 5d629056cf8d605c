// Step 1 of the compiler: glslang's HLSL preprocessor, with `#include` confined to the effect's own
// folder and the caller's include folders (case-insensitive fallback, as effects written on Windows
// expect), cycles reported, and user `#define`s applied.
#pragma once

#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "source_map.h"

namespace fxport::xlate {

struct PreprocessedEffect {
    std::string text;        // preprocessed, `#line` markers blanked; line k maps through `map`
    SourceMap map;
    std::vector<std::string> includedFiles;  // absolute paths read (for cache keys / dependency lists)
};

// `displayPath` is how diagnostics name the root file; `absolutePath` is where it lives (its folder
// is the include root). Throws CompileError on preprocessor errors.
PreprocessedEffect preprocessEffect(const std::string& source, const std::string& displayPath,
                                    const std::string& absolutePath, const CompileOptions& options);

// Rejects input that is not text (NUL bytes, invalid UTF-8) with a diagnostic naming the line.
void checkIsText(const std::string& source, const std::string& displayPath);

}  // namespace fxport::xlate
