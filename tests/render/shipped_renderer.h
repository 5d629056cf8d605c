// The deferred demo's own renderer, as the render tests drive it: demo/deferred's DeferredRenderer
// and SSAO at the tests' size (effects from hlsl/xna-deferred, the content from the build's content/),
// made once per process, a BaseCamera with a test camera's matrices, and the tests' scene mesh as a
// Model (Model::FromVertices), which the shipped MakeGBuffer and LightManager.DrawShadowMaps draw as
// they draw the demo's glTF scene. A test uploads its inputs into the renderer's targets, runs one
// pass (the pass methods are public for this) and reads the target back: every pass image the
// render tests check is drawn by the shipped code.
#pragma once

#include <memory>

#include "fxport/framework/content_manager.h"
#include "deferred/Cameras/base_camera.h"
#include "deferred/deferred_renderer.h"
#include "deferred/ssao.h"
#include "deferred_scene.h"

namespace fxport::render_test {

// A BaseCamera with the test camera's matrices (the renderer reads View, Projection, Position; SSAO
// the frustum's FieldOfView, AspectRatio, FarPlane).
struct FixedCamera : TheCansinDeferredRenderer::BaseCamera {
    explicit FixedCamera(const TestCamera& c);
};

struct ShippedRenderer {
    fxport::ContentManager content;
    std::unique_ptr<TheCansinDeferredRenderer::DeferredRenderer> renderer;
    std::unique_ptr<TheCansinDeferredRenderer::SSAO> ssao;

    explicit ShippedRenderer(GraphicsDevice& device);
    RenderTarget2D& gbuffer(int i) const;
    // A light volume as the renderer draws it (the content's model, part 0 of mesh 0, under the
    // light's World only): positions and triangles for the reference's coverage.
    Mesh lightVolume(const char* asset);
    // The content's random-normal texture that SSAO samples, read back (it has no mip levels).
    CpuTexture randomNormals();
};

// The one instance (on the tests' device).
ShippedRenderer& shippedRenderer(GraphicsDevice& device);

// `mesh` (its positions, normals, UVs and tangent frames, rounded to float) as a Model of one part
// with the given material maps, for the shipped passes that draw Models.
std::unique_ptr<Model> toModel(GraphicsDevice& device, const Mesh& mesh, const ModelMaterialTextures& textures);

// Unbinds every target and texture slot and restores the default states (between tests).
void resetDevice(GraphicsDevice& device);

}  // namespace fxport::render_test
