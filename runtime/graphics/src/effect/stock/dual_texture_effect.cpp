// DualTextureEffect: XNA's properties -> one of DualTextureEffect.fx's 4 permutations.
#include "fxport/graphics/dual_texture_effect.h"

#include "fxport/graphics/texture.h"
#include "fxport_generated/dual_texture_effect_source.h"  // runtime/graphics/shaders/DualTextureEffect.fx
#include "effect/stock/stock_effect_support.h"

namespace fxport {

namespace {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = {"DualTextureEffect_V0_F0", "DualTextureEffect_V0_F1",
                                                   "DualTextureEffect_V1_F0", "DualTextureEffect_V1_F1"};
    return names;
}

}  // namespace

DualTextureEffect::DualTextureEffect(GraphicsDevice& device)
    : Effect(device, detail::stockEffectSource("DualTextureEffect.fx", detail::kDualTextureEffectSource)),
      permutations_(std::make_unique<detail::StockPermutations>(*this, techniqueNames())),
      constants_(std::make_unique<detail::StockConstants>(*this)) {
    Name = "DualTextureEffect";
    CurrentTechnique = Techniques[techniqueNames()[std::size_t(permutation())]];
}

std::unique_ptr<Effect> DualTextureEffect::Clone() {
    auto clone = std::make_unique<DualTextureEffect>(device());
    copyValuesTo(*clone);
    clone->IEffectMatrices::operator=(*this);
    clone->IEffectFog::operator=(*this);
    clone->DiffuseColor = DiffuseColor;
    clone->Alpha = Alpha;
    clone->Texture = Texture;
    clone->Texture2 = Texture2;
    clone->VertexColorEnabled = VertexColorEnabled;
    return clone;
}

DualTextureEffect::~DualTextureEffect() = default;

int DualTextureEffect::permutation() const { return (VertexColorEnabled ? 2 : 0) + (FogEnabled ? 1 : 0); }

std::string DualTextureEffect::PermutationName() const { return techniqueNames()[std::size_t(permutation())]; }

EffectPass& DualTextureEffect::OnApply(EffectPass&) {
    constants_->setMatrices(*this);
    constants_->setMaterial(DiffuseColor, Vector3(0, 0, 0), Vector3(0, 0, 0), Alpha, false);
    if (FogEnabled) constants_->setFog(*this, *this);
    Parameters["Texture"].SetValue(Texture);
    Parameters["Texture2"].SetValue(Texture2);
    return permutations_->select(*this, permutation());
}

}  // namespace fxport
