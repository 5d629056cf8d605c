// EnvironmentMapEffect: XNA's properties -> one of EnvironmentMapEffect.fx's 8 permutations.
#include "fxport/graphics/environment_map_effect.h"

#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"
#include "fxport_generated/environment_map_effect_source.h"  // runtime/graphics/shaders/EnvironmentMapEffect.fx
#include "effect/stock/stock_effect_support.h"

namespace fxport {

namespace {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (int fresnel = 0; fresnel < 2; ++fresnel)
            for (int specular = 0; specular < 2; ++specular)
                for (int fog = 0; fog < 2; ++fog)
                    out.push_back("EnvironmentMapEffect_R" + std::to_string(fresnel) + "_S" + std::to_string(specular) +
                                  "_F" + std::to_string(fog));
        return out;
    }();
    return names;
}

}  // namespace

EnvironmentMapEffect::EnvironmentMapEffect(GraphicsDevice& device)
    : Effect(device, detail::stockEffectSource("EnvironmentMapEffect.fx", detail::kEnvironmentMapEffectSource)),
      permutations_(std::make_unique<detail::StockPermutations>(*this, techniqueNames())),
      constants_(std::make_unique<detail::StockConstants>(*this)) {
    Name = "EnvironmentMapEffect";
    LightingEnabled = true;
    DirectionalLight0.Enabled = true;
    CurrentTechnique = Techniques[techniqueNames()[std::size_t(permutation())]];
}

std::unique_ptr<Effect> EnvironmentMapEffect::Clone() {
    auto clone = std::make_unique<EnvironmentMapEffect>(device());
    copyValuesTo(*clone);
    clone->IEffectMatrices::operator=(*this);
    clone->IEffectLights::operator=(*this);
    clone->IEffectFog::operator=(*this);
    clone->DiffuseColor = DiffuseColor;
    clone->EmissiveColor = EmissiveColor;
    clone->Alpha = Alpha;
    clone->Texture = Texture;
    clone->EnvironmentMap = EnvironmentMap;
    clone->EnvironmentMapAmount = EnvironmentMapAmount;
    clone->EnvironmentMapSpecular = EnvironmentMapSpecular;
    clone->FresnelFactor = FresnelFactor;
    return clone;
}

EnvironmentMapEffect::~EnvironmentMapEffect() = default;

int EnvironmentMapEffect::permutation() const {
    const bool specular = EnvironmentMapSpecular != Vector3(0, 0, 0);
    return ((FresnelFactor != 0 ? 1 : 0) * 2 + (specular ? 1 : 0)) * 2 + (FogEnabled ? 1 : 0);
}

std::string EnvironmentMapEffect::PermutationName() const { return techniqueNames()[std::size_t(permutation())]; }

EffectPass& EnvironmentMapEffect::OnApply(EffectPass&) {
    if (!LightingEnabled)
        throw InvalidOperation("EnvironmentMapEffect.LightingEnabled = false: the effect is always lit (as in XNA)");
    constants_->setMatrices(*this);
    constants_->setMaterial(DiffuseColor, EmissiveColor, AmbientLightColor, Alpha, true);
    constants_->setLights(*this);
    if (FogEnabled) constants_->setFog(*this, *this);
    Parameters["Texture"].SetValue(Texture);
    Parameters["EnvironmentMap"].SetValue(EnvironmentMap);
    Parameters["EnvironmentMapAmount"].SetValue(EnvironmentMapAmount);
    Parameters["EnvironmentMapSpecular"].SetValue(EnvironmentMapSpecular);
    Parameters["FresnelFactor"].SetValue(FresnelFactor);
    return permutations_->select(*this, permutation());
}

}  // namespace fxport
