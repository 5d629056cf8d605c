// AlphaTestEffect: XNA's properties -> one of AlphaTestEffect.fx's 8 permutations and the
// AlphaTest vector that encodes the comparison.
#include "fxport/graphics/alpha_test_effect.h"

#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"
#include "fxport_generated/alpha_test_effect_source.h"  // runtime/graphics/shaders/AlphaTestEffect.fx
#include "effect/stock/stock_effect_support.h"

namespace fxport {

namespace {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (int compare = 0; compare < 2; ++compare)
            for (int color = 0; color < 2; ++color)
                for (int fog = 0; fog < 2; ++fog)
                    out.push_back("AlphaTestEffect_C" + std::to_string(compare) + "_V" + std::to_string(color) + "_F" +
                                  std::to_string(fog));
        return out;
    }();
    return names;
}

bool comparesEquality(CompareFunction f) { return f == CompareFunction::Equal || f == CompareFunction::NotEqual; }

}  // namespace

AlphaTestEffect::AlphaTestEffect(GraphicsDevice& device)
    : Effect(device, detail::stockEffectSource("AlphaTestEffect.fx", detail::kAlphaTestEffectSource)),
      permutations_(std::make_unique<detail::StockPermutations>(*this, techniqueNames())),
      constants_(std::make_unique<detail::StockConstants>(*this)) {
    Name = "AlphaTestEffect";
    CurrentTechnique = Techniques[techniqueNames()[std::size_t(permutation())]];
}

std::unique_ptr<Effect> AlphaTestEffect::Clone() {
    auto clone = std::make_unique<AlphaTestEffect>(device());
    copyValuesTo(*clone);
    clone->IEffectMatrices::operator=(*this);
    clone->IEffectFog::operator=(*this);
    clone->DiffuseColor = DiffuseColor;
    clone->Alpha = Alpha;
    clone->AlphaFunction = AlphaFunction;
    clone->ReferenceAlpha = ReferenceAlpha;
    clone->Texture = Texture;
    clone->VertexColorEnabled = VertexColorEnabled;
    return clone;
}

AlphaTestEffect::~AlphaTestEffect() = default;

int AlphaTestEffect::permutation() const {
    return ((comparesEquality(AlphaFunction) ? 1 : 0) * 2 + (VertexColorEnabled ? 1 : 0)) * 2 + (FogEnabled ? 1 : 0);
}

std::string AlphaTestEffect::PermutationName() const { return techniqueNames()[std::size_t(permutation())]; }

EffectPass& AlphaTestEffect::OnApply(EffectPass&) {
    if (ReferenceAlpha < 0 || ReferenceAlpha > 255)
        throw ArgumentError("AlphaTestEffect.ReferenceAlpha = " + std::to_string(ReferenceAlpha) +
                            ": must be 0..255");
    constants_->setMatrices(*this);
    constants_->setMaterial(DiffuseColor, Vector3(0, 0, 0), Vector3(0, 0, 0), Alpha, false);
    if (FogEnabled) constants_->setFog(*this, *this);
    Parameters["Texture"].SetValue(Texture);

    // AlphaTest = (threshold, equality band, sign when the test holds, sign when it does not); the
    // shader keeps the pixel when the chosen sign is positive (see AlphaTestEffect.fx).
    const float reference = float(ReferenceAlpha) / 255.0f;
    const float band = 0.5f / 255.0f;
    Vector4 test;
    switch (AlphaFunction) {
    case CompareFunction::Less: test = Vector4(reference - band, 0, 1, -1); break;
    case CompareFunction::LessEqual: test = Vector4(reference + band, 0, 1, -1); break;
    case CompareFunction::GreaterEqual: test = Vector4(reference - band, 0, -1, 1); break;
    case CompareFunction::Greater: test = Vector4(reference + band, 0, -1, 1); break;
    case CompareFunction::Equal: test = Vector4(reference, band, 1, -1); break;
    case CompareFunction::NotEqual: test = Vector4(reference, band, -1, 1); break;
    case CompareFunction::Always: test = Vector4(0, 0, 1, 1); break;
    case CompareFunction::Never: test = Vector4(0, 0, -1, -1); break;
    }
    Parameters["AlphaTest"].SetValue(test);
    return permutations_->select(*this, permutation());
}

}  // namespace fxport
