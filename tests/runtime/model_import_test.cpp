// Model::Load of the formats XNA games ship besides glTF (.obj, .x; through Assimp), on small files
// written here with known contents: the node hierarchy as bones, vertex positions and texture
// coordinates (v down, as D3D addresses textures), XNA's clockwise winding, the material as a
// BasicEffect, a texture named with Windows separators and another case, and bad files refused
// with the file's name.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fxport/graphics.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

class ModelImport : public ::testing::Test {
protected:
    static GraphicsDevice& device() {
        static GraphicsDevice d(PresentationParameters{});
        return d;
    }
    void SetUp() override {
        dir = fs::temp_directory_path() / ("fxport-model-import-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "tex");
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
        return dir / name;
    }
    fs::path dir;
};

std::vector<ModelVertex> verticesOf(const ModelMeshPart& part) {
    std::vector<ModelVertex> all(std::size_t(part.VertexBuffer->VertexCount()));
    part.VertexBuffer->GetData(all.data(), all.size());
    return {all.begin() + part.VertexOffset, all.begin() + part.VertexOffset + part.NumVertices};
}

std::vector<std::uint32_t> indicesOf(const ModelMeshPart& part) {
    std::vector<std::uint32_t> out;
    if (part.IndexBuffer->IndexElementSize() == IndexElementSize::SixteenBits) {
        std::vector<std::uint16_t> all(std::size_t(part.IndexBuffer->IndexCount()));
        part.IndexBuffer->GetData(all.data(), all.size());
        out.assign(all.begin() + part.StartIndex, all.begin() + part.StartIndex + 3 * part.PrimitiveCount);
    } else {
        std::vector<std::uint32_t> all(std::size_t(part.IndexBuffer->IndexCount()));
        part.IndexBuffer->GetData(all.data(), all.size());
        out.assign(all.begin() + part.StartIndex, all.begin() + part.StartIndex + 3 * part.PrimitiveCount);
    }
    return out;
}

// Seen from +z (the normal's side), an XNA front face is clockwise: (b - a) x (c - a) points to -z.
void expectClockwiseFromPlusZ(const std::vector<ModelVertex>& v, const std::vector<std::uint32_t>& indices) {
    ASSERT_EQ(indices.size() % 3, 0u);
    for (std::size_t i = 0; i < indices.size(); i += 3) {
        const Vector3 a = v[indices[i]].Position, b = v[indices[i + 1]].Position, c = v[indices[i + 2]].Position;
        EXPECT_LT(Vector3::Cross(b - a, c - a).Z, 0) << "triangle " << i / 3;
    }
}

const char* kQuadObj = R"(mtllib quad.mtl
o Quad
v 0 0 0
v 2 0 0
v 2 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl Painted
f 1/1/1 2/2/1 3/3/1
f 1/1/1 3/3/1 4/4/1
)";

TEST_F(ModelImport, ObjQuadKeepsPositionsFlipsVAndWindsClockwise) {
    // The texture named as a Windows tool writes it: backslash, another case.
    Texture2D texture(device(), 2, 1, false, SurfaceFormat::Color);
    const Color texels[2] = {Color(200, 10, 10, 255), Color(10, 200, 10, 255)};
    texture.SetData(texels, 2);
    texture.SaveAsPng((dir / "tex" / "checker.png").string());
    write("quad.mtl", "newmtl Painted\nKd 0.5 0.25 1\nKe 0.1 0 0\nd 0.75\nmap_Kd tex\\Checker.PNG\n");
    const auto model = Model::Load(device(), write("quad.obj", kQuadObj).string());

    ASSERT_EQ(model->Meshes.Count(), 1);
    const ModelMesh& mesh = model->Meshes[0];
    EXPECT_EQ(mesh.Name, "Quad");
    ASSERT_NE(mesh.ParentBone, nullptr);
    EXPECT_EQ(mesh.ParentBone->Parent, model->Root);  // the file's root node, then the object's
    ASSERT_EQ(mesh.MeshParts.size(), 1u);
    const ModelMeshPart& part = mesh.MeshParts[0];
    const std::vector<ModelVertex> v = verticesOf(part);
    ASSERT_EQ(v.size(), 4u);  // shared corners joined
    EXPECT_EQ(part.PrimitiveCount, 2);
    // Each corner keeps its position; OBJ's v (up from the bottom) becomes D3D's (down from the top).
    const struct { Vector3 position; Vector2 uv; } corners[4] = {
        {Vector3(0, 0, 0), Vector2(0, 1)}, {Vector3(2, 0, 0), Vector2(1, 1)}, {Vector3(2, 1, 0), Vector2(1, 0)}, {Vector3(0, 1, 0), Vector2(0, 0)}};
    for (const auto& corner : corners) {
        int found = 0;
        for (const ModelVertex& vertex : v)
            if (vertex.Position == corner.position) {
                ++found;
                EXPECT_EQ(vertex.TextureCoordinate, corner.uv) << corner.position.X << "," << corner.position.Y;
                EXPECT_EQ(vertex.Normal, Vector3(0, 0, 1));
                EXPECT_NEAR(vertex.Tangent.X, 1, 1e-5);  // towards increasing u
                EXPECT_NEAR(vertex.Binormal.Y, 1, 1e-5);  // towards the top of the image
            }
        EXPECT_EQ(found, 1);
    }
    expectClockwiseFromPlusZ(v, indicesOf(part));
    EXPECT_NEAR(mesh.BoundingSphere.Center.X, 1, 1e-5);

    auto* effect = dynamic_cast<BasicEffect*>(part.Effect);
    ASSERT_NE(effect, nullptr);
    EXPECT_EQ(effect->DiffuseColor, Vector3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(effect->Alpha, 0.75f);
    EXPECT_EQ(effect->EmissiveColor, Vector3(0.1f, 0, 0));
    EXPECT_TRUE(effect->TextureEnabled);
    ASSERT_NE(effect->Texture, nullptr);
    EXPECT_EQ(effect->Texture->GetData<Color>(), std::vector<Color>(texels, texels + 2));
}

// XNA's ModelProcessor runs material textures through the TextureProcessor with its defaults:
// magenta becomes transparent black, colours are premultiplied by alpha (round(v * a / 255)).
TEST_F(ModelImport, MaterialTexturesAreKeyedAndPremultipliedAsXnasModelProcessorDoes) {
    Texture2D texture(device(), 2, 1, false, SurfaceFormat::Color);
    const Color texels[2] = {Color(255, 0, 255, 255), Color(200, 100, 51, 128)};
    texture.SetData(texels, 2);
    texture.SaveAsPng((dir / "tex" / "keyed.png").string());
    write("quad.mtl", "newmtl Painted\nmap_Kd tex/keyed.png\n");
    const auto model = Model::Load(device(), write("quad.obj", kQuadObj).string());
    auto* effect = dynamic_cast<BasicEffect*>(model->Meshes[0].MeshParts[0].Effect);
    ASSERT_NE(effect, nullptr);
    ASSERT_NE(effect->Texture, nullptr);
    EXPECT_EQ(effect->Texture->GetData<Color>(), (std::vector<Color>{Color(0, 0, 0, 0), Color(100, 50, 26, 128)}));
}

// DirectX's own text format, as XNA's samples ship models: a frame hierarchy with a transform
// (translation 5 along x) and a one-triangle mesh. .x is left-handed; XNA's importers hand the
// processor right-handed, clockwise data (its "Tips for Developing Custom Importers"): z negated.
TEST_F(ModelImport, XFileFramesBecomeBonesWithTheirTransforms) {
    const char* x = R"(xof 0303txt 0032
Frame Root {
  FrameTransformMatrix { 1.0,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 5.0,0.0,0.0,1.0;; }
  Frame Child {
    FrameTransformMatrix { 1.0,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 0.0,2.0,0.0,1.0;; }
    Mesh Tri {
      3;
      0.0;0.0;1.0;,
      1.0;0.0;1.0;,
      0.0;1.0;1.0;;
      1;
      3;0,2,1;;
    }
  }
}
)";
    const auto model = Model::Load(device(), write("tri.x", x).string());
    EXPECT_EQ(model->Meshes[0].MeshParts[0].Textures.Texture->Width(), 1);  // no material: the default texture
    const ModelBone* child = nullptr;
    for (int i = 0; i < model->Bones.Count(); ++i)
        if (model->Bones[i].Name == "Child") child = &model->Bones[i];
    ASSERT_NE(child, nullptr);
    ASSERT_NE(child->Parent, nullptr);
    std::vector<Matrix> absolute;
    model->CopyAbsoluteBoneTransformsTo(absolute);
    const Vector3 origin = Vector3::Transform(Vector3(0, 0, 0), absolute[std::size_t(child->Index)]);
    EXPECT_NEAR(origin.X, 5, 1e-5);
    EXPECT_NEAR(origin.Y, 2, 1e-5);
    EXPECT_NEAR(origin.Z, 0, 1e-5);
    ASSERT_EQ(model->Meshes.Count(), 1);
    const ModelMeshPart& part = model->Meshes[0].MeshParts[0];
    const std::vector<ModelVertex> v = verticesOf(part);
    ASSERT_EQ(v.size(), 3u);
    for (const ModelVertex& vertex : v) EXPECT_NEAR(vertex.Position.Z, -1, 1e-5);  // left- to right-handed
}

// Models made for Direct3D name .dds textures: read with the DDS loader (an uncompressed 1x1 here).
TEST_F(ModelImport, ADdsTextureTheModelNamesIsRead) {
    std::vector<std::uint8_t> dds(128, 0);
    const std::uint32_t fields[][2] = {{4, 124}, {8, 0x1007}, {12, 1}, {16, 1}, {76, 32}, {80, 0x41}, {88, 32},
                                       {92, 0xFF0000}, {96, 0xFF00}, {100, 0xFF}, {104, 0xFF000000u}, {108, 0x1000}};
    dds[0] = 'D', dds[1] = 'D', dds[2] = 'S', dds[3] = ' ';
    for (const auto& f : fields)
        for (int k = 0; k < 4; ++k) dds[f[0] + std::uint32_t(k)] = std::uint8_t(f[1] >> (8 * k));
    for (std::uint8_t byte : {30, 20, 10, 255}) dds.push_back(byte);  // B, G, R, A
    std::ofstream(dir / "tex" / "Wall.dds", std::ios::binary).write(reinterpret_cast<const char*>(dds.data()), std::streamsize(dds.size()));
    write("quad.mtl", "newmtl Painted\nmap_Kd tex/Wall.dds\n");
    const auto model = Model::Load(device(), write("quad.obj", kQuadObj).string());
    auto* effect = dynamic_cast<BasicEffect*>(model->Meshes[0].MeshParts[0].Effect);
    ASSERT_NE(effect, nullptr);
    ASSERT_NE(effect->Texture, nullptr);
    EXPECT_EQ(effect->Texture->GetData<Color>(), std::vector<Color>{Color(10, 20, 30, 255)});
}

TEST_F(ModelImport, BadFilesAreRefusedNamingTheFile) {
    const std::string truncated = write("broken.obj", "v 0 0 0\nf 1 2 3\n").string();
    auto expectRefused = [&](const std::string& path, const std::string& words) {
        try {
            Model::Load(device(), path);
            ADD_FAILURE() << path << " loaded";
        } catch (const ArgumentError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path, 0), 0u) << what;
            EXPECT_NE(what.find(words), std::string::npos) << what;
        }
    };
    expectRefused(truncated, "");
    expectRefused((dir / "missing.fbx").string(), "not a regular file");
    expectRefused(dir.string() + "/tex", "not a regular file");  // a folder
    write("quad.mtl", "newmtl Painted\nmap_Kd nowhere.png\n");
    expectRefused(write("quad.obj", kQuadObj).string(), "names texture 'nowhere.png'");
}

}  // namespace
}  // namespace fxport
