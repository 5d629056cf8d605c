// cube_game: the example game's entry point. Runs CubeGame headless (OSMesa; FXPORT_PLATFORM=egl for a
// GPU, glfw for a window) for a number of frames at XNA's fixed 1/60 s step, saves the frame as OUT/frame.png, and with
// --check compares that PNG with a CPU computation of the same scene (exit 1 when it differs).
//   cube_game [--frames N] [--size WxH] [--out DIR] [--check]
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "cube_game.h"
#include "frame_check.h"

namespace {

struct Options {
    int frames = 3;
    int width = 160;
    int height = 120;
    std::string out = ".";
    bool check = false;
};

const char* kUsage = "usage: cube_game [--frames N] [--size WxH] [--out DIR] [--check]\n";

// One line naming the option and the value; exit status 2 (as the fxport CLI does).
[[noreturn]] void usageError(const std::string& option, const std::string& problem) {
    std::cerr << "cube_game: option '" << option << "' " << problem << "\n";
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usageError(a, "needs a value");
            return argv[++i];
        };
        if (a == "--help" || a == "-h") {
            std::cout << kUsage;
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
            usageError(a, "is unknown (see 'cube_game --help')");
        }
    }
    return o;
}

// Content sits beside the executable, as XNA's Content folder does.
std::string contentRoot(const char* argv0) {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) exe = std::filesystem::absolute(argv0);
    return (exe.parent_path() / "Content").string();
}

}  // namespace

int main(int argc, char** argv) {
    Options options = parse(argc, argv);
    try {
        example::CubeGame game(options.width, options.height, contentRoot(argv[0]));
        game.FrameLimit = options.frames;  // headless: Run returns after that many frames
        game.Run();
        std::filesystem::create_directories(options.out);
        std::string path = (std::filesystem::path(options.out) / "frame.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(path);
        std::cout << "cube_game: " << options.frames << " frames, wrote " << path << "\n";
        if (options.check) {
            // The PNG as a viewer reads it, not the back buffer: the file is what is checked.
            auto saved = fxport::Texture2D::FromFile(*game.GraphicsDevice, path);
            example::FrameCheck check = example::checkFrame(saved->GetData<fxport::Color>(), options.width, options.height, game.SceneSeconds());
            std::cout << "cube_game check: " << check.summary() << "\n";
            return check.passed() ? 0 : 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "cube_game: " << e.what() << "\n";
        return 1;
    }
}
