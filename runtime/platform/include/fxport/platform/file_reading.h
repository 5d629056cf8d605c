// Reading a file a game or a content file names (an effect, a texture, a font, a glTF buffer):
// regular files only, opened without blocking (a FIFO or a device such as /dev/zero would block
// forever or never end), and no more than a size cap, checked before anything is read. Every
// runtime loader reads through here, so each refuses such a path at once with an error naming it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace fxport::platform {

// Far above any asset fxport loads (a 16384x16384 RGBA PNG is at most 1 GiB raw, far less packed).
inline constexpr std::size_t kMaxAssetFileBytes = std::size_t{512} << 20;

struct FileBytes {
    std::vector<unsigned char> bytes;
    std::string error;  // empty on success; else why, naming the path
    bool tooLarge = false;
    bool ok() const { return error.empty(); }
};

FileBytes readUntrustedFile(const std::string& path, std::size_t maxBytes = kMaxAssetFileBytes);

}  // namespace fxport::platform
