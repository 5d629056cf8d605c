#include "deferred/Cameras/free_camera.h"

#include <cmath>

namespace TheCansinDeferredRenderer {

// Reconstructed: seed 000 is cut here (it has no camera code at all; see base_camera.h).
FreeCamera::FreeCamera(Game& game, Vector3 Position, Vector3 Target, Vector3 Up) : BaseCamera(game, Position), up(Up) {
    //Yaw and Pitch that look from Position at Target
    Vector3 direction = Vector3::Normalize(Target - Position);
    yaw = std::atan2(-direction.X, -direction.Z);
    pitch = std::asin(MathHelper::Clamp(direction.Y, -1.0f, 1.0f));
    //Make View
    UpdateView();
}

void FreeCamera::Update(Game& game, const KeyboardState& currentK, const KeyboardState& previousK,
                        const MouseState& currentM) {
    (void)game;
    (void)previousK;
    //Turn while the left button is held
    if (currentM.LeftButton == ButtonState::Pressed && previousM.LeftButton == ButtonState::Pressed) {
        yaw -= float(currentM.X - previousM.X) * turnSpeed;
        pitch -= float(currentM.Y - previousM.Y) * turnSpeed;
        pitch = MathHelper::Clamp(pitch, -MathHelper::PiOver2 + 0.01f, MathHelper::PiOver2 - 0.01f);
    }
    previousM = currentM;

    //Move
    Matrix rotation = Matrix::CreateFromYawPitchRoll(yaw, pitch, 0);
    float step = speed * (currentK.IsKeyDown(Keys::LeftShift) ? 4.0f : 1.0f);
    if (currentK.IsKeyDown(Keys::W)) Position += rotation.Forward() * step;
    if (currentK.IsKeyDown(Keys::S)) Position -= rotation.Forward() * step;
    if (currentK.IsKeyDown(Keys::D)) Position += rotation.Right() * step;
    if (currentK.IsKeyDown(Keys::A)) Position -= rotation.Right() * step;
    if (currentK.IsKeyDown(Keys::E)) Position += up * step;
    if (currentK.IsKeyDown(Keys::Q)) Position -= up * step;

    //Remake View
    UpdateView();
}

void FreeCamera::UpdateView() {
    Matrix rotation = Matrix::CreateFromYawPitchRoll(yaw, pitch, 0);
    View = Matrix::CreateLookAt(Position, Position + rotation.Forward(), up);
}

}  // namespace TheCansinDeferredRenderer
