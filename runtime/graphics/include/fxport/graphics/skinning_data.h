// SkinningData: what XNA's SkinnedModel sample keeps in Model.Tag -- the skeleton's bind pose,
// inverse bind pose and hierarchy, and the animation clips as keyframes per bone -- filled by
// Model::Load from a file's skin weights and animations (assimp_skin.cpp; see model.h) and played
// by AnimationPlayer (animation_player.h).
//
//   auto* skinning = std::any_cast<SkinningData>(&model->Tag);   // C#: model.Tag as SkinningData
//   AnimationPlayer player(*skinning);
//   player.StartClip(skinning->AnimationClips.at("Walk"));
//   player.Update(elapsedSeconds, true, Matrix::Identity);
//   effect->SetBoneTransforms(player.GetSkinTransforms());
//
// Skeleton bone i is not Model::Bones[i]: SkeletonModelBones[i] names the model bone it stands for.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport {

// One bone's local transform (relative to its skeleton parent) from Time on.
struct Keyframe {
    int Bone = 0;      // skeleton bone index
    double Time = 0;   // seconds from the clip's start
    Matrix Transform = Matrix::Identity;
};

struct AnimationClip {
    std::string Name;
    double Duration = 0;              // seconds
    std::vector<Keyframe> Keyframes;  // sorted by Time (stable: a bone's keys keep their order)
};

struct SkinningData {
    std::map<std::string, AnimationClip> AnimationClips;
    std::vector<Matrix> BindPose;         // local transform of each skeleton bone at bind time
    std::vector<Matrix> InverseBindPose;  // mesh space -> bone space at bind time
    std::vector<int> SkeletonHierarchy;   // parent skeleton bone, -1 for the root (parents first)
    std::vector<int> SkeletonModelBones;  // fxport: the Model::Bones index of each skeleton bone
};

}  // namespace fxport
