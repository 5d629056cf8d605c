// Issue 27 item 1: a skinned, animated .x model (written here) loads as XNA's SkinnedModelProcessor
// makes it -- SkinningData in Model::Tag, SkinnedModelVertex blend data, a SkinnedEffect per part --
// and AnimationPlayer poses it as XNA's SkinnedModel sample does. The oracle is computed from the
// file's own numbers: each bone's local matrix (the key in force at time t, the sample holds keys),
// absolute = local * parent's, skin = offset * absolute, vertex = sum of weight * position * skin,
// all in the file's left-handed space, then z negated (XNA's importers hand right-handed data on).
// Checked twice: the model's bone palette applied on the CPU to the vertices it loaded, and the
// pixels SkinnedEffect renders (covered / not covered away from triangle edges).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "fxport/graphics.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

std::string xMatrix(const Matrix& m) {
    const float v[16] = {m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24,
                         m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44};
    std::string s;
    char buffer[32];
    for (int i = 0; i < 16; ++i) {
        std::snprintf(buffer, sizeof buffer, "%s%.7f", i ? "," : "", double(v[i]));
        s += buffer;
    }
    return s;
}

// The file: Root { Hip { Knee }, Body { Mesh } }, a strip of 6 vertices at y = 1, 2, 3 weighted to
// Hip and Knee, and a clip "Bend" with matrix keys (100 ticks a second).
struct Rig {
    Matrix hipBind = Matrix::CreateTranslation(0, 1, 0);
    Matrix kneeBind = Matrix::CreateTranslation(0, 2, 0);
    // Keys (tick, local matrix) per bone.
    std::vector<std::pair<int, Matrix>> hipKeys = {{0, Matrix::CreateTranslation(0, 1, 0)},
                                                   {100, Matrix::CreateRotationZ(0.35f) * Matrix::CreateTranslation(0.5f, 1, 0)}};
    std::vector<std::pair<int, Matrix>> kneeKeys = {
        {0, Matrix::CreateTranslation(0, 2, 0)},
        {50, Matrix::CreateScale(1.2f) * Matrix::CreateRotationZ(-0.8f) * Matrix::CreateTranslation(0, 2, 0)}};
    std::vector<Vector3> positions = {Vector3(-0.5f, 1, 0.3f), Vector3(0.5f, 1, 0.3f), Vector3(-0.5f, 2, 0.3f),
                                      Vector3(0.5f, 2, 0.3f),  Vector3(-0.5f, 3, 0.3f), Vector3(0.5f, 3, 0.3f)};
    // (hip weight, knee weight) per vertex.
    std::vector<std::pair<float, float>> weights = {{1, 0}, {1, 0}, {0.7f, 0.3f}, {0.4f, 0.6f}, {0, 1}, {0, 1}};

    std::string file() const {
        std::string x = "xof 0303txt 0032\nAnimTicksPerSecond { 100; }\n";
        x += "Frame Root {\n FrameTransformMatrix { " + xMatrix(Matrix::Identity) + ";; }\n";
        x += " Frame Hip {\n  FrameTransformMatrix { " + xMatrix(hipBind) + ";; }\n";
        x += "  Frame Knee {\n   FrameTransformMatrix { " + xMatrix(kneeBind) + ";; }\n  }\n }\n";
        x += " Frame Body {\n  FrameTransformMatrix { " + xMatrix(Matrix::Identity) + ";; }\n  Mesh Strip {\n   6;\n";
        for (std::size_t i = 0; i < positions.size(); ++i) {
            char line[96];
            std::snprintf(line, sizeof line, "   %.3f;%.3f;%.3f;%s\n", double(positions[i].X), double(positions[i].Y),
                          double(positions[i].Z), i + 1 < positions.size() ? "," : ";");
            x += line;
        }
        x += "   4;\n   3;0,2,1;,\n   3;1,2,3;,\n   3;2,4,3;,\n   3;3,4,5;;\n";
        x += "   XSkinMeshHeader { 2; 2; 2; }\n";
        x += skinWeights("Hip", true, Matrix::Invert(hipBind));
        x += skinWeights("Knee", false, Matrix::Invert(kneeBind * hipBind));
        x += "  }\n }\n}\n";
        x += "AnimationSet Bend {\n";
        x += animation("Hip", hipKeys) + animation("Knee", kneeKeys) + "}\n";
        return x;
    }
    std::string skinWeights(const std::string& bone, bool hip, const Matrix& offset) const {
        std::string indices, values;
        int count = 0;
        for (std::size_t i = 0; i < weights.size(); ++i) {
            const float w = hip ? weights[i].first : weights[i].second;
            if (w == 0) continue;
            indices += (count ? "," : "") + std::to_string(i);
            values += (count ? "," : "") + std::to_string(w);
            ++count;
        }
        return "   SkinWeights {\n    \"" + bone + "\";\n    " + std::to_string(count) + ";\n    " + indices + ";\n    " + values +
               ";\n    " + xMatrix(offset) + ";;\n   }\n";
    }
    static std::string animation(const std::string& bone, const std::vector<std::pair<int, Matrix>>& keys) {
        std::string s = " Animation {\n  { " + bone + " }\n  AnimationKey {\n   4;\n   " + std::to_string(keys.size()) + ";\n";
        for (std::size_t k = 0; k < keys.size(); ++k)
            s += "   " + std::to_string(keys[k].first) + ";16;" + xMatrix(keys[k].second) + ";;" + (k + 1 < keys.size() ? ",\n" : ";\n");
        return s + "  }\n }\n";
    }

    // The key in force at `tick` (the last at or before it).
    static Matrix keyAt(const std::vector<std::pair<int, Matrix>>& keys, double tick) {
        Matrix m = keys[0].second;
        for (const auto& key : keys)
            if (key.first <= tick + 1e-9) m = key.second;
        return m;
    }
    // Every vertex posed at `seconds`, right-handed.
    std::vector<Vector3> posed(double seconds) const {
        const Matrix hip = keyAt(hipKeys, seconds * 100), knee = keyAt(kneeKeys, seconds * 100) * hip;
        const Matrix hipSkin = Matrix::Invert(hipBind) * hip, kneeSkin = Matrix::Invert(kneeBind * hipBind) * knee;
        std::vector<Vector3> out;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const Vector3 p = Vector3::Transform(positions[i], hipSkin) * weights[i].first +
                              Vector3::Transform(positions[i], kneeSkin) * weights[i].second;
            out.push_back(Vector3(p.X, p.Y, -p.Z));
        }
        return out;
    }
    // The bind position (right-handed) of vertex i.
    Vector3 bind(std::size_t i) const { return Vector3(positions[i].X, positions[i].Y, -positions[i].Z); }
};

class ModelSkinning : public ::testing::Test {
protected:
    static GraphicsDevice& device() {
        static GraphicsDevice d(PresentationParameters{});
        return d;
    }
    void SetUp() override {
        dir = fs::temp_directory_path() / ("fxport-model-skinning-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
        return (dir / name).string();
    }
    fs::path dir;
};

// The mesh's vertices as loaded, with the bind position of the rig each one is (joined vertices
// may come in another order).
std::vector<SkinnedModelVertex> loadedVertices(const ModelMeshPart& part) {
    std::vector<SkinnedModelVertex> all(std::size_t(part.VertexBuffer->VertexCount()));
    part.VertexBuffer->GetData(all.data(), all.size());
    return {all.begin() + part.VertexOffset, all.begin() + part.VertexOffset + part.NumVertices};
}

std::size_t rigVertex(const Rig& rig, Vector3 position) {
    for (std::size_t i = 0; i < rig.positions.size(); ++i)
        if (Vector3::Distance(rig.bind(i), position) < 1e-4f) return i;
    ADD_FAILURE() << "loaded vertex (" << position.X << ", " << position.Y << ", " << position.Z << ") is none of the file's";
    return 0;
}

TEST_F(ModelSkinning, SkinningDataBlendDataAndPaletteMatchTheFile) {
    const Rig rig;
    const auto model = Model::Load(device(), write("strip.x", rig.file()));
    const auto* skinning = std::any_cast<SkinningData>(&model->Tag);
    ASSERT_NE(skinning, nullptr) << "Model::Tag holds no SkinningData";
    ASSERT_EQ(skinning->AnimationClips.count("Bend"), 1u);
    const AnimationClip& clip = skinning->AnimationClips.at("Bend");
    EXPECT_NEAR(clip.Duration, 1.0, 1e-6);
    // The skeleton names the model bones it stands for; Hip's parent is Root's skeleton bone.
    std::map<std::string, int> skeletonIndex;
    for (std::size_t b = 0; b < skinning->SkeletonModelBones.size(); ++b)
        skeletonIndex[model->Bones[skinning->SkeletonModelBones[b]].Name] = int(b);
    ASSERT_EQ(skeletonIndex.count("Hip"), 1u);
    ASSERT_EQ(skeletonIndex.count("Knee"), 1u);
    EXPECT_EQ(skinning->SkeletonHierarchy[std::size_t(skeletonIndex["Knee"])], skeletonIndex["Hip"]);
    EXPECT_EQ(skinning->SkeletonHierarchy[0], -1);

    ASSERT_EQ(model->Meshes.Count(), 1);
    const ModelMeshPart& part = model->Meshes[0].MeshParts[0];
    auto* effect = dynamic_cast<SkinnedEffect*>(part.Effect);
    ASSERT_NE(effect, nullptr) << "the part's effect is not a SkinnedEffect";
    EXPECT_EQ(effect->WeightsPerVertex, 4);
    ASSERT_EQ(part.VertexBuffer->VertexDeclaration().VertexStride(), 76);
    const std::vector<SkinnedModelVertex> vertices = loadedVertices(part);
    ASSERT_EQ(vertices.size(), rig.positions.size());
    for (const SkinnedModelVertex& v : vertices) {
        const std::size_t i = rigVertex(rig, v.Position);
        std::map<int, float> weights;
        const float w[4] = {v.BlendWeight.X, v.BlendWeight.Y, v.BlendWeight.Z, v.BlendWeight.W};
        for (int k = 0; k < 4; ++k)
            if (w[k] > 0) weights[v.BlendIndices[std::size_t(k)]] += w[k];
        EXPECT_NEAR(weights[skeletonIndex["Hip"]], rig.weights[i].first, 1e-6) << "vertex " << i;
        EXPECT_NEAR(weights[skeletonIndex["Knee"]], rig.weights[i].second, 1e-6) << "vertex " << i;
    }

    // The palette at several times (absolute, then relative: 0.6 + 0.5 wraps to 0.1) applied to
    // the loaded vertices on the CPU.
    AnimationPlayer player(*skinning);
    player.StartClip(clip);
    const struct { double time; bool relative; double expectedTime; } steps[] = {
        {0.0, false, 0.0}, {0.3, false, 0.3}, {0.6, false, 0.6}, {0.5, true, 0.1}, {1.0, false, 1.0}};
    for (const auto& step : steps) {
        SCOPED_TRACE("t = " + std::to_string(step.expectedTime));
        player.Update(step.time, step.relative, Matrix::Identity);
        EXPECT_NEAR(player.CurrentTime(), step.expectedTime, 1e-9);
        const std::vector<Vector3> expected = rig.posed(step.expectedTime);
        const std::vector<Matrix>& skin = player.GetSkinTransforms();
        for (const SkinnedModelVertex& v : vertices) {
            const std::size_t i = rigVertex(rig, v.Position);
            Vector3 p(0, 0, 0);
            const float w[4] = {v.BlendWeight.X, v.BlendWeight.Y, v.BlendWeight.Z, v.BlendWeight.W};
            for (int k = 0; k < 4; ++k) p += Vector3::Transform(v.Position, skin[v.BlendIndices[std::size_t(k)]]) * w[k];
            EXPECT_NEAR(p.X, expected[i].X, 1e-4) << "vertex " << i;
            EXPECT_NEAR(p.Y, expected[i].Y, 1e-4) << "vertex " << i;
            EXPECT_NEAR(p.Z, expected[i].Z, 1e-4) << "vertex " << i;
        }
    }
    EXPECT_THROW(player.Update(1.5, false, Matrix::Identity), ArgumentError);
}

// Which pixel centres the posed strip covers: 1 inside every edge by more than `margin` pixels,
// 0 outside some edge by more than it, -1 too close to call.
int coverage(const std::vector<Vector3>& p, const int tri[][3], int triangles, float px, float py, int w, int h, float margin) {
    auto screen = [&](const Vector3& v) { return Vector2((v.X + 4) / 8 * float(w), (5 - v.Y) / 6 * float(h)); };
    bool near = false;
    for (int t = 0; t < triangles; ++t) {
        const Vector2 a = screen(p[std::size_t(tri[t][0])]), b = screen(p[std::size_t(tri[t][1])]), c = screen(p[std::size_t(tri[t][2])]);
        const float area = (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
        const Vector2 q(px, py);
        float minDistance = 1e9f;
        bool inside = true;
        for (int e = 0; e < 3; ++e) {
            const Vector2 u = e == 0 ? a : e == 1 ? b : c, v = e == 0 ? b : e == 1 ? c : a;
            const float cross = ((v.X - u.X) * (q.Y - u.Y) - (v.Y - u.Y) * (q.X - u.X)) * (area > 0 ? 1.0f : -1.0f);
            const float distance = cross / Vector2::Distance(u, v);
            inside = inside && distance > 0;
            minDistance = std::min(minDistance, std::abs(distance));
        }
        if (inside && minDistance > margin) return 1;
        if (minDistance <= margin) near = true;
    }
    return near ? -1 : 0;
}

TEST_F(ModelSkinning, SkinnedEffectRendersThePosedStrip) {
    const Rig rig;
    const auto model = Model::Load(device(), write("strip.x", rig.file()));
    const auto* skinning = std::any_cast<SkinningData>(&model->Tag);
    ASSERT_NE(skinning, nullptr);
    AnimationPlayer player(*skinning);
    player.StartClip(skinning->AnimationClips.at("Bend"));
    player.Update(0.6, false, Matrix::Identity);

    GraphicsDevice& d = device();
    const int w = 128, h = 96;
    RenderTarget2D target(d, w, h, false, SurfaceFormat::Color);
    d.SetRenderTarget(target);
    d.Clear(Color::Black);
    d.DepthStencilState = DepthStencilState::None;
    d.RasterizerState = RasterizerState::CullNone;
    d.BlendState = BlendState::Opaque;
    for (ModelMesh& mesh : model->Meshes) {
        for (Effect* e : mesh.Effects()) {
            auto* effect = dynamic_cast<SkinnedEffect*>(e);
            ASSERT_NE(effect, nullptr);
            effect->SetBoneTransforms(player.GetSkinTransforms());
            effect->DirectionalLight0.Enabled = false;  // emissive white only: covered = white
            effect->DiffuseColor = Vector3(0, 0, 0);
            effect->SpecularColor = Vector3(0, 0, 0);
            effect->EmissiveColor = Vector3(1, 1, 1);
            effect->View = Matrix::Identity;
            effect->Projection = Matrix::CreateOrthographicOffCenter(-4, 4, -1, 5, -10, 10);
        }
        mesh.Draw();
    }
    d.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<Color> pixels(std::size_t(w * h));
    target.GetData(pixels.data(), pixels.size());

    const std::vector<Vector3> expected = rig.posed(0.6);
    const int tri[4][3] = {{0, 2, 1}, {1, 2, 3}, {2, 4, 3}, {3, 4, 5}};
    int inside = 0, wrong = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int want = coverage(expected, tri, 4, float(x) + 0.5f, float(y) + 0.5f, w, h, 0.75f);
            if (want < 0) continue;
            const bool lit = pixels[std::size_t(y * w + x)].R > 128;
            inside += want;
            if (lit != (want == 1)) {
                if (++wrong <= 5) ADD_FAILURE() << "pixel (" << x << ", " << y << ") " << (lit ? "covered" : "empty") << ", the CPU pose says otherwise";
            }
        }
    }
    EXPECT_GT(inside, 150) << "the posed strip covers too few pixels to tell";
    EXPECT_EQ(wrong, 0);
}

TEST_F(ModelSkinning, ABoneNamingNoFrameIsRefusedNamingTheFile) {
    Rig rig;
    std::string text = rig.file();
    const std::string from = "\"Knee\";";
    text.replace(text.find(from), from.size(), "\"Ankle\";");
    const std::string path = write("broken.x", text);
    try {
        Model::Load(device(), path);
        ADD_FAILURE() << "loaded";
    } catch (const ArgumentError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("Ankle"), std::string::npos) << e.what();
    }
}

TEST(AnimationPlayer, RefusesInconsistentDataAndUpdatesWithoutAClip) {
    SkinningData data;
    data.BindPose = {Matrix::Identity, Matrix::Identity};
    data.InverseBindPose = {Matrix::Identity};
    data.SkeletonHierarchy = {-1, 0};
    EXPECT_THROW(AnimationPlayer{data}, ArgumentError);
    data.InverseBindPose.push_back(Matrix::Identity);
    AnimationPlayer player(data);
    EXPECT_THROW(player.Update(0, false, Matrix::Identity), InvalidOperation);
    AnimationClip clip{"Bad", 1.0, {{5, 0.0, Matrix::Identity}}};
    EXPECT_THROW(player.StartClip(clip), ArgumentError);
}

}  // namespace
}  // namespace fxport
