// hlsl/xna-deferred/GBuffer.fx drawn as the deferred demo draws a mesh part, for one quad whose
// vertex normal/tangent/binormal the case chooses (zero-length, denormal ...), into three targets.
#pragma once

#include <memory>
#include <string>

#include "fxport/graphics.h"
#include "stability/stability_cases.h"

namespace fxport::stability {

struct GBufferQuad {
    // A quad filling the view: its corners at view depth `distance`, half-size `halfExtent`,
    // in the plane z = -distance of the camera at the origin looking down -z (View = identity).
    double distance = 5;
    double halfExtent = 10;
    Vector3 normal = Vector3(0, 0, 1), tangent = Vector3(1, 0, 0), binormal = Vector3(0, 1, 0);
    Matrix projection;
    SurfaceFormat normalFormat = SurfaceFormat::Vector4;  // the tutorial's: Rgba64
    float specularIntensity = 0.5f, specularPower = 0.2f;  // SpecularMap's x (albedo.w), y (normals.w = power / 255)
};

struct GBufferTargets {
    std::unique_ptr<RenderTarget2D> albedo, normals, depth;  // depth: Vector2 (z/w, view z), the tutorial's
};

// Draws the quad with GBuffer.fx (Texture white, NormalMap the flat (0.5, 0.5, 1), SpecularMap as
// given, all 1x1 float textures) into size x size targets; FiniteCheck names the pass "GBuffer".
GBufferTargets drawGBufferQuad(GraphicsDevice& device, Effect& gbuffer, const GBufferQuad& q, int size, CaseResult& r);

}  // namespace fxport::stability
