// XNA's SkinnedModel sample's AnimationPlayer (see animation_player.h).
#include "fxport/graphics/animation_player.h"

#include <cmath>
#include <string>

#include "fxport/graphics/errors.h"

namespace fxport {

AnimationPlayer::AnimationPlayer(const SkinningData& data) : data_(data) {
    const std::size_t n = data.BindPose.size();
    if (data.InverseBindPose.size() != n || data.SkeletonHierarchy.size() != n)
        throw ArgumentError("AnimationPlayer: SkinningData has " + std::to_string(n) + " bind-pose matrices, " +
                            std::to_string(data.InverseBindPose.size()) + " inverse bind-pose matrices and " +
                            std::to_string(data.SkeletonHierarchy.size()) + " parents; they must agree");
    for (std::size_t b = 0; b < n; ++b)
        if (data.SkeletonHierarchy[b] >= int(b) || (b > 0 && data.SkeletonHierarchy[b] < 0))
            throw ArgumentError("AnimationPlayer: skeleton bone " + std::to_string(b) + " has parent " +
                                std::to_string(data.SkeletonHierarchy[b]) + "; bone 0 is the root and parents come first");
    bones_ = data.BindPose;
    world_.resize(n);
    skin_.resize(n);
}

void AnimationPlayer::StartClip(const AnimationClip& clip) {
    for (const Keyframe& key : clip.Keyframes)
        if (key.Bone < 0 || std::size_t(key.Bone) >= bones_.size())
            throw ArgumentError("AnimationPlayer::StartClip('" + clip.Name + "'): a keyframe names bone " + std::to_string(key.Bone) +
                                " of a skeleton of " + std::to_string(bones_.size()));
    clip_ = &clip;
    time_ = 0;
    keyframe_ = 0;
    bones_ = data_.BindPose;
}

void AnimationPlayer::Update(double time, bool relativeToCurrentTime, const Matrix& rootTransform) {
    if (!clip_) throw InvalidOperation("AnimationPlayer::Update: no clip started (call StartClip first)");
    const double duration = clip_->Duration;
    if (relativeToCurrentTime) {
        time += time_;
        if (duration > 0) {
            time = std::fmod(time, duration);  // the sample's `while (time >= duration) time -= duration`
            if (time < 0) time += duration;
        } else {
            time = 0;
        }
    }
    if (!(time >= 0 && (time < duration || time == duration)))
        throw ArgumentError("AnimationPlayer::Update: time " + std::to_string(time) + " s is outside clip '" + clip_->Name +
                            "' (0 to " + std::to_string(duration) + " s)");
    if (time < time_) {  // going back: replay from the bind pose
        keyframe_ = 0;
        bones_ = data_.BindPose;
    }
    time_ = time;
    for (; keyframe_ < clip_->Keyframes.size() && clip_->Keyframes[keyframe_].Time <= time_; ++keyframe_)
        bones_[std::size_t(clip_->Keyframes[keyframe_].Bone)] = clip_->Keyframes[keyframe_].Transform;

    for (std::size_t b = 0; b < bones_.size(); ++b) {
        const int parent = data_.SkeletonHierarchy[b];
        world_[b] = bones_[b] * (parent < 0 ? rootTransform : world_[std::size_t(parent)]);
        skin_[b] = data_.InverseBindPose[b] * world_[b];
    }
}

}  // namespace fxport
