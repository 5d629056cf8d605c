// fxdemo: runs one of the programs that registered themselves (common/program_registry.h): the four
// ported tutorials (demo/) and the quality tools (quality/).
//
//   fxdemo --help                     lists the programs
//   fxdemo <program> --help           the program's options (exit 0)
//   fxdemo <program> [options]        runs it
//
// Usage errors are one line, "fxdemo <program>: <option> wants <what>, not '<value>'", exit 2
// (common/run_options.h); a run that fails exits 1 with the error's message.
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "common/program_registry.h"
#include "common/run_options.h"

namespace {

const char* kCommonOptions =
    "Options the programs share (each usage line says which it takes):\n"
    "  --size WxH        the back buffer / target size, W and H from 1 to the driver's GL_MAX_TEXTURE_SIZE\n"
    "  --frames N        frames to run headless          --out DIR   where the images go\n"
    "  --gpu             headless on the GPU (EGL)       --window    a GLFW window instead of headless OSMesa\n"
    "  --check-finite    (the four demos) after each pass, stop at the first NaN/Inf in a target\n"
    "  --bounds          (the four demos) each pass's bound and ms / bound in the timing table: the bytes\n"
    "                    and fragments it wrote at this GPU's fill rates, its texture fetches at the fetch\n"
    "                    rate (GpuLimits, measured once and cached), the larger of the two\n"
    "  --define N=V      (the four demos, repeatable) a #define every effect is compiled with,\n"
    "                    e.g. --define 'pow(x, y)=pow(max(x, 1e-30), y)' (see fxdemo stability)\n";

void listPrograms(std::FILE* out) {
    std::fprintf(out, "usage: fxdemo <program> [options]   (fxdemo <program> --help: its options)\nprograms:\n");
    for (const auto& [name, program] : fxdemo::programs()) {
        // The first line after the synopsis (and its "[--option]" continuation lines) says what it is.
        std::string summary;
        std::size_t at = program.usage.find('\n');
        while (at != std::string::npos && summary.empty()) {
            const std::size_t end = program.usage.find('\n', at + 1);
            const std::string line = program.usage.substr(at + 1, end == std::string::npos ? end : end - at - 1);
            const std::size_t text = line.find_first_not_of(' ');
            if (text != std::string::npos && line[text] != '[') summary = line.substr(text);
            at = end;
        }
        std::fprintf(out, "  %-12s %s\n", name.c_str(), summary.c_str());
    }
}

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h" || arg == "help"; }

// The value given to --size, if any (to name it when the run runs out of memory).
std::string sizeArgument(int argc, char** argv) {
    std::string size;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--size") size = argv[i + 1];
    return size;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        listPrograms(stderr);
        return 2;
    }
    const std::string name = argv[1];
    if (isHelp(name)) {
        listPrograms(stdout);
        std::printf("\n%s", kCommonOptions);
        return 0;
    }
    const auto found = fxdemo::programs().find(name);
    if (found == fxdemo::programs().end()) {
        std::string known;
        for (const auto& [registered, program] : fxdemo::programs()) known += (known.empty() ? "" : ", ") + registered;
        std::fprintf(stderr, "fxdemo: unknown program '%s' (fxdemo --help lists them: %s)\n", name.c_str(), known.c_str());
        return 2;
    }
    for (int i = 2; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            std::printf("usage: %s\n\n%s", found->second.usage.c_str(), kCommonOptions);
            return 0;
        }
    try {
        return found->second.main(argc - 1, argv + 1);
    } catch (const std::bad_alloc&) {
        // A size the driver accepts can still be more than this machine's memory.
        const std::string size = sizeArgument(argc - 1, argv + 1);
        if (!size.empty())
            return fxport::demo::usageError(name, fxport::demo::wants("--size", "a size that fits in memory (out of memory)", size.c_str()));
        std::fprintf(stderr, "fxdemo %s: out of memory\n", name.c_str());
        return 1;
    } catch (const std::exception& e) {  // e.g. --check-finite's NonFiniteError, an effect's compile error
        std::fprintf(stderr, "fxdemo %s: %s\n", name.c_str(), e.what());
        return 1;
    }
}
