// Model: XNA 4's Model, loaded from glTF 2.0 (.gltf with its .bin/images, or .glb) or, through
// Assimp, the formats XNA games ship (.x, .fbx, .obj, .dae ...), so that the tutorials' drawing
// loops port line by line:
//
//   std::unique_ptr<Model> model = Model::Load(device, "content/scene.glb");
//   std::vector<Matrix> transforms(model->Bones.Count());
//   model->CopyAbsoluteBoneTransformsTo(transforms);
//   for (ModelMesh& mesh : model->Meshes) {
//       for (ModelMeshPart& part : mesh.MeshParts) {
//           device.SetVertexBuffer(part.VertexBuffer, part.VertexOffset);
//           device.Indices = part.IndexBuffer;
//           gbuffer.Parameters["World"].SetValue(transforms[mesh.ParentBone->Index] * world);
//           gbuffer.Parameters["Texture"].SetValue(part.Effect->Parameters["Texture"].GetValueTexture2D());
//           gbuffer.CurrentTechnique->Passes[0].Apply();
//           device.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, part.NumVertices,
//                                        part.StartIndex, part.PrimitiveCount);
//       }
//   }
//
// Other formats (assimp_loader.h) follow the same rules with Assimp's node tree in place of the
// glTF scene: bones depth-first from the file's root node, one ModelMesh per node with meshes (one
// part per Assimp mesh, named after the node), data right-handed and clockwise as XNA's importers
// give it (.x files are converted from left-handed), v down, flat normals where the file has none,
// generated tangent frames; material diffuse colour/opacity/emissive and diffuse, normal and
// specular textures (files beside the model, Windows separators and any case accepted, or embedded).
// Skinned models load as XNA's SkinnedModel sample's SkinnedModelProcessor makes them:
//  * The skeleton is every node a mesh's bones or an animation's channels name, every node holding
//    a skinned mesh, and their ancestors up to the file's root, in Bones order (skeleton bone 0 is
//    the root); at most SkinnedEffect::MaxBones (72), else ArgumentError. Model::Tag holds its
//    SkinningData (skinning_data.h): BindPose = each bone's Transform, InverseBindPose = the file's
//    bone offset matrix (mesh space -> bone space; else the inverse of the node's absolute
//    transform), SkeletonHierarchy, and one AnimationClip per animation.
//  * Animations become keyframes per skeleton bone, one at each time any of the channel's
//    position, rotation or scale keys has (the others interpolated there, linearly and by slerp):
//    Transform = CreateScale(s) * CreateFromQuaternion(r) * CreateTranslation(p); Time and Duration
//    in seconds (ticks / the file's ticks per second, 25 when it gives none). AnimationPlayer
//    (animation_player.h) plays them as the sample does, holding each key until the next.
//  * A node with a skinned mesh gets SkinnedModelVertex vertices (BLENDINDICES0: the four heaviest
//    skeleton bones, BLENDWEIGHT0: their weights scaled to sum 1) and a SkinnedEffect per part
//    (material colours and texture as for BasicEffect, WeightsPerVertex 4). Vertices without
//    weights (and the node's meshes without bones) follow the node's own skeleton bone rigidly.
//    Draw as the sample does: effect->SetBoneTransforms(player.GetSkinTransforms()), World left
//    at the identity (the skin matrices already place the mesh; Model::Draw would apply the mesh's
//    bone transform on top).
//
// How glTF becomes an XNA model:
//  * Bones: one per node of the default scene (else scene 0, else every node that is no node's
//    child), in depth-first order with children in the order the file lists them, so a parent
//    always comes before its children. Root is Bones[0]: the scene's single root node, or, when the
//    scene has several (or none), an added bone with an identity transform named after the scene
//    ("Root" when the scene has no name) whose children are the scene's root nodes. Nodes outside
//    the scene are not loaded.
//  * ModelBone::Transform is the node's local transform as an XNA (row-vector) matrix: a node
//    `matrix` is read as written (glTF's column-major array of a column-vector matrix is, element
//    for element, the XNA matrix in M11, M12, ... order); translation/rotation/scale become
//    CreateScale(s) * CreateFromQuaternion(r) * CreateTranslation(t). Absolute transforms follow XNA:
//    absolute(bone) = bone.Transform * absolute(bone.Parent). glTF and XNA are both right-handed with
//    +Y up: no axis conversion.
//  * Meshes: one ModelMesh per node that has a mesh, in bone order; its ParentBone is that node's
//    bone and its Name the node's name (the glTF mesh's name when the node has none). Nodes that
//    instance the same glTF mesh share its buffers. One ModelMeshPart per triangle primitive.
//  * Vertices: ModelVertex below (POSITION0, NORMAL0, TEXCOORD0, TANGENT0, BINORMAL0), what
//    hlsl/xna-deferred/GBuffer.fx reads. The parts of one glTF mesh share one VertexBuffer and one
//    IndexBuffer; a part's indices count from its first vertex, so draw with
//    SetVertexBuffer(part.VertexBuffer, part.VertexOffset) and baseVertex 0 (as above), or with
//    SetVertexBuffer(part.VertexBuffer) and baseVertex = part.VertexOffset (as XNA's ModelMesh.Draw).
//    Indices are 16-bit when every part of the mesh has fewer than 65536 vertices, else 32-bit.
//    Triangle strips and fans become lists; points and lines are refused.
//  * Winding: glTF's front faces are counter-clockwise, XNA's clockwise (the default
//    RasterizerState.CullCounterClockwise culls the back). Every triangle's winding is reversed on
//    load (glTF indices a, b, c become a, c, b), so models draw with XNA's default states.
//  * Missing normals become flat normals (the triangles are unshared first), as glTF prescribes.
//  * Tangent frames: with a TANGENT attribute, Tangent = TANGENT.xyz and
//    Binormal = cross(Normal, TANGENT.xyz) * TANGENT.w (glTF's definition). Without one they are
//    generated from the texture coordinates (per-triangle UV derivatives, summed per vertex,
//    Gram-Schmidt against the normal) with the same convention: Tangent points towards increasing u,
//    Binormal = cross(Normal, Tangent) * w points towards decreasing v, i.e. towards the top of the
//    image, which is where glTF normal textures put +Y (green up, "OpenGL" normal maps).
//    DirectX-style normal maps (green down) need their green channel inverted by the content tool.
//  * Materials: each part gets its own BasicEffect, set up from its glTF material as XNA's content
//    pipeline sets up a model's BasicEffects: DiffuseColor/Alpha <- pbrMetallicRoughness.baseColorFactor,
//    EmissiveColor <- emissiveFactor, Texture <- baseColorTexture with TextureEnabled = true (else
//    the default white texture, TextureEnabled = false); everything else stays BasicEffect's
//    default (lighting off: call EnableDefaultLighting, as XNA programs do). The effect's "Texture"
//    parameter holds the texture from load on, so ported code can read it as the tutorials do.
//    part.Textures (an fxport addition) keeps the material's maps whatever Effect the part has:
//        Texture     <- pbrMetallicRoughness.baseColorTexture            (default: 1x1 white)
//        NormalMap   <- normalTexture                                    (default: 1x1 (128, 128, 255))
//        SpecularMap <- extensions.KHR_materials_specular.specularTexture, else the fxport convention
//                       extras: { "fxportSpecularMap": <texture index> } (default: 1x1 (0, 0, 0, 0))
//    e.g. "materials": [{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } },
//                         "normalTexture": { "index": 1 }, "extras": { "fxportSpecularMap": 2 } }].
//    Texture colours are loaded as SurfaceFormat::Color with a full mip chain (box-filtered);
//    samplers, texCoord sets other than 0 and KHR_texture_transform are ignored. The default
//    textures are shared by the parts of one Model.
//  * Drawing as XNA: model->Draw(world, view, projection) sets World (the mesh's absolute bone
//    transform times `world`), View and Projection on every effect of every mesh through
//    IEffectMatrices (an effect without it makes Draw throw InvalidOperation, as in XNA), then
//    draws each mesh with ModelMesh::Draw(): for each part, its buffers and every pass of its
//    Effect's CurrentTechnique. Lights and fog are set by the host through mesh.Effects():
//        for (ModelMesh& mesh : model->Meshes)
//            for (Effect* effect : mesh.Effects())
//                if (auto* lights = dynamic_cast<IEffectLights*>(effect)) lights->EnableDefaultLighting();
//  * Not loaded from glTF: skins, morph targets, animations, cameras, lights, vertex colours,
//    TEXCOORD_1+ (Assimp's formats load skins and animations, above).
//
// A Model owns everything it made (buffers, textures, effects); parts point into it, so the Model
// must outlive their use. Bad input (missing or unreadable file, bad JSON, broken accessors, a
// hierarchy that is not a tree, an unsupported primitive mode, a missing image) throws ArgumentError
// whose message starts with the file's path and names the mesh/node/image at fault.
#pragma once

#include <any>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/basic_effect.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/vertex_buffer.h"
#include "fxport/graphics/vertex_declaration.h"
#include "fxport/math.h"

namespace fxport {

class GraphicsDevice;
class Model;
class ModelBone;
class ModelMesh;
namespace detail {
struct GltfModel;
}

// The vertex of every Model (56 bytes), laid out as its VertexDeclaration says.
struct ModelVertex {
    Vector3 Position;           // POSITION0
    Vector3 Normal;             // NORMAL0
    Vector2 TextureCoordinate;  // TEXCOORD0
    Vector3 Tangent;            // TANGENT0
    Vector3 Binormal;           // BINORMAL0
    static const fxport::VertexDeclaration VertexDeclaration;
};

// The vertex of a skinned mesh (76 bytes): ModelVertex's then BLENDINDICES0 (Byte4: skeleton bone
// indices) and BLENDWEIGHT0 (Vector4), what SkinnedEffect reads.
struct SkinnedModelVertex {
    Vector3 Position;
    Vector3 Normal;
    Vector2 TextureCoordinate;
    Vector3 Tangent;
    Vector3 Binormal;
    std::array<std::uint8_t, 4> BlendIndices;
    Vector4 BlendWeight;
    static const fxport::VertexDeclaration VertexDeclaration;
};

// A read-only list of a Model's bones or meshes, as XNA's ModelBoneCollection/ModelMeshCollection:
// indexed by position or by name, iterated as references (for (ModelMesh& mesh : model->Meshes)).
template <class T>
class ModelItemCollection {
public:
    class iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = T;
        using difference_type = std::ptrdiff_t;
        using pointer = T*;
        using reference = T&;
        iterator() = default;
        explicit iterator(typename std::vector<T*>::const_iterator it) : it_(it) {}
        T& operator*() const { return **it_; }
        T* operator->() const { return *it_; }
        iterator& operator++() { ++it_; return *this; }
        iterator operator++(int) { iterator old = *this; ++it_; return old; }
        bool operator==(const iterator&) const = default;

    private:
        typename std::vector<T*>::const_iterator it_;
    };

    int Count() const { return int(items_.size()); }
    // Throw ArgumentError naming the model (and, for names, listing the known ones) when absent.
    T& operator[](int index) const;
    T& operator[](const std::string& name) const;
    // The first item with that name, or nullptr (XNA's TryGetValue).
    T* find(const std::string& name) const;
    iterator begin() const { return iterator(items_.begin()); }
    iterator end() const { return iterator(items_.end()); }

private:
    friend class Model;
    const char* kind_ = "item";
    const std::string* owner_ = nullptr;  // the model's path, for messages
    std::vector<T*> items_;
};

using ModelBoneCollection = ModelItemCollection<ModelBone>;
using ModelMeshCollection = ModelItemCollection<ModelMesh>;

class ModelBone {
public:
    std::string Name;
    int Index = 0;                       // position in Model::Bones
    Matrix Transform = Matrix::Identity; // relative to Parent (XNA row-vector matrix)
    ModelBone* Parent = nullptr;         // nullptr for Model::Root
    ModelBoneCollection Children;
};

// fxport: a part's glTF material maps (see the file comment), kept whatever its Effect is.
struct ModelMaterialTextures {
    fxport::Texture2D* Texture = nullptr;
    fxport::Texture2D* NormalMap = nullptr;
    fxport::Texture2D* SpecularMap = nullptr;
};

struct ModelMeshPart {
    fxport::VertexBuffer* VertexBuffer = nullptr;
    fxport::IndexBuffer* IndexBuffer = nullptr;
    int VertexOffset = 0;    // first vertex of the part in VertexBuffer
    int NumVertices = 0;     // vertices of the part (indices run 0 .. NumVertices - 1)
    int StartIndex = 0;      // first index of the part in IndexBuffer
    int PrimitiveCount = 0;  // triangles
    // The part's effect: a BasicEffect set up from the glTF material (see the file comment), owned
    // by the Model. May be replaced by the user's (which must outlive its use).
    fxport::Effect* Effect = nullptr;
    // fxport: the glTF material's name ("" when the primitive has none) and maps.
    std::string materialName;
    ModelMaterialTextures Textures;
};

// XNA's ModelEffectCollection: the distinct effects of a mesh's parts, in part order.
class ModelEffectCollection {
public:
    int Count() const { return int(items_.size()); }
    fxport::Effect* operator[](int index) const { return items_.at(std::size_t(index)); }
    auto begin() const { return items_.begin(); }
    auto end() const { return items_.end(); }

private:
    friend class ModelMesh;
    std::vector<fxport::Effect*> items_;
};

class ModelMesh {
public:
    std::string Name;
    ModelBone* ParentBone = nullptr;
    // Bounds of the mesh's vertices in its bone's space (centre of the bounding box, radius to the
    // farthest vertex).
    fxport::BoundingSphere BoundingSphere;
    std::vector<ModelMeshPart> MeshParts;

    // The parts' effects as they are now (XNA's mesh.Effects; a method because part.Effect is a
    // field the user may change at any time).
    ModelEffectCollection Effects() const;
    // Draws every part with every pass of its Effect's CurrentTechnique (vertex buffer, indices,
    // Apply, DrawIndexedPrimitives with baseVertex = VertexOffset), as XNA's ModelMesh.Draw.
    // Throws InvalidOperation naming the mesh when a part has no Effect.
    void Draw();

private:
    friend class Model;
    fxport::GraphicsDevice* device_ = nullptr;
};

class Model {
public:
    // Loads a .gltf or .glb file (see the file comment). Throws ArgumentError naming the file.
    static std::unique_ptr<Model> Load(fxport::GraphicsDevice& device, const std::string& path);
    // fxport: a Model of one mesh with one part under one bone (identity transform), all named
    // `name`, made from vertices and triangle-list indices in memory, for geometry a program makes
    // itself (XNA makes Models only in its content pipeline). The indices are drawn as given, so
    // front faces are clockwise, as XNA's. The part has a BasicEffect and Textures as Load gives an
    // untextured glTF primitive; each map given in `textures` replaces its default (Texture also
    // becomes the BasicEffect's texture, TextureEnabled). The given textures are not owned: they
    // must outlive the Model. Throws ArgumentError naming `name` for no vertices, indices that are
    // not whole triangles, or an index past the vertices.
    static std::unique_ptr<Model> FromVertices(fxport::GraphicsDevice& device, const std::string& name,
                                               const std::vector<ModelVertex>& vertices,
                                               const std::vector<std::uint32_t>& indices,
                                               const ModelMaterialTextures& textures = {});
    ~Model();
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;

    ModelBoneCollection Bones;
    ModelMeshCollection Meshes;
    ModelBone* Root = nullptr;
    // XNA's Model.Tag: a SkinningData when the file has skin weights or animations (see the file
    // comment; std::any_cast<SkinningData>(&model->Tag)), else empty. Free for the program's use.
    std::any Tag;

    // transforms[i] = the absolute transform of Bones[i] (Transform times every ancestor's, child
    // first). The vector is resized to Bones.Count() when it is smaller; the pointer overload writes
    // Bones.Count() matrices (size the array with Bones.Count(), as in XNA).
    void CopyAbsoluteBoneTransformsTo(std::vector<Matrix>& transforms) const;
    void CopyAbsoluteBoneTransformsTo(Matrix* transforms) const;
    // Every bone's local Transform, and back. CopyBoneTransformsFrom throws ArgumentError when given
    // fewer than Bones.Count() matrices.
    void CopyBoneTransformsTo(std::vector<Matrix>& transforms) const;
    void CopyBoneTransformsFrom(const std::vector<Matrix>& transforms);

    // XNA's Model.Draw: World = absolute bone transform * world, View and Projection set on each
    // mesh's effects through IEffectMatrices, then each mesh drawn (see the file comment). Throws
    // InvalidOperation naming the mesh and effect when an effect lacks IEffectMatrices.
    void Draw(const Matrix& world, const Matrix& view, const Matrix& projection);

    // fxport: the file it was loaded from.
    const std::string& sourcePath() const { return path_; }

private:
    struct Resources;
    Model();
    // Makes the GPU side of a parsed model (Load's and FromVertices' common part); `path` names it.
    static std::unique_ptr<Model> build(fxport::GraphicsDevice& device, const detail::GltfModel& source,
                                        const std::string& path);
    std::string path_;
    std::unique_ptr<Resources> resources_;
    std::vector<Matrix> drawTransforms_;  // Draw's absolute bone transforms (kept to avoid reallocating)
};

// The collections' out-of-line members are defined, and instantiated for these two, in model.cpp.
extern template class ModelItemCollection<ModelBone>;
extern template class ModelItemCollection<ModelMesh>;

}  // namespace fxport
