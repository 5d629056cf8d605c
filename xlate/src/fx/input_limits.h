// Limits on what one effect may cost, and the scans of source text that enforce them before
// glslang sees it: glslang 12 recurses once per nesting level and per nested macro call and has no
// limits of its own, so an effect nobody would write (or a fuzzer would) overflows its stack.
// docs/limits.md lists the values; each kind of limit has its own diagnostic id.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fxport/xlate/diagnostics.h"

namespace fxport::xlate {

namespace limits {
inline constexpr size_t kMaxFileBytes = size_t{4} << 20;          // one source file (FX1005)
inline constexpr size_t kMaxTotalBytes = size_t{16} << 20;        // the effect and all its includes (FX1005)
inline constexpr size_t kMaxPreprocessedBytes = size_t{32} << 20; // the text after macro expansion (FX1106)
inline constexpr size_t kMaxIncludeDepth = 32;                    // files open at once, the effect included (FX1105)
inline constexpr size_t kMaxIncludeFiles = 1024;                  // #include directives followed (FX1105)
inline constexpr int kMaxNesting = 256;                           // ( [ { open at once; constant expressions (FX1203)
inline constexpr long long kMaxArrayElements = 65536;             // elements of one declared array (FX1204)
inline constexpr size_t kMaxMembers = 16384;                      // globals of one cbuffer ($Global too), members of one struct (FX1205)
inline constexpr size_t kMaxStatements = 65536;                   // `;` in all function bodies of one effect (FX1206)
inline constexpr size_t kMaxVariableBytes = size_t{1} << 20;      // one global, cbuffer member or local, in bytes (FX1204)
inline constexpr size_t kMaxEffectFileBytes = size_t{256} << 20;  // a compiled effect or cache entry, before reading (FX3101)
inline constexpr int kMaxEffectFileNesting = 64;                  // [ { nested in a compiled effect's JSON, before parsing (FX3101)
}  // namespace limits

// Checks one source file's raw text: its size, bracket nesting outside comments and strings
// (directive lines included: `#if` expressions recurse in glslang too), and `#line` values that
// would overflow a line number in the lines that follow. The problem, located in `displayPath`.
std::optional<Diagnostic> checkSourceText(std::string_view text, const std::string& displayPath);

struct TextPosition {
    int line = 0;    // 1-based
    int column = 0;  // 1-based
};
// The first bracket of `text` that opens nesting level kMaxNesting + 1, outside comments and strings.
std::optional<TextPosition> findNestingPastLimit(std::string_view text);

// Line `line` (1-based) of `text`, cut to 200 characters: what a diagnostic quotes.
std::string lineOf(std::string_view text, int line);

// `n` elements in total for the dimensions `dims` (0 = unsized), saturated at LLONG_MAX.
long long arrayElementCount(const std::vector<int>& dims);

}  // namespace fxport::xlate
