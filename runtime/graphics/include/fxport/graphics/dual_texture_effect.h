// DualTextureEffect: XNA 4's DualTextureEffect: two textures with their own texture coordinates
// (TEXCOORD0, TEXCOORD1), the second modulating the first at twice its value (light maps, detail
// textures: a mid-grey Texture2 leaves Texture unchanged). Unlit, optional vertex colour and fog.
// Public fields read at each Apply (see effect_interfaces.h); 4 permutations in
// runtime/graphics/shaders/DualTextureEffect.fx.
//
//   diffuse = saturate((DiffuseColor * Alpha, Alpha) [* vertex colour])   (per vertex)
//   colour  = Texture(uv0) * (2, 2, 2, 1) * Texture2(uv1) * diffuse; then fog
// All four channels of Texture2 multiply, its alpha too, as in XNA's shader.
// Texture is sampled through register s0, Texture2 through s1 (GraphicsDevice::SamplerStates[0/1]).
#pragma once

#include <memory>
#include <string>

#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;

namespace detail {
class StockPermutations;
class StockConstants;
}  // namespace detail

class DualTextureEffect : public Effect, public IEffectMatrices, public IEffectFog {
public:
    explicit DualTextureEffect(fxport::GraphicsDevice& device);
    ~DualTextureEffect() override;
    // XNA's Clone: a DualTextureEffect with these properties and the parameter values.
    std::unique_ptr<Effect> Clone() override;

    Vector3 DiffuseColor = Vector3(1, 1, 1);
    float Alpha = 1;
    fxport::Texture2D* Texture = nullptr;   // not owned
    fxport::Texture2D* Texture2 = nullptr;  // not owned
    bool VertexColorEnabled = false;

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
