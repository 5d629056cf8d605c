// Small string helpers shared by the compiler's passes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fxport::xlate {

std::string toLower(std::string_view s);
std::string toUpper(std::string_view s);
bool iequals(std::string_view a, std::string_view b);
std::string_view trim(std::string_view s);
bool startsWithI(std::string_view s, std::string_view prefix);
// `s` unchanged if it is valid UTF-8; otherwise every byte that is not part of a valid UTF-8
// sequence is read as Latin-1 (so a GBK or Shift-JIS annotation string becomes readable-ish text
// instead of invalid output).
std::string toValidUtf8(std::string_view s);
// Reads a whole file; nullopt if it cannot be opened.
std::optional<std::string> readFile(const std::string& path);
// The same, refusing (nullopt) a file of more than `maxBytes`, checked before reading it whole.
std::optional<std::string> readFile(const std::string& path, size_t maxBytes);
// 64-bit FNV-1a, as hex: stable across runs and machines (cache keys).
std::string hashHex(std::string_view data);
// 128 bits as 32 hex digits (two independent 64-bit hashes): names cache entries and fingerprints
// file contents, where a collision would silently return another effect.
std::string contentHash(std::string_view data);

}  // namespace fxport::xlate
