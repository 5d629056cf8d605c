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
// Reads a whole file; nullopt if it cannot be opened.
std::optional<std::string> readFile(const std::string& path);
// 64-bit FNV-1a, as hex: stable across runs and machines (cache keys).
std::string hashHex(std::string_view data);

}  // namespace fxport::xlate
