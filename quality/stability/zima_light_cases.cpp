// Catalin Zima's PointLight.fx and SpotLight.fx (hlsl/zima-lights, the effects of fxdemo
// pointlights) on the same stiff inputs as xna-deferred's: pow(0, 0) on cleared G-buffer pixels,
// and light radius 0.
//
// Cleared pixels: ClearGBuffer.fx writes color 0 (specular intensity 0), normal 0.5 (the zero
// vector, specular power 0) and depth 1 (the far plane). Every lit term is multiplied by 0, so the
// light map must be exactly 0. But specularLight = specularIntensity * pow(saturate(dot(R, E)), 0)
// is pow(0, 0) wherever R = reflect(-L, 0) = -L faces away from the eye, and 0 * NaN = NaN on a
// GPU that computes pow as exp2(y log2 x). fxdemo pointlights's light volumes cover background
// pixels wherever a light sits near the room's walls. The tutorial's Color lightRT hides it: GL
// clamps a blend's source to [0, 1] for a fixed-point target, which takes a NaN to (in practice) 0;
// the HalfVector4/Vector4 light maps of `--gbuffer half16|float32` keep it, and additive blending
// spreads it (dst + NaN = NaN). The fix is the one the xna-deferred cases use: pow(x, y) ->
// pow(max(x, 1e-30), y) by a #define the runtime passes.
//
// Radius 0: attenuation = saturate(1 - length(L) / 0) = saturate(-Inf) = 0 for every surface point
// not at the light (IEEE division, which D3D10 requires and GPUs give); the light map must be 0.
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"

namespace fxport::stability {

namespace {

constexpr float kNear = 0.1f, kFar = 100.0f;

struct ZimaLight {
    std::string name;
    bool spot = false;
    Vector3 camera, target;
    Vector3 light;
    float radius = 20;
    Vector3 spotAt;  // the spot's axis points from the light at this point
};

// The Zima G-buffer of one constant texel per target (float formats, no rounding).
struct ZimaGBuffer {
    Vector4 color, normal;
    float depth = 1;
};

CaseResult runZimaLight(GraphicsDevice& device, Effect& effect, const ZimaLight& s, const ZimaGBuffer& g,
                        SurfaceFormat lightFormat, const std::string& group, const std::string& variant, int size) {
    CaseResult r;
    r.group = group;
    r.name = s.name + " " + surfaceFormatName(lightFormat);
    r.variant = variant;
    r.relative = false;
    const std::size_t n = std::size_t(size) * std::size_t(size);
    Texture2D color(device, size, size, false, SurfaceFormat::Vector4);
    Texture2D normals(device, size, size, false, SurfaceFormat::Vector4);
    Texture2D depth(device, size, size, false, SurfaceFormat::Single);
    color.SetData(std::vector<Vector4>(n, g.color));
    normals.SetData(std::vector<Vector4>(n, g.normal));
    depth.SetData(std::vector<float>(n, g.depth));
    RenderTarget2D lightMap(device, size, size, false, lightFormat, DepthFormat::None);
    lightMap.Name = std::string("lightRT (") + surfaceFormatName(lightFormat) + ")";

    const Matrix view = Matrix::CreateLookAt(s.camera, s.target, Vector3::Up);
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 1.0f, kNear, kFar);
    auto& p = effect.Parameters;
    // The light volume as a full-screen quad (World = View = Projection = identity): every pixel is
    // lit once, ScreenPosition being the quad's clip position.
    p["World"].SetValue(Matrix::Identity);
    p["View"].SetValue(Matrix::Identity);
    p["Projection"].SetValue(Matrix::Identity);
    p["InvertViewProjection"].SetValue(Matrix::Invert(view * projection));
    p["cameraPosition"].SetValue(s.camera);
    p["lightPosition"].SetValue(s.light);
    p["lightRadius"].SetValue(s.radius);
    p["lightIntensity"].SetValue(1.0f);
    p["Color"].SetValue(Vector3(1, 1, 1));
    p["halfPixel"].SetValue(Vector2(0.5f / float(size), 0.5f / float(size)));
    p["colorMap"].SetValue(&color);
    p["normalMap"].SetValue(&normals);
    p["depthMap"].SetValue(&depth);
    if (s.spot) {
        p["spotDirection"].SetValue(Vector3::Normalize(s.spotAt - s.light));
        p["spotLightAngleCosine"].SetValue(std::cos(0.6f));
        p["spotDecayExponent"].SetValue(20.0f);
    }

    FiniteCheck check(device);
    check.beginPass(s.spot ? "SpotLight" : "PointLight");
    device.SetRenderTarget(lightMap);
    device.Clear(Color::TransparentBlack);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    effect.CurrentTechnique->Passes[0].Apply();
    drawFullTargetQuad(device);
    device.SetRenderTarget(nullptr);
    takeFindings(check.endPass(), r);

    // How many pixels take the path the case is about (so that a 0 is not vacuous): in the cone
    // (spot), and for a cleared G-buffer, R = -L facing away from the eye (pow(0, 0)).
    int onPath = 0;
    const Matrix inverse = Matrix::Invert(view * projection);
    const Vector3 spotDirection = Vector3::Normalize(s.spotAt - s.light);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            Vector4 w = Vector4::Transform(Vector4(float(pixelNdcX(x, size)), float(pixelNdcY(y, size)), g.depth, 1), inverse);
            const Vector3 P(w.X / w.W, w.Y / w.W, w.Z / w.W);
            const Vector3 L = Vector3::Normalize(s.light - P), E = Vector3::Normalize(s.camera - P);
            const bool inCone = !s.spot || Vector3::Dot(spotDirection, -L) > std::cos(0.6f);
            const bool pow00 = g.normal.W == 0 && Vector3::Dot(-L, E) <= 0;
            onPath += inCone && (pow00 || g.normal.W != 0);
        }

    // Reference: 0 everywhere (cleared: every term multiplied by 0; radius 0: attenuation 0).
    errorAgainstZero(lightMap).into(r);
    char note[256];
    std::snprintf(note, sizeof note,
                  "zima-lights/%s.fx, radius %g; must light to exactly 0; error = max |channel|; %d of %d pixels %s",
                  s.spot ? "SpotLight" : "PointLight", double(s.radius), onPath, size * size,
                  g.normal.W == 0 ? "compute pow(0, 0)" : (s.spot ? "in the cone" : "lit but for the radius"));
    r.note = note;
    return r;
}

// Post-projection z / w of the plane z = -distance seen by a camera looking down -z.
float planeDepth(float distance) {
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 1.0f, kNear, kFar);
    const Vector4 clip = Vector4::Transform(Vector4(0, 0, -distance, 1), projection);
    return clip.Z / clip.W;
}

}  // namespace

void runZimaLightCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/zima-lights/";
    EffectOptions safePow;
    safePow.defines.push_back({"pow(x, y)", "pow(max(x, 1e-30), y)"});
    const std::string fixName = "#define pow(x,y) pow(max(x,1e-30),y)";
    const int n = options.size;

    // pow(0, 0): a cleared G-buffer, the camera and light of an ordinary frame.
    const ZimaGBuffer cleared{Vector4(0, 0, 0, 0), Vector4(0.5f, 0.5f, 0.5f, 0.0f), 1.0f};
    const ZimaLight clearedLights[] = {
        {"cleared, point", false, Vector3(0, 2, 10), Vector3(0, 0, 0), Vector3(3, 5, 0), 20.0f, Vector3()},
        // Aimed at the far plane (where cleared depth 1 puts the pixels).
        {"cleared, spot", true, Vector3(0, 2, 10), Vector3(0, 0, 0), Vector3(3, 5, 0), 20.0f, Vector3(0, -15, -80)},
    };
    // Radius 0 on a lit plane (normal towards the camera, specular power 0.2 * 255, intensity 0.5).
    const ZimaGBuffer plane{Vector4(1, 1, 1, 0.5f), Vector4(0.5f, 0.5f, 1.0f, 0.2f), planeDepth(5)};
    const ZimaLight radiusLights[] = {
        {"r=0, point", false, Vector3(0, 0, 0), Vector3(0, 0, -1), Vector3(1, 2, -3), 0.0f, Vector3()},
        {"r=0, spot", true, Vector3(0, 0, 0), Vector3(0, 0, -1), Vector3(1, 2, -3), 0.0f, Vector3(0, 0, -5)},
    };
    for (bool spot : {false, true}) {
        Effect written(device, fx + (spot ? "SpotLight.fx" : "PointLight.fx"));
        Effect fixed(device, fx + (spot ? "SpotLight.fx" : "PointLight.fx"), safePow);
        for (SurfaceFormat format : {SurfaceFormat::HalfVector4, SurfaceFormat::Vector4}) {
            const ZimaLight& c = clearedLights[spot ? 1 : 0];
            results.push_back(runZimaLight(device, written, c, cleared, format, "pow00", "as written", n));
            results.push_back(runZimaLight(device, fixed, c, cleared, format, "pow00", fixName, n));
            results.push_back(
                runZimaLight(device, written, radiusLights[spot ? 1 : 0], plane, format, "zima-radius", "as written", n));
        }
    }
}

}  // namespace fxport::stability
