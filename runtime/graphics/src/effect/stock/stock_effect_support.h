// What the five stock effects (BasicEffect, AlphaTestEffect, DualTextureEffect,
// EnvironmentMapEffect, SkinnedEffect) share on the C++ side: their embedded source, the
// permutation table, and turning the XNA properties (matrices, material, lights, fog) into the
// constants StockEffects.fxh declares. Internal to fxport_graphics; uses Effect's public API only.
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"

namespace fxport::detail {

// StockEffects.fxh followed by the effect's own text, each from its line 1 (#line), compiled as
// "<builtin>/<fileName>".
EffectSource stockEffectSource(const char* fileName, const char* effectText);

// The techniques of one stock effect, one per shader permutation, found once by name.
class StockPermutations {
public:
    StockPermutations(Effect& effect, const std::vector<std::string>& names);
    // Makes `index` the effect's CurrentTechnique and returns its (only) pass.
    EffectPass& select(Effect& effect, int index);

private:
    std::vector<EffectTechnique*> techniques_;
};

// Sets a parameter when the effect has it (the common constants not every effect reads are still
// declared by StockEffects.fxh, so a missing one means a renamed constant: that throws).
class StockConstants {
public:
    explicit StockConstants(Effect& effect);

    // WorldViewProj, World, WorldInverseTranspose, EyePosition (the inverse view's translation).
    void setMatrices(const IEffectMatrices& matrices);
    // DiffuseColor/EmissiveColor premultiplied as XNA does: lit -> (diffuse * alpha, alpha) and
    // (emissive + ambient * diffuse) * alpha; unlit -> ((diffuse + emissive) * alpha, alpha).
    void setMaterial(Vector3 diffuse, Vector3 emissive, Vector3 ambient, float alpha, bool lit);
    void setSpecular(Vector3 color, float power);
    // The three lights; a disabled one is sent black.
    void setLights(const IEffectLights& lights);
    // FogVector from World * View: dot(position, FogVector) = (depth - start) / (end - start);
    // start == end fogs everything (XNA).
    void setFog(const IEffectFog& fog, const IEffectMatrices& matrices);

private:
    EffectParameter& worldViewProj_;
    EffectParameter& world_;
    EffectParameter& worldInverseTranspose_;
    EffectParameter& eyePosition_;
    EffectParameter& diffuseColor_;
    EffectParameter& emissiveColor_;
    EffectParameter& specularColor_;
    EffectParameter& specularPower_;
    EffectParameter* lightDirection_[3];
    EffectParameter* lightDiffuse_[3];
    EffectParameter* lightSpecular_[3];
    EffectParameter& fogVector_;
    EffectParameter& fogColor_;
};

}  // namespace fxport::detail
