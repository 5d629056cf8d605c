// Model loaded from glTF: bones, transforms, meshes and parts, vertex and index data read back from
// the GPU buffers, material textures, generated tangent frames, error messages. Every glTF file is
// written by the test itself (JSON + .bin or .glb + PNGs in a temporary folder), so each expected
// value below is known independently of the loader.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

#include "cpu_raster.h"
#include "fxport/graphics.h"
#include "fxport/graphics/model.h"
#include "xna_lighting_reference.h"
#include "helpers/gltf_loader.h"         // runtime/graphics/src: gltfNodeMatrix
#include "helpers/tangent_generation.h"  // runtime/graphics/src: generateTangents

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace fxport {
namespace {

// ---------------------------------------------------------------------------------------------
// Writing glTF files

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class GltfBuilder {
public:
    json doc = {{"asset", {{"version", "2.0"}, {"generator", "fxport model_test"}}}};

    // Appends `data` (4-byte aligned) as a buffer view and an accessor over it; returns the accessor.
    template <class T>
    int accessor(const std::vector<T>& data, const char* type, int componentType, int components, int target) {
        while (bin_.size() % 4) {
            bin_.push_back(0);
        }
        const std::size_t offset = bin_.size();
        const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
        bin_.insert(bin_.end(), bytes, bytes + data.size() * sizeof(T));
        json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", data.size() * sizeof(T)}};
        if (target) {
            view["target"] = target;
        }
        doc["bufferViews"].push_back(view);
        json acc = {{"bufferView", doc["bufferViews"].size() - 1},
                    {"componentType", componentType},
                    {"count", data.size() / std::size_t(components)},
                    {"type", type}};
        if (std::string(type) == "VEC3" && componentType == kFloat) {  // POSITION needs min/max
            std::vector<double> lo(3, 1e30), hi(3, -1e30);
            for (std::size_t i = 0; i < data.size(); ++i) {
                lo[i % 3] = std::min(lo[i % 3], double(data[i]));
                hi[i % 3] = std::max(hi[i % 3], double(data[i]));
            }
            acc["min"] = lo;
            acc["max"] = hi;
        }
        doc["accessors"].push_back(acc);
        return int(doc["accessors"].size() - 1);
    }
    int vec3(const std::vector<float>& v) { return accessor(v, "VEC3", kFloat, 3, kArrayBuffer); }
    int vec2(const std::vector<float>& v) { return accessor(v, "VEC2", kFloat, 2, kArrayBuffer); }
    int vec4(const std::vector<float>& v) { return accessor(v, "VEC4", kFloat, 4, kArrayBuffer); }
    int indices16(const std::vector<std::uint16_t>& v) {
        return accessor(v, "SCALAR", kUnsignedShort, 1, kElementArrayBuffer);
    }
    int indices32(const std::vector<std::uint32_t>& v) {
        return accessor(v, "SCALAR", kUnsignedInt, 1, kElementArrayBuffer);
    }

    // .gltf + .bin beside it.
    void writeGltf(const fs::path& path) {
        const fs::path binPath = fs::path(path).replace_extension(".bin");
        std::ofstream(binPath, std::ios::binary).write(reinterpret_cast<const char*>(bin_.data()), std::streamsize(bin_.size()));
        json out = doc;
        out["buffers"] = json::array({{{"uri", binPath.filename().string()}, {"byteLength", bin_.size()}}});
        std::ofstream(path) << out.dump(2);
    }

    // Binary glTF: header, JSON chunk, BIN chunk.
    void writeGlb(const fs::path& path) {
        json out = doc;
        out["buffers"] = json::array({{{"byteLength", bin_.size()}}});
        std::string text = out.dump();
        while (text.size() % 4) {
            text += ' ';
        }
        std::vector<unsigned char> bin = bin_;
        while (bin.size() % 4) {
            bin.push_back(0);
        }
        std::vector<unsigned char> glb;
        auto u32 = [&](std::uint32_t v) {
            for (int i = 0; i < 4; ++i) {
                glb.push_back(std::uint8_t(v >> (8 * i)));
            }
        };
        glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
        u32(2);
        u32(std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
        u32(std::uint32_t(text.size()));
        glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
        glb.insert(glb.end(), text.begin(), text.end());
        u32(std::uint32_t(bin.size()));
        glb.insert(glb.end(), {'B', 'I', 'N', '\0'});
        glb.insert(glb.end(), bin.begin(), bin.end());
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(glb.data()), std::streamsize(glb.size()));
    }

private:
    std::vector<unsigned char> bin_;
};

void writePng(const fs::path& path, int width, int height, const std::vector<Color>& texels) {
    ASSERT_EQ(texels.size(), std::size_t(width * height));
    ASSERT_NE(stbi_write_png(path.string().c_str(), width, height, 4, texels.data(), width * 4), 0) << path;
}

// The quad every test mesh uses: the unit square in the XY plane facing +Z, u along +X and v along
// -Y (glTF's texture origin is the top left, so the image's top row lies at y = 1).
const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kQuadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
const std::vector<float> kQuadUvs = {0, 1, 1, 1, 1, 0, 0, 0};
// Counter-clockwise seen from +Z (glTF's front).
const std::vector<std::uint16_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

const std::vector<Color> kAlbedoTexels = {Color(255, 0, 0, 255), Color(0, 255, 0, 255), Color(0, 0, 255, 255),
                                          Color(255, 255, 255, 255)};
const std::vector<Color> kNormalTexels = {Color(10, 20, 250, 255)};
const std::vector<Color> kSpecularTexels = {Color(40, 80, 0, 255), Color(120, 160, 0, 255)};

// ---------------------------------------------------------------------------------------------
// Fixture: one device and one folder for the whole suite.

class ModelTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(fs::temp_directory_path() / ("fxport_model_test_" + std::to_string(::getpid())));
        fs::create_directories(*dir_);
        device_ = new GraphicsDevice(PresentationParameters{});
    }
    static void TearDownTestSuite() {
        delete device_;
        device_ = nullptr;
        std::error_code ignored;
        fs::remove_all(*dir_, ignored);
        delete dir_;
        dir_ = nullptr;
    }
    static GraphicsDevice& device() { return *device_; }
    static fs::path file(const std::string& name) { return *dir_ / name; }

    // The scene of most tests:
    //   node 0 "Base":   rotation 90 degrees about +Z, translation (1, 2, 3); mesh 0; children 1, 2
    //   node 1 "Arm":    translation (1, 0, 0), scale 2; mesh 1
    //   node 2 "Marker": matrix = scale x by 3, translation (4, 5, 6); no mesh
    //   mesh 0 "TexturedQuad": the quad with TANGENT (w = -1 on vertex 3), 16-bit indices, material 0
    //     (base colour 2x2 PNG, normal 1x1 PNG, specular via extras.fxportSpecularMap 2x1 PNG)
    //   mesh 1 "Plain": primitive 0 = the quad without tangents, 32-bit indices, material 1 (only
    //     KHR_materials_specular.specularTexture); primitive 1 = one triangle in the XZ plane
    //     without indices, normals, UVs or material.
    static GltfBuilder sceneBuilder() {
        writePng(file("albedo.png"), 2, 2, kAlbedoTexels);
        writePng(file("normal.png"), 1, 1, kNormalTexels);
        writePng(file("specular.png"), 2, 1, kSpecularTexels);

        GltfBuilder b;
        const float s = std::sqrt(0.5f);
        b.doc["scene"] = 0;
        b.doc["scenes"] = json::array({{{"nodes", {0}}}});
        b.doc["nodes"] = json::array({
            {{"name", "Base"}, {"rotation", {0, 0, s, s}}, {"translation", {1, 2, 3}}, {"mesh", 0}, {"children", {1, 2}}},
            {{"name", "Arm"}, {"translation", {1, 0, 0}}, {"scale", {2, 2, 2}}, {"mesh", 1}},
            {{"name", "Marker"}, {"matrix", {3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1}}},
        });
        b.doc["images"] = json::array({{{"uri", "albedo.png"}}, {{"uri", "normal.png"}}, {{"uri", "specular.png"}}});
        b.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}, {{"source", 2}}});
        b.doc["materials"] = json::array({
            {{"name", "Painted"},
             {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
             {"normalTexture", {{"index", 1}}},
             {"extras", {{"fxportSpecularMap", 2}}}},
            {{"name", "Shiny"},
             {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.6, 0.9, 0.5}}}},
             {"emissiveFactor", {0.1, 0.0, 0.05}},
             {"extensions", {{"KHR_materials_specular", {{"specularTexture", {{"index", 2}}}}}}}},
        });
        b.doc["extensionsUsed"] = {"KHR_materials_specular"};

        const std::vector<float> tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1};
        json texturedQuad = {{"mode", 4},
                             {"material", 0},
                             {"indices", b.indices16(kQuadIndices)},
                             {"attributes",
                              {{"POSITION", b.vec3(kQuadPositions)},
                               {"NORMAL", b.vec3(kQuadNormals)},
                               {"TEXCOORD_0", b.vec2(kQuadUvs)},
                               {"TANGENT", b.vec4(tangents)}}}};
        json plainQuad = {{"material", 1},
                          {"indices", b.indices32({0, 1, 2, 0, 2, 3})},
                          {"attributes",
                           {{"POSITION", b.vec3(kQuadPositions)},
                            {"NORMAL", b.vec3(kQuadNormals)},
                            {"TEXCOORD_0", b.vec2(kQuadUvs)}}}};
        // Counter-clockwise seen from +Y: face normal +Y.
        json bareTriangle = {{"attributes", {{"POSITION", b.vec3({0, 0, 0, 0, 0, 1, 1, 0, 0})}}}};
        b.doc["meshes"] = json::array({
            {{"name", "TexturedQuad"}, {"primitives", {texturedQuad}}},
            {{"name", "Plain"}, {"primitives", {plainQuad, bareTriangle}}},
        });
        return b;
    }

    static std::string writeScene() {
        sceneBuilder().writeGltf(file("scene.gltf"));
        return file("scene.gltf").string();
    }

    // Loads a file that must fail; returns the message.
    static std::string loadError(const fs::path& path) {
        try {
            Model::Load(device(), path.string());
        } catch (const ArgumentError& e) {
            return e.what();
        }
        ADD_FAILURE() << "loading " << path << " did not throw ArgumentError";
        return "";
    }

    static GraphicsDevice* device_;
    static fs::path* dir_;
};

GraphicsDevice* ModelTest::device_ = nullptr;
fs::path* ModelTest::dir_ = nullptr;

// ---------------------------------------------------------------------------------------------
// Helpers for comparing

void expectNear(const Matrix& actual, const Matrix& expected, float tolerance = 1e-5f) {
    for (int i = 0; i < 16; ++i) {
        EXPECT_NEAR(actual.data()[i], expected.data()[i], tolerance) << "element " << i << " (M" << (i / 4 + 1)
                                                                      << (i % 4 + 1) << ")";
    }
}

void expectNear(Vector3 actual, Vector3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.X, expected.X, tolerance);
    EXPECT_NEAR(actual.Y, expected.Y, tolerance);
    EXPECT_NEAR(actual.Z, expected.Z, tolerance);
}

std::vector<ModelVertex> readVertices(const VertexBuffer& buffer) {
    std::vector<ModelVertex> vertices(std::size_t(buffer.VertexCount()));
    buffer.GetData(vertices.data(), vertices.size());
    return vertices;
}

// One of part.Textures by its glTF role: "Texture", "NormalMap" or "SpecularMap".
Texture2D* materialTexture(const ModelMeshPart& part, const std::string& which) {
    return which == "Texture" ? part.Textures.Texture : which == "NormalMap" ? part.Textures.NormalMap : part.Textures.SpecularMap;
}

std::vector<Color> texels(const ModelMeshPart& part, const char* which) {
    Texture2D* texture = materialTexture(part, which);
    EXPECT_NE(texture, nullptr) << which;
    return texture ? texture->GetData<Color>() : std::vector<Color>();
}

// ---------------------------------------------------------------------------------------------
// Tangent generation (runtime/graphics/src/tangent_generation.cpp)

std::vector<Vector3> toVector3(const std::vector<float>& v) {
    std::vector<Vector3> out;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
        out.emplace_back(v[i], v[i + 1], v[i + 2]);
    }
    return out;
}

std::vector<Vector2> toVector2(const std::vector<float>& v) {
    std::vector<Vector2> out;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) {
        out.emplace_back(v[i], v[i + 1]);
    }
    return out;
}

const std::vector<std::uint32_t> kQuadIndices32(kQuadIndices.begin(), kQuadIndices.end());

TEST(TangentGeneration, QuadWithUAlongXGivesTangentXAndBinormalTowardsImageTop) {
    const auto positions = toVector3(kQuadPositions);
    const auto normals = toVector3(kQuadNormals);
    const auto tangents = detail::generateTangents(positions, normals, toVector2(kQuadUvs), kQuadIndices32);
    ASSERT_EQ(tangents.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        expectNear(Vector3(tangents[i].X, tangents[i].Y, tangents[i].Z), Vector3::UnitX);
        EXPECT_EQ(tangents[i].W, 1.0f);
        // glTF: binormal = cross(N, T) * w; v grows along -Y, so "decreasing v" is +Y.
        expectNear(Vector3::Cross(normals[i], Vector3::UnitX) * tangents[i].W, Vector3::UnitY);
    }
}

TEST(TangentGeneration, MirroredUvsFlipHandedness) {
    // u grows along -X now; v still along -Y.
    const std::vector<float> mirrored = {1, 1, 0, 1, 0, 0, 1, 0};
    const auto normals = toVector3(kQuadNormals);
    const auto tangents =
        detail::generateTangents(toVector3(kQuadPositions), normals, toVector2(mirrored), kQuadIndices32);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        expectNear(Vector3(tangents[i].X, tangents[i].Y, tangents[i].Z), -Vector3::UnitX);
        EXPECT_EQ(tangents[i].W, -1.0f);
        expectNear(Vector3::Cross(normals[i], -Vector3::UnitX) * tangents[i].W, Vector3::UnitY);
    }
}

TEST(TangentGeneration, TangentIsOrthogonalisedAgainstTheNormal) {
    // Normals tilted towards +X by 36.87 degrees: dP/du = +X loses its normal part,
    // (1, 0, 0) - n * 0.6 = (0.64, 0, -0.48) -> (0.8, 0, -0.6).
    const std::vector<Vector3> normals(4, Vector3(0.6f, 0.0f, 0.8f));
    const auto tangents = detail::generateTangents(toVector3(kQuadPositions), normals, toVector2(kQuadUvs), kQuadIndices32);
    for (const Vector4& t : tangents) {
        expectNear(Vector3(t.X, t.Y, t.Z), Vector3(0.8f, 0.0f, -0.6f));
    }
}

TEST(TangentGeneration, DegenerateUvsGiveAUnitTangentOrthogonalToTheNormal) {
    const std::vector<Vector2> zeroUvs(4);
    const auto normals = toVector3(kQuadNormals);
    for (const Vector4& t : detail::generateTangents(toVector3(kQuadPositions), normals, zeroUvs, kQuadIndices32)) {
        const Vector3 xyz(t.X, t.Y, t.Z);
        EXPECT_NEAR(xyz.Length(), 1.0f, 1e-6f);
        EXPECT_NEAR(Vector3::Dot(xyz, normals[0]), 0.0f, 1e-6f);
        EXPECT_EQ(t.W, 1.0f);
    }
    // A zero normal too: still finite.
    const std::vector<Vector3> zeroNormals(4);
    for (const Vector4& t : detail::generateTangents(toVector3(kQuadPositions), zeroNormals, zeroUvs, kQuadIndices32)) {
        EXPECT_NEAR(Vector3(t.X, t.Y, t.Z).Length(), 1.0f, 1e-6f);
    }
}

// ---------------------------------------------------------------------------------------------
// Node transforms (no device needed)

TEST(GltfNodeMatrix, TranslationRotationScaleAndMatrix) {
    const double s = std::sqrt(0.5);
    // Rotation by 90 degrees about +Z turns +X into +Y; XNA rows are the images of the axes.
    expectNear(detail::gltfNodeMatrix({}, {1, 2, 3}, {0, 0, s, s}, {}),
               Matrix(0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1));
    // Scale applies first, then rotation, then translation.
    expectNear(detail::gltfNodeMatrix({}, {1, 2, 3}, {0, 0, s, s}, {2, 3, 4}),
               Matrix(0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1));
    // A matrix is the same 16 numbers in XNA's order.
    expectNear(detail::gltfNodeMatrix({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, {9, 9, 9}, {}, {}),
               Matrix(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16));
    // Agrees with the math library's own composition for an arbitrary rotation.
    Quaternion q = Quaternion::Normalize(Quaternion(0.3f, -0.5f, 0.2f, 0.8f));
    expectNear(detail::gltfNodeMatrix({}, {-1, 0.5, 7}, {q.X, q.Y, q.Z, q.W}, {0.5, 2, 1.5}),
               Matrix::CreateScale(0.5f, 2.0f, 1.5f) * Matrix::CreateFromQuaternion(q) *
                   Matrix::CreateTranslation(-1.0f, 0.5f, 7.0f));
}

// ---------------------------------------------------------------------------------------------
// Loading

TEST_F(ModelTest, BonesFollowTheNodeHierarchy) {
    const auto model = Model::Load(device(), writeScene());
    ASSERT_EQ(model->Bones.Count(), 3);
    EXPECT_EQ(model->Bones[0].Name, "Base");
    EXPECT_EQ(model->Bones[1].Name, "Arm");
    EXPECT_EQ(model->Bones[2].Name, "Marker");
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(model->Bones[i].Index, i);
    }
    ASSERT_EQ(model->Root, &model->Bones[0]);
    EXPECT_EQ(model->Root->Parent, nullptr);
    EXPECT_EQ(model->Bones["Arm"].Parent, model->Root);
    EXPECT_EQ(model->Bones["Marker"].Parent, model->Root);
    ASSERT_EQ(model->Root->Children.Count(), 2);
    EXPECT_EQ(&model->Root->Children[0], &model->Bones[1]);
    EXPECT_EQ(&model->Root->Children["Marker"], &model->Bones[2]);
    EXPECT_EQ(model->Bones.find("Nothing"), nullptr);
    EXPECT_THROW((void)model->Bones["Nothing"], ArgumentError);
    EXPECT_THROW((void)model->Bones[3], ArgumentError);

    // Local transforms.
    expectNear(model->Bones[0].Transform, Matrix(0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1));
    expectNear(model->Bones[1].Transform, Matrix(2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 1));
    expectNear(model->Bones[2].Transform, Matrix(3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1));
    EXPECT_EQ(model->Bones[0].Transform.Translation(), Vector3(1, 2, 3));

    // Absolute = local * parent's absolute (XNA order), worked out by hand:
    //   Arm: rows (2,0,0)->(0,2,0), (0,2,0)->(-2,0,0), translation (1,0,0)->(0,1,0)+(1,2,3).
    //   Marker: translation (4,5,6) -> (-5,4,6) + (1,2,3).
    std::vector<Matrix> transforms;
    model->CopyAbsoluteBoneTransformsTo(transforms);
    ASSERT_EQ(transforms.size(), 3u);
    expectNear(transforms[0], model->Bones[0].Transform);
    expectNear(transforms[1], Matrix(0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 3, 3, 1));
    expectNear(transforms[2], Matrix(0, 3, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, -4, 6, 9, 1));
    expectNear(transforms[1].Translation(), Vector3(1, 3, 3));
    // The child's point (1, 0, 0) lands where the parent's transform puts the child's (2, 0, 0)+(1, 0, 0).
    expectNear(Vector3::Transform(Vector3(1, 0, 0), transforms[1]), Vector3(1, 5, 3));

    Matrix array[3];
    model->CopyAbsoluteBoneTransformsTo(array);
    expectNear(array[2], transforms[2]);

    // Changing a bone's Transform moves its children.
    std::vector<Matrix> locals;
    model->CopyBoneTransformsTo(locals);
    locals[0] = Matrix::CreateTranslation(10, 0, 0);
    model->CopyBoneTransformsFrom(locals);
    model->CopyAbsoluteBoneTransformsTo(transforms);
    expectNear(transforms[1].Translation(), Vector3(11, 0, 0));
    EXPECT_THROW(model->CopyBoneTransformsFrom(std::vector<Matrix>(2)), ArgumentError);
}

TEST_F(ModelTest, MeshesAndParts) {
    const auto model = Model::Load(device(), writeScene());
    ASSERT_EQ(model->Meshes.Count(), 2);
    ModelMesh& base = model->Meshes[0];
    ModelMesh& arm = model->Meshes["Arm"];
    EXPECT_EQ(base.Name, "Base");  // the node's name
    EXPECT_EQ(&arm, &model->Meshes[1]);
    EXPECT_EQ(base.ParentBone, &model->Bones[0]);
    EXPECT_EQ(arm.ParentBone, &model->Bones[1]);
    EXPECT_THROW((void)model->Meshes["Marker"], ArgumentError);  // a bone without a mesh

    int visited = 0;
    for (ModelMesh& mesh : model->Meshes) {
        for (ModelMeshPart& part : mesh.MeshParts) {
            EXPECT_NE(part.Effect, nullptr);
            ++visited;
        }
    }
    EXPECT_EQ(visited, 3);

    ASSERT_EQ(base.MeshParts.size(), 1u);
    const ModelMeshPart& quad = base.MeshParts[0];
    EXPECT_EQ(quad.VertexOffset, 0);
    EXPECT_EQ(quad.NumVertices, 4);
    EXPECT_EQ(quad.StartIndex, 0);
    EXPECT_EQ(quad.PrimitiveCount, 2);
    EXPECT_EQ(quad.materialName, "Painted");
    ASSERT_NE(quad.VertexBuffer, nullptr);
    ASSERT_NE(quad.IndexBuffer, nullptr);
    EXPECT_EQ(quad.VertexBuffer->VertexCount(), 4);
    EXPECT_EQ(quad.VertexBuffer->VertexDeclaration(), ModelVertex::VertexDeclaration);
    EXPECT_EQ(quad.IndexBuffer->IndexElementSize(), IndexElementSize::SixteenBits);

    ASSERT_EQ(arm.MeshParts.size(), 2u);
    const ModelMeshPart& plain = arm.MeshParts[0];
    const ModelMeshPart& bare = arm.MeshParts[1];
    EXPECT_EQ(plain.VertexBuffer, bare.VertexBuffer);  // one buffer per glTF mesh
    EXPECT_EQ(plain.IndexBuffer, bare.IndexBuffer);
    EXPECT_EQ(plain.VertexOffset, 0);
    EXPECT_EQ(plain.NumVertices, 4);
    EXPECT_EQ(plain.StartIndex, 0);
    EXPECT_EQ(plain.PrimitiveCount, 2);
    EXPECT_EQ(bare.VertexOffset, 4);
    EXPECT_EQ(bare.NumVertices, 3);
    EXPECT_EQ(bare.StartIndex, 6);
    EXPECT_EQ(bare.PrimitiveCount, 1);
    EXPECT_EQ(bare.materialName, "");
    EXPECT_EQ(plain.VertexBuffer->VertexCount(), 7);
    EXPECT_EQ(plain.IndexBuffer->IndexCount(), 9);
    // 32-bit glTF indices still make a 16-bit buffer when the parts are small.
    EXPECT_EQ(plain.IndexBuffer->IndexElementSize(), IndexElementSize::SixteenBits);
    EXPECT_NE(plain.Effect, bare.Effect);  // one effect per part

    // Bounding spheres in the bone's space: the quad's box centre and its half diagonal.
    expectNear(base.BoundingSphere.Center, Vector3(0.5f, 0.5f, 0.0f));
    EXPECT_NEAR(base.BoundingSphere.Radius, std::sqrt(0.5f), 1e-6f);
}

TEST_F(ModelTest, VertexAndIndexDataMatchTheFile) {
    const auto model = Model::Load(device(), writeScene());
    // Textured quad: every attribute as written; tangents from the file, binormal = cross(N, T) * w.
    {
        const ModelMeshPart& part = model->Meshes[0].MeshParts[0];
        const auto vertices = readVertices(*part.VertexBuffer);
        ASSERT_EQ(vertices.size(), 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            SCOPED_TRACE(i);
            EXPECT_EQ(vertices[i].Position, Vector3(kQuadPositions[3 * i], kQuadPositions[3 * i + 1], kQuadPositions[3 * i + 2]));
            EXPECT_EQ(vertices[i].Normal, Vector3(0, 0, 1));
            EXPECT_EQ(vertices[i].TextureCoordinate, Vector2(kQuadUvs[2 * i], kQuadUvs[2 * i + 1]));
            EXPECT_EQ(vertices[i].Tangent, Vector3(1, 0, 0));
            EXPECT_EQ(vertices[i].Binormal, i == 3 ? Vector3(0, -1, 0) : Vector3(0, 1, 0));
        }
        // Winding reversed for XNA: (0 1 2)(0 2 3) -> (0 2 1)(0 3 2).
        EXPECT_EQ(part.IndexBuffer->GetIndices(), (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
    }
    // Plain mesh: the quad with generated tangents, then the bare triangle with a flat normal.
    {
        const ModelMeshPart& part = model->Meshes[1].MeshParts[0];
        const auto vertices = readVertices(*part.VertexBuffer);
        ASSERT_EQ(vertices.size(), 7u);
        for (std::size_t i = 0; i < 4; ++i) {
            SCOPED_TRACE(i);
            EXPECT_EQ(vertices[i].Position, Vector3(kQuadPositions[3 * i], kQuadPositions[3 * i + 1], kQuadPositions[3 * i + 2]));
            EXPECT_EQ(vertices[i].TextureCoordinate, Vector2(kQuadUvs[2 * i], kQuadUvs[2 * i + 1]));
            expectNear(vertices[i].Tangent, Vector3(1, 0, 0));  // u grows along +X
            expectNear(vertices[i].Binormal, Vector3(0, 1, 0));  // v shrinks along +Y
        }
        const Vector3 triangle[3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}};
        for (std::size_t i = 4; i < 7; ++i) {
            SCOPED_TRACE(i);
            EXPECT_EQ(vertices[i].Position, triangle[i - 4]);
            EXPECT_EQ(vertices[i].Normal, Vector3(0, 1, 0));  // flat: cross(b - a, c - a)
            EXPECT_EQ(vertices[i].TextureCoordinate, Vector2(0, 0));
            // No UVs: any unit frame orthogonal to the normal, never NaN.
            EXPECT_NEAR(vertices[i].Tangent.Length(), 1.0f, 1e-6f);
            EXPECT_NEAR(Vector3::Dot(vertices[i].Tangent, vertices[i].Normal), 0.0f, 1e-6f);
            EXPECT_NEAR(vertices[i].Binormal.Length(), 1.0f, 1e-6f);
            EXPECT_NEAR(Vector3::Dot(vertices[i].Binormal, vertices[i].Tangent), 0.0f, 1e-6f);
        }
        EXPECT_EQ(part.IndexBuffer->GetIndices(), (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2, 0, 2, 1}));
    }
}

TEST_F(ModelTest, MaterialTexturesAndDefaults) {
    const auto model = Model::Load(device(), writeScene());
    const ModelMeshPart& quad = model->Meshes[0].MeshParts[0];
    const ModelMeshPart& plain = model->Meshes[1].MeshParts[0];
    const ModelMeshPart& bare = model->Meshes[1].MeshParts[1];

    EXPECT_EQ(texels(quad, "Texture"), kAlbedoTexels);
    EXPECT_EQ(texels(quad, "NormalMap"), kNormalTexels);
    EXPECT_EQ(texels(quad, "SpecularMap"), kSpecularTexels);  // extras.fxportSpecularMap
    Texture2D* albedo = quad.Effect->Parameters["Texture"].GetValueTexture2D();
    ASSERT_NE(albedo, nullptr);
    EXPECT_EQ(albedo->Width(), 2);
    EXPECT_EQ(albedo->Height(), 2);
    EXPECT_EQ(albedo->Format(), SurfaceFormat::Color);
    // A full mip chain, the 1x1 level the rounded average of the four texels.
    ASSERT_EQ(albedo->LevelCount(), 2);
    Color average;
    albedo->getData(1, &average, sizeof average);
    EXPECT_EQ(average, Color(128, 128, 128, 255));

    EXPECT_EQ(texels(plain, "Texture"), std::vector<Color>{Color(255, 255, 255, 255)});
    EXPECT_EQ(texels(plain, "NormalMap"), std::vector<Color>{Color(128, 128, 255, 255)});
    EXPECT_EQ(texels(plain, "SpecularMap"), kSpecularTexels);  // KHR_materials_specular
    EXPECT_EQ(texels(bare, "Texture"), std::vector<Color>{Color(255, 255, 255, 255)});
    EXPECT_EQ(texels(bare, "NormalMap"), std::vector<Color>{Color(128, 128, 255, 255)});
    EXPECT_EQ(texels(bare, "SpecularMap"), std::vector<Color>{Color(0, 0, 0, 0)});

    // Textures are shared: one per image, one set of defaults per model.
    EXPECT_EQ(quad.Textures.SpecularMap, plain.Textures.SpecularMap);
    EXPECT_EQ(plain.Textures.Texture, bare.Textures.Texture);

    // Each part's effect is a BasicEffect set up from the material, its "Texture" parameter
    // holding the base colour texture from load on.
    auto* quadEffect = dynamic_cast<BasicEffect*>(quad.Effect);
    auto* plainEffect = dynamic_cast<BasicEffect*>(plain.Effect);
    ASSERT_NE(quadEffect, nullptr);
    ASSERT_NE(plainEffect, nullptr);
    EXPECT_TRUE(quadEffect->TextureEnabled);
    EXPECT_EQ(quadEffect->Texture, albedo);
    EXPECT_EQ(quad.Effect->Parameters["Texture"].GetValueTexture2D(), albedo);
    EXPECT_FALSE(plainEffect->TextureEnabled);
    EXPECT_FALSE(quadEffect->LightingEnabled);
    EXPECT_EQ(plainEffect->DiffuseColor, Vector3(0.2f, 0.6f, 0.9f));  // baseColorFactor
    EXPECT_EQ(plainEffect->Alpha, 0.5f);
    EXPECT_EQ(plainEffect->EmissiveColor, Vector3(0.1f, 0.0f, 0.05f));  // emissiveFactor
    EXPECT_EQ(quadEffect->DiffuseColor, Vector3(1, 1, 1));
    EXPECT_EQ(quadEffect->Alpha, 1.0f);
}

// Model::FromVertices: one bone, one mesh, one part over the caller's vertices and indices (as
// given: no winding change), the given maps in place of the defaults, bounds as Load computes them.
TEST_F(ModelTest, FromVerticesMakesOnePartOverTheGivenData) {
    std::vector<ModelVertex> vertices(4);
    const Vector3 corners[4] = {Vector3(0, 0, 0), Vector3(2, 0, 0), Vector3(2, 2, 0), Vector3(0, 2, 0)};
    for (int i = 0; i < 4; ++i) {
        vertices[std::size_t(i)].Position = corners[i];
        vertices[std::size_t(i)].Normal = Vector3(0, 0, 1);
        vertices[std::size_t(i)].TextureCoordinate = Vector2(float(i), 0.5f);
    }
    const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
    Texture2D albedo(device(), 1, 1, false, SurfaceFormat::Color), normals(device(), 1, 1, false, SurfaceFormat::Color);
    const auto model = Model::FromVertices(device(), "quad", vertices, indices, {&albedo, &normals, nullptr});

    ASSERT_EQ(model->Bones.Count(), 1);
    EXPECT_EQ(model->Root, &model->Bones[0]);
    EXPECT_EQ(model->Bones[0].Name, "quad");
    expectNear(model->Bones[0].Transform, Matrix::Identity);
    ASSERT_EQ(model->Meshes.Count(), 1);
    const ModelMesh& mesh = model->Meshes["quad"];
    EXPECT_EQ(mesh.ParentBone, &model->Bones[0]);
    expectNear(mesh.BoundingSphere.Center, Vector3(1, 1, 0));
    EXPECT_NEAR(mesh.BoundingSphere.Radius, std::sqrt(2.0f), 1e-6f);
    ASSERT_EQ(mesh.MeshParts.size(), 1u);
    const ModelMeshPart& part = mesh.MeshParts[0];
    EXPECT_EQ(part.VertexOffset, 0);
    EXPECT_EQ(part.NumVertices, 4);
    EXPECT_EQ(part.StartIndex, 0);
    EXPECT_EQ(part.PrimitiveCount, 2);
    EXPECT_EQ(part.VertexBuffer->VertexDeclaration(), ModelVertex::VertexDeclaration);
    const auto stored = readVertices(*part.VertexBuffer);
    ASSERT_EQ(stored.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(stored[i].Position, vertices[i].Position) << i;
        EXPECT_EQ(stored[i].TextureCoordinate, vertices[i].TextureCoordinate) << i;
    }
    EXPECT_EQ(part.IndexBuffer->GetIndices(), indices);

    // The given maps replace the defaults; the one not given stays the default.
    EXPECT_EQ(part.Textures.Texture, &albedo);
    EXPECT_EQ(part.Textures.NormalMap, &normals);
    EXPECT_EQ(texels(part, "SpecularMap"), std::vector<Color>{Color(0, 0, 0, 0)});
    auto* effect = dynamic_cast<BasicEffect*>(part.Effect);
    ASSERT_NE(effect, nullptr);
    EXPECT_TRUE(effect->TextureEnabled);
    EXPECT_EQ(part.Effect->Parameters["Texture"].GetValueTexture2D(), &albedo);

    // Without maps: Load's defaults, untextured.
    const auto plain = Model::FromVertices(device(), "plain", vertices, indices);
    const ModelMeshPart& plainPart = plain->Meshes[0].MeshParts[0];
    EXPECT_EQ(texels(plainPart, "Texture"), std::vector<Color>{Color(255, 255, 255, 255)});
    EXPECT_EQ(texels(plainPart, "NormalMap"), std::vector<Color>{Color(128, 128, 255, 255)});
    auto* plainEffect = dynamic_cast<BasicEffect*>(plainPart.Effect);
    ASSERT_NE(plainEffect, nullptr);
    EXPECT_FALSE(plainEffect->TextureEnabled);
}

TEST_F(ModelTest, FromVerticesRefusesBrokenData) {
    std::vector<ModelVertex> vertices(3);
    auto error = [&](const std::vector<ModelVertex>& v, const std::vector<std::uint32_t>& i) -> std::string {
        try {
            Model::FromVertices(device(), "broken", v, i);
        } catch (const ArgumentError& e) {
            return e.what();
        }
        ADD_FAILURE() << "FromVertices did not throw ArgumentError";
        return "";
    };
    EXPECT_NE(error({}, {0, 1, 2}).find("Model::FromVertices('broken'): 0 vertices"), std::string::npos);
    EXPECT_NE(error(vertices, {0, 1}).find("whole triangles"), std::string::npos);
    EXPECT_NE(error(vertices, {0, 1, 3}).find("index 2 is 3, past the 3 vertices"), std::string::npos);
}

TEST_F(ModelTest, BinaryGltfLoadsTheSame) {
    sceneBuilder().writeGlb(file("scene.glb"));
    const auto model = Model::Load(device(), file("scene.glb").string());
    ASSERT_EQ(model->Bones.Count(), 3);
    ASSERT_EQ(model->Meshes.Count(), 2);
    const ModelMeshPart& quad = model->Meshes[0].MeshParts[0];
    const auto vertices = readVertices(*quad.VertexBuffer);
    ASSERT_EQ(vertices.size(), 4u);
    EXPECT_EQ(vertices[2].Position, Vector3(1, 1, 0));
    EXPECT_EQ(vertices[2].TextureCoordinate, Vector2(1, 0));
    EXPECT_EQ(texels(quad, "Texture"), kAlbedoTexels);
}

TEST_F(ModelTest, SeveralRootNodesGetARootBone) {
    GltfBuilder b;
    b.doc["scenes"] = json::array({{{"name", "Stage"}, {"nodes", {0, 1}}}});
    b.doc["nodes"] = json::array({{{"mesh", 0}, {"translation", {0, 0, -5}}}, {{"name", "Second"}}});
    b.doc["meshes"] = json::array({{{"name", "Lonely"},
                                    {"primitives", {{{"attributes", {{"POSITION", b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}}}}}});
    b.writeGltf(file("roots.gltf"));
    const auto model = Model::Load(device(), file("roots.gltf").string());
    ASSERT_EQ(model->Bones.Count(), 3);
    EXPECT_EQ(model->Root->Name, "Stage");
    EXPECT_EQ(model->Root->Transform, Matrix::Identity);
    ASSERT_EQ(model->Root->Children.Count(), 2);
    EXPECT_EQ(model->Bones[1].Parent, model->Root);
    EXPECT_EQ(model->Bones[2].Name, "Second");
    ASSERT_EQ(model->Meshes.Count(), 1);
    EXPECT_EQ(model->Meshes[0].Name, "Lonely");  // the node has no name
    EXPECT_EQ(model->Meshes[0].ParentBone, &model->Bones[1]);
    std::vector<Matrix> transforms;
    model->CopyAbsoluteBoneTransformsTo(transforms);
    EXPECT_EQ(transforms[1].Translation(), Vector3(0, 0, -5));
}

TEST_F(ModelTest, StripsAndFansBecomeTriangleLists) {
    GltfBuilder b;
    const int strip = b.vec3({0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0});
    const int fan = b.vec3({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0});
    b.doc["nodes"] = json::array({{{"name", "N"}, {"mesh", 0}}});
    b.doc["meshes"] = json::array({{{"primitives",
                                     {{{"mode", 5}, {"attributes", {{"POSITION", strip}, {"NORMAL", b.vec3(std::vector<float>(12, 0.0f))}}}},
                                      {{"mode", 6}, {"attributes", {{"POSITION", fan}}}}}}}});
    b.writeGltf(file("strips.gltf"));
    const auto model = Model::Load(device(), file("strips.gltf").string());
    const ModelMesh& mesh = model->Meshes[0];
    ASSERT_EQ(mesh.MeshParts.size(), 2u);
    EXPECT_EQ(mesh.MeshParts[0].PrimitiveCount, 2);
    EXPECT_EQ(mesh.MeshParts[1].PrimitiveCount, 3);
    const auto indices = mesh.MeshParts[0].IndexBuffer->GetIndices();
    // Strip (0 1 2)(1 3 2), reversed: (0 2 1)(1 2 3). The fan has no normals, so its 3 triangles
    // (1 2 0)(2 3 0)(3 4 0) are unshared into 9 vertices: (0 2 1)(3 5 4)(6 8 7).
    EXPECT_EQ(indices, (std::vector<std::uint32_t>{0, 2, 1, 1, 2, 3, 0, 2, 1, 3, 5, 4, 6, 8, 7}));
    EXPECT_EQ(mesh.MeshParts[1].NumVertices, 9);
    const auto vertices = readVertices(*mesh.MeshParts[0].VertexBuffer);
    // Zero normals in the file stay zero (no NaN); the fan's flat normals face +Z.
    EXPECT_EQ(vertices[0].Normal, Vector3(0, 0, 0));
    EXPECT_FALSE(std::isnan(vertices[0].Tangent.X));
    EXPECT_EQ(vertices[4].Normal, Vector3(0, 0, 1));
    EXPECT_EQ(vertices[4 + 2].Position, Vector3(0, 0, 0));  // fan triangle 0 = v1 v2 v0
}

TEST_F(ModelTest, LargePartsGetThirtyTwoBitIndices) {
    // 70002 unindexed vertices (23334 triangles, no normals): over 65535 vertices in one part.
    std::vector<float> positions;
    for (int i = 0; i < 70002; ++i) {
        positions.insert(positions.end(), {float(i % 3 == 1), float(i % 3 == 2), float(i / 3) * 0.001f});
    }
    GltfBuilder b;
    b.doc["nodes"] = json::array({{{"name", "Big"}, {"mesh", 0}}});
    b.doc["meshes"] = json::array({{{"primitives", {{{"attributes", {{"POSITION", b.vec3(positions)}}}}}}}});
    b.writeGltf(file("big.gltf"));
    const auto model = Model::Load(device(), file("big.gltf").string());
    const ModelMeshPart& part = model->Meshes[0].MeshParts[0];
    EXPECT_EQ(part.NumVertices, 70002);
    EXPECT_EQ(part.PrimitiveCount, 23334);
    ASSERT_EQ(part.IndexBuffer->IndexElementSize(), IndexElementSize::ThirtyTwoBits);
    const auto indices = part.IndexBuffer->GetIndices();
    ASSERT_EQ(indices.size(), 70002u);
    EXPECT_EQ(indices[69999], 69999u);
    EXPECT_EQ(indices[70000], 70001u);
    EXPECT_EQ(indices[70001], 70000u);
}

TEST_F(ModelTest, DrawsWithXnaDefaultStatesAndItsOwnMaterial) {
    // The textured quad, drawn by mesh.Draw() with its part's BasicEffect over a 5x5 target:
    // front-facing after the winding flip (the default CullCounterClockwise keeps it), each pixel
    // showing the texel under it unlit (D3D9 rasterisation: pixel i samples u = i / 5; point
    // sampling, clamped).
    const auto model = Model::Load(device(), writeScene());
    ModelMesh& mesh = model->Meshes[0];
    RenderTarget2D target(device(), 5, 5, false, SurfaceFormat::Color, DepthFormat::Depth24);
    device().SetRenderTarget(&target);
    device().Clear(Color::Black);
    auto& matrices = dynamic_cast<IEffectMatrices&>(*mesh.MeshParts[0].Effect);
    matrices.World = Matrix::Identity;
    matrices.View = Matrix::Identity;
    matrices.Projection = Matrix::CreateOrthographicOffCenter(0, 1, 0, 1, -1, 1);
    device().BlendState = BlendState::Opaque;
    device().DepthStencilState = DepthStencilState::Default;
    device().RasterizerState = RasterizerState::CullCounterClockwise;
    device().SamplerStates[0] = SamplerState::PointClamp;
    mesh.Draw();
    device().SetRenderTarget(nullptr);
    const auto pixels = target.GetData<Color>();
    ASSERT_EQ(pixels.size(), 25u);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 5; ++x) {
            SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
            const int tx = x < 3 ? 0 : 1, ty = y < 3 ? 0 : 1;  // u = x / 5 -> texel floor(2u)
            EXPECT_EQ(pixels[std::size_t(y * 5 + x)], kAlbedoTexels[std::size_t(ty * 2 + tx)]);
        }
    }
}

// Model.Draw(world, view, projection) of the scene (two meshes under a two-level bone hierarchy,
// three parts, two materials and a part without material) with the parts' default BasicEffects,
// unlit and then lit by XNA's default rig per pixel, against a CPU reference that builds the
// absolute transforms itself (Base = R_z(90) * T(1, 2, 3); Arm = S(2) * T(1, 0, 0) * Base), turns
// glTF's counter-clockwise triangles into XNA's clockwise ones, and shades with BasicEffect's
// equations in double. Largest |GPU - CPU| per channel: 0.001 (float target, point-sampled
// texture; pixels within 0.02 texel of a texel edge are left out).
TEST_F(ModelTest, ModelDrawMatchesTheCpuReference) {
    using namespace stock_test;
    const auto model = Model::Load(device(), writeScene());
    ASSERT_EQ(model->Meshes.Count(), 2);
    const int size = 96;
    const Matrix world = Matrix::CreateRotationY(0.25f) * Matrix::CreateTranslation(0.3f, -0.2f, 0.0f);
    const Matrix view = Matrix::CreateLookAt(Vector3(-2.0f, 2.6f, 7.0f), Vector3(0.3f, 3.0f, 3.5f), Vector3(0, 1, 0));
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(0.7f, 1.0f, 1.0f, 20.0f);

    // The reference's transforms, built from the glTF nodes in double.
    DMat base, arm;
    base.m[0][1] = 1;
    base.m[1][0] = -1;
    base.m[2][2] = 1;
    base.m[3][0] = 1;
    base.m[3][1] = 2;
    base.m[3][2] = 3;
    base.m[3][3] = 1;
    for (int i = 0; i < 3; ++i) arm.m[i][i] = 2;
    arm.m[3][0] = 1;
    arm.m[3][3] = 1;
    const DMat worldD = toDMat(world);
    const DMat viewProjection = toDMat(view) * toDMat(projection);
    const DMat viewInverse = inverse(toDMat(view));
    const D3 eye{viewInverse.m[3][0], viewInverse.m[3][1], viewInverse.m[3][2]};

    // The three parts: surface 0 = textured quad (mesh 0), 1 = plain quad, 2 = bare triangle (mesh 1).
    struct Surface {
        DMat world;
        std::vector<float> positions, normals, uvs;
        std::vector<std::uint32_t> indices;  // glTF order (counter-clockwise)
        Material material;
        bool textured;
    };
    Material painted, shiny, plain;
    shiny.diffuse = {0.2f, 0.6f, 0.9f};
    shiny.alpha = 0.5f;
    shiny.emissive = {0.1f, 0.0f, 0.05f};
    const std::vector<std::uint32_t> quad = {0, 1, 2, 0, 2, 3};
    const std::vector<Surface> surfaces = {
        {base * worldD, kQuadPositions, kQuadNormals, kQuadUvs, quad, painted, true},
        {arm * base * worldD, kQuadPositions, kQuadNormals, kQuadUvs, quad, shiny, false},
        {arm * base * worldD, {0, 0, 0, 0, 0, 1, 1, 0, 0}, {0, 1, 0, 0, 1, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 0}, {0, 1, 2}, plain, false},
    };

    auto render = [&](bool lit, const std::string& name) {
        RenderTarget2D target(device(), size, size, false, SurfaceFormat::Vector4, DepthFormat::Depth24);
        device().SetRenderTarget(&target);
        device().Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0.1f, 0.2f, 0.3f, 0.4f), 1.0f, 0);
        device().BlendState = BlendState::Opaque;
        device().DepthStencilState = DepthStencilState::Default;
        device().RasterizerState = RasterizerState::CullCounterClockwise;
        device().SamplerStates[0] = SamplerState::PointClamp;
        model->Draw(world, view, projection);
        device().SetRenderTarget(nullptr);
        const std::vector<Vector4> gpu = target.GetDataAsVector4();

        Lights lights;
        if (lit) lights = lightsOf(dynamic_cast<IEffectLights&>(*model->Meshes[0].MeshParts[0].Effect));
        const D3 ambient = lit ? D3{0.05333332f, 0.09882354f, 0.1819608f} : D3{};
        std::vector<RasterVertex> vertices;
        std::vector<std::uint32_t> indices;
        std::vector<int> surfaceOf;
        for (std::size_t s = 0; s < surfaces.size(); ++s) {
            const Surface& surface = surfaces[s];
            const std::uint32_t first = std::uint32_t(vertices.size());
            const DMat normalMatrix = transpose(inverse(surface.world));
            for (std::size_t v = 0; v < surface.positions.size() / 3; ++v) {
                const D4 p{surface.positions[v * 3], surface.positions[v * 3 + 1], surface.positions[v * 3 + 2], 1};
                const D4 worldPosition = mul(p, surface.world);
                RasterVertex out;
                out.clip = mul(worldPosition, viewProjection);
                const D3 n{surface.normals[v * 3], surface.normals[v * 3 + 1], surface.normals[v * 3 + 2]};
                const D3 worldNormal = normalize(mul3(n, normalMatrix));
                out.varyings = {worldPosition.x, worldPosition.y, worldPosition.z, worldNormal.x, worldNormal.y, worldNormal.z,
                                surface.uvs[v * 2], surface.uvs[v * 2 + 1], double(s)};
                vertices.push_back(out);
            }
            for (std::size_t i = 0; i + 2 < surface.indices.size(); i += 3) {
                // XNA's winding: a, c, b.
                indices.push_back(first + surface.indices[i]);
                indices.push_back(first + surface.indices[i + 2]);
                indices.push_back(first + surface.indices[i + 1]);
                surfaceOf.push_back(int(s));
            }
        }
        const std::vector<RasterPixel> pixels = rasterize(size, size, vertices, indices, surfaceOf);
        double maxError = 0;
        int compared = 0, perSurface[3] = {0, 0, 0};
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            if (pixels[i].kind == PixelKind::Unsure) continue;
            D4 expected{0.1f, 0.2f, 0.3f, 0.4f};
            if (pixels[i].kind == PixelKind::Covered) {
                const std::vector<double>& in = pixels[i].varyings;
                const Surface& surface = surfaces[std::size_t(pixels[i].surface)];
                Material m = surface.material;
                m.ambient = ambient;
                D4 color = {(m.diffuse.x + m.emissive.x) * m.alpha, (m.diffuse.y + m.emissive.y) * m.alpha,
                            (m.diffuse.z + m.emissive.z) * m.alpha, m.alpha};
                if (lit) color = {1, 1, 1, m.alpha};
                if (surface.textured) {
                    const double tx = in[6] * 2, ty = in[7] * 2;  // 2x2 texels, point sampled
                    if (std::fabs(tx - std::round(tx)) < 0.02 || std::fabs(ty - std::round(ty)) < 0.02) continue;
                    const Color t = kAlbedoTexels[std::size_t(std::clamp(int(ty), 0, 1) * 2 + std::clamp(int(tx), 0, 1))];
                    color = color * D4{t.R / 255.0, t.G / 255.0, t.B / 255.0, t.A / 255.0};
                }
                if (lit) {
                    bool nearTerminator = false;
                    const LightResult r = light(lights, m, normalize(eye - D3{in[0], in[1], in[2]}),
                                                normalize(D3{in[3], in[4], in[5]}), &nearTerminator);
                    if (nearTerminator) continue;
                    const D3 rgb = color.xyz() * r.diffuse + r.specular * color.w;
                    color = {rgb.x, rgb.y, rgb.z, color.w};
                }
                expected = color;
                ++perSurface[pixels[i].surface];
            }
            const Vector4& g = gpu[i];
            maxError = std::max({maxError, std::fabs(g.X - expected.x), std::fabs(g.Y - expected.y),
                                 std::fabs(g.Z - expected.z), std::fabs(g.W - expected.w)});
            ++compared;
        }
        std::printf("[model] %s: compared %d pixels (textured quad %d, plain quad %d, triangle %d), max |GPU - CPU| %.5f\n",
                    name.c_str(), compared, perSurface[0], perSurface[1], perSurface[2], maxError);
        EXPECT_LE(maxError, 0.001) << name;
        for (int s = 0; s < 3; ++s) EXPECT_GE(perSurface[s], 60) << name << ": surface " << s << " barely visible";
        if (const char* folder = std::getenv("FXPORT_TEST_OUTPUT")) {
            std::vector<Color> png;
            for (const Vector4& g : gpu) png.push_back(Color(g.X, g.Y, g.Z, 1.0f));
            writePng(fs::path(folder) / ("model_draw_" + name + ".png"), size, size, png);
        }
    };

    render(false, "unlit");
    for (ModelMesh& mesh : model->Meshes) {
        EXPECT_EQ(mesh.Effects().Count(), int(mesh.MeshParts.size()));
        for (Effect* effect : mesh.Effects()) {
            dynamic_cast<IEffectLights&>(*effect).EnableDefaultLighting();
            dynamic_cast<BasicEffect&>(*effect).PreferPerPixelLighting = true;
        }
    }
    render(true, "lit");

    // An effect without World/View/Projection cannot be drawn by Model.Draw.
    Effect plainEffect(device(), std::string(FXPORT_RUNTIME_FIXTURES) + "/SpriteRedChannel.fx");
    model->Meshes[1].MeshParts[0].Effect = &plainEffect;
    EXPECT_THROW(model->Draw(world, view, projection), InvalidOperation);
}

TEST_F(ModelTest, DestroyingTheModelFreesItsGpuObjects) {
    const std::string path = writeScene();
    const GpuObjectCounts before = device().liveGpuObjects();
    {
        const auto model = Model::Load(device(), path);
        const GpuObjectCounts loaded = device().liveGpuObjects();
        EXPECT_EQ(loaded.textures, before.textures + 6);  // 3 defaults + 3 images
        // A vertex and an index buffer per glTF mesh, plus whatever the effects hold (constants).
        EXPECT_GE(loaded.buffers, before.buffers + 4);
    }
    const GpuObjectCounts after = device().liveGpuObjects();
    EXPECT_EQ(after.textures, before.textures);
    EXPECT_EQ(after.buffers, before.buffers);
    EXPECT_EQ(after.total(), before.total());
}

// ---------------------------------------------------------------------------------------------
// Errors: ArgumentError naming the file (and what in it), never a crash

TEST_F(ModelTest, MissingFile) {
    const std::string message = loadError(file("no_such_model.gltf"));
    EXPECT_NE(message.find("no_such_model.gltf"), std::string::npos) << message;
}

TEST_F(ModelTest, BadJson) {
    std::ofstream(file("bad.gltf")) << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ {";
    const std::string message = loadError(file("bad.gltf"));
    EXPECT_NE(message.find("bad.gltf"), std::string::npos) << message;
    std::ofstream(file("empty.glb")) << "glTF";
    EXPECT_NE(loadError(file("empty.glb")).find("empty.glb"), std::string::npos);
}

TEST_F(ModelTest, UnsupportedPrimitiveMode) {
    GltfBuilder b;
    b.doc["nodes"] = json::array({{{"mesh", 0}}});
    b.doc["meshes"] = json::array({{{"name", "Wires"},
                                    {"primitives", {{{"mode", 1}, {"attributes", {{"POSITION", b.vec3({0, 0, 0, 1, 0, 0})}}}}}}}});
    b.writeGltf(file("lines.gltf"));
    const std::string message = loadError(file("lines.gltf"));
    EXPECT_NE(message.find("lines.gltf"), std::string::npos) << message;
    EXPECT_NE(message.find("mesh 0 'Wires'"), std::string::npos) << message;
    EXPECT_NE(message.find("mode 1"), std::string::npos) << message;
}

TEST_F(ModelTest, BrokenReferences) {
    auto expectError = [&](const std::string& name, json doc, const std::string& needle) {
        SCOPED_TRACE(name);
        GltfBuilder b;
        const int position = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
        b.doc["nodes"] = json::array({{{"mesh", 0}}});
        b.doc["meshes"] = json::array({{{"primitives", {{{"attributes", {{"POSITION", position}}}}}}}});
        b.doc.merge_patch(doc);
        b.writeGltf(file(name));
        const std::string message = loadError(file(name));
        EXPECT_NE(message.find(name), std::string::npos) << message;
        EXPECT_NE(message.find(needle), std::string::npos) << message;
    };
    // More elements than the buffer view holds.
    expectError("overrun.gltf", {{"accessors", {{{"bufferView", 0}, {"componentType", kFloat}, {"count", 1000}, {"type", "VEC3"}}}}},
                "overrun buffer view 0");
    // An index past the last vertex (the bits of 1.0f read as an unsigned int).
    expectError("index.gltf",
                {{"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
                 {"accessors", {{{"bufferView", 0}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}},
                                {{"bufferView", 0}, {"byteOffset", 12}, {"componentType", kUnsignedInt}, {"count", 3},
                                 {"type", "SCALAR"}}}}},
                "index 1065353216 is out of range");
    // A node hierarchy with a cycle.
    expectError("cycle.gltf", {{"scenes", {{{"nodes", {0}}}}}, {"nodes", {{{"children", {1}}}, {{"children", {0}}}}}},
                "not a tree");
    // A material whose image file is missing.
    expectError("image.gltf",
                {{"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
                 {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
                 {"textures", {{{"source", 0}}}},
                 {"images", {{{"uri", "missing.png"}}}}},
                "image 0 'missing.png' could not be loaded");
    // A primitive without positions.
    expectError("noposition.gltf", {{"meshes", {{{"name", "Empty"}, {"primitives", {{{"attributes", {{"NORMAL", 0}}}}}}}}}},
                "no POSITION");
}

}  // namespace
}  // namespace fxport
