#include "lighting2d/light_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace _2DLightingSystem {

using fxport::demo::PassTimer;

LightRenderer::LightRenderer(GraphicsDeviceManager& _graphics, fxport::GraphicsDevice& device)
    : graphics(_graphics), GraphicsDevice(device) {}

void LightRenderer::Initialize() {
    const int W = GraphicsDevice.Viewport.Width;
    const int H = GraphicsDevice.Viewport.Height;
    backBufferCache = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H);
    midGroundTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H);
    lightMap = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H, false, SurfaceFormat::Color, DepthFormat::None, 1,
                                                RenderTargetUsage::PreserveContents);
    // Square (W x W): each column is one ray (pair), each row a fraction along it. HdrBlendable
    // (RGBA16F) for the distance precision; sampled with PointClamp only (seed, Part 3).
    // fxport: rayCount x rayCount in occlusionFormat when the knobs are set (see the header).
    if (rayCount < 0 || rayCount > 16384)
        throw ArgumentError("LightRenderer: rayCount " + std::to_string(rayCount) + " is outside 0..16384");
    const int rays = rayCount > 0 ? rayCount : W;
    unwrapTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, rays, rays, false, occlusionFormat,
                                                    DepthFormat::None);
    fullScreen = Rectangle(0, 0, W, H);
    occlusionMap = std::make_unique<RenderTarget2D>(GraphicsDevice, rays, 1, false, occlusionFormat,
                                                    DepthFormat::None);

    collapseBlendState = BlendState();
    collapseBlendState.ColorBlendFunction = BlendFunction::Min;
    collapseBlendState.AlphaBlendFunction = BlendFunction::Min;
    collapseBlendState.ColorSourceBlend = Blend::One;
    collapseBlendState.ColorDestinationBlend = Blend::One;
    collapseBlendState.AlphaSourceBlend = Blend::One;
    collapseBlendState.AlphaDestinationBlend = Blend::One;

    scissorState = RasterizerState::CullCounterClockwise;
    scissorState.ScissorTestEnable = true;

    postProcessTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H);
    horizontalBlurTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H);
    verticalBlurTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, W, H);
    // fxport: names for messages (fxdemo --check-finite) and debug labels.
    backBufferCache->Name = "backBufferCache", midGroundTarget->Name = "midGroundTarget", lightMap->Name = "lightMap";
    unwrapTarget->Name = "unwrapTarget", occlusionMap->Name = "occlusionMap", postProcessTarget->Name = "postProcessTarget";
    horizontalBlurTarget->Name = "horizontalBlurTarget", verticalBlurTarget->Name = "verticalBlurTarget";
}

void LightRenderer::LoadContent(ContentManager& Content) {
    spriteBatch = std::make_unique<SpriteBatch>(GraphicsDevice);
    // fxport (issue 6): the light types' effects wait for a light of that type (LoadLightEffects).
    content = &Content;
    verticalBlur = Content.Load<Effect>("Effects/VerticalBlur");
    horizontalBlur = Content.Load<Effect>("Effects/HorizontalBlur");
    lightBlend = Content.Load<Effect>("Effects/LightBlend");
}

void LightRenderer::LoadLightEffects() {
    if (!content) throw InvalidOperation("LightRenderer: DrawLitScene before LoadContent (no ContentManager to load the light effects from)");
    if (!spotLights.empty() && !spotLight) {
        unwrapSpotlight = content->Load<Effect>("Effects/UnwrapSpotlight");
        spotLight = content->Load<Effect>("Effects/SpotLight");
    }
    if (!pointLights.empty() && !pointLight) {
        unwrap = content->Load<Effect>("Effects/Unwrap");
        pointLight = content->Load<Effect>("Effects/PointLight");
    }
}

void LightRenderer::BeginDrawBackground() {
    GraphicsDevice.SetRenderTarget(backBufferCache.get());
}

void LightRenderer::BeginDrawShadowCasters() {
    GraphicsDevice.SetRenderTarget(midGroundTarget.get());
    GraphicsDevice.Clear(Color::Transparent);
}

void LightRenderer::DrawLitScene() {
    // Error checking: the seed's "remember to set these" sentinels.
    if (lightBias < 0) std::fprintf(stderr, "LightRenderer: lightBias is not set (%g)\n", double(lightBias));
    if (minLight < 0) std::fprintf(stderr, "LightRenderer: minLight is not set (%g)\n", double(minLight));

    PrepareResources();

    for (const SpotLight& sLight : spotLights) {
        // Spotlight specific calculations
        const float lightDirAngle = sLight.GetBiasedAngle();
        { PassTimer t(gpuTimer, "Unwrap"); UnwrapShadowCasters(sLight, lightDirAngle); }
        { PassTimer t(gpuTimer, "OcclusionMap"); CreateOcclusionMap(); }
        { PassTimer t(gpuTimer, "LightMap"); CreateLightMap(sLight, lightDirAngle); }
        { PassTimer t(gpuTimer, "Blur"); BlurLightMaps(sLight); }
        if (afterLight) afterLight(*this, sLight, true, afterLightUser);
        { PassTimer t(gpuTimer, "Accumulate"); AccumulateLightMaps(sLight); }
    }
    for (const PointLight& pLight : pointLights) {
        { PassTimer t(gpuTimer, "Unwrap"); UnwrapShadowCasters(pLight); }
        { PassTimer t(gpuTimer, "OcclusionMap"); CreateOcclusionMap(); }
        { PassTimer t(gpuTimer, "LightMap"); CreateLightMap(pLight); }
        { PassTimer t(gpuTimer, "Blur"); BlurLightMaps(pLight); }
        if (afterLight) afterLight(*this, pLight, false, afterLightUser);
        { PassTimer t(gpuTimer, "Accumulate"); AccumulateLightMaps(pLight); }
    }
    { PassTimer t(gpuTimer, "FinalScene"); RenderFinalScene(); }
}

void LightRenderer::PrepareResources() {
    screenDims = Vector2(float(GraphicsDevice.Viewport.Width), float(GraphicsDevice.Viewport.Height));
    const float DiagonalLength = screenDims.Length();

    LoadLightEffects();
    for (Effect* e : {unwrap, unwrapSpotlight}) {
        if (!e) continue;  // fxport: no light of that type drawn yet
        e->Parameters["TextureWidth"].SetValue(screenDims.X);
        e->Parameters["TextureHeight"].SetValue(screenDims.Y);
        e->Parameters["DiagonalLength"].SetValue(DiagonalLength);
    }
    for (Effect* e : {pointLight, spotLight}) {
        if (!e) continue;
        e->Parameters["ScreenDimensions"].SetValue(screenDims);
        e->Parameters["DiagonalLength"].SetValue(DiagonalLength);
        e->Parameters["Bias"].SetValue(lightBias);
    }

    horizontalBlur->Parameters["ScreenDims"].SetValue(screenDims);
    horizontalBlur->Parameters["minBlur"].SetValue(minBlur);
    horizontalBlur->Parameters["maxBlur"].SetValue(maxBlur);
    verticalBlur->Parameters["ScreenDims"].SetValue(screenDims);
    verticalBlur->Parameters["minBlur"].SetValue(minBlur);
    verticalBlur->Parameters["maxBlur"].SetValue(maxBlur);

    // MinLight is a float4 in LightBlend.fx: the seed's float goes in as Vector4(minLight).
    lightBlend->Parameters["MinLight"].SetValue(Vector4(minLight, minLight, minLight, minLight));

    GraphicsDevice.SetRenderTarget(lightMap.get());
    GraphicsDevice.Clear(Color::Black);
}

// The pixels a light's screen-space steps can change. PointLight.fx / SpotLight.fx write black
// (0,0,0,1), the light map's clear colour, wherever pixDist - Bias >= Radius (their light condition
// is pixDist - Bias < min(Radius, dist)); each blur tap reaches at most 6 * max(|minBlur|, |maxBlur|)
// pixels along its axis, plus one for the bilinear footprint, and a kernel over black gives black;
// the additive accumulation of black (alpha 1 on a light map whose alpha is 1) changes nothing. Two
// pixels more absorb the pixel-centre and float rounding of the shaders' distances. A spot light
// lights only pixels whose angle (SpotLight.fx: 0 = +y, growing towards +x) is within HalfOuterArc
// of CenterAngle, so its reach is the bounding box of that sector, not of the whole disc.
Rectangle LightRenderer::LightReach(const Light& light) const {
    const float blurReach = 6.f * std::max(std::fabs(minBlur), std::fabs(maxBlur)) + 1.f;
    const double r = double(light.radius) + std::max(double(lightBias), 0.0);
    // Offsets from the light of the lit region's bounding box (before the blur's reach).
    double lx = -r, ly = -r, hx = r, hy = r;
    const auto* spot = dynamic_cast<const SpotLight*>(&light);
    const double half = spot ? double(spot->outerAngle) / 2.0 : M_PI;
    if (spot && half < M_PI) {
        const double center = spot->GetBiasedAngle();
        lx = ly = hx = hy = 0;  // the apex
        auto include = [&](double angle) {
            const double x = r * std::sin(angle), y = r * std::cos(angle);
            lx = std::min(lx, x), hx = std::max(hx, x), ly = std::min(ly, y), hy = std::max(hy, y);
        };
        include(center - half);
        include(center + half);
        for (double axis : {0.0, M_PI / 2, M_PI, 3 * M_PI / 2}) {  // the circle's extremes inside the arc
            double d = std::fmod(std::fabs(axis - center), 2 * M_PI);
            if (std::min(d, 2 * M_PI - d) < half) include(axis);
        }
    }
    const double pad = double(blurReach) + 2.0;
    const int W = fullScreen.Width, H = fullScreen.Height;
    const int x0 = std::clamp(int(std::floor(light.Position.X + lx - pad)), 0, W);
    const int y0 = std::clamp(int(std::floor(light.Position.Y + ly - pad)), 0, H);
    const int x1 = std::clamp(int(std::ceil(light.Position.X + hx + pad)) + 1, 0, W);
    const int y1 = std::clamp(int(std::ceil(light.Position.Y + hy + pad)) + 1, 0, H);
    return Rectangle(x0, y0, x1 - x0, y1 - y0);
}

const RasterizerState* LightRenderer::ScissorTo(const Rectangle& reach) {
    if (!scissorLights) return nullptr;
    GraphicsDevice.ScissorRectangle = reach;
    return &scissorState;
}

void LightRenderer::UnwrapShadowCasters(const SpotLight& sLight, float lightDirAngle) {
    unwrapSpotlight->Parameters["LightPos"].SetValue(sLight.Position);
    unwrapSpotlight->Parameters["MinAngle"].SetValue(lightDirAngle - sLight.outerAngle / 2.f);
    unwrapSpotlight->Parameters["MaxAngle"].SetValue(lightDirAngle + sLight.outerAngle / 2.f);

    GraphicsDevice.SetRenderTarget(unwrapTarget.get());
    GraphicsDevice.Clear(Color::Transparent);
    // (issue 16: the sprite below covers the whole target, opaque, through an effect that never
    // discards, so the device drops this clear itself: ClearStatistics::covered.)
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr,
                       unwrapSpotlight);
    // fxport: the unwrap target's size (the seed: fullScreen.Width square; see rayCount).
    spriteBatch->Draw(*midGroundTarget, Rectangle(0, 0, RayCount(), RayCount()), Color::White);
    spriteBatch->End();
}

void LightRenderer::UnwrapShadowCasters(const PointLight& pLight) {
    unwrap->Parameters["LightPos"].SetValue(pLight.Position);

    GraphicsDevice.SetRenderTarget(unwrapTarget.get());
    GraphicsDevice.Clear(Color::Transparent);
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr, unwrap);
    spriteBatch->Draw(*midGroundTarget, Rectangle(0, 0, RayCount(), RayCount()), Color::White);
    spriteBatch->End();
}

void LightRenderer::CreateOcclusionMap() {
    GraphicsDevice.SetRenderTarget(occlusionMap.get());
    GraphicsDevice.Clear(Color::White);  // 1 = no occluder: the start value of the Min blend

    spriteBatch->Begin(SpriteSortMode::Deferred, collapseBlendState, SamplerState::PointClamp, nullptr, nullptr);
    // fxport: RayCount() rows and columns (the seed: fullScreen.Width and the viewport's width, equal there).
    for (int i = 0; i < RayCount(); i++)
        spriteBatch->Draw(*unwrapTarget, Rectangle(0, 0, RayCount(), 1), Rectangle(0, i, RayCount(), 1), Color::White);
    spriteBatch->End();
}

void LightRenderer::CreateLightMap(const SpotLight& sLight, float lightDirAngle) {
    spotLight->Parameters["LightPos"].SetValue(sLight.Position);
    spotLight->Parameters["LightPow"].SetValue(sLight.Power);
    spotLight->Parameters["Radius"].SetValue(sLight.radius);
    spotLight->Parameters["OuterMinAngle"].SetValue(lightDirAngle - sLight.outerAngle / 2.f);
    spotLight->Parameters["OuterMaxAngle"].SetValue(lightDirAngle + sLight.outerAngle / 2.f);
    spotLight->Parameters["CenterAngle"].SetValue(lightDirAngle);
    spotLight->Parameters["HalfInnerArc"].SetValue(sLight.innerAngle / 2.f);
    spotLight->Parameters["HalfOuterArc"].SetValue(sLight.outerAngle / 2.f);
    spotLight->Parameters["AngleBias"].SetValue(sLight.GetAngleBias());

    GraphicsDevice.SetRenderTarget(postProcessTarget.get());
    GraphicsDevice.Clear(Color::Black);
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr,
                       ScissorTo(LightReach(sLight)), spotLight);
    spriteBatch->Draw(*occlusionMap, fullScreen, Color::White);
    spriteBatch->End();
}

void LightRenderer::CreateLightMap(const PointLight& pLight) {
    pointLight->Parameters["LightPos"].SetValue(pLight.Position);
    pointLight->Parameters["LightPow"].SetValue(pLight.Power);
    pointLight->Parameters["Radius"].SetValue(pLight.radius);

    GraphicsDevice.SetRenderTarget(postProcessTarget.get());
    GraphicsDevice.Clear(Color::Black);
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr,
                       ScissorTo(LightReach(pLight)), pointLight);
    spriteBatch->Draw(*occlusionMap, fullScreen, Color::White);
    spriteBatch->End();
}

void LightRenderer::BlurLightMaps(const Light& light) {
    horizontalBlur->Parameters["LightPos"].SetValue(light.Position);
    horizontalBlur->Parameters["Radius"].SetValue(light.radius);
    const Rectangle reach = LightReach(light);
    GraphicsDevice.SetRenderTarget(horizontalBlurTarget.get());
    // fxport: scissored, the pixels outside the reach keep this clear: the black the blur writes there.
    if (scissorLights) GraphicsDevice.Clear(Color::Black);
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, nullptr, nullptr, ScissorTo(reach), horizontalBlur);
    spriteBatch->Draw(*postProcessTarget, fullScreen, Color::White);
    spriteBatch->End();

    verticalBlur->Parameters["LightPos"].SetValue(light.Position);
    verticalBlur->Parameters["Radius"].SetValue(light.radius);
    GraphicsDevice.SetRenderTarget(verticalBlurTarget.get());
    if (scissorLights) GraphicsDevice.Clear(Color::Black);
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, nullptr, nullptr, ScissorTo(reach), verticalBlur);
    spriteBatch->Draw(*horizontalBlurTarget, fullScreen, Color::White);
    spriteBatch->End();
}

void LightRenderer::AccumulateLightMaps(const Light& light) {
    GraphicsDevice.SetRenderTarget(lightMap.get());  // PreserveContents: the lights so far stay
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Additive, nullptr, nullptr, ScissorTo(LightReach(light)));
    spriteBatch->Draw(*verticalBlurTarget, fullScreen, light.color);
    spriteBatch->End();
}

void LightRenderer::RenderFinalScene() {
    GraphicsDevice.SetRenderTarget(nullptr);
    GraphicsDevice.Textures[1] = lightMap;
    spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend, nullptr, nullptr, nullptr, lightBlend);
    spriteBatch->Draw(*backBufferCache, fullScreen, Color::White);
    spriteBatch->End();
    GraphicsDevice.Textures[1] = nullptr;

    spriteBatch->Begin();
    spriteBatch->Draw(*midGroundTarget, fullScreen, Color::White);
    spriteBatch->End();
}

}  // namespace _2DLightingSystem
