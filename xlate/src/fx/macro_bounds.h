// The size a macro can expand to, bounded before glslang expands anything: glslang 12's
// preprocessor has no limit of its own, and `#define D1 D0 D0` ... `#define D40 D39 D39` makes
// 2^40 tokens (it ran until the worker's CPU limit, 60 s). Each file's #define lines join one table
// (the effect's, then each include's as glslang opens it); every use of a macro outside a #define
// is bounded (and every name used before is bounded again when an include adds definitions, within
// a budget of 64 M names) by adding up its body, each macro in it bounded the same way, a function-like
// macro's call as its body with every parameter occurrence replaced by all of its arguments
// (`#define D(a) a a` called as `D(D(D(x)))` doubles per level). A macro inside its own expansion
// counts as its name, as the preprocessor leaves it. #undef and #if are not followed: the largest
// body a name was ever given counts, so the bound is never below what glslang would make.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "fxport/xlate/diagnostics.h"

namespace fxport::xlate {

class MacroBounds {
public:
    // Adds `text`'s definitions, then bounds every macro the file names outside a #define: FX1106
    // at the first whose expansion would pass limits::kMaxPreprocessedBytes.
    std::optional<Diagnostic> addFile(std::string_view text, const std::string& displayPath);

    static constexpr size_t kMaxDepth = 1000;  // macros expanding inside one another (FX1106 past it)
    // Calls written inside another call's arguments, `F(F(F(x)))`: glslang expands each level's
    // arguments again, so its time grows with depth x length (250 deep over 46 KB: 2 s; 64: 0.45 s).
    static constexpr int kMaxCallNesting = 64;

private:
    struct Tokens {
        std::vector<std::string> text;
        std::vector<size_t> close;  // for each "(", the index of its ")" (text.size() when unclosed)
    };
    struct Macro {
        bool function = false;
        std::vector<Tokens> bodies;  // every body the name was given
    };
    struct Cost {
        unsigned long long bytes = 0;   // outside parameters, saturated past the limit
        unsigned long long params = 0;  // parameter occurrences
    };
    struct Walk {  // one bounding pass: sizes found so far, the macros being expanded
        std::map<std::string, Cost, std::less<>> memo;
        std::set<std::string, std::less<>> open;
        bool tooDeep = false;
        int callNesting = 0;  // calls open in the text being walked
        bool callsTooDeep = false;
    };
    Cost sequence(const Tokens& tokens, size_t begin, size_t end, Walk& walk) const;
    Cost expansion(const std::string& name, const Macro& macro, Walk& walk) const;
    std::map<std::string, Macro, std::less<>> macros_;
    std::map<std::string, SourceLocation, std::less<>> usedNames_;  // every name used outside a #define, where first
    long long recheckBudget_ = 64 << 20;                            // names bounded again as includes add definitions
};

}  // namespace fxport::xlate
