// cube_game: the example game's entry point. Runs CubeGame headless (OSMesa; FXPORT_PLATFORM=egl for a
// GPU, glfw for a window) for a number of frames at XNA's fixed 1/60 s step, saves the frame as OUT/frame.png, and with
// --check compares that PNG with a CPU computation of the same scene (exit 1 when it differs).
//   cube_game [--frames N] [--size WxH] [--out DIR] [--check]
#include <filesystem>
#include <iostream>
#include <string>

#include "cube_game.h"
#include "frame_check.h"
#include "game_options.h"

int main(int argc, char** argv) {
    example::GameOptions options = example::ParseGameOptions("cube_game", argc, argv, 160, 120);
    try {
        example::CubeGame game(options.width, options.height, example::ContentRootBesideExecutable(argv[0]));
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
