// What the stability cases share: error accumulation, FiniteCheck findings, the G-buffer a light
// pass reads (made directly as textures, so that every texel is a value the CPU reference knows),
// and a light pass drawn over the whole target.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "stability/stability_cases.h"

namespace fxport::stability {

// RMS and worst of an error.
struct Accumulator {
    double sumSq = 0, worst = 0;
    int n = 0;
    void add(double e) {
        sumSq += e * e;
        worst = std::fmax(worst, e);
        ++n;
    }
    void into(CaseResult& r) const {
        r.pixels = n;
        r.rmsError = n ? std::sqrt(sumSq / n) : 0;
        r.maxError = worst;
    }
};

// Adds FiniteCheck's findings of one pass to the case.
void takeFindings(const std::vector<NonFiniteTarget>& found, CaseResult& r);

// D3D9 pixel centres as the runtime emulates them: pixel (x, y) of a full-target quad is
// interpolated at NDC (2 x / W - 1, 1 - 2 (y + 1/256) / H) (exact across, 1/256 pixel down).
inline constexpr double kPixelBiasY = 1.0 / 256;
inline double pixelNdcX(int x, int w) { return 2.0 * x / w - 1; }
inline double pixelNdcY(int y, int h) { return 1 - 2 * (y + kPixelBiasY) / h; }

// A G-buffer of size x size as the xna-deferred light passes read it, every texel given:
// albedo.w = specular intensity, normals = encoded (n + 1) / 2 and .w = specular power / 255,
// depth = post-projection z / w. Float formats, so no texel is rounded.
struct GBufferTextures {
    Texture2D albedo, normals, depth;
    GBufferTextures(GraphicsDevice& device, int size, const std::vector<Vector4>& albedoTexels,
                    const std::vector<Vector4>& normalTexels, const std::vector<float>& depthTexels);
};

// Two triangles covering the target at NDC z = 0.5, UV (0, 0) top left (for a light pass whose
// World = View = Projection = identity: every pixel runs the pass once).
void drawFullTargetQuad(GraphicsDevice& device);

// max |channel| of each finite texel against a reference of 0 (NaN/Inf texels are FiniteCheck's).
Accumulator errorAgainstZero(RenderTarget2D& target);

// xna-deferred PointLight.fx as every case uses it: a white light of intensity 1 with Shadows
// off (DepthBias, DepthPrecision and shadowMapSize set anyway, to values the shadow branch would
// accept). The shadow cube is still sampled-bound: `UnitShadowCube` is a 1x1 cube of ones.
void setUnshadowedPointLight(Effect& pointLight, const Matrix& inverseView, const Matrix& inverseViewProjection,
                             Vector3 camera, Vector3 light, float radius);
struct UnitShadowCube {
    TextureCube cube;
    explicit UnitShadowCube(GraphicsDevice& device);
};

// Draws `effect` (a light pass whose vertex shader is World*View*Projection) over the whole
// `target` with a quad at NDC z = 0.5 (World = View = Projection = identity), the G-buffer on
// samplers 0..2 and the cookie and shadow map on 3 and 4, point sampling; FiniteCheck names the
// pass `passName`. The caller has set the effect's other parameters.
struct LightInputs {
    Texture* albedo = nullptr;
    Texture* normals = nullptr;
    Texture* depth = nullptr;
    Texture* slot3 = nullptr;  // SpotLight.fx: the cookie
    Texture* slot4 = nullptr;  // the shadow map
};
void drawLightOverTarget(GraphicsDevice& device, Effect& effect, RenderTarget2D& target, const LightInputs& inputs,
                         const std::string& passName, CaseResult& r);

// xna-deferred PointLight.fx (Shadows off) in double, for pixel (x, y) of an n x n full-target
// light pass whose G-buffer holds the plane z = -distance seen by a camera at the origin looking
// down -z (fov `fov`, aspect 1), with G-buffer normal N (view = world space: inverseView = I).
struct PointLightScene {
    double distance, fov;
    double light[3];
    double radius;
};
void pointLightReference(const PointLightScene& scene, int x, int y, int n, const double N[3], double specularIntensity,
                         double specularPower, double out[4]);

// Light map read back as RGBA floats.
std::vector<Vector4> readBack(RenderTarget2D& target);

}  // namespace fxport::stability
