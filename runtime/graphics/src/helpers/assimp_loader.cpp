#include "helpers/assimp_loader.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stb/stb_image.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "device/dds_image.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture_processor.h"
#include "device/image_io.h"
#include "helpers/assimp_skin.h"
#include "helpers/tangent_generation.h"

namespace fxport::detail {

namespace {

namespace fs = std::filesystem;

// Assimp's matrices are column-vector (translation in a4, b4, c4); XNA's row-vector (M41..M43).
Matrix toXna(const aiMatrix4x4& m) { return assimpToXna(m); }

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Deeper node chains are refused rather than walked (the walk recurses).
constexpr int kMaxBoneDepth = 1024;

class AssimpReader {
public:
    AssimpReader(const std::string& path, const aiScene& scene)
        : path_(path), scene_(scene), folder_(fs::path(path).parent_path()), skin_(path, scene) {}

    GltfModel read() {
        addBone(*scene_.mRootNode, -1);
        if (!skin_.empty()) model_.skinning = skin_.finish();
        return std::move(model_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw ArgumentError(path_ + ": " + what); }

    // Depth-first, parents before children, as model.h says for glTF nodes.
    void addBone(const aiNode& node, int parent, int depth = 0) {
        if (depth > kMaxBoneDepth) fail("its node hierarchy is more than " + std::to_string(kMaxBoneDepth) + " levels deep");
        const int index = int(model_.bones.size());
        GltfBone bone;
        bone.name = node.mName.C_Str();
        bone.parent = parent;
        bone.transform = toXna(node.mTransformation);
        model_.bones.push_back(bone);
        if (node.mNumMeshes > 0) model_.bones[std::size_t(index)].mesh = addMesh(node);
        for (unsigned i = 0; i < node.mNumChildren; ++i) addBone(*node.mChildren[i], index, depth + 1);
    }

    int addMesh(const aiNode& node) {
        GltfMesh mesh;
        mesh.name = node.mName.C_Str();
        const bool skinned = skin_.skinnedNode(node);
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& source = *scene_.mMeshes[node.mMeshes[i]];
            if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;  // points and lines (SortByPType split them off)
            if (mesh.name.empty()) mesh.name = source.mName.C_Str();
            addPart(mesh, source);
            if (skinned) skin_.addVertices(node, source, mesh);
        }
        if (mesh.parts.empty()) fail("node '" + std::string(node.mName.C_Str()) + "' has meshes but no triangles");
        mesh.bounds = vertexBounds(mesh.vertices);
        for (const GltfPart& part : mesh.parts) mesh.sixteenBitIndices = mesh.sixteenBitIndices && part.numVertices < 65536;
        model_.meshes.push_back(std::move(mesh));
        return int(model_.meshes.size()) - 1;
    }

    void addPart(GltfMesh& mesh, const aiMesh& source) {
        const std::size_t n = source.mNumVertices;
        std::vector<Vector3> p(n), normals(n);
        std::vector<Vector2> uv(n);
        for (std::size_t i = 0; i < n; ++i) {
            p[i] = Vector3(source.mVertices[i].x, source.mVertices[i].y, source.mVertices[i].z);
            if (source.mNormals) {
                Vector3 normal(source.mNormals[i].x, source.mNormals[i].y, source.mNormals[i].z);
                float length = normal.Length();
                normals[i] = length > 0 && std::isfinite(length) ? normal / length : Vector3(0, 0, 0);
            }
            if (source.mTextureCoords[0]) uv[i] = Vector2(source.mTextureCoords[0][i].x, source.mTextureCoords[0][i].y);
        }
        std::vector<std::uint32_t> triangles;
        triangles.reserve(std::size_t(source.mNumFaces) * 3);
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            const aiFace& face = source.mFaces[f];
            if (face.mNumIndices != 3) continue;  // Triangulate leaves only triangles among the triangle meshes
            for (int k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= n) fail("mesh '" + std::string(source.mName.C_Str()) + "' indexes past its vertices");
                triangles.push_back(face.mIndices[k]);
            }
        }
        std::vector<Vector4> t = generateTangents(p, normals, uv, triangles);

        GltfPart part;
        part.vertexOffset = int(mesh.vertices.size());
        part.numVertices = int(n);
        part.startIndex = int(mesh.indices.size());
        part.primitiveCount = int(triangles.size() / 3);
        part.material = materialFor(source.mMaterialIndex);
        for (std::size_t i = 0; i < n; ++i) {
            ModelVertex vertex;
            vertex.Position = p[i];
            vertex.Normal = normals[i];
            vertex.TextureCoordinate = uv[i];
            vertex.Tangent = Vector3(t[i].X, t[i].Y, t[i].Z);
            vertex.Binormal = Vector3::Cross(normals[i], vertex.Tangent) * t[i].W;
            mesh.vertices.push_back(vertex);
        }
        // Assimp's fronts are counter-clockwise, XNA's clockwise: reverse each triangle.
        for (std::size_t i = 0; i < triangles.size(); i += 3)
            mesh.indices.insert(mesh.indices.end(), {triangles[i], triangles[i + 2], triangles[i + 1]});
        mesh.parts.push_back(part);
    }

    int materialFor(unsigned index) {
        if (index >= scene_.mNumMaterials) return -1;
        if (auto it = materials_.find(index); it != materials_.end()) return it->second;
        const aiMaterial& source = *scene_.mMaterials[index];
        GltfMaterial material;
        material.name = source.GetName().C_Str();
        aiColor4D diffuse(1, 1, 1, 1), emissive(0, 0, 0, 1);
        source.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse);
        source.Get(AI_MATKEY_COLOR_EMISSIVE, emissive);
        float opacity = 1;
        source.Get(AI_MATKEY_OPACITY, opacity);
        material.baseColorFactor = Vector4(diffuse.r, diffuse.g, diffuse.b, opacity);
        material.emissiveFactor = Vector3(emissive.r, emissive.g, emissive.b);
        material.texture = imageFor(source, aiTextureType_DIFFUSE);
        material.normalMap = imageFor(source, aiTextureType_NORMALS);
        material.specularMap = imageFor(source, aiTextureType_SPECULAR);
        model_.materials.push_back(material);
        return materials_[index] = int(model_.materials.size()) - 1;
    }

    int imageFor(const aiMaterial& material, aiTextureType type) {
        aiString name;
        if (material.GetTextureCount(type) == 0 || material.GetTexture(type, 0, &name) != AI_SUCCESS) return -1;
        const std::string key = name.C_Str();
        if (auto it = images_.find(key); it != images_.end()) return it->second;
        const bool embedded = key.size() > 1 && key[0] == '*';
        GltfImage image = embedded ? embeddedImage(key) : fileImage(material, key);
        if (embedded || !isDds(key)) image = asModelProcessorMakesIt(std::move(image));
        model_.images.push_back(std::move(image));
        return images_[key] = int(model_.images.size()) - 1;
    }

    static bool isDds(const std::string& key) { return lower(fs::path(key).extension().string()) == ".dds"; }

    // XNA's ModelProcessor runs each material texture through the TextureProcessor with its own
    // defaults: magenta keyed out and alpha premultiplied (PremultiplyTextureAlpha); its mips are
    // made when the texture is (model.cpp). .dds files stay as authored, as for Content.Load.
    static GltfImage asModelProcessorMakesIt(GltfImage image) {
        TextureProcessor::Output out = TextureProcessor{}.Process(std::move(image.texels), image.width, image.height);
        image.texels = std::move(out.levels[0]);
        return image;
    }

    GltfImage embeddedImage(const std::string& key) {
        const aiTexture* texture = scene_.GetEmbeddedTexture(key.c_str());
        if (!texture) fail("embedded texture '" + key + "' is missing");
        GltfImage image;
        image.name = key;
        if (texture->mHeight == 0) {  // a compressed file (PNG, JPEG ...) of mWidth bytes
            int w = 0, h = 0, channels = 0;
            stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(texture->pcData), int(texture->mWidth), &w, &h, &channels, 4);
            if (!data) fail("embedded texture '" + key + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unreadable"));
            image.width = w;
            image.height = h;
            for (int i = 0; i < w * h; ++i) image.texels.push_back(Color(data[4 * i], data[4 * i + 1], data[4 * i + 2], data[4 * i + 3]));
            stbi_image_free(data);
            return image;
        }
        image.width = int(texture->mWidth);
        image.height = int(texture->mHeight);
        for (unsigned i = 0; i < texture->mWidth * texture->mHeight; ++i) {
            const aiTexel& texel = texture->pcData[i];
            image.texels.push_back(Color(texel.r, texel.g, texel.b, texel.a));
        }
        return image;
    }

    // A texture file the model names: relative to the model's folder, Windows separators and any
    // case allowed (models come from Windows tools), else by its file name beside the model.
    GltfImage fileImage(const aiMaterial& material, const std::string& key) {
        std::string portable = key;
        for (char& c : portable)
            if (c == '\\') c = '/';
        const fs::path named(portable);
        std::vector<fs::path> tries;
        if (!named.is_absolute()) tries.push_back(folder_ / named);
        else tries.push_back(named);
        tries.push_back(folder_ / named.filename());
        for (const fs::path& candidate : tries) {
            if (fs::path found = existingIgnoringCase(candidate); !found.empty()) {
                if (lower(found.extension().string()) == ".dds") {  // what .x models made for D3D usually name
                    DdsImage dds = readDds(found.string());
                    return GltfImage{key, dds.width, dds.height, std::move(dds.levels[0])};
                }
                Image loaded = loadImage(found.string());
                return GltfImage{key, loaded.width, loaded.height, std::move(loaded.pixels)};
            }
        }
        fail("material '" + std::string(material.GetName().C_Str()) + "' names texture '" + key + "', which is not at " +
             tries[0].string() + " nor " + tries[1].string());
    }

    static fs::path existingIgnoringCase(const fs::path& path) {
        std::error_code error;
        if (fs::is_regular_file(path, error)) return path;
        const std::string wanted = lower(path.filename().string());
        for (const auto& entry : fs::directory_iterator(path.parent_path(), error))
            if (lower(entry.path().filename().string()) == wanted && entry.is_regular_file(error)) return entry.path();
        return {};
    }

    std::string path_;
    const aiScene& scene_;
    fs::path folder_;
    GltfModel model_;
    std::map<unsigned, int> materials_;
    std::map<std::string, int> images_;
    AssimpSkin skin_;
};

}  // namespace

GltfModel loadWithAssimp(const std::string& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw ArgumentError(path + ": not a regular file (or missing)");
    const auto bytes = fs::file_size(path, error);
    if (error || bytes > std::uintmax_t(kMaxModelFileBytes))
        throw ArgumentError(path + ": " + std::to_string(bytes) + " bytes, more than the " + std::to_string(kMaxModelFileBytes) +
                            " a model file may have");
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Triangles only, v down as D3D/XNA address textures, flat normals where the file has none
    // (as the glTF loader makes them), shared vertices joined.
    const unsigned steps = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_GenNormals | aiProcess_JoinIdenticalVertices |
                           aiProcess_FlipUVs | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, steps);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw ArgumentError(path + ": " + (importer.GetErrorString()[0] ? importer.GetErrorString() : "Assimp read no scene"));
    return AssimpReader(path, *scene).read();
}

}  // namespace fxport::detail
