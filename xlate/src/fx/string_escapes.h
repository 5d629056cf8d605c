// Escape sequences in string literals (annotation and parameter strings: `string a = "A\nB\s";`),
// as fxc reads them (vkd3d's strings pins the forms fxc takes). glslang's preprocessor decodes
// the ones it knows into the characters themselves (a `\n` became a newline, which ended the
// literal for fxport's lexer) and stops at the others (`\s`, `\e`, `\u002a`: "Invalid escape
// sequence"). So each backslash in a string literal is hidden from glslang (protectStringEscapes,
// a control byte checkIsText never lets into a source), given back in its output
// (restoreStringEscapes), and the lexer decodes a string's value with fxc's rules
// (decodeStringEscapes).
#pragma once

#include <string>
#include <string_view>

namespace fxport::xlate {

// `text` with each backslash inside a string literal replaced by one byte, 0x01, and the quote of
// an escaped quote by 0x02 (same length, so every column stays). Comments, and lines of preprocessor directives (`#include "a\b.h"`), are
// left alone, as is a backslash ending a line (a line continuation).
std::string protectStringEscapes(const std::string& text);

// Each 0x01 byte becomes a backslash again, each 0x02 a quote.
void restoreStringEscapes(std::string& text);

// The value of a string literal's contents: \n \t \r \f \v \a \b \\ \" \' \?, octal (up to three
// digits, the low byte kept) and hex (\x and its digits, the low byte kept); any other escaped
// character stands for itself (fxc warns about those; fxport keeps the character).
std::string decodeStringEscapes(std::string_view raw);

}  // namespace fxport::xlate
