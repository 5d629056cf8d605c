// Writing the command line's outputs (-o, --depfile) without turning them against the user: a
// regular file is replaced whole or not at all (temporary file, renamed over it once complete); a
// device or a FIFO with a reader (/dev/null, /dev/stdout, a shell's >(...)) is written through,
// never replaced by a regular file; a folder, a FIFO without a reader and a read-only file are
// refused. Every write is checked through close, and each failure names the OS's reason.
#pragma once

#include <string>
#include <vector>

namespace fxport::cli {

// Writes `text` to `path`; false with `error` ("cannot write 'PATH' (reason)") when it cannot.
bool writeOutputFile(const std::string& path, const std::string& text, std::string& error);

// A file the command reads or writes, by the option that names it (for distinctness checks).
struct NamedFile {
    std::string option;  // "-o", "--depfile", "the input", "the included file"
    std::string path;
};

// An output that is the same file as another output or as an input (by identity when both
// exist, else by their absolute, normalised paths), as "-o 'A' is also the input 'B' ..."; empty
// when all are distinct.
std::string findSameFile(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

}  // namespace fxport::cli
