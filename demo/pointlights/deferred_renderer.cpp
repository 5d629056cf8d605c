#include "pointlights/deferred_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace DeferredLighting {

// Reconstructed (the series' Initialize/LoadContent, chapters 2-3, with what seed 001 adds):
// XNA 4 form of the targets: colorRT carries the depth buffer the scene is drawn with.
DeferredRenderer::DeferredRenderer(fxport::GraphicsDevice& GraphicsDevice, ContentManager& Content, Camera& camera,
                                   QuadRenderer& quadRenderer, Scene& scene, const Quality& quality)
    : camera(&camera), quadRenderer(&quadRenderer), scene(&scene), quality(quality), GraphicsDevice(GraphicsDevice) {
    int backbufferWidth = GraphicsDevice.PresentationParameters().BackBufferWidth;
    int backbufferHeight = GraphicsDevice.PresentationParameters().BackBufferHeight;

    // fxport: the formats are a knob of `fxdemo report` (Quality::gbufferFormats; Tutorial = the series').
    SurfaceFormat colorFormat = SurfaceFormat::Color, depthFormat = SurfaceFormat::Single,
                  lightFormat = SurfaceFormat::Color;
    if (quality.gbufferFormats == GBufferFormats::Half16) {
        colorFormat = lightFormat = SurfaceFormat::HalfVector4;
        depthFormat = SurfaceFormat::HalfSingle;
    } else if (quality.gbufferFormats == GBufferFormats::Float32) {
        colorFormat = lightFormat = SurfaceFormat::Vector4;
    }
    colorRT = std::make_unique<RenderTarget2D>(GraphicsDevice, backbufferWidth, backbufferHeight, false,
                                               colorFormat, DepthFormat::Depth24);
    normalRT = std::make_unique<RenderTarget2D>(GraphicsDevice, backbufferWidth, backbufferHeight, false,
                                                colorFormat, DepthFormat::None);
    depthRT = std::make_unique<RenderTarget2D>(GraphicsDevice, backbufferWidth, backbufferHeight, false,
                                               depthFormat, DepthFormat::None);
    lightRT = std::make_unique<RenderTarget2D>(GraphicsDevice, backbufferWidth, backbufferHeight, false,
                                               lightFormat, DepthFormat::None);
    colorRT->Name = "colorRT";
    normalRT->Name = "normalRT";
    depthRT->Name = "depthRT";
    lightRT->Name = "lightRT";

    scene.InitializeScene(Content);

    clearBufferEffect = Content.Load<Effect>("ClearGBuffer");
    directionalLightEffect = Content.Load<Effect>("DirectionalLight");
    finalCombineEffect = Content.Load<Effect>("CombineFinal");
    pointLightEffect = Content.Load<Effect>("PointLight");
    // fxport: the chapter's sphere.x has radius 1; the deferred demo's PointLightGeometry has
    // radius 100 (content/README.md), which DrawPointLight scales back (lightRig.sphereModelRadius).
    sphereModel = Content.Load<Model>("PointLightGeometry");
    // fxport (report knob): a UV sphere of Quality::sphereSegments x sphereSegments/2, built as the
    // content tool builds PointLightGeometry (same radius, vertex order and winding).
    if (quality.sphereSegments > 0) {
        if (quality.sphereSegments < 3)
            throw ArgumentError("DeferredRenderer: sphereSegments " + std::to_string(quality.sphereSegments) +
                                " is below 3");
        const int segments = quality.sphereSegments, rings = std::max(2, segments / 2), columns = segments + 1;
        for (int j = 0; j <= rings; ++j) {
            const float phi = MathHelper::Pi * (float(j) / float(rings) - 0.5f);
            const float cosPhi = (j == 0 || j == rings) ? 0.0f : std::cos(phi);
            const float sinPhi = j == 0 ? -1.0f : (j == rings ? 1.0f : std::sin(phi));
            for (int i = 0; i <= segments; ++i) {
                const float theta = i == segments ? 0.0f : MathHelper::TwoPi * float(i) / float(segments);
                const Vector3 n(cosPhi * std::sin(theta), sinPhi, cosPhi * std::cos(theta));
                sphereVertices.push_back(VertexPositionColor(n * lightRig.sphereModelRadius, Color::White));
            }
        }
        for (int j = 0; j < rings; ++j)
            for (int i = 0; i < segments; ++i) {
                auto at = [&](int ii, int jj) { return jj * columns + ii; };
                if (j != 0) sphereIndices.insert(sphereIndices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                if (j != rings - 1) sphereIndices.insert(sphereIndices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
    }
    // The exercise: "For the light volume, use cone.x". fxport: SpotLightGeometry.gltf, apex at the
    // origin, axis -Z, length 1, base radius 0.5 (content/README.md).
    // fxport: loaded with the first spot light drawn (DrawSpotLight).
    content = &Content;

    halfPixel.X = 0.5f / float(GraphicsDevice.PresentationParameters().BackBufferWidth);
    halfPixel.Y = 0.5f / float(GraphicsDevice.PresentationParameters().BackBufferHeight);

    // XNA 3.1's AlphaBlendEnable, SourceBlend = One, DestinationBlend = One, BlendFunction.Add,
    // SeparateAlphaBlendEnabled = false, as an XNA 4 BlendState.
    lightBlendState.ColorSourceBlend = Blend::One;
    lightBlendState.ColorDestinationBlend = Blend::One;
    lightBlendState.ColorBlendFunction = BlendFunction::Add;
    lightBlendState.AlphaSourceBlend = Blend::One;
    lightBlendState.AlphaDestinationBlend = Blend::One;
    lightBlendState.AlphaBlendFunction = BlendFunction::Add;
}

void DeferredRenderer::SetGBuffer() {
    GraphicsDevice.SetRenderTargets({colorRT.get(), normalRT.get(), depthRT.get()});
}

void DeferredRenderer::ResolveGBuffer() {
    //set all rendertargets to null. In XNA 2.0, switching a rendertarget causes the resolving of the previous rendertarget.
    // In XNA 4 (and fxport) the targets are textures as soon as they are unbound.
    GraphicsDevice.SetRenderTarget(nullptr);
}

void DeferredRenderer::ClearGBuffer() {
    GraphicsDevice.DepthStencilState = DepthStencilState::None;
    // fxport (issue 16): the quad writes every pixel of the three targets with blending off, so the
    // colour SetRenderTargets cleared them to is never seen: the device drops that clear (D3D11.1's
    // DiscardView; FXPORT_HONOUR_DISCARDS=0 keeps it). The same image.
    GraphicsDevice.DiscardContents(ClearOptions::Target);
    clearBufferEffect->Techniques[0]->Passes[0].Apply();
    quadRenderer->Render(Vector2::One * -1, Vector2::One);
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
}

void DeferredRenderer::DrawDirectionalLight(Vector3 lightDirection, Color color) {
    drawnDirection = lightDirection;
    drawnDirectionalColor = color.ToVector3();
    //set all parameters
    directionalLightEffect->Parameters["colorMap"].SetValue(colorRT.get());
    directionalLightEffect->Parameters["normalMap"].SetValue(normalRT.get());
    directionalLightEffect->Parameters["depthMap"].SetValue(depthRT.get());
    directionalLightEffect->Parameters["lightDirection"].SetValue(lightDirection);
    directionalLightEffect->Parameters["Color"].SetValue(color.ToVector3());
    directionalLightEffect->Parameters["cameraPosition"].SetValue(camera->Position);
    directionalLightEffect->Parameters["InvertViewProjection"].SetValue(Matrix::Invert(camera->View * camera->Projection));
    directionalLightEffect->Parameters["halfPixel"].SetValue(halfPixel);

    directionalLightEffect->Techniques[0]->Passes[0].Apply();
    //draw a full-screen quad
    quadRenderer->Render(Vector2::One * -1, Vector2::One);
}

void DeferredRenderer::DrawPointLight(Vector3 lightPosition, Color color, float lightRadius, float lightIntensity) {
    // fxport: the chapter's light positions and radii are in the units of its ship model, centred
    // at the origin; our Scene is a 14-unit courtyard with its floor at y = 0. lightRig maps them
    // (positions scaled about the origin and moved to lightRig.center, radii scaled), so that the
    // seed's DrawLights below stays as written.
    lightPosition = lightRig.center + lightPosition * lightRig.scale;
    lightRadius *= lightRig.scale;

    // fxport (issue 6): frustum culling. The volume drawn is the sphere of lightRadius (the model's
    // vertices lie on it); if the camera's frustum does not meet it, the light lights no pixel seen.
    const bool culled = frustumCulling && !BoundingFrustum(camera->View * camera->Projection)
                                               .Intersects(BoundingSphere(lightPosition, lightRadius));
    const bool cameraInside = Vector3::Distance(camera->Position, lightPosition) < lightRadius + camera->NearDistance;
    drawnPointLights.push_back({lightPosition, color.ToVector3(), lightRadius, lightIntensity, cameraInside, culled});
    if (culled) {
        ++culledLights;
        return;
    }

    //set the G-Buffer parameters
    pointLightEffect->Parameters["colorMap"].SetValue(colorRT.get());
    pointLightEffect->Parameters["normalMap"].SetValue(normalRT.get());
    pointLightEffect->Parameters["depthMap"].SetValue(depthRT.get());
    //compute the light world matrix
    //scale according to light radius, and translate it to light position
    // fxport: divided by the radius of PointLightGeometry.gltf (100; the chapter's sphere.x: 1).
    Matrix sphereWorldMatrix =
        Matrix::CreateScale(lightRadius / lightRig.sphereModelRadius) * Matrix::CreateTranslation(lightPosition);
    pointLightEffect->Parameters["World"].SetValue(sphereWorldMatrix);
    pointLightEffect->Parameters["View"].SetValue(camera->View);
    pointLightEffect->Parameters["Projection"].SetValue(camera->Projection);
    //light position
    pointLightEffect->Parameters["lightPosition"].SetValue(lightPosition);
    //set the color, radius and Intensity
    pointLightEffect->Parameters["Color"].SetValue(color.ToVector3());
    pointLightEffect->Parameters["lightRadius"].SetValue(lightRadius);
    pointLightEffect->Parameters["lightIntensity"].SetValue(lightIntensity);
    //parameters for specular computations
    pointLightEffect->Parameters["cameraPosition"].SetValue(camera->Position);
    pointLightEffect->Parameters["InvertViewProjection"].SetValue(Matrix::Invert(camera->View * camera->Projection));
    //size of a halfpixel, for texture coordinates alignment
    pointLightEffect->Parameters["halfPixel"].SetValue(halfPixel);
    //calculate the distance between the camera and light center
    float cameraToCenter = Vector3::Distance(camera->Position, lightPosition);
    //if we are inside the light volume, draw the sphere's inside face
    // (with the near-plane correction of the chapter's comments (czaurel): the rendering "starts"
    // from the near plane, not from the camera position)
    if (cameraToCenter < lightRadius + camera->NearDistance) {
        GraphicsDevice.RasterizerState = RasterizerState::CullClockwise;
        ++insideLights;
    } else {
        GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
        ++outsideLights;
    }

    pointLightEffect->Techniques[0]->Passes[0].Apply();
    DrawLightSphere();
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
}

void DeferredRenderer::DrawLightSphere() {
    if (!sphereVertices.empty()) {  // fxport: the generated sphere (Quality::sphereSegments)
        GraphicsDevice.DrawUserIndexedPrimitives(PrimitiveType::TriangleList, sphereVertices.data(), 0,
                                                 int(sphereVertices.size()), sphereIndices.data(), 0,
                                                 int(sphereIndices.size() / 3));
        return;
    }
    for (ModelMesh& mesh : sphereModel->Meshes) {
        for (ModelMeshPart& meshPart : mesh.MeshParts) {
            GraphicsDevice.SetVertexBuffer(meshPart.VertexBuffer, meshPart.VertexOffset);
            GraphicsDevice.Indices = meshPart.IndexBuffer;
            GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, meshPart.NumVertices,
                                                 meshPart.StartIndex, meshPart.PrimitiveCount);
        }
    }
}

// fxport (report knob): Quality::lightCount lights in the chapter's pattern: alternately on its
// first ring (radius 12, intensity 2) and second ring (radius 20, intensity 1), evenly spaced and
// turning with the game time, colours cycling through the chapter's ten. The intensities are
// scaled by min(1, 22 / N) so that the light map's total stays near the chapter's 22 lights'.
void DeferredRenderer::DrawManyPointLights(const GameTime& gameTime, const Color* colors) {
    const int n = quality.lightCount, perRing = (n + 1) / 2;
    const float scale = std::min(1.0f, 22.0f / float(n));
    for (int k = 0; k < n; k++) {
        const int i = k / 2;
        const double a = i * MathHelper::TwoPi / perRing + gameTime.TotalGameTime.TotalSeconds();
        if (k % 2 == 0)
            DrawPointLight(Vector3(float(std::sin(a)), 0.3f, float(std::cos(a))) * 20, colors[i % 10], 12, 2 * scale);
        else
            DrawPointLight(Vector3(float(std::cos(a)), -0.6f, float(std::sin(a))) * 20, colors[i % 10], 20, scale);
    }
}

// The chapter's exercise (fxport; not in the seed, which leaves it to the reader): the point
// light's parameters plus spotDirection, spotLightAngleCosine and spotDecayExponent; the cone's
// world matrix "made from: scaling on the Y axis, based on the radius of the light, scaling on the
// XZ plane, based on the cone angle, rotations based on the cone direction, and finally,
// translation based on the light position" (our cone's axis is -Z, so the axis scale is on Z).
void DeferredRenderer::DrawSpotLight(Vector3 lightPosition, Vector3 spotDirection, Color color, float lightRadius,
                                     float lightIntensity, float spotLightAngle, float spotDecayExponent) {
    spotDirection = Vector3::Normalize(spotDirection);
    if (!spotLightEffect) {  // fxport: on first use
        spotLightEffect = content->Load<Effect>("SpotLight");
        coneModel = content->Load<Model>("SpotLightGeometry");
    }
    //set the G-Buffer parameters
    spotLightEffect->Parameters["colorMap"].SetValue(colorRT.get());
    spotLightEffect->Parameters["normalMap"].SetValue(normalRT.get());
    spotLightEffect->Parameters["depthMap"].SetValue(depthRT.get());
    //cone world matrix: base radius 0.5 at length 1 -> lightRadius * tan(angle) at lightRadius
    float coneScale = lightRadius * std::tan(spotLightAngle) / 0.5f;
    Vector3 up = std::fabs(spotDirection.Y) > 0.99f ? Vector3::Forward : Vector3::Up;
    Matrix coneWorldMatrix = Matrix::CreateScale(coneScale, coneScale, lightRadius) *
                             Matrix::CreateWorld(lightPosition, spotDirection, up);
    spotLightEffect->Parameters["World"].SetValue(coneWorldMatrix);
    spotLightEffect->Parameters["View"].SetValue(camera->View);
    spotLightEffect->Parameters["Projection"].SetValue(camera->Projection);
    spotLightEffect->Parameters["lightPosition"].SetValue(lightPosition);
    spotLightEffect->Parameters["Color"].SetValue(color.ToVector3());
    spotLightEffect->Parameters["lightRadius"].SetValue(lightRadius);
    spotLightEffect->Parameters["lightIntensity"].SetValue(lightIntensity);
    spotLightEffect->Parameters["spotDirection"].SetValue(spotDirection);
    spotLightEffect->Parameters["spotLightAngleCosine"].SetValue(std::cos(spotLightAngle));
    spotLightEffect->Parameters["spotDecayExponent"].SetValue(spotDecayExponent);
    spotLightEffect->Parameters["cameraPosition"].SetValue(camera->Position);
    spotLightEffect->Parameters["InvertViewProjection"].SetValue(Matrix::Invert(camera->View * camera->Projection));
    spotLightEffect->Parameters["halfPixel"].SetValue(halfPixel);
    //camera inside the cone (near plane included, as for the point lights): draw the inner faces
    Vector3 toCamera = camera->Position - lightPosition;
    float along = Vector3::Dot(toCamera, spotDirection);
    float distance = toCamera.Length();
    bool inside = distance < camera->NearDistance ||
                  (along < lightRadius + camera->NearDistance &&
                   along > 0 && std::acos(std::min(1.0f, along / distance)) <
                                    spotLightAngle + std::asin(std::min(1.0f, camera->NearDistance / distance)));
    spotInside = inside;
    GraphicsDevice.RasterizerState = inside ? RasterizerState::CullClockwise : RasterizerState::CullCounterClockwise;

    spotLightEffect->Techniques[0]->Passes[0].Apply();
    for (ModelMesh& mesh : coneModel->Meshes) {
        for (ModelMeshPart& meshPart : mesh.MeshParts) {
            GraphicsDevice.SetVertexBuffer(meshPart.VertexBuffer, meshPart.VertexOffset);
            GraphicsDevice.Indices = meshPart.IndexBuffer;
            GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, meshPart.NumVertices,
                                                 meshPart.StartIndex, meshPart.PrimitiveCount);
        }
    }
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
}

void DeferredRenderer::DrawLights(const GameTime& gameTime) {
    GraphicsDevice.SetRenderTarget(lightRT.get());
    //clear all components to 0
    GraphicsDevice.Clear(Color::TransparentBlack);
    //use additive blending, and make sure the blending factors are as we need them
    GraphicsDevice.BlendState = lightBlendState;
    // Reconstructed: the light volumes are drawn without the depth test (lightRT has no depth
    // buffer in XNA 4: the G-buffer's depth stays with colorRT), so the cull-mode switch below is
    // what makes each pixel lit once.
    GraphicsDevice.DepthStencilState = DepthStencilState::None;

    insideLights = outsideLights = culledLights = 0;
    drawnPointLights.clear();
    {
        PassTimer timed(gpuTimer, "DirectionalLight");
        DrawDirectionalLight(Vector3(0, -1.0f, 1), Color::DimGray);
    }
    {
        PassTimer timed(gpuTimer, "PointLights");
        Color colors[10];
        colors[0] = Color::ForestGreen;
        colors[1] = Color::Blue;
        colors[2] = Color::Pink;
        colors[3] = Color::Yellow;
        colors[4] = Color::Orange;
        colors[5] = Color::Green;
        colors[6] = Color::Crimson;
        colors[7] = Color::CornflowerBlue;
        colors[8] = Color::Gold;
        colors[9] = Color::Honeydew;
        float angle = float(gameTime.TotalGameTime.TotalSeconds());
        (void)angle;
        if (quality.lightCount > 0) DrawManyPointLights(gameTime, colors);
        for (int i = 0; i < 10 && quality.lightCount == 0; i++) {
            Vector3 pos = Vector3(float(std::sin(i * MathHelper::TwoPi / 10 + gameTime.TotalGameTime.TotalSeconds())), 0.3f,
                                  float(std::cos(i * MathHelper::TwoPi / 10 + gameTime.TotalGameTime.TotalSeconds())));
            DrawPointLight(pos * 20, colors[i], 12, 2);
            pos = Vector3(float(std::cos(i * MathHelper::TwoPi / 10 + gameTime.TotalGameTime.TotalSeconds())), -0.6f,
                          float(std::sin(i * MathHelper::TwoPi / 10 + gameTime.TotalGameTime.TotalSeconds())));
            DrawPointLight(pos * 20, colors[i], 20, 1);
        }
        if (quality.lightCount == 0) {
            DrawPointLight(Vector3(0, float(std::sin(gameTime.TotalGameTime.TotalSeconds() * 0.8)) * 40, 0), Color::Red, 30, 5);
            DrawPointLight(Vector3(0, 0, 70), Color::Wheat, 55 + 10 * float(std::sin(5 * gameTime.TotalGameTime.TotalSeconds())), 3);
        }
    }
    if (drawSpotLight) {
        // fxport: the exercise's spot light, in Scene units: 7.5 above the courtyard's centre,
        // sweeping around the vertical, 25 degree half-angle, reaching 14 units.
        PassTimer timed(gpuTimer, "SpotLight");
        double t = gameTime.TotalGameTime.TotalSeconds();
        DrawSpotLight(Vector3(0, 7.5f, 0), Vector3(0.6f * float(std::sin(t)), -1.0f, 0.6f * float(std::cos(t))),
                      Color::White, 14.0f, 3.0f, MathHelper::ToRadians(25.0f), 4.0f);
    }

    GraphicsDevice.BlendState = BlendState::Opaque;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
    GraphicsDevice.SetRenderTarget(nullptr);

    PassTimer timed(gpuTimer, "FinalCombine");
    // fxport (issue 16): the quad below covers the back buffer, opaque, so the colour binding it
    // cleared is never seen: the device drops that clear (see ClearGBuffer).
    GraphicsDevice.DiscardContents(ClearOptions::Target);
    //set the effect parameters
    finalCombineEffect->Parameters["colorMap"].SetValue(colorRT.get());
    finalCombineEffect->Parameters["lightMap"].SetValue(lightRT.get());
    finalCombineEffect->Parameters["halfPixel"].SetValue(halfPixel);

    finalCombineEffect->Techniques[0]->Passes[0].Apply();
    //render a full-screen quad
    quadRenderer->Render(Vector2::One * -1, Vector2::One);
}

void DeferredRenderer::Draw(const GameTime& gameTime) {
    {
        PassTimer timed(gpuTimer, "GBuffer");
        SetGBuffer();
        ClearGBuffer();
        scene->DrawScene(GraphicsDevice, *camera, gameTime);
        ResolveGBuffer();
    }
    DrawLights(gameTime);
}

}  // namespace DeferredLighting
