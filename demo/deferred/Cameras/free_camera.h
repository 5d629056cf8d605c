// FreeCamera: a fly-through camera. W/S forward and back, A/D sideways, Q/E down and up (Shift: 4x
// faster), mouse with the left button held turns it.
//
// Reconstructed: seed 000 is cut here (it has no camera code at all; see base_camera.h). The
// constructor and Update take what the seed's Game1 passes: new FreeCamera(this, new Vector3(0, 0,
// 5), new Vector3(0, 0, 0), Vector3.Up) - read here as position, target, up - and
// Camera.Update(this, currentK, previousK, currentM).
#pragma once

#include "deferred/Cameras/base_camera.h"

namespace TheCansinDeferredRenderer {

class FreeCamera : public BaseCamera {
    //Rotation about Y (0 looks down -Z) and about the camera's X (positive looks up), radians
    float yaw;
    float pitch;
    //Up Vector
    Vector3 up;
    //Movement per Update and Rotation per Mouse Pixel
    float speed = 0.1f;
    float turnSpeed = 0.005f;
    //Previous Mouse State (fxport's Mouse has no SetPosition, so turning uses the change since the
    //last Update instead of the distance from the window's centre)
    MouseState previousM;

public:
    //Constructor
    FreeCamera(Game& game, Vector3 Position, Vector3 Target, Vector3 Up);
    //Update from Keyboard and Mouse
    void Update(Game& game, const KeyboardState& currentK, const KeyboardState& previousK, const MouseState& currentM);

private:
    //Remake View from Position, yaw and pitch
    void UpdateView();
};

}  // namespace TheCansinDeferredRenderer
