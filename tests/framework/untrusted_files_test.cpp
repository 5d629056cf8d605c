// Untrusted files (issue 26 items 3, 12): every runtime loader reads through one checked reader
// (fxport/platform/file_reading.h): a FIFO or a device is refused at once with an error naming the
// path, sizes are capped before reading, a truncated font is refused before stb_truetype reads
// past it, and ContentManager loads nothing outside its RootDirectory. Each case runs in a child
// process (a gtest death-test fork, with an alarm and a memory limit) that must exit normally.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "fxport/framework.h"
#include "fxport/framework/sprite_font_import.h"
#include "fxport/graphics/model.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

class UntrustedFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("fxport-untrusted-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string fifo(const std::string& name) {
        std::string path = (dir / name).string();
        EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
        return path;
    }
    fs::path dir;
};

// In the child: a hang ends in SIGALRM and a runaway allocation fails, so either fails the test
// instead of the machine.
void limitChild() {
    ::alarm(20);
#if !defined(__SANITIZE_ADDRESS__)
    rlimit memory{rlim_t{4} << 30, rlim_t{4} << 30};
    ::setrlimit(RLIMIT_AS, &memory);
#endif
}

// Runs `load` in the child; prints what it threw and exits 0.
template <class F> void loadAndExit(F&& load) {
    limitChild();
    try {
        load();
        std::cerr << "loaded\n";
    } catch (const std::exception& e) {
        std::cerr << "refused: " << e.what() << "\n";
    }
    std::exit(0);
}

TEST_F(UntrustedFiles, EffectFromDevZeroIsRefusedAtOnce) {
    EXPECT_EXIT(loadAndExit([] {
                    GraphicsDevice device(PresentationParameters{});
                    Effect effect(device, "/dev/zero");
                }),
                ::testing::ExitedWithCode(0), "refused: .*/dev/zero.*not a regular file");
}

TEST_F(UntrustedFiles, EffectFromAFifoIsRefusedAtOnce) {
    std::string path = fifo("effect.fx");
    EXPECT_EXIT(loadAndExit([&] {
                    GraphicsDevice device(PresentationParameters{});
                    Effect effect(device, path);
                }),
                ::testing::ExitedWithCode(0), "refused: .*effect.fx.*not a regular file \\(a FIFO\\)");
}

TEST_F(UntrustedFiles, TextureFromAFifoIsRefusedAtOnce) {
    std::string path = fifo("image.png");
    EXPECT_EXIT(loadAndExit([&] {
                    GraphicsDevice device(PresentationParameters{});
                    Texture2D::FromFile(device, path);
                }),
                ::testing::ExitedWithCode(0), "refused: .*image.png.*a FIFO");
}

TEST_F(UntrustedFiles, GltfBufferNamingAFifoIsRefusedAtOnce) {
    fifo("data.bin");
    std::string gltf = (dir / "scene.gltf").string();
    std::ofstream(gltf) << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "data.bin", "byteLength": 12}],
        "bufferViews": [{"buffer": 0, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1, "type": "VEC3", "min": [0,0,0], "max": [0,0,0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
    EXPECT_EXIT(loadAndExit([&] {
                    GraphicsDevice device(PresentationParameters{});
                    Model::Load(device, gltf);
                }),
                ::testing::ExitedWithCode(0), "refused: .*scene.gltf.*data.bin.*a FIFO");
}

TEST_F(UntrustedFiles, TruncatedTrueTypeFontIsRefused) {
    const std::string dejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    ASSERT_TRUE(fs::exists(dejaVu)) << dejaVu << " (Debian's fonts-dejavu-core, which scripts/install-deps installs)";
    std::string truncated = (dir / "cut.ttf").string();
    fs::copy_file(dejaVu, truncated);
    fs::resize_file(truncated, 4096);  // the table directory, but not the tables it lists
    EXPECT_EXIT(loadAndExit([&] {
                    GraphicsDevice device(PresentationParameters{});
                    FontDescription description;
                    description.Size = 12;
                    BuildSpriteFont(device, truncated, description);
                }),
                ::testing::ExitedWithCode(0), "refused: .*cut.ttf.*not a TrueType");
}

TEST_F(UntrustedFiles, ContentManagerRefusesNamesOutsideItsRoot) {
    fs::create_directories(dir / "root");
    fs::create_directories(dir / "outside");
    {
        GraphicsDevice device(PresentationParameters{});
        Texture2D texture(device, 1, 1, false, SurfaceFormat::Color);
        texture.SaveAsPng((dir / "outside" / "secret.png").string());
        ContentManager content(device, (dir / "root").string());
        for (const std::string& name : {std::string("../outside/secret"), (dir / "outside" / "secret").string(), std::string("a/../../outside/secret")}) {
            try {
                content.Load<Texture2D>(name);
                ADD_FAILURE() << "loaded '" << name << "' from outside the root";
            } catch (const ContentLoadException& e) {
                EXPECT_NE(std::string(e.what()).find("leaves the RootDirectory"), std::string::npos) << e.what();
            }
        }
    }
}

}  // namespace
}  // namespace fxport
