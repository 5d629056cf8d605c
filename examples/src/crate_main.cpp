// crate_game: the crate game's entry point. Runs CrateGame headless (OSMesa; FXPORT_PLATFORM=egl for
// a GPU, glfw for a window) for a number of frames, saves the last as OUT/frame.png, and with
// --check compares that PNG with a CPU ray-cast of the same scene (exit 1 when it differs).
//   crate_game [--frames N] [--size WxH] [--out DIR] [--check]
#include <filesystem>
#include <iostream>
#include <string>

#include "crate_check.h"
#include "crate_game.h"
#include "game_options.h"

int main(int argc, char** argv) {
    const example::GameOptions options = example::ParseGameOptions("crate_game", argc, argv, 160, 120);
    try {
        // "Content", as an XNA game writes it: found beside the executable (XNA's TitleContainer).
        example::CrateGame game(options.width, options.height, "Content");
        game.FrameLimit = options.frames;  // headless: Run returns after that many frames
        game.Run();
        std::filesystem::create_directories(options.out);
        const std::string path = (std::filesystem::path(options.out) / "frame.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(path);
        std::cout << "crate_game: " << options.frames << " frames, wrote " << path << "\n";
        if (!options.check) return 0;
        auto saved = fxport::Texture2D::FromFile(*game.GraphicsDevice, path);  // the PNG as a viewer reads it
        const example::CrateCheck check = example::checkCrateFrame(saved->GetData<fxport::Color>(), options.width, options.height);
        std::cout << "crate_game check: " << check.summary() << "\n";
        return check.passed() ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "crate_game: " << e.what() << "\n";
        return 1;
    }
}
