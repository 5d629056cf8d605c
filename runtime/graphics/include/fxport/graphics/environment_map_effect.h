// EnvironmentMapEffect: XNA 4's EnvironmentMapEffect: a texture lit per vertex by the three
// directional lights (diffuse only) and blended with a cube map seen in the reflected view
// direction (chrome, water, glossy paint). Always lit: Apply throws InvalidOperation when
// LightingEnabled is false (XNA's setter refuses it). Public fields read at each Apply (see
// effect_interfaces.h); 8 permutations in runtime/graphics/shaders/EnvironmentMapEffect.fx
// (Fresnel on when FresnelFactor != 0, specular on when EnvironmentMapSpecular != 0, fog).
//
//   colour = Texture(uv) * (lit diffuse (as BasicEffect's, per vertex), Alpha)
//   env    = EnvironmentMap(reflect(-toEye, N)) * colour.a
//   colour.rgb = lerp(colour.rgb, env.rgb, EnvironmentMapAmount [* pow(1 - |toEye.N|, FresnelFactor)])
//   colour.rgb += EnvironmentMapSpecular * env.a; then fog
// Texture is sampled through register s0, EnvironmentMap through s1.
#pragma once

#include <memory>
#include <string>

#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;
class TextureCube;

namespace detail {
class StockPermutations;
class StockConstants;
}  // namespace detail

class EnvironmentMapEffect : public Effect, public IEffectMatrices, public IEffectLights, public IEffectFog {
public:
    // Defaults as XNA: lighting on with DirectionalLight0 enabled, amount 1, no specular, Fresnel 1.
    explicit EnvironmentMapEffect(fxport::GraphicsDevice& device);
    ~EnvironmentMapEffect() override;
    // XNA's Clone: a EnvironmentMapEffect with these properties and the parameter values.
    std::unique_ptr<Effect> Clone() override;

    Vector3 DiffuseColor = Vector3(1, 1, 1);
    Vector3 EmissiveColor = Vector3(0, 0, 0);
    float Alpha = 1;
    fxport::Texture2D* Texture = nullptr;           // not owned
    fxport::TextureCube* EnvironmentMap = nullptr;  // not owned
    float EnvironmentMapAmount = 1;
    Vector3 EnvironmentMapSpecular = Vector3(0, 0, 0);
    float FresnelFactor = 1;

    // fxport: the technique the current properties select.
    std::string PermutationName() const;

protected:
    EffectPass& OnApply(EffectPass& pass) override;

private:
    int permutation() const;
    std::unique_ptr<detail::StockPermutations> permutations_;
    std::unique_ptr<detail::StockConstants> constants_;
};

}  // namespace fxport
