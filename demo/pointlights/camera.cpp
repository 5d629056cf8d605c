#include "pointlights/camera.h"

#include <algorithm>
#include <cmath>

namespace DeferredLighting {

Camera::Camera(float aspectRatio) {
    Projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, aspectRatio, NearDistance, FarDistance);
    UpdateView();
}

void Camera::Update(const GameTime& gameTime, const KeyboardState& keyboardState) {
    float time = float(gameTime.ElapsedGameTime.TotalSeconds()) * 60.0f;
    if (keyboardState.IsKeyDown(Keys::Up)) cameraArc += time * 0.5f;
    if (keyboardState.IsKeyDown(Keys::Down)) cameraArc -= time * 0.5f;
    //limit the arc movement
    cameraArc = std::clamp(cameraArc, -90.0f, 90.0f);
    if (keyboardState.IsKeyDown(Keys::Right)) cameraRotation += time * 0.5f;
    if (keyboardState.IsKeyDown(Keys::Left)) cameraRotation -= time * 0.5f;
    if (keyboardState.IsKeyDown(Keys::W) || keyboardState.IsKeyDown(Keys::PageUp)) cameraDistance -= time * 0.1f;
    if (keyboardState.IsKeyDown(Keys::S) || keyboardState.IsKeyDown(Keys::PageDown)) cameraDistance += time * 0.1f;
    //limit the camera distance
    cameraDistance = std::clamp(cameraDistance, 2.0f, 60.0f);
    UpdateView();
}

void Camera::UpdateView() {
    Matrix rotation = Matrix::CreateRotationX(MathHelper::ToRadians(cameraArc)) *
                      Matrix::CreateRotationY(MathHelper::ToRadians(cameraRotation));
    Position = target + Vector3::Transform(Vector3(0, 0, cameraDistance), rotation);
    View = Matrix::CreateLookAt(Position, target, Vector3::Up);
}

}  // namespace DeferredLighting
