// fence_game: the fence game's entry point. Runs FenceGame headless (OSMesa; FXPORT_PLATFORM=egl for a
// GPU, glfw for a window) for a number of frames, saves the last as OUT/frame.png, and with --check
// compares that PNG with a CPU computation of the same scene (exit 1 when it differs).
//   fence_game [--frames N] [--size WxH] [--out DIR] [--check]
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "fence_check.h"
#include "fence_game.h"
#include "game_options.h"

int main(int argc, char** argv) {
    const example::GameOptions options = example::ParseGameOptions("fence_game", argc, argv, 320, 240);
    try {
        const std::string contentRoot = example::ContentRootBesideExecutable(argv[0]);
        example::FenceGame game(options.width, options.height, contentRoot);
        game.FrameLimit = options.frames;  // headless: Run returns after that many frames
        game.Run();
        std::filesystem::create_directories(options.out);
        const std::string path = (std::filesystem::path(options.out) / "frame.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(path);
        std::cout << "fence_game: " << options.frames << " frames, wrote " << path << "\n";
        if (!options.check) return 0;

        // The PNG as a viewer reads it (not the back buffer), and the fence texture as the game
        // loaded it.
        fxport::GraphicsDevice& device = *game.GraphicsDevice;
        const std::vector<fxport::Color> pixels = fxport::Texture2D::FromFile(device, path)->GetData<fxport::Color>();
        auto fence = fxport::Texture2D::FromFile(device, contentRoot + "/Fence.png");
        // XNA's content pipeline, written out here: magenta keyed to transparent black, then each
        // colour premultiplied by alpha, rounded (what Content.Load gave the game).
        std::vector<fxport::Color> fenceTexels = fence->GetData<fxport::Color>();
        for (fxport::Color& c : fenceTexels) {
            if (c == fxport::Color(255, 0, 255, 255)) c = fxport::Color(0, 0, 0, 0);
            auto premultiplied = [&](int v) { return int(std::lround(v * c.A / 255.0)); };
            c = fxport::Color(premultiplied(c.R), premultiplied(c.G), premultiplied(c.B), c.A);
        }
        example::FenceFrame frame;
        frame.pixels = &pixels;
        frame.width = options.width;
        frame.height = options.height;
        frame.totalSeconds = game.SceneSeconds();
        frame.fenceTexels = &fenceTexels;
        frame.fenceWidth = fence->Width();
        frame.fenceHeight = fence->Height();
        const std::string& text = game.HudText();
        frame.textPosition = example::FenceScene::HudPosition();
        frame.textSize = game.HudFont().MeasureString(text);
        for (std::size_t i = 0; i < text.size(); ++i) {
            const float before = i == 0 ? 0.0f : game.HudFont().MeasureString(text.substr(0, i)).X;
            const float after = game.HudFont().MeasureString(text.substr(0, i + 1)).X;
            frame.characterAdvances.emplace_back(before, text[i] == ' ' ? before : after);
        }
        const example::FenceFrameCheck check = example::checkFenceFrame(frame);
        std::cout << "fence_game check (\"" << text << "\" measured " << frame.textSize.X << " x " << frame.textSize.Y
                  << "): " << check.summary() << "\n";
        return check.passed() ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "fence_game: " << e.what() << "\n";
        return 1;
    }
}
