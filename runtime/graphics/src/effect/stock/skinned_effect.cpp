// SkinnedEffect: XNA's properties and bone palette -> one of SkinnedEffect.fx's 12 permutations.
#include "fxport/graphics/skinned_effect.h"

#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"
#include "fxport_generated/skinned_effect_source.h"  // runtime/graphics/shaders/SkinnedEffect.fx
#include "effect/stock/stock_effect_support.h"

namespace fxport {

namespace {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (int weights : {1, 2, 4})
            for (int perPixel = 0; perPixel < 2; ++perPixel)
                for (int fog = 0; fog < 2; ++fog)
                    out.push_back("SkinnedEffect_W" + std::to_string(weights) + "_P" + std::to_string(perPixel) + "_F" +
                                  std::to_string(fog));
        return out;
    }();
    return names;
}

}  // namespace

SkinnedEffect::SkinnedEffect(GraphicsDevice& device)
    : Effect(device, detail::stockEffectSource("SkinnedEffect.fx", detail::kSkinnedEffectSource)),
      permutations_(std::make_unique<detail::StockPermutations>(*this, techniqueNames())),
      constants_(std::make_unique<detail::StockConstants>(*this)) {
    Name = "SkinnedEffect";
    LightingEnabled = true;
    DirectionalLight0.Enabled = true;
    bones_.fill(Matrix::Identity);
    CurrentTechnique = Techniques[techniqueNames()[std::size_t(permutation())]];
}

std::unique_ptr<Effect> SkinnedEffect::Clone() {
    auto clone = std::make_unique<SkinnedEffect>(device());
    copyValuesTo(*clone);
    clone->IEffectMatrices::operator=(*this);
    clone->IEffectLights::operator=(*this);
    clone->IEffectFog::operator=(*this);
    clone->DiffuseColor = DiffuseColor;
    clone->EmissiveColor = EmissiveColor;
    clone->SpecularColor = SpecularColor;
    clone->SpecularPower = SpecularPower;
    clone->Alpha = Alpha;
    clone->PreferPerPixelLighting = PreferPerPixelLighting;
    clone->Texture = Texture;
    clone->WeightsPerVertex = WeightsPerVertex;
    clone->bones_ = bones_;
    return clone;
}

SkinnedEffect::~SkinnedEffect() = default;

void SkinnedEffect::SetBoneTransforms(std::span<const Matrix> boneTransforms) {
    if (boneTransforms.size() > std::size_t(MaxBones))
        throw ArgumentError("SkinnedEffect.SetBoneTransforms: " + std::to_string(boneTransforms.size()) +
                            " bones, at most " + std::to_string(MaxBones));
    std::copy(boneTransforms.begin(), boneTransforms.end(), bones_.begin());
    bonesChanged_ = true;
}

std::vector<Matrix> SkinnedEffect::GetBoneTransforms(int count) const {
    if (count < 0 || count > MaxBones)
        throw ArgumentError("SkinnedEffect.GetBoneTransforms(" + std::to_string(count) + "): count must be 0.." +
                            std::to_string(MaxBones));
    return std::vector<Matrix>(bones_.begin(), bones_.begin() + count);
}

int SkinnedEffect::permutation() const {
    const int weights = WeightsPerVertex == 1 ? 0 : WeightsPerVertex == 2 ? 1 : 2;
    return (weights * 2 + (PreferPerPixelLighting ? 1 : 0)) * 2 + (FogEnabled ? 1 : 0);
}

std::string SkinnedEffect::PermutationName() const { return techniqueNames()[std::size_t(permutation())]; }

EffectPass& SkinnedEffect::OnApply(EffectPass&) {
    if (WeightsPerVertex != 1 && WeightsPerVertex != 2 && WeightsPerVertex != 4)
        throw ArgumentError("SkinnedEffect.WeightsPerVertex = " + std::to_string(WeightsPerVertex) +
                            ": must be 1, 2 or 4");
    if (!LightingEnabled)
        throw InvalidOperation("SkinnedEffect.LightingEnabled = false: the effect is always lit (as in XNA)");
    constants_->setMatrices(*this);
    constants_->setMaterial(DiffuseColor, EmissiveColor, AmbientLightColor, Alpha, true);
    constants_->setSpecular(SpecularColor, SpecularPower);
    constants_->setLights(*this);
    if (FogEnabled) constants_->setFog(*this, *this);
    Parameters["Texture"].SetValue(Texture);
    if (bonesChanged_) {
        Parameters["Bones"].SetValue(std::span<const Matrix>(bones_));
        bonesChanged_ = false;
    }
    return permutations_->select(*this, permutation());
}

}  // namespace fxport
