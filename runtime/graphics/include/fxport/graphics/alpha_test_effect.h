// AlphaTestEffect: XNA 4's AlphaTestEffect: a textured, unlit effect (optional vertex colour and
// fog) that discards each pixel whose alpha fails `alpha AlphaFunction ReferenceAlpha / 255`
// (cut-out foliage, fences, sprites without sorting). Properties are public fields read at each
// Apply (see effect_interfaces.h); 8 permutations in runtime/graphics/shaders/AlphaTestEffect.fx.
//
//   colour = Texture(uv) * (DiffuseColor * Alpha, Alpha) [* vertex colour]; kept when it passes; fog.
// The comparison is made on the shaded alpha, within half an 8-bit step: Equal keeps
// |alpha - ref| < 0.5/255, Less keeps alpha < ref - 0.5/255, LessEqual alpha < ref + 0.5/255,
// Greater and GreaterEqual their complements; Always keeps every pixel, Never none.
// ReferenceAlpha outside 0..255 makes Apply throw ArgumentError.
#pragma once

#include <memory>
#include <string>

#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;

namespace detail {
class StockPermutations;
class StockConstants;
}  // namespace detail

class AlphaTestEffect : public Effect, public IEffectMatrices, public IEffectFog {
public:
    explicit AlphaTestEffect(fxport::GraphicsDevice& device);
    ~AlphaTestEffect() override;
    // XNA's Clone: a AlphaTestEffect with these properties and the parameter values.
    std::unique_ptr<Effect> Clone() override;

    Vector3 DiffuseColor = Vector3(1, 1, 1);
    float Alpha = 1;
    CompareFunction AlphaFunction = CompareFunction::Greater;
    int ReferenceAlpha = 0;
    fxport::Texture2D* Texture = nullptr;  // not owned; sampled through register s0
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
