#include "helpers/assimp_skin.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/skinned_effect.h"

namespace fxport::detail {

Matrix assimpToXna(const aiMatrix4x4& m) {
    return Matrix(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

namespace {

constexpr int kMaxDepth = 1024;  // as assimp_loader.cpp: deeper chains are refused, not recursed

// A channel's value at `time` (ticks): linear between its neighbouring keys, held before the first
// and after the last.
template <class Key, class Lerp>
auto keyAt(const Key* keys, unsigned count, double time, Lerp lerp) {
    if (count == 1 || time <= keys[0].mTime) return keys[0].mValue;
    for (unsigned k = 1; k < count; ++k) {
        if (time <= keys[k].mTime) {
            const double span = keys[k].mTime - keys[k - 1].mTime;
            const float t = span > 0 ? float((time - keys[k - 1].mTime) / span) : 1.0f;
            return lerp(keys[k - 1].mValue, keys[k].mValue, t);
        }
    }
    return keys[count - 1].mValue;
}

Vector3 unitOrZero(Vector3 v) {
    const float length = v.Length();
    return length > 0 && std::isfinite(length) ? v / length : Vector3(0, 0, 0);
}

aiVector3D lerpVector(const aiVector3D& a, const aiVector3D& b, float t) { return a + (b - a) * t; }

aiQuaternion slerp(const aiQuaternion& a, const aiQuaternion& b, float t) {
    aiQuaternion out;
    aiQuaternion::Interpolate(out, a, b, t);
    return out;
}

}  // namespace

AssimpSkin::AssimpSkin(const std::string& path, const aiScene& scene) : path_(path), scene_(scene) {
    walk(*scene.mRootNode, -1, 0);
    inSkeleton_.assign(nodes_.size(), false);
    for (const aiNode* node : nodes_) {
        for (unsigned m = 0; m < node->mNumMeshes; ++m) {
            const aiMesh& mesh = *scene.mMeshes[node->mMeshes[m]];
            for (unsigned b = 0; b < mesh.mNumBones; ++b) {
                const aiNode* bone = scene.mRootNode->FindNode(mesh.mBones[b]->mName);
                if (!bone) fail("bone '" + std::string(mesh.mBones[b]->mName.C_Str()) + "' of mesh '" + mesh.mName.C_Str() + "' names no node");
                mark(bone);
            }
            if (mesh.mNumBones > 0) mark(node);
        }
    }
    for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
        const aiAnimation& animation = *scene.mAnimations[a];
        for (unsigned c = 0; c < animation.mNumChannels; ++c) {
            const aiNode* node = scene.mRootNode->FindNode(animation.mChannels[c]->mNodeName);
            if (!node) fail("animation '" + std::string(animation.mName.C_Str()) + "' animates '" + animation.mChannels[c]->mNodeName.C_Str() +
                            "', which is no node");
            mark(node);
        }
    }
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        if (!inSkeleton_[i]) continue;
        skeletonIndex_[nodes_[i]] = int(skeleton_.size());
        skeleton_.push_back(int(i));
    }
    if (int(skeleton_.size()) > SkinnedEffect::MaxBones)
        fail("its skeleton has " + std::to_string(skeleton_.size()) + " bones (skinned, animated nodes and their ancestors), more than the " +
             std::to_string(SkinnedEffect::MaxBones) + " SkinnedEffect supports");
    // The inverse bind pose: the file's own offset where a mesh's bone gives one, else the inverse
    // of the node's absolute transform.
    for (const aiNode* node : nodes_)
        for (unsigned m = 0; m < node->mNumMeshes; ++m) {
            const aiMesh& mesh = *scene.mMeshes[node->mMeshes[m]];
            for (unsigned b = 0; b < mesh.mNumBones; ++b)
                offsets_.emplace(skeletonBone(*scene.mRootNode->FindNode(mesh.mBones[b]->mName)), assimpToXna(mesh.mBones[b]->mOffsetMatrix));
        }
}

void AssimpSkin::fail(const std::string& what) const { throw ArgumentError(path_ + ": " + what); }

// Depth-first, children in order: the same order assimp_loader.cpp gives the model's bones.
void AssimpSkin::walk(const aiNode& node, int parent, int depth) {
    if (depth > kMaxDepth) fail("its node hierarchy is more than " + std::to_string(kMaxDepth) + " levels deep");
    const int index = int(nodes_.size());
    nodeIndex_[&node] = index;
    nodes_.push_back(&node);
    parents_.push_back(parent);
    const Matrix local = assimpToXna(node.mTransformation);
    absoluteBind_.push_back(parent < 0 ? local : local * absoluteBind_[std::size_t(parent)]);
    for (unsigned i = 0; i < node.mNumChildren; ++i) walk(*node.mChildren[i], index, depth + 1);
}

void AssimpSkin::mark(const aiNode* node) {
    for (int i = nodeIndex_.at(node); i >= 0 && !inSkeleton_[std::size_t(i)]; i = parents_[std::size_t(i)]) inSkeleton_[std::size_t(i)] = true;
}

int AssimpSkin::skeletonBone(const aiNode& node) const { return skeletonIndex_.at(&node); }

bool AssimpSkin::skinnedNode(const aiNode& node) const {
    for (unsigned m = 0; m < node.mNumMeshes; ++m)
        if (scene_.mMeshes[node.mMeshes[m]]->mNumBones > 0) return true;
    return false;
}

void AssimpSkin::addVertices(const aiNode& node, const aiMesh& source, GltfMesh& mesh) const {
    const std::size_t n = source.mNumVertices, first = mesh.vertices.size() - n;
    std::vector<std::vector<std::pair<float, int>>> influences(n);
    for (unsigned b = 0; b < source.mNumBones; ++b) {
        const aiBone& bone = *source.mBones[b];
        const int index = skeletonBone(*scene_.mRootNode->FindNode(bone.mName));
        for (unsigned w = 0; w < bone.mNumWeights; ++w) {
            const aiVertexWeight& weight = bone.mWeights[w];
            if (weight.mVertexId >= n) fail("bone '" + std::string(bone.mName.C_Str()) + "' weighs vertex " + std::to_string(weight.mVertexId) +
                                            " of mesh '" + source.mName.C_Str() + "', which has " + std::to_string(n));
            if (weight.mWeight > 0 && std::isfinite(weight.mWeight)) influences[weight.mVertexId].push_back({weight.mWeight, index});
        }
    }
    const int own = skeletonBone(node);
    const Matrix bind = absoluteBind_[std::size_t(nodeIndex_.at(&node))];
    for (std::size_t v = 0; v < n; ++v) {
        auto& list = influences[v];
        std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        if (list.size() > 4) list.resize(4);
        float sum = 0;
        for (const auto& influence : list) sum += influence.first;
        std::array<std::uint8_t, 4> indices{};
        float w[4] = {0, 0, 0, 0};
        if (list.empty()) {  // rigid: bind to the node's bone, in model space
            ModelVertex& vertex = mesh.vertices[first + v];
            vertex.Position = Vector3::Transform(vertex.Position, bind);
            vertex.Normal = unitOrZero(Vector3::TransformNormal(vertex.Normal, bind));
            vertex.Tangent = unitOrZero(Vector3::TransformNormal(vertex.Tangent, bind));
            vertex.Binormal = unitOrZero(Vector3::TransformNormal(vertex.Binormal, bind));
            indices[0] = std::uint8_t(own);
            w[0] = 1;
        }
        for (std::size_t k = 0; k < list.size(); ++k) {
            indices[k] = std::uint8_t(list[k].second);
            w[k] = list[k].first / sum;
        }
        mesh.blendIndices.push_back(indices);
        mesh.blendWeights.push_back(Vector4(w[0], w[1], w[2], w[3]));
    }
}

AnimationClip AssimpSkin::clipOf(const aiAnimation& animation, int index) const {
    AnimationClip clip;
    clip.Name = animation.mName.length > 0 ? animation.mName.C_Str() : "Take " + std::to_string(index + 1);
    const double ticks = animation.mTicksPerSecond > 0 ? animation.mTicksPerSecond : 25.0;  // Assimp's "unknown": 25, as its viewer plays it
    clip.Duration = animation.mDuration / ticks;
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        const aiNodeAnim& channel = *animation.mChannels[c];
        const aiNode& node = *scene_.mRootNode->FindNode(channel.mNodeName);
        const int bone = skeletonBone(node);
        std::vector<double> times;
        for (unsigned k = 0; k < channel.mNumPositionKeys; ++k) times.push_back(channel.mPositionKeys[k].mTime);
        for (unsigned k = 0; k < channel.mNumRotationKeys; ++k) times.push_back(channel.mRotationKeys[k].mTime);
        for (unsigned k = 0; k < channel.mNumScalingKeys; ++k) times.push_back(channel.mScalingKeys[k].mTime);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        aiVector3D scale0(1, 1, 1), position0;
        aiQuaternion rotation0;
        node.mTransformation.Decompose(scale0, rotation0, position0);  // a channel without keys of a kind keeps the node's
        for (double time : times) {
            const aiVector3D s = channel.mNumScalingKeys ? keyAt(channel.mScalingKeys, channel.mNumScalingKeys, time, lerpVector) : scale0;
            const aiQuaternion r = channel.mNumRotationKeys ? keyAt(channel.mRotationKeys, channel.mNumRotationKeys, time, slerp) : rotation0;
            const aiVector3D p = channel.mNumPositionKeys ? keyAt(channel.mPositionKeys, channel.mNumPositionKeys, time, lerpVector) : position0;
            const Matrix transform = Matrix::CreateScale(Vector3(s.x, s.y, s.z)) * Matrix::CreateFromQuaternion(Quaternion(r.x, r.y, r.z, r.w)) *
                                     Matrix::CreateTranslation(Vector3(p.x, p.y, p.z));
            clip.Keyframes.push_back({bone, time / ticks, transform});
        }
    }
    std::stable_sort(clip.Keyframes.begin(), clip.Keyframes.end(), [](const Keyframe& a, const Keyframe& b) { return a.Time < b.Time; });
    return clip;
}

SkinningData AssimpSkin::finish() const {
    SkinningData data;
    for (std::size_t b = 0; b < skeleton_.size(); ++b) {
        const std::size_t node = std::size_t(skeleton_[b]);
        data.BindPose.push_back(assimpToXna(nodes_[node]->mTransformation));
        auto offset = offsets_.find(int(b));
        data.InverseBindPose.push_back(offset != offsets_.end() ? offset->second : Matrix::Invert(absoluteBind_[node]));
        const int parent = parents_[node];
        data.SkeletonHierarchy.push_back(parent < 0 ? -1 : skeletonIndex_.at(nodes_[std::size_t(parent)]));
        data.SkeletonModelBones.push_back(int(node));
    }
    for (unsigned a = 0; a < scene_.mNumAnimations; ++a) {
        AnimationClip clip = clipOf(*scene_.mAnimations[a], int(a));
        std::string name = clip.Name;
        for (int k = 2; data.AnimationClips.count(name); ++k) name = clip.Name + " (" + std::to_string(k) + ")";
        clip.Name = name;
        data.AnimationClips.emplace(name, std::move(clip));
    }
    return data;
}

}  // namespace fxport::detail
