// The fuzzers' input format: one effect and the headers it may #include, in one byte string.
//   <main.fx text>
//   //--- name.fxh
//   <that header's text>
//   ...
// Headers are written into a private folder beside main.fx (tmpfs when there is one), so the real
// include resolver runs, cycles included. Names are cut to [A-Za-z0-9_.] and 24 characters.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace fxport::fuzz {

struct FuzzFile {
    std::string name;
    std::string text;
};

inline std::vector<FuzzFile> splitInput(std::string_view input) {
    static constexpr std::string_view kMarker = "\n//--- ";
    std::vector<FuzzFile> files;
    size_t at = input.find(kMarker);
    files.push_back({"main.fx", std::string(input.substr(0, at))});
    while (at != std::string_view::npos && files.size() < 16) {
        size_t nameStart = at + kMarker.size();
        size_t nameEnd = input.find('\n', nameStart);
        if (nameEnd == std::string_view::npos) break;
        std::string name;
        for (char c : input.substr(nameStart, nameEnd - nameStart))
            if ((std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.') && name.size() < 24) name += c;
        at = input.find(kMarker, nameEnd);
        std::string text(input.substr(nameEnd + 1, at == std::string_view::npos ? std::string_view::npos : at - nameEnd - 1));
        if (name.empty() || name == "." || name == ".." || name == "main.fx") continue;
        files.push_back({name, std::move(text)});
    }
    return files;
}

// A folder of this process's own, emptied and refilled for every input.
inline std::filesystem::path writeFiles(const std::vector<FuzzFile>& files) {
    namespace fs = std::filesystem;
    static const fs::path dir = [] {
        std::error_code ec;
        fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
        fs::path d = base / ("fxport-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(d, ec);
        return d;
    }();
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove(entry.path(), ec);
    for (const auto& f : files) std::ofstream(dir / f.name, std::ios::binary).write(f.text.data(), static_cast<std::streamsize>(f.text.size()));
    return dir;
}

}  // namespace fxport::fuzz
