// Quotes that open no literal: `#error ... it's likely not valid anymore` (CMAA2) and FXAA 3.11's
// `#error ... can't be enabled together`, in groups that #if skips. A C preprocessor reads the
// text lines of a skipped group only to find the next directive (MSVC and GCC accept an unmatched
// quote there, at most with a warning); glslang's scans them as tokens and stops at the quote
// ("''' : expected", "end of line in string"). So, before glslang:
//  - an #error's message becomes one string literal (its text kept whole, apostrophes included;
//    its own double quotes hidden as below);
//  - every other ' or " that does not start a literal closed on its line is hidden as one control
//    byte (checkIsText keeps those out of sources), which glslang passes on as an ordinary token,
//    and restored in its output, so taken code still shows the quote to the compiler.
// Each line keeps its number; columns after a changed #error can move by the added quotes.
#pragma once

#include <string>

namespace fxport::xlate {

std::string hideStrayQuotes(const std::string& text);

// Each hidden quote becomes its quote again (in glslang's output and in its messages).
void restoreStrayQuotes(std::string& text);

}  // namespace fxport::xlate
