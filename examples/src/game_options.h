// The command line both example games take, and where their content is. Headless (OSMesa) runs draw
// a few frames at XNA's fixed 1/60 s step and save the last as OUT/frame.png; --check compares that
// PNG with a CPU computation of the same scene (the program then exits 1 when it differs).
//   <game> [--frames N] [--size WxH] [--out DIR] [--check]
#pragma once

#include <string>

namespace example {

struct GameOptions {
    int frames = 3;
    int width = 0;
    int height = 0;
    std::string out = ".";
    bool check = false;
};

// Parses argv; --help prints the usage and exits 0; a bad option prints one line naming it and its
// value and exits 2 (as the fxport CLI does).
GameOptions ParseGameOptions(const char* program, int argc, char** argv, int defaultWidth, int defaultHeight);

// The Content folder beside the executable, as XNA's is (XNA's Content.RootDirectory).
std::string ContentRootBesideExecutable(const char* argv0);

}  // namespace example
