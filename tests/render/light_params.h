// The CPU references' parameters of the deferred demo's light passes for the tests' camera and
// light setups (deferred_scene.h), as the shipped DeferredRenderer.MakeLightMap sets them at the
// tests' target size, and the cull mode it picks for each light volume. The per-pass and the
// end-to-end tests build their references from these.
#pragma once

#include "deferred_scene.h"
#include "reference/deferred_reference.h"

namespace fxport::render_test {

DirectionalLightParams directionalParams(const TestCamera& camera, const DirectionalLightSetup& light);
SpotLightParams spotParams(const TestCamera& camera, const SpotLightSetup& light);
PointLightParams pointParams(const TestCamera& camera, const PointLightSetup& light);

// MakeLightMap's choices: the spot cone's back faces when the camera is inside its angle, the point
// sphere's back faces when the camera is inside it (the seed's distance / 100 against the radius).
Cull spotCull(const TestCamera& camera, const SpotLightSetup& light);
Cull pointCull(const TestCamera& camera, const PointLightSetup& light);

}  // namespace fxport::render_test
