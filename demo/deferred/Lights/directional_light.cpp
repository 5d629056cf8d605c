#include "deferred/Lights/directional_light.h"

namespace TheCansinDeferredRenderer::Lights {

//Constructor
DirectionalLight::DirectionalLight(Vector3 Direction, Vector4 Color, float Intensity) {
    setDirection(Direction);
    setColor(Color);
    setIntensity(Intensity);
}

//Constructor
DirectionalLight::DirectionalLight(Vector3 Direction, Color Color, float Intensity) {
    setDirection(Direction);
    setColor(Color);
    setIntensity(Intensity);
}

}  // namespace TheCansinDeferredRenderer::Lights
