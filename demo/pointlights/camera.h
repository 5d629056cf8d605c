// Camera (the series' camera component; not in seed 001, reconstructed): an orbit camera in the
// style of the XNA samples the series starts from (cameraArc, cameraRotation, cameraDistance), with
// the Position, View and Projection the renderer reads, and the near plane distance the
// cull-mode test of seed 001's comments (czaurel) adds to the light radius.
#pragma once

#include "pointlights/xna.h"

namespace DeferredLighting {

class Camera {
public:
    Camera(float aspectRatio);

    // Arrow keys orbit, W/S (PageUp/PageDown) move closer/further; only in a window.
    void Update(const GameTime& gameTime, const KeyboardState& keyboardState);
    // Recomputes Position and View from the orbit values.
    void UpdateView();

    Vector3 Position;
    Matrix View;
    Matrix Projection;
    float NearDistance = 1.0f;
    float FarDistance = 200.0f;

    // fxport: the demo's starting orbit (the series' values frame its ship model; these frame our
    // Scene's courtyard from above its front parapet). Degrees, degrees, units.
    float cameraArc = -25.0f;
    float cameraRotation = 0.0f;
    float cameraDistance = 20.0f;
    Vector3 target = Vector3(0.0f, 2.0f, 0.0f);
};

}  // namespace DeferredLighting
