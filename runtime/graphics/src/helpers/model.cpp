// Model: the GPU side of a glTF model (buffers, textures, one material Effect per part) and XNA's
// bone/mesh API. Parsing is gltf_loader.cpp's job.
#include "fxport/graphics/model.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <utility>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/effect_interfaces.h"
#include "fxport/graphics/skinned_effect.h"
#include "device/image_io.h"
#include "helpers/assimp_loader.h"
#include "helpers/gltf_loader.h"

namespace fxport {

const fxport::VertexDeclaration ModelVertex::VertexDeclaration(
    int(sizeof(ModelVertex)),
    {
        VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
        VertexElement(12, VertexElementFormat::Vector3, VertexElementUsage::Normal, 0),
        VertexElement(24, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
        VertexElement(32, VertexElementFormat::Vector3, VertexElementUsage::Tangent, 0),
        VertexElement(44, VertexElementFormat::Vector3, VertexElementUsage::Binormal, 0),
    });
static_assert(sizeof(ModelVertex) == 56, "ModelVertex must be tightly packed: its declaration says 56 bytes");

const fxport::VertexDeclaration SkinnedModelVertex::VertexDeclaration(
    int(sizeof(SkinnedModelVertex)),
    {
        VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
        VertexElement(12, VertexElementFormat::Vector3, VertexElementUsage::Normal, 0),
        VertexElement(24, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
        VertexElement(32, VertexElementFormat::Vector3, VertexElementUsage::Tangent, 0),
        VertexElement(44, VertexElementFormat::Vector3, VertexElementUsage::Binormal, 0),
        VertexElement(56, VertexElementFormat::Byte4, VertexElementUsage::BlendIndices, 0),
        VertexElement(60, VertexElementFormat::Vector4, VertexElementUsage::BlendWeight, 0),
    });
static_assert(sizeof(SkinnedModelVertex) == 76, "SkinnedModelVertex must be tightly packed: its declaration says 76 bytes");

// ---------------------------------------------------------------------------------------------
// Collections

template <class T>
T& ModelItemCollection<T>::operator[](int index) const {
    if (index < 0 || index >= Count()) {
        throw ArgumentError((owner_ ? "Model '" + *owner_ + "'" : std::string("Model")) + ": " + kind_ + " index " +
                            std::to_string(index) + " is out of range (" + std::to_string(Count()) + " " + kind_ +
                            "s)");
    }
    return *items_[std::size_t(index)];
}

template <class T>
T* ModelItemCollection<T>::find(const std::string& name) const {
    for (T* item : items_) {
        if (item->Name == name) {
            return item;
        }
    }
    return nullptr;
}

template <class T>
T& ModelItemCollection<T>::operator[](const std::string& name) const {
    if (T* item = find(name)) {
        return *item;
    }
    std::string known;
    for (T* item : items_) {
        known += (known.empty() ? "'" : ", '") + item->Name + "'";
    }
    throw ArgumentError((owner_ ? "Model '" + *owner_ + "'" : std::string("Model")) + ": no " + kind_ + " named '" +
                        name + "' (has " + (known.empty() ? std::string("none") : known) + ")");
}

template class ModelItemCollection<ModelBone>;
template class ModelItemCollection<ModelMesh>;

// ---------------------------------------------------------------------------------------------
// Model

// Everything the model made. Declaration order is destruction order reversed: effects (which point
// at textures) go before the textures, and the bones/meshes that point at both go first.
struct Model::Resources {
    std::vector<std::unique_ptr<Texture2D>> textures;
    std::vector<std::unique_ptr<VertexBuffer>> vertexBuffers;
    std::vector<std::unique_ptr<IndexBuffer>> indexBuffers;
    std::vector<std::unique_ptr<Effect>> effects;
    std::vector<std::unique_ptr<ModelBone>> bones;
    std::vector<std::unique_ptr<ModelMesh>> meshes;
};

Model::Model() : resources_(std::make_unique<Resources>()) {}
Model::~Model() = default;

namespace {

// Number of mip levels of a full chain down to 1x1.
int fullMipCount(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) {
        ++levels;
    }
    return levels;
}

std::unique_ptr<Texture2D> makeTexture(GraphicsDevice& device, const detail::GltfImage& image) {
    auto texture = std::make_unique<Texture2D>(device, image.width, image.height, true, SurfaceFormat::Color);
    texture->Name = image.name;
    std::vector<Color> level = image.texels;
    int width = image.width, height = image.height;
    const int levels = std::min(texture->LevelCount(), fullMipCount(width, height));
    for (int i = 0; i < levels; ++i) {
        texture->SetData(i, nullptr, level.data(), level.size());
        if (i + 1 < levels) {
            level = detail::halve(level, width, height);
            width = std::max(1, width / 2);
            height = std::max(1, height / 2);
        }
    }
    return texture;
}

std::unique_ptr<Texture2D> makeSolidTexture(GraphicsDevice& device, Color color, const char* name) {
    auto texture = std::make_unique<Texture2D>(device, 1, 1, false, SurfaceFormat::Color);
    texture->Name = name;
    texture->SetData(&color, 1);
    return texture;
}

std::unique_ptr<VertexBuffer> makeVertexBuffer(GraphicsDevice& device, const detail::GltfMesh& mesh) {
    std::unique_ptr<VertexBuffer> vb;
    if (mesh.blendIndices.empty()) {
        vb = std::make_unique<VertexBuffer>(device, ModelVertex::VertexDeclaration, int(mesh.vertices.size()));
        vb->SetData(mesh.vertices);
    } else {
        std::vector<SkinnedModelVertex> skinned(mesh.vertices.size());
        for (std::size_t i = 0; i < skinned.size(); ++i) {
            const ModelVertex& v = mesh.vertices[i];
            skinned[i] = {v.Position, v.Normal, v.TextureCoordinate, v.Tangent, v.Binormal, mesh.blendIndices[i], mesh.blendWeights[i]};
        }
        vb = std::make_unique<VertexBuffer>(device, SkinnedModelVertex::VertexDeclaration, int(skinned.size()));
        vb->SetData(skinned);
    }
    vb->Name = mesh.name;
    return vb;
}

// XNA's BasicMaterialContent -> BasicEffect.
std::unique_ptr<Effect> makeBasicEffect(GraphicsDevice& device, const detail::GltfMaterial* mat, Texture2D* texture,
                                        const std::string& path) {
    auto effect = std::make_unique<BasicEffect>(device);
    effect->Name = "BasicEffect of material '" + (mat ? mat->name : std::string()) + "' of " + path;
    const Vector4 base = mat ? mat->baseColorFactor : Vector4(1, 1, 1, 1);
    effect->DiffuseColor = Vector3(base.X, base.Y, base.Z);
    effect->Alpha = base.W;
    effect->EmissiveColor = mat ? mat->emissiveFactor : Vector3(0, 0, 0);
    effect->TextureEnabled = mat && mat->texture >= 0;
    effect->Texture = texture;
    effect->Parameters["Texture"].SetValue(texture);
    return effect;
}

// XNA's SkinnedMaterialContent -> SkinnedEffect (always textured: the default texture is white).
std::unique_ptr<Effect> makeSkinnedEffect(GraphicsDevice& device, const detail::GltfMaterial* mat, Texture2D* texture,
                                          const std::string& path) {
    auto effect = std::make_unique<SkinnedEffect>(device);
    effect->Name = "SkinnedEffect of material '" + (mat ? mat->name : std::string()) + "' of " + path;
    const Vector4 base = mat ? mat->baseColorFactor : Vector4(1, 1, 1, 1);
    effect->DiffuseColor = Vector3(base.X, base.Y, base.Z);
    effect->Alpha = base.W;
    effect->EmissiveColor = mat ? mat->emissiveFactor : Vector3(0, 0, 0);
    effect->Texture = texture;
    effect->Parameters["Texture"].SetValue(texture);
    return effect;
}

}  // namespace

std::unique_ptr<Model> Model::Load(GraphicsDevice& device, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".gltf" || extension == ".glb") return build(device, detail::loadGltf(path), path);
    return build(device, detail::loadWithAssimp(path), path);
}

std::unique_ptr<Model> Model::FromVertices(GraphicsDevice& device, const std::string& name,
                                           const std::vector<ModelVertex>& vertices,
                                           const std::vector<std::uint32_t>& indices,
                                           const ModelMaterialTextures& textures) {
    const std::string what = "Model::FromVertices('" + name + "')";
    if (vertices.empty() || indices.empty() || indices.size() % 3 != 0) {
        throw ArgumentError(what + ": " + std::to_string(vertices.size()) + " vertices and " + std::to_string(indices.size()) +
                            " indices; it needs vertices and whole triangles (a multiple of 3 indices)");
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertices.size()) {
            throw ArgumentError(what + ": index " + std::to_string(i) + " is " + std::to_string(indices[i]) + ", past the " +
                                std::to_string(vertices.size()) + " vertices");
        }
    }
    // The model a one-node glTF file with one untextured primitive would give.
    detail::GltfModel source;
    source.bones.push_back({name, -1, Matrix::Identity, 0});
    detail::GltfMesh mesh;
    mesh.name = name;
    mesh.vertices = vertices;
    mesh.indices = indices;
    mesh.parts.push_back({0, int(vertices.size()), 0, int(indices.size() / 3), -1});
    mesh.bounds = detail::vertexBounds(vertices);
    mesh.sixteenBitIndices = vertices.size() < 65536;
    source.meshes.push_back(std::move(mesh));
    std::unique_ptr<Model> model = build(device, source, name);

    // The caller's maps replace the defaults (the BasicEffect textured as Load's would be).
    ModelMeshPart& part = model->Meshes[0].MeshParts[0];
    if (textures.Texture) {
        part.Textures.Texture = textures.Texture;
        auto& effect = static_cast<BasicEffect&>(*part.Effect);
        effect.TextureEnabled = true;
        effect.Texture = textures.Texture;
        effect.Parameters["Texture"].SetValue(textures.Texture);
    }
    if (textures.NormalMap) part.Textures.NormalMap = textures.NormalMap;
    if (textures.SpecularMap) part.Textures.SpecularMap = textures.SpecularMap;
    return model;
}

std::unique_ptr<Model> Model::build(GraphicsDevice& device, const detail::GltfModel& source, const std::string& path) {
    std::unique_ptr<Model> model(new Model());
    model->path_ = path;
    Resources& res = *model->resources_;
    model->Bones.kind_ = "bone";
    model->Bones.owner_ = &model->path_;
    model->Meshes.kind_ = "mesh";
    model->Meshes.owner_ = &model->path_;

    // Bones (parents come first in `source.bones`).
    for (std::size_t i = 0; i < source.bones.size(); ++i) {
        auto bone = std::make_unique<ModelBone>();
        bone->Name = source.bones[i].name;
        bone->Index = int(i);
        bone->Transform = source.bones[i].transform;
        bone->Children.kind_ = "bone";
        bone->Children.owner_ = &model->path_;
        if (source.bones[i].parent >= 0) {
            bone->Parent = res.bones[std::size_t(source.bones[i].parent)].get();
            bone->Parent->Children.items_.push_back(bone.get());
        }
        model->Bones.items_.push_back(bone.get());
        res.bones.push_back(std::move(bone));
    }
    model->Root = res.bones.empty() ? nullptr : res.bones[0].get();
    if (source.skinning) model->Tag = *source.skinning;

    // Textures: the defaults, then the images the materials use.
    res.textures.push_back(makeSolidTexture(device, Color(255, 255, 255, 255), "ModelDefaultTexture"));
    res.textures.push_back(makeSolidTexture(device, Color(128, 128, 255, 255), "ModelDefaultNormalMap"));
    res.textures.push_back(makeSolidTexture(device, Color(0, 0, 0, 0), "ModelDefaultSpecularMap"));
    Texture2D* const defaults[3] = {res.textures[0].get(), res.textures[1].get(), res.textures[2].get()};
    const std::size_t firstImage = res.textures.size();
    for (const detail::GltfImage& image : source.images) {
        res.textures.push_back(makeTexture(device, image));
    }
    auto textureOr = [&](int image, int fallback) {
        return image >= 0 ? res.textures[firstImage + std::size_t(image)].get() : defaults[fallback];
    };

    // Buffers, one vertex and one index buffer per glTF mesh.
    struct MeshBuffers {
        VertexBuffer* vertices = nullptr;
        IndexBuffer* indices = nullptr;
    };
    std::vector<MeshBuffers> buffers(source.meshes.size());
    for (std::size_t m = 0; m < source.meshes.size(); ++m) {
        const detail::GltfMesh& mesh = source.meshes[m];
        if (mesh.vertices.empty()) {
            continue;
        }
        auto vb = makeVertexBuffer(device, mesh);
        std::unique_ptr<IndexBuffer> ib;
        if (mesh.sixteenBitIndices) {
            std::vector<std::uint16_t> narrow(mesh.indices.begin(), mesh.indices.end());
            ib = std::make_unique<IndexBuffer>(device, IndexElementSize::SixteenBits, int(narrow.size()));
            ib->SetData(narrow);
        } else {
            ib = std::make_unique<IndexBuffer>(device, IndexElementSize::ThirtyTwoBits, int(mesh.indices.size()));
            ib->SetData(mesh.indices);
        }
        ib->Name = mesh.name;
        buffers[m] = {vb.get(), ib.get()};
        res.vertexBuffers.push_back(std::move(vb));
        res.indexBuffers.push_back(std::move(ib));
    }

    // Meshes in bone order, each part with its own material effect.
    for (std::size_t b = 0; b < source.bones.size(); ++b) {
        const int meshIndex = source.bones[b].mesh;
        if (meshIndex < 0) {
            continue;
        }
        const detail::GltfMesh& sourceMesh = source.meshes[std::size_t(meshIndex)];
        auto mesh = std::make_unique<ModelMesh>();
        mesh->device_ = &device;
        mesh->Name = !source.bones[b].name.empty() ? source.bones[b].name : sourceMesh.name;
        mesh->ParentBone = res.bones[b].get();
        mesh->BoundingSphere = sourceMesh.bounds;
        for (const detail::GltfPart& sourcePart : sourceMesh.parts) {
            const detail::GltfMaterial* mat =
                sourcePart.material >= 0 ? &source.materials[std::size_t(sourcePart.material)] : nullptr;
            ModelMaterialTextures textures;
            textures.Texture = textureOr(mat ? mat->texture : -1, 0);
            textures.NormalMap = textureOr(mat ? mat->normalMap : -1, 1);
            textures.SpecularMap = textureOr(mat ? mat->specularMap : -1, 2);
            std::unique_ptr<Effect> effect = sourceMesh.blendIndices.empty() ? makeBasicEffect(device, mat, textures.Texture, path)
                                                                             : makeSkinnedEffect(device, mat, textures.Texture, path);

            ModelMeshPart part;
            part.VertexBuffer = buffers[std::size_t(meshIndex)].vertices;
            part.IndexBuffer = buffers[std::size_t(meshIndex)].indices;
            part.VertexOffset = sourcePart.vertexOffset;
            part.NumVertices = sourcePart.numVertices;
            part.StartIndex = sourcePart.startIndex;
            part.PrimitiveCount = sourcePart.primitiveCount;
            part.Effect = effect.get();
            part.materialName = mat ? mat->name : std::string();
            part.Textures = textures;
            mesh->MeshParts.push_back(std::move(part));
            res.effects.push_back(std::move(effect));
        }
        model->Meshes.items_.push_back(mesh.get());
        res.meshes.push_back(std::move(mesh));
    }
    return model;
}

ModelEffectCollection ModelMesh::Effects() const {
    ModelEffectCollection effects;
    for (const ModelMeshPart& part : MeshParts) {
        if (part.Effect && std::find(effects.items_.begin(), effects.items_.end(), part.Effect) == effects.items_.end()) {
            effects.items_.push_back(part.Effect);
        }
    }
    return effects;
}

void ModelMesh::Draw() {
    for (std::size_t p = 0; p < MeshParts.size(); ++p) {
        ModelMeshPart& part = MeshParts[p];
        if (part.PrimitiveCount <= 0) {
            continue;
        }
        if (!part.Effect) {
            throw InvalidOperation("ModelMesh '" + Name + "'.Draw(): part " + std::to_string(p) + " has no Effect");
        }
        device_->SetVertexBuffer(part.VertexBuffer);
        device_->Indices = part.IndexBuffer;
        for (EffectPass& pass : part.Effect->CurrentTechnique->Passes) {
            pass.Apply();
            device_->DrawIndexedPrimitives(PrimitiveType::TriangleList, part.VertexOffset, 0, part.NumVertices,
                                           part.StartIndex, part.PrimitiveCount);
        }
    }
}

void Model::Draw(const Matrix& world, const Matrix& view, const Matrix& projection) {
    CopyAbsoluteBoneTransformsTo(drawTransforms_);
    for (ModelMesh& mesh : Meshes) {
        for (Effect* effect : mesh.Effects()) {
            auto* matrices = dynamic_cast<IEffectMatrices*>(effect);
            if (!matrices) {
                throw InvalidOperation("Model '" + path_ + "'.Draw(): mesh '" + mesh.Name + "' has effect '" + effect->Name +
                                       "', which has no World/View/Projection (IEffectMatrices); set them yourself "
                                       "and call mesh.Draw()");
            }
            matrices->World = drawTransforms_[std::size_t(mesh.ParentBone->Index)] * world;
            matrices->View = view;
            matrices->Projection = projection;
        }
        mesh.Draw();
    }
}

void Model::CopyAbsoluteBoneTransformsTo(Matrix* transforms) const {
    // Parents precede children in Bones, so one pass suffices.
    for (const ModelBone& bone : Bones) {
        transforms[bone.Index] = bone.Parent ? bone.Transform * transforms[bone.Parent->Index] : bone.Transform;
    }
}

void Model::CopyAbsoluteBoneTransformsTo(std::vector<Matrix>& transforms) const {
    if (transforms.size() < std::size_t(Bones.Count())) {
        transforms.resize(std::size_t(Bones.Count()));
    }
    CopyAbsoluteBoneTransformsTo(transforms.data());
}

void Model::CopyBoneTransformsTo(std::vector<Matrix>& transforms) const {
    if (transforms.size() < std::size_t(Bones.Count())) {
        transforms.resize(std::size_t(Bones.Count()));
    }
    for (const ModelBone& bone : Bones) {
        transforms[std::size_t(bone.Index)] = bone.Transform;
    }
}

void Model::CopyBoneTransformsFrom(const std::vector<Matrix>& transforms) {
    if (transforms.size() < std::size_t(Bones.Count())) {
        throw ArgumentError("Model '" + path_ + "': CopyBoneTransformsFrom got " + std::to_string(transforms.size()) +
                            " matrices for " + std::to_string(Bones.Count()) + " bones");
    }
    for (ModelBone& bone : Bones) {
        bone.Transform = transforms[std::size_t(bone.Index)];
    }
}

}  // namespace fxport
