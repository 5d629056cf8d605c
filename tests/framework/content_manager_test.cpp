// fxport::ContentManager: asset name -> file mapping (content_manager.h), caching by name, Unload,
// and the errors that name the asset and every path tried. Files are written to a temp folder.
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

class ContentManagerTest : public ::testing::Test {
protected:
    static GraphicsDevice& device() {
        static GraphicsDevice d(PresentationParameters{});
        return d;
    }
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("fxport-content-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root / "Textures");
        fs::create_directories(root / "Effects");
    }
    void TearDown() override { fs::remove_all(root); }

    // A 2x1 PNG: red, then green.
    void writeTexture(const fs::path& path) {
        Texture2D texture(device(), 2, 1, false, SurfaceFormat::Color);
        const Color texels[2] = {Color::Red, Color::Lime};
        texture.SetData(texels, 2);
        texture.SaveAsPng(path.string());
    }

    fs::path root;
};

TEST_F(ContentManagerTest, LoadsATextureByNameWithoutExtensionAndCachesIt) {
    writeTexture(root / "Textures" / "Pair.png");
    ContentManager content(device(), root.string());
    Texture2D* texture = content.Load<Texture2D>("Textures/Pair");
    ASSERT_NE(texture, nullptr);
    EXPECT_EQ(texture->Width(), 2);
    EXPECT_EQ(texture->Height(), 1);
    Color texels[2];
    texture->GetData(texels, 2);
    EXPECT_TRUE(texels[0] == Color::Red);
    EXPECT_TRUE(texels[1] == Color::Lime);
    EXPECT_EQ(content.Load<Texture2D>("Textures/Pair"), texture);  // same object for the same name
    ASSERT_EQ(content.loadLog().size(), 1u);
    EXPECT_EQ(content.loadLog()[0].path, (root / "Textures" / "Pair.png").string());
    content.Unload();
    EXPECT_TRUE(content.loadLog().empty());
    Texture2D* again = content.Load<Texture2D>("Textures/Pair");
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(content.loadLog().size(), 1u);  // loaded from the file again
}

// A cube map from a .dds (1x1 A8R8G8B8 faces, each its own colour): every face as stored, cached by name.
TEST_F(ContentManagerTest, LoadsATextureCubeFromADds) {
    std::vector<unsigned char> dds(128, 0);
    auto put = [&](std::size_t at, std::uint32_t v) {
        for (int k = 0; k < 4; ++k) dds[at + std::size_t(k)] = static_cast<unsigned char>(v >> (8 * k));
    };
    dds[0] = 'D', dds[1] = 'D', dds[2] = 'S', dds[3] = ' ';
    put(4, 124), put(8, 0x1007), put(12, 1), put(16, 1), put(76, 32), put(80, 0x41), put(88, 32);
    put(92, 0xFF0000), put(96, 0xFF00), put(100, 0xFF), put(104, 0xFF000000u), put(108, 0x1008), put(112, 0xFE00);
    const Color faces[6] = {Color(10, 20, 30, 255), Color(40, 50, 60, 255), Color(70, 80, 90, 255),
                            Color(100, 110, 120, 255), Color(130, 140, 150, 255), Color(160, 170, 180, 128)};
    for (const Color& c : faces)
        for (unsigned char byte : {c.B, c.G, c.R, c.A}) dds.push_back(byte);
    std::ofstream(root / "Textures" / "Sky.dds", std::ios::binary).write(reinterpret_cast<const char*>(dds.data()), std::streamsize(dds.size()));
    ContentManager content(device(), root.string());
    TextureCube* cube = content.Load<TextureCube>("Textures/Sky");
    ASSERT_NE(cube, nullptr);
    EXPECT_EQ(cube->Size(), 1);
    for (int face = 0; face < 6; ++face) {
        Color texel;
        cube->GetData(CubeMapFace(face), &texel, 1);
        EXPECT_EQ(texel, faces[face]) << "face " << face;
    }
    EXPECT_EQ(content.Load<TextureCube>("Textures/Sky"), cube);
    EXPECT_EQ(content.loadLog().back().type, "TextureCube");
}

// XNA content comes from Windows: backslash folders and names in any case resolve to the one file
// that matches; several files matching ignoring case are an error listing them.
TEST_F(ContentManagerTest, WindowsAssetNamesResolveIgnoringCaseWhenUnique) {
    writeTexture(root / "Textures" / "Pair.png");
    ContentManager content(device(), root.string());
    Texture2D* texture = content.Load<Texture2D>("textures\\PAIR");
    ASSERT_NE(texture, nullptr);
    EXPECT_EQ(content.loadLog().back().path, (root / "Textures" / "Pair.png").string());
    EXPECT_EQ(content.Load<Texture2D>("Textures\\Pair"), content.Load<Texture2D>("Textures/Pair"));

    writeTexture(root / "Textures" / "Tree.png");
    writeTexture(root / "Textures" / "TREE.png");
    EXPECT_NE(content.Load<Texture2D>("Textures/Tree"), nullptr);  // the exact name wins
    try {
        content.Load<Texture2D>("Textures/tree");
        ADD_FAILURE() << "two files matched ignoring case";
    } catch (const ContentLoadException& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("several files match"), std::string::npos) << what;
        EXPECT_NE(what.find("Tree.png"), std::string::npos) << what;
        EXPECT_NE(what.find("TREE.png"), std::string::npos) << what;
    }
    // Still confined to the root: '..' in Windows spelling too.
    EXPECT_THROW(content.Load<Texture2D>("..\\outside"), ContentLoadException);
}

// XNA's Content folder lives beside the game's executable (TitleContainer), wherever the game is
// started from; a relative RootDirectory is still found from the working directory too.
TEST_F(ContentManagerTest, ARelativeRootIsFoundBesideTheExecutableThenInTheWorkingDirectory) {
    const fs::path executableFolder = fs::read_symlink("/proc/self/exe").parent_path();
    const std::string relative = "fxport-content-beside-" + std::to_string(::getpid());
    const fs::path beside = executableFolder / relative;
    fs::create_directories(beside / "Textures");
    writeTexture(beside / "Textures" / "Pair.png");
    const fs::path startedFrom = fs::current_path();
    fs::current_path(root);  // somewhere else: the working directory has no such folder
    {
        ContentManager content(device(), relative);
        EXPECT_NE(content.Load<Texture2D>("Textures/Pair"), nullptr);
        EXPECT_EQ(fs::path(content.loadLog().back().path), beside / "Textures" / "Pair.png");
    }
    fs::remove_all(beside);
    writeTexture(root / "Textures" / "Pair.png");  // now only from the working directory
    {
        ContentManager content(device(), ".");
        EXPECT_NE(content.Load<Texture2D>("Textures/Pair"), nullptr);
        EXPECT_EQ(fs::path(content.loadLog().back().path), fs::path(".") / "Textures" / "Pair.png");
    }
    fs::current_path(startedFrom);
}

TEST_F(ContentManagerTest, MissingAssetNamesTheAssetAndEveryPathTried) {
    ContentManager content(device(), root.string());
    auto expectMessage = [&](auto load, const std::string& type, const std::string& asset,
                             std::initializer_list<const char*> extensions) {
        try {
            load();
            ADD_FAILURE() << type << " " << asset << " loaded";
        } catch (const ContentLoadException& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("Load<" + type + ">(\"" + asset + "\")"), std::string::npos) << message;
            for (const char* extension : extensions)
                EXPECT_NE(message.find((root / (asset + extension)).string()), std::string::npos)
                    << extension << " missing from: " << message;
        }
    };
    expectMessage([&] { content.Load<Texture2D>("Textures/Nope"); }, "Texture2D", "Textures/Nope",
                  {".png", ".jpg", ".jpeg", ".bmp", ".tga", ".dds"});
    expectMessage([&] { content.Load<Model>("Nope"); }, "Model", "Nope", {".gltf", ".glb", ".fbx", ".x", ".obj", ".dae"});
    expectMessage([&] { content.Load<Effect>("Effects/Nope"); }, "Effect", "Effects/Nope", {".fx", ".fxeffect"});
    expectMessage([&] { content.Load<SpriteFont>("Nope"); }, "SpriteFont", "Nope",
                  {".spritefont", ".fnt", ".ttf", ".otf"});
}

TEST_F(ContentManagerTest, UnreadableFileNamesTheAssetAndTheFile) {
    std::ofstream(root / "Textures" / "Broken.png") << "not a png";
    ContentManager content(device(), root.string());
    try {
        content.Load<Texture2D>("Textures/Broken");
        ADD_FAILURE() << "a broken PNG loaded";
    } catch (const ContentLoadException& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("Load<Texture2D>(\"Textures/Broken\")"), std::string::npos) << message;
        EXPECT_NE(message.find("Broken.png"), std::string::npos) << message;
    }
}

TEST_F(ContentManagerTest, EffectsFromRootOrEffectDirectory) {
    const fs::path fixture = fs::path(FXPORT_RUNTIME_FIXTURES) / "Conventions.fx";
    fs::copy_file(fixture, root / "Effects" / "Conventions.fx");
    ContentManager content(device(), root.string());
    Effect* effect = content.Load<Effect>("Effects/Conventions");
    ASSERT_NE(effect, nullptr);
    EXPECT_EQ(effect->Name, "Conventions");
    EXPECT_GT(effect->Techniques.Count(), 0);
    // docs/API.md rule 2: indexers throw naming the key, find() is the C# null test.
    EXPECT_EQ(effect->Techniques.find("NoSuchTechnique"), nullptr);
    EXPECT_THROW(effect->Techniques["NoSuchTechnique"], ArgumentError);
    EffectTechnique* first = effect->Techniques[0];
    EXPECT_EQ(effect->Techniques.find(first->Name()), first);
    EXPECT_EQ(first->Passes.find("NoSuchPass"), nullptr);
    EXPECT_EQ(first->Passes.find(first->Passes[0].Name()), &first->Passes[0]);
    EXPECT_EQ(effect->Parameters.find("NoSuchParameter"), nullptr);
    EXPECT_EQ(content.findLoadedEffect("Effects/Conventions"), effect);
    EXPECT_EQ(content.findLoadedEffect("Effects/Other"), nullptr);

    // EffectDirectory: the .fx files where they are, found by the asset's last path component.
    ContentManager sources(device(), (root / "elsewhere").string());
    sources.EffectDirectory = fixture.parent_path().string();
    Effect* fromSources = sources.Load<Effect>("Effects/Conventions");
    ASSERT_NE(fromSources, nullptr);
    EXPECT_EQ(sources.loadLog()[0].path, fixture.string());
}

TEST_F(ContentManagerTest, LoadWithoutADeviceIsAnError) {
    writeTexture(root / "Textures" / "Pair.png");
    ContentManager content;
    content.RootDirectory = root.string();
    EXPECT_THROW(content.Load<Texture2D>("Textures/Pair"), InvalidOperation);
}

}  // namespace
}  // namespace fxport
