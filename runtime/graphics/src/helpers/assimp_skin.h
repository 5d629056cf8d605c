// Skin weights, skeleton and animations of an Assimp scene -> fxport's SkinningData (what XNA's
// SkinnedModelProcessor puts in Model.Tag) and per-vertex BLENDINDICES/BLENDWEIGHT (internal to
// fxport_graphics; assimp_loader.cpp calls it, model.h documents the rules).
#pragma once

#include <assimp/scene.h>

#include <map>
#include <string>
#include <vector>

#include "helpers/gltf_loader.h"

namespace fxport::detail {

// Assimp's column-vector matrix as XNA's row-vector one.
Matrix assimpToXna(const aiMatrix4x4& m);

class AssimpSkin {
public:
    // Finds the skeleton: every node a mesh's bones or an animation's channels name, every node
    // holding a skinned mesh, and their ancestors, in the order the model's bones have (depth-first
    // from the root). Throws ArgumentError starting with `path` for a bone or channel naming no node
    // or a skeleton of more than SkinnedEffect::MaxBones bones.
    AssimpSkin(const std::string& path, const aiScene& scene);

    bool empty() const { return skeleton_.empty(); }
    // Whether the node's meshes become skinned vertices (one of them has bones).
    bool skinnedNode(const aiNode& node) const;
    // Appends one BLENDINDICES/BLENDWEIGHT per vertex of `source` (a mesh of `node`, whose
    // vertices were just appended to mesh.vertices) to `mesh`: its four largest weights, scaled to
    // sum to 1. A vertex without weights (or a mesh without bones) follows the node's own bone
    // rigidly: its position and frame are moved into model space at bind time.
    void addVertices(const aiNode& node, const aiMesh& source, GltfMesh& mesh) const;
    // The skeleton and every animation as keyframes (see skinning_data.h).
    SkinningData finish() const;

private:
    [[noreturn]] void fail(const std::string& what) const;
    void walk(const aiNode& node, int parent, int depth);
    void mark(const aiNode* node);
    int skeletonBone(const aiNode& node) const;
    AnimationClip clipOf(const aiAnimation& animation, int index) const;

    std::string path_;
    const aiScene& scene_;
    std::vector<const aiNode*> nodes_;       // depth-first: index = Model::Bones index
    std::vector<int> parents_;               // model bone parent of each node
    std::vector<Matrix> absoluteBind_;       // each node's absolute transform in the file
    std::map<const aiNode*, int> nodeIndex_;
    std::vector<bool> inSkeleton_;
    std::vector<int> skeleton_;              // model bone index of each skeleton bone
    std::map<const aiNode*, int> skeletonIndex_;
    std::map<int, Matrix> offsets_;          // skeleton bone -> the first mesh's aiBone offset
};

}  // namespace fxport::detail
