// ParseGameOptions and ContentRootBesideExecutable: see game_options.h.
#include "game_options.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace example {

GameOptions ParseGameOptions(const char* program, int argc, char** argv, int defaultWidth, int defaultHeight) {
    GameOptions o;
    o.width = defaultWidth;
    o.height = defaultHeight;
    const std::string name = program;
    auto usageError = [&](const std::string& option, const std::string& problem) {
        std::cerr << name << ": option '" << option << "' " << problem << "\n";
        std::exit(2);
    };
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usageError(a, "needs a value");
            return argv[++i];
        };
        if (a == "--help" || a == "-h") {
            std::cout << "usage: " << name << " [--frames N] [--size WxH] [--out DIR] [--check]\n";
            std::exit(0);
        } else if (a == "--frames") {
            std::string v = value();
            if (std::sscanf(v.c_str(), "%d", &o.frames) != 1 || o.frames < 1 || o.frames > 100000)
                usageError(a, "has a bad value '" + v + "' (want 1..100000)");
        } else if (a == "--size") {
            std::string v = value();
            char x = 0;
            if (std::sscanf(v.c_str(), "%d%c%d", &o.width, &x, &o.height) != 3 || x != 'x' || o.width < 1 || o.height < 1 ||
                o.width > 4096 || o.height > 4096)
                usageError(a, "has a bad value '" + v + "' (want WxH, 1..4096 each)");
        } else if (a == "--out") {
            o.out = value();
        } else if (a == "--check") {
            o.check = true;
        } else {
            usageError(a, "is unknown (see '" + name + " --help')");
        }
    }
    return o;
}

std::string ContentRootBesideExecutable(const char* argv0) {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) exe = std::filesystem::absolute(argv0);
    return (exe.parent_path() / "Content").string();
}

}  // namespace example
