// BasicEffect: XNA's properties -> one of BasicEffect.fx's 24 permutations and its constants.
#include "fxport/graphics/basic_effect.h"

#include "fxport/graphics/texture.h"
#include "fxport_generated/basic_effect_source.h"  // runtime/graphics/shaders/BasicEffect.fx
#include "effect/stock/stock_effect_support.h"

namespace fxport {

namespace {

// Technique index = ((lighting * 2 + texture) * 2 + vertex colour) * 2 + fog, as the .fx lists them.
std::vector<std::string> basicEffectTechniques() {
    std::vector<std::string> names;
    for (int lighting = 0; lighting < 3; ++lighting)
        for (int texture = 0; texture < 2; ++texture)
            for (int color = 0; color < 2; ++color)
                for (int fog = 0; fog < 2; ++fog)
                    names.push_back("BasicEffect_L" + std::to_string(lighting) + "_T" + std::to_string(texture) + "_V" +
                                    std::to_string(color) + "_F" + std::to_string(fog));
    return names;
}

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = basicEffectTechniques();
    return names;
}

}  // namespace

BasicEffect::BasicEffect(GraphicsDevice& device)
    : Effect(device, detail::stockEffectSource("BasicEffect.fx", detail::kBasicEffectSource)),
      permutations_(std::make_unique<detail::StockPermutations>(*this, techniqueNames())),
      constants_(std::make_unique<detail::StockConstants>(*this)) {
    Name = "BasicEffect";
    DirectionalLight0.Enabled = true;
    CurrentTechnique = Techniques[techniqueNames()[std::size_t(permutation())]];
}

std::unique_ptr<Effect> BasicEffect::Clone() {
    auto clone = std::make_unique<BasicEffect>(device());
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
    clone->TextureEnabled = TextureEnabled;
    clone->Texture = Texture;
    clone->VertexColorEnabled = VertexColorEnabled;
    return clone;
}

BasicEffect::~BasicEffect() = default;

int BasicEffect::permutation() const {
    const int lighting = LightingEnabled ? (PreferPerPixelLighting ? 2 : 1) : 0;
    return ((lighting * 2 + (TextureEnabled ? 1 : 0)) * 2 + (VertexColorEnabled ? 1 : 0)) * 2 + (FogEnabled ? 1 : 0);
}

std::string BasicEffect::PermutationName() const { return techniqueNames()[std::size_t(permutation())]; }

EffectPass& BasicEffect::OnApply(EffectPass&) {
    constants_->setMatrices(*this);
    constants_->setMaterial(DiffuseColor, EmissiveColor, AmbientLightColor, Alpha, LightingEnabled);
    if (LightingEnabled) {
        constants_->setSpecular(SpecularColor, SpecularPower);
        constants_->setLights(*this);
    }
    if (FogEnabled) constants_->setFog(*this, *this);
    if (TextureEnabled) Parameters["Texture"].SetValue(Texture);
    return permutations_->select(*this, permutation());
}

}  // namespace fxport
