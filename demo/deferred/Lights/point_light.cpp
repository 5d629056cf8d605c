#include "deferred/Lights/point_light.h"

namespace TheCansinDeferredRenderer::Lights {

//Constructor
PointLight::PointLight(GraphicsDevice& GraphicsDevice, Vector3 Position, float Radius, Vector4 Color,
                       float Intensity, bool isWithShadows, int shadowMapResoloution) {
    //Set Position
    setPosition(Position);
    //Set Radius
    setRadius(Radius);
    //Set Color
    setColor(Color);
    //Set Intensity
    setIntensity(Intensity);
    //Set isWithShadows
    this->isWithShadows = isWithShadows;
    //Set shadowMapResoloution
    this->shadowMapResoloution = shadowMapResoloution;
    //Make ShadowMap
    // fxport: made on first use (MakeShadowMap).
    graphicsDevice = &GraphicsDevice;
}

RenderTargetCube& PointLight::MakeShadowMap() {
    // The seed's map; made again if the resolution changed since.
    if (!shadowMap || shadowMap->Size() != getShadowMapResoloution()) {
        shadowMap = std::make_unique<RenderTargetCube>(*graphicsDevice, getShadowMapResoloution(), false,
                                                       SurfaceFormat::Single, DepthFormat::Depth24Stencil8);
        shadowMap->Name = "PointLight.shadowMap";
    }
    return *shadowMap;
}

//Create World Matrix for Deferred Rendering Geometry
Matrix PointLight::World() const {
    //Make Scaling Matrix
    Matrix scale = Matrix::CreateScale(radius / 100.0f);
    //Make Translation Matrix
    Matrix translation = Matrix::CreateTranslation(position);
    //Return World Transform
    return (scale * translation);
}

}  // namespace TheCansinDeferredRenderer::Lights
