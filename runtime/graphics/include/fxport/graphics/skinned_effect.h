// SkinnedEffect: XNA 4's SkinnedEffect: BasicEffect's textured lighting (per vertex, or per pixel
// with PreferPerPixelLighting) on vertices skinned by up to 72 bones with 1, 2 or 4 weights each.
// Always lit (Apply throws InvalidOperation when LightingEnabled is false, as XNA's setter refuses
// it). Public fields read at each Apply (see effect_interfaces.h); 12 permutations in
// runtime/graphics/shaders/SkinnedEffect.fx.
//
//   skin = sum_{i < WeightsPerVertex} BoneTransforms[BLENDINDICES0[i]] * BLENDWEIGHT0[i]
//   position = position * skin, normal = normal * (3x3 of skin), then BasicEffect's lit equations
// Vertices need POSITION0, NORMAL0, TEXCOORD0, BLENDINDICES0 (Byte4) and BLENDWEIGHT0 (Vector4).
// Bone matrices are affine: their fourth column is ignored (the shader keeps a 4x3 per bone).
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;

namespace detail {
class StockPermutations;
class StockConstants;
}  // namespace detail

class SkinnedEffect : public Effect, public IEffectMatrices, public IEffectLights, public IEffectFog {
public:
    static constexpr int MaxBones = 72;

    // Defaults as XNA: lighting on with DirectionalLight0 enabled, white specular of power 16,
    // 4 weights per vertex, every bone the identity.
    explicit SkinnedEffect(fxport::GraphicsDevice& device);
    ~SkinnedEffect() override;
    // XNA's Clone: a SkinnedEffect with these properties and the parameter values.
    std::unique_ptr<Effect> Clone() override;

    Vector3 DiffuseColor = Vector3(1, 1, 1);
    Vector3 EmissiveColor = Vector3(0, 0, 0);
    Vector3 SpecularColor = Vector3(1, 1, 1);
    float SpecularPower = 16;
    float Alpha = 1;
    bool PreferPerPixelLighting = false;
    fxport::Texture2D* Texture = nullptr;  // not owned; sampled through register s0
    int WeightsPerVertex = 4;              // 1, 2 or 4; anything else makes Apply throw ArgumentError

    // Bones 0 .. size-1; throws ArgumentError beyond MaxBones. The others keep their matrices.
    void SetBoneTransforms(std::span<const Matrix> boneTransforms);
    void SetBoneTransforms(const std::vector<Matrix>& boneTransforms) {
        SetBoneTransforms(std::span<const Matrix>(boneTransforms));
    }
    // The first `count` bone matrices (throws ArgumentError when count is outside 0..MaxBones).
    std::vector<Matrix> GetBoneTransforms(int count) const;

    // fxport: the technique the current properties select.
    std::string PermutationName() const;

protected:
    EffectPass& OnApply(EffectPass& pass) override;

private:
    int permutation() const;
    std::array<Matrix, MaxBones> bones_;
    bool bonesChanged_ = true;
    std::unique_ptr<detail::StockPermutations> permutations_;
    std::unique_ptr<detail::StockConstants> constants_;
};

}  // namespace fxport
