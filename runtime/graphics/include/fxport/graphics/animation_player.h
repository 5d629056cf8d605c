// AnimationPlayer: XNA's SkinnedModel sample's player. Update(time) applies every keyframe of the
// current clip up to `time` (keys hold until the next one, as the sample does: no interpolation),
// then computes each skeleton bone's local (GetBoneTransforms), model-space times rootTransform
// (GetWorldTransforms) and skinning matrix, InverseBindPose * world (GetSkinTransforms: what
// SkinnedEffect::SetBoneTransforms takes).
#pragma once

#include <vector>

#include "fxport/graphics/skinning_data.h"

namespace fxport {

class AnimationPlayer {
public:
    // Throws ArgumentError when the data's arrays disagree in length or a parent does not precede
    // its child. Keeps a reference: `data` must outlive the player.
    explicit AnimationPlayer(const SkinningData& data);

    // Starts `clip` at time 0 (the bind pose, then its keyframes at time 0). Keeps a reference.
    // Throws ArgumentError when a keyframe names a bone outside the skeleton.
    void StartClip(const AnimationClip& clip);

    // Advances to `time` seconds (relativeToCurrentTime: that much past the current time, wrapping
    // past the clip's end). Throws InvalidOperation without a clip and ArgumentError when an absolute
    // time is outside [0, Duration) (Duration itself is allowed for a clip of one instant).
    void Update(double time, bool relativeToCurrentTime, const Matrix& rootTransform);

    const AnimationClip* CurrentClip() const { return clip_; }
    double CurrentTime() const { return time_; }
    const std::vector<Matrix>& GetBoneTransforms() const { return bones_; }
    const std::vector<Matrix>& GetWorldTransforms() const { return world_; }
    const std::vector<Matrix>& GetSkinTransforms() const { return skin_; }

private:
    const SkinningData& data_;
    const AnimationClip* clip_ = nullptr;
    double time_ = 0;
    std::size_t keyframe_ = 0;
    std::vector<Matrix> bones_, world_, skin_;
};

}  // namespace fxport
