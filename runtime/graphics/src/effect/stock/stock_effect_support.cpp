// The stock effects' shared C++ side (see stock_effect_support.h).
#include "effect/stock/stock_effect_support.h"

#include <string>

#include "fxport_generated/stock_effects_source.h"  // runtime/graphics/shaders/StockEffects.fxh

namespace fxport::detail {

EffectSource stockEffectSource(const char* fileName, const char* effectText) {
    EffectSource source;
    source.virtualPath = std::string("<builtin>/") + fileName;
    source.text = std::string("#line 1 \"StockEffects.fxh\"\n") + kStockEffectsSource + "\n#line 1 \"" + fileName +
                  "\"\n" + effectText;
    return source;
}

StockPermutations::StockPermutations(Effect& effect, const std::vector<std::string>& names) {
    for (const std::string& name : names) techniques_.push_back(effect.Techniques[name]);
}

EffectPass& StockPermutations::select(Effect& effect, int index) {
    effect.CurrentTechnique = techniques_[std::size_t(index)];
    return effect.CurrentTechnique->Passes[0];
}

StockConstants::StockConstants(Effect& effect)
    : worldViewProj_(effect.Parameters["WorldViewProj"]),
      world_(effect.Parameters["World"]),
      worldInverseTranspose_(effect.Parameters["WorldInverseTranspose"]),
      eyePosition_(effect.Parameters["EyePosition"]),
      diffuseColor_(effect.Parameters["DiffuseColor"]),
      emissiveColor_(effect.Parameters["EmissiveColor"]),
      specularColor_(effect.Parameters["SpecularColor"]),
      specularPower_(effect.Parameters["SpecularPower"]),
      fogVector_(effect.Parameters["FogVector"]),
      fogColor_(effect.Parameters["FogColor"]) {
    for (int i = 0; i < 3; ++i) {
        const std::string light = "DirLight" + std::to_string(i);
        lightDirection_[i] = &effect.Parameters[light + "Direction"];
        lightDiffuse_[i] = &effect.Parameters[light + "DiffuseColor"];
        lightSpecular_[i] = &effect.Parameters[light + "SpecularColor"];
    }
}

void StockConstants::setMatrices(const IEffectMatrices& m) {
    worldViewProj_.SetValue(m.World * m.View * m.Projection);
    world_.SetValue(m.World);
    worldInverseTranspose_.SetValue(Matrix::Transpose(Matrix::Invert(m.World)));
    eyePosition_.SetValue(Matrix::Invert(m.View).Translation());
}

void StockConstants::setMaterial(Vector3 diffuse, Vector3 emissive, Vector3 ambient, float alpha, bool lit) {
    if (lit) {
        diffuseColor_.SetValue(Vector4(diffuse * alpha, alpha));
        emissiveColor_.SetValue((emissive + ambient * diffuse) * alpha);
    } else {
        diffuseColor_.SetValue(Vector4((diffuse + emissive) * alpha, alpha));
        emissiveColor_.SetValue(Vector3(0, 0, 0));
    }
}

void StockConstants::setSpecular(Vector3 color, float power) {
    specularColor_.SetValue(color);
    specularPower_.SetValue(power);
}

void StockConstants::setLights(const IEffectLights& lights) {
    const DirectionalLight* all[3] = {&lights.DirectionalLight0, &lights.DirectionalLight1, &lights.DirectionalLight2};
    for (int i = 0; i < 3; ++i) {
        const DirectionalLight& light = *all[i];
        lightDirection_[i]->SetValue(light.Direction);
        lightDiffuse_[i]->SetValue(light.Enabled ? light.DiffuseColor : Vector3(0, 0, 0));
        lightSpecular_[i]->SetValue(light.Enabled ? light.SpecularColor : Vector3(0, 0, 0));
    }
}

void StockConstants::setFog(const IEffectFog& fog, const IEffectMatrices& m) {
    fogColor_.SetValue(fog.FogColor);
    if (fog.FogStart == fog.FogEnd) {
        fogVector_.SetValue(Vector4(0, 0, 0, 1));
        return;
    }
    // View-space z of an object-space point p is p . (M13, M23, M33) + M43 of World * View; the
    // depth in front of the camera is its negation.
    const Matrix worldView = m.World * m.View;
    const float scale = 1.0f / (fog.FogEnd - fog.FogStart);
    fogVector_.SetValue(Vector4(-worldView.M13 * scale, -worldView.M23 * scale, -worldView.M33 * scale,
                                (-worldView.M43 - fog.FogStart) * scale));
}

}  // namespace fxport::detail
