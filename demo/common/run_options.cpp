#include "common/run_options.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "fxport/graphics.h"

namespace fxport::demo {

namespace {

// Every GL 4.1+ driver (the runtime's minimum) has GL_MAX_TEXTURE_SIZE >= 16384.
constexpr long kGuaranteedTextureSize = 16384;
// Beyond this a size is not worth asking a driver about (and W * H * 4 would overflow int).
constexpr long kLargestSize = 1 << 20;

// A whole decimal number in [lo, hi]; false for anything else ("12x", "", "1e3", out of range).
bool parseInteger(const std::string& text, long lo, long hi, long& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(text.c_str(), &end, 10);
    return errno == 0 && *end == '\0' && out >= lo && out <= hi;
}

}  // namespace

std::string wants(const std::string& option, const std::string& what, const char* value) {
    return option + " wants " + what + (value ? ", not '" + std::string(value) + "'" : ", not '' (no value given)");
}

std::string unknownOption(const std::string& program, const std::string& arg) {
    return "unknown option '" + arg + "' (fxdemo " + program + " --help lists the options)";
}

int usageError(const std::string& program, const std::string& message) {
    std::fprintf(stderr, "fxdemo %s: %s\n", program.c_str(), message.c_str());
    return 2;
}

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
        const std::string text = v ? v : "";
        const std::size_t x = text.find('x');
        long w = 0, h = 0;
        if (x == std::string::npos || !parseInteger(text.substr(0, x), 1, kLargestSize, w) ||
            !parseInteger(text.substr(x + 1), 1, kLargestSize, h)) {
            error = wants("--size", "WxH with W and H from 1 to the driver's GL_MAX_TEXTURE_SIZE, e.g. 800x600", v);
            return OptionResult::Error;
        }
        o.width = int(w);
        o.height = int(h);
    } else if (arg == "--frames") {
        const char* v = value();
        long n = 0;
        if (!v || !parseInteger(v, 1, 1000000000, n)) {
            error = wants("--frames", "a positive number", v);
            return OptionResult::Error;
        }
        o.frames = int(n);
    } else if (arg == "--out") {
        const char* v = value();
        if (!v || !*v) {
            error = wants("--out", "a folder", v);
            return OptionResult::Error;
        }
        o.outDir = v;
        o.outDirGiven = true;
    } else if (arg == "--gpu") {
        o.platform = "egl";
    } else if (arg == "--window") {
        o.platform = "glfw";
    } else if (arg == "--bounds") {
        o.bounds = true;
    } else if (arg == "--check-finite") {
        o.checkFinite = true;
    } else if (arg == "--fill-rate") {
        const char* v = value();
        char* end = nullptr;
        const double rate = v ? std::strtod(v, &end) : 0;
        if (!v || *end || !(rate > 0 && rate < 1e6)) {
            error = wants("--fill-rate", "GB/s of fragment output, a number above 0", v);
            return OptionResult::Error;
        }
        o.fillRateGBps = rate;
    } else if (arg == "--define") {
        const char* v = value();
        std::pair<std::string, std::string> define;
        if (!v || !parseDefine(v, define)) {
            error = wants("--define", "NAME=VALUE", v);
            return OptionResult::Error;
        }
        o.defines.push_back(define);
    } else {
        return OptionResult::NotMine;
    }
    return OptionResult::Consumed;
}

bool checkCommonOptions(const CommonOptions& o, std::string& error) {
    if (o.width <= kGuaranteedTextureSize && o.height <= kGuaranteedTextureSize) return true;
    const std::string size = std::to_string(o.width) + "x" + std::to_string(o.height);
    int limit = 0;
    try {
        // A 1x1 device of the platform the run will use (a window's: its headless OSMesa stands in).
        PresentationParameters probe;
        probe.BackBufferWidth = probe.BackBufferHeight = 1;
        probe.platform = o.platform == "glfw" ? "osmesa" : o.platform;
        limit = GraphicsDevice(probe).maxTextureSize();
    } catch (const std::exception& e) {
        error = wants("--size", "a size the driver can make (no driver to ask: " + std::string(e.what()) + ")", size.c_str());
        return false;
    }
    if (o.width > limit || o.height > limit) {
        error = wants("--size", "W and H from 1 to " + std::to_string(limit) + " (the driver's GL_MAX_TEXTURE_SIZE)", size.c_str());
        return false;
    }
    return true;
}

}  // namespace fxport::demo
