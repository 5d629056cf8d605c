// Source text encodings fxc reads: UTF-8 with or without a byte-order mark, and UTF-16 LE/BE with
// one (Visual Studio saves effects both ways). Everything after this point sees UTF-8 without BOM.
#pragma once

#include <string>
#include <string_view>

namespace fxport::xlate {

// The text as UTF-8: a UTF-8 BOM is dropped, UTF-16 with a BOM is converted (an unpaired
// surrogate or a lone last byte becomes U+FFFD). Anything else is returned unchanged; checkIsText
// judges it later. Dropping the BOM keeps line and column numbers those of the file as shown.
// Trailing Ctrl-Z bytes (DOS end of file) are dropped and a lone CR (classic Mac) ends a line; a
// Shift-JIS character ending a `//` comment in 0x5C continues no line.
std::string sourceTextAsUtf8(std::string_view raw);

}  // namespace fxport::xlate
