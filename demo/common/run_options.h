// The options every fxdemo program shares: --size WxH, --frames N, --out DIR, --gpu, --window,
// --check-finite (scan every pass's targets for NaN/Inf: common/finite_check.h), --define NAME=VALUE
// (a #define every effect of the program is compiled with; repeatable), --fill-rate GB/s (the timing
// table's bound per pass: common/pass_bound.h).
// A program's argument loop hands each argument to parseCommonOption first and handles its own
// options only when it answers NotMine; after the loop, checkCommonOptions asks the driver what only
// it knows. Every usage error is one line in one wording (usageError), exit status 2; --help is
// answered by the dispatcher (fxdemo_main.cpp) from the program's registered usage.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fxport::demo {

struct CommonOptions {
    int width = 800;
    int height = 600;
    std::optional<int> frames;       // unset: the program's default
    std::string outDir;              // the program's default until --out
    bool outDirGiven = false;
    std::string platform = "osmesa"; // --gpu: egl, --window: glfw
    bool checkFinite = false;        // --check-finite
    double fillRateGBps = 0;         // --fill-rate GB/s: the timing table's bound column (PassBound)
    bool bounds = false;             // --bounds: GpuLimits' rates, counted fragments and fetches (PassBound)
    // --define NAME=VALUE: passed to every effect (EffectOptions::defines), e.g. the stability
    // suite's opt-in fixes: --define 'pow(x, y)=pow(max(x, 1e-30), y)'. Split at the first '='.
    std::vector<std::pair<std::string, std::string>> defines;
};

// Parses --define's NAME=VALUE; false when there is no '=' or no name.
bool parseDefine(const std::string& text, std::pair<std::string, std::string>& out);

enum class OptionResult { Consumed, NotMine, Error };

// Looks at argv[i]; consumes its value too (advancing i). On Error, `error` says what was wrong
// (wants()'s wording).
OptionResult parseCommonOption(int argc, char** argv, int& i, CommonOptions& options, std::string& error);

// What the driver decides: a --size above GL_MAX_TEXTURE_SIZE (every GL 4.1 driver, which the
// runtime requires, takes 16384; a larger size is asked of the driver the run will use). False with
// `error` set when the size cannot be made.
bool checkCommonOptions(const CommonOptions& options, std::string& error);

// The one wording of a bad value: "<option> wants <what>, not '<value>'" (value null: no value given).
std::string wants(const std::string& option, const std::string& what, const char* value);
// An argument no option of the program matches.
std::string unknownOption(const std::string& program, const std::string& arg);
// Prints "fxdemo <program>: <message>" as one line on stderr; returns 2 (a usage error).
int usageError(const std::string& program, const std::string& message);

}  // namespace fxport::demo
