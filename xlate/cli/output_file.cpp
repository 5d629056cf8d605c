// See output_file.h. POSIX calls rather than iostreams: ofstream reports neither errno nor a
// failure of close (a full disk or an NFS quota is often only reported there).
#include "output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;

namespace fxport::cli {

namespace {

std::string failure(const std::string& path, const std::string& reason) { return "cannot write '" + path + "' (" + reason + ")"; }

// Writes all of `text` to `fd` and closes it; the OS's reason on failure.
bool writeAndClose(int fd, const std::string& text, std::string& reason) {
    const char* data = text.data();
    size_t left = text.size();
    while (left > 0) {
        ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            reason = n < 0 ? std::strerror(errno) : "the device took nothing";
            ::close(fd);
            return false;
        }
        data += n;
        left -= static_cast<size_t>(n);
    }
    if (::close(fd) != 0) {
        reason = std::strerror(errno);
        return false;
    }
    return true;
}

// A device or FIFO: written in place. O_NONBLOCK so a FIFO nobody reads is refused (ENXIO) instead
// of blocking forever; the writes themselves block as usual.
bool writeThrough(const std::string& path, const std::string& text, std::string& error) {
    int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        error = failure(path, errno == ENXIO ? "a FIFO that nothing reads" : std::strerror(errno));
        return false;
    }
    int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    std::string reason;
    if (!writeAndClose(fd, text, reason)) {
        error = failure(path, reason);
        return false;
    }
    return true;
}

// A regular file (or none yet): a temporary file beside it, renamed over it once complete, so a
// compile killed mid-write leaves the previous output, never half a file.
bool replaceWhole(const std::string& path, const std::string& text, std::string& error) {
    std::string tmp = path + ".tmp" + std::to_string(::getpid());
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        error = failure(path, std::strerror(errno));
        return false;
    }
    std::string reason;
    if (!writeAndClose(fd, text, reason)) {
        ::unlink(tmp.c_str());
        error = failure(path, reason);
        return false;
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        error = failure(path, std::strerror(errno));
        ::unlink(tmp.c_str());
        return false;
    }
    return true;
}

}  // namespace

bool writeOutputFile(const std::string& path, const std::string& text, std::string& error) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return replaceWhole(path, text, error);
        error = failure(path, std::strerror(errno));
        return false;
    }
    if (S_ISDIR(st.st_mode)) {
        error = failure(path, "it is a folder; name a file");
        return false;
    }
    if (!S_ISREG(st.st_mode)) return writeThrough(path, text, error);
    // By the mode bits, not access(): root may write anything, but a file its owner made
    // read-only is not meant to be replaced by a build.
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(path.c_str(), W_OK) != 0) {
        error = failure(path, "it is read-only");
        return false;
    }
    return replaceWhole(path, text, error);
}

std::string findSameFile(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
    auto normal = [](const std::string& p) {
        std::error_code ec;
        return fs::weakly_canonical(fs::absolute(p, ec), ec).lexically_normal();
    };
    auto same = [&](const NamedFile& a, const NamedFile& b) {
        std::error_code ec;
        if (!fs::exists(a.path, ec) || !fs::exists(b.path, ec)) return normal(a.path) == normal(b.path);
        // Two outputs on /dev/null (or any device) harm nothing.
        if (!fs::is_regular_file(a.path, ec) && !fs::is_regular_file(b.path, ec) && !fs::is_directory(a.path, ec)) return false;
        return fs::equivalent(a.path, b.path, ec) && !ec;
    };
    for (size_t i = 0; i < outputs.size(); ++i) {
        const NamedFile& out = outputs[i];
        for (size_t j = i + 1; j < outputs.size(); ++j)
            if (same(out, outputs[j])) return out.option + " '" + out.path + "' is also " + outputs[j].option + " '" + outputs[j].path + "'";
        for (const NamedFile& in : inputs)
            if (same(out, in)) return out.option + " '" + out.path + "' is also " + in.option + " '" + in.path + "', which it would overwrite";
    }
    return {};
}

}  // namespace fxport::cli
