#include "deferred/Cameras/base_camera.h"

namespace TheCansinDeferredRenderer {

// Reconstructed: seed 000 is cut here (it has no camera code at all; see base_camera.h).
BaseCamera::BaseCamera(Game& game, Vector3 Position) : Position(Position) {
    //Aspect Ratio of the back buffer
    AspectRatio = game.GraphicsDevice->Viewport.AspectRatio();
    //Make Projection
    UpdateProjection();
}

void BaseCamera::UpdateProjection() {
    Projection = Matrix::CreatePerspectiveFieldOfView(FieldOfView, AspectRatio, NearPlane, FarPlane);
}

}  // namespace TheCansinDeferredRenderer
