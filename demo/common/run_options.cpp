#include "common/run_options.h"

#include <cstdio>
#include <cstdlib>

namespace fxport::demo {

bool parseDefine(const std::string& text, std::pair<std::string, std::string>& out) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) return false;
    out = {text.substr(0, eq), text.substr(eq + 1)};
    return true;
}

OptionResult parseCommonOption(int argc, char** argv, int& i, CommonOptions& o, std::string& error) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    if (arg == "--size") {
        const char* v = value();
        if (!v || std::sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width <= 0 || o.height <= 0) {
            error = "--size wants WxH, e.g. 800x600";
            return OptionResult::Error;
        }
    } else if (arg == "--frames") {
        const char* v = value();
        if (!v || std::atoi(v) <= 0) {
            error = "--frames wants a positive number";
            return OptionResult::Error;
        }
        o.frames = std::atoi(v);
    } else if (arg == "--out") {
        const char* v = value();
        if (!v) {
            error = "--out wants a folder";
            return OptionResult::Error;
        }
        o.outDir = v;
        o.outDirGiven = true;
    } else if (arg == "--gpu") {
        o.platform = "egl";
    } else if (arg == "--window") {
        o.platform = "glfw";
    } else if (arg == "--check-finite") {
        o.checkFinite = true;
    } else if (arg == "--define") {
        const char* v = value();
        std::pair<std::string, std::string> define;
        if (!v || !parseDefine(v, define)) {
            error = std::string("--define wants NAME=VALUE, not '") + (v ? v : "") + "'";
            return OptionResult::Error;
        }
        o.defines.push_back(define);
    } else {
        return OptionResult::NotMine;
    }
    return OptionResult::Consumed;
}

}  // namespace fxport::demo
