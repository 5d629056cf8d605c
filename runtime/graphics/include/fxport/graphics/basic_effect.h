// BasicEffect: XNA 4's BasicEffect, the stock effect most XNA games draw with.
//
//   BasicEffect effect(device);
//   effect.World = world; effect.View = view; effect.Projection = projection;
//   effect.EnableDefaultLighting();
//   effect.TextureEnabled = true; effect.Texture = texture.get();
//   for (EffectPass& pass : effect.CurrentTechnique->Passes) { pass.Apply(); device.DrawIndexedPrimitives(...); }
//
// Properties are public fields (the rule of effect_interfaces.h): each Apply reads them, picks the
// shader permutation they need (lighting off / per vertex / per pixel x texture x vertex colour x
// fog: 24 techniques of runtime/graphics/shaders/BasicEffect.fx) and sets its constants. A
// permutation is compiled at its first Apply, so only the ones a program uses are ever compiled.
//
// What it computes (XNA's documented behaviour, in StockEffects.fxh):
//   unlit:  colour = ((DiffuseColor + EmissiveColor) * Alpha, Alpha) [* vertex colour] [* texel]
//   lit:    colour = (sum_i max(N.L_i, 0) * light_i.Diffuse * DiffuseColor
//                     + EmissiveColor + AmbientLightColor * DiffuseColor) * Alpha, alpha Alpha,
//           [* vertex colour] [* texel], then rgb += specular * colour.a with
//           specular = sum_i pow(max(N.H_i, 0), SpecularPower) * light_i.Specular * SpecularColor
//           (H = normalize(toEye - light direction); no highlight where N.L < 0). Per vertex
//           (Gouraud) unless PreferPerPixelLighting.
//   The per-vertex colours (the diffuse colour with vertex colour, and per vertex the highlight) are
//   clamped to [0, 1] before interpolation, as Direct3D 9 clamps XNA's vs_2_0 colour outputs.
//   fog:    rgb = lerp(rgb, FogColor * colour.a, saturate((depth - FogStart) / (FogEnd - FogStart))),
//           the factor computed per vertex from the view-space depth.
// Colours are premultiplied by Alpha (draw with BlendState::AlphaBlend, as in XNA). The texture is
// sampled through sampler register s0: GraphicsDevice::SamplerStates[0] decides filtering.
// Vertices need POSITION0, plus NORMAL0 when lit, TEXCOORD0 when textured, COLOR0 with vertex colour.
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

class BasicEffect : public Effect, public IEffectMatrices, public IEffectLights, public IEffectFog {
public:
    // Defaults as XNA: white diffuse, no emissive, white specular of power 16, opaque,
    // DirectionalLight0 enabled (white, pointing down -Z), lighting off.
    explicit BasicEffect(fxport::GraphicsDevice& device);
    ~BasicEffect() override;
    // XNA's Clone: a BasicEffect with these properties and the parameter values.
    std::unique_ptr<Effect> Clone() override;

    Vector3 DiffuseColor = Vector3(1, 1, 1);
    Vector3 EmissiveColor = Vector3(0, 0, 0);
    Vector3 SpecularColor = Vector3(1, 1, 1);
    float SpecularPower = 16;
    float Alpha = 1;
    bool PreferPerPixelLighting = false;
    bool TextureEnabled = false;
    fxport::Texture2D* Texture = nullptr;  // not owned; must outlive its use
    bool VertexColorEnabled = false;

    // fxport: the technique the current properties select (what the next Apply runs).
    std::string PermutationName() const;

protected:
    EffectPass& OnApply(EffectPass& pass) override;

private:
    int permutation() const;
    std::unique_ptr<detail::StockPermutations> permutations_;
    std::unique_ptr<detail::StockConstants> constants_;
};

}  // namespace fxport
