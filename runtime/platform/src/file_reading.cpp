// See file_reading.h. The type and size come from fstat of the descriptor that is read, so a path
// swapped between a check and the read cannot slip a FIFO or a bigger file past them.
#include "fxport/platform/file_reading.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fxport::platform {

FileBytes readUntrustedFile(const std::string& path, std::size_t maxBytes) {
    FileBytes out;
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        out.error = "cannot open '" + path + "' (" + std::strerror(errno) + ")";
        return out;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        out.error = "'" + path + "' is not a regular file" +
                    (S_ISDIR(st.st_mode) ? " (a folder)" : S_ISFIFO(st.st_mode) ? " (a FIFO)" : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? " (a device)" : "");
        ::close(fd);
        return out;
    }
    if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
        out.error = "'" + path + "' has " + std::to_string(st.st_size) + " bytes, more than the " + std::to_string(maxBytes >> 20) +
                    " MiB fxport reads";
        out.tooLarge = true;
        ::close(fd);
        return out;
    }
    out.bytes.resize(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    while (done < out.bytes.size()) {
        ssize_t n = ::read(fd, out.bytes.data() + done, out.bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            out.error = "cannot read '" + path + "' (" + std::strerror(errno) + ")";
            break;
        }
        if (n == 0) break;  // shrank while read: what is there
        done += static_cast<std::size_t>(n);
    }
    out.bytes.resize(done);
    ::close(fd);
    return out;
}

}  // namespace fxport::platform
