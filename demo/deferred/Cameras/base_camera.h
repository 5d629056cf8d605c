// BaseCamera: what the renderer reads from a camera (Camera.View, Camera.Projection,
// Camera.Position; SSAO also needs the frustum: FieldOfView, AspectRatio, FarPlane).
//
// Reconstructed: seed 000 is cut here (it has no camera code at all; chapter 2, line 304: "For the
// Camera, just go ahead and copy the Camera classes from the source code", which is not part of the
// seed). Written from what the other classes use; see demo/deferred/RECONSTRUCTED.md.
#pragma once

#include "deferred/xna.h"

namespace TheCansinDeferredRenderer {

class BaseCamera {
public:
    //Position
    Vector3 Position;
    //View Matrix
    Matrix View = Matrix::Identity;
    //Projection Matrix
    Matrix Projection = Matrix::Identity;
    //Projection values: vertical Field of View (radians), Aspect Ratio, Near and Far Plane
    float FieldOfView = MathHelper::PiOver4;
    float AspectRatio = 1.0f;
    float NearPlane = 0.1f;
    float FarPlane = 1000.0f;

    virtual ~BaseCamera() = default;

protected:
    //Constructor: a perspective projection filling the game's viewport
    BaseCamera(Game& game, Vector3 Position);
    // fxport: a camera whose matrices the subclass sets itself (the render tests' fixed camera).
    BaseCamera() = default;
    //Remake Projection from FieldOfView, AspectRatio, NearPlane and FarPlane
    void UpdateProjection();
};

}  // namespace TheCansinDeferredRenderer
