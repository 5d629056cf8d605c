/// <summary>
/// A Point Light
/// </summary>
// Lights.PointLight (seed 000, chapter 5).
#pragma once

#include <memory>

#include "deferred/xna.h"

namespace TheCansinDeferredRenderer::Lights {

class PointLight {
    //Position
    Vector3 position;
    //Radius
    float radius;
    //Color
    Vector4 color;
    //Intensity
    float intensity;
    //ShadowMap
    std::unique_ptr<RenderTargetCube> shadowMap;
    //Is this Light with Shadows?
    bool isWithShadows;
    //Shadow Map Resoloution
    int shadowMapResoloution;

public:
    // #region Get Functions
    //Get Position
    Vector3 getPosition() const { return position; }
    //Get Radius
    float getRadius() const { return radius; }
    //Get Color
    Vector4 getColor() const { return color; }
    //Get Intensity
    float getIntensity() const { return intensity; }
    //Get IsWithShadows
    bool getIsWithShadows() const { return isWithShadows; }
    //Get ShadowMapResoloution
    int getShadowMapResoloution() const {
        if (shadowMapResoloution < 2048) return shadowMapResoloution;
        else return 2048;
    }
    //Get DepthBias
    float getDepthBias() const { return (1.0f / (20 * radius)); }
    //Get ShadowMap
    // fxport: nullptr until the light's shadow map is first drawn (MakeShadowMap).
    RenderTargetCube* getShadowMap() const { return shadowMap.get(); }
    // #endregion

    // #region Set Functions
    //Set Position
    void setPosition(Vector3 position) { this->position = position; }
    //Set Radius
    void setRadius(float radius) { this->radius = radius; }
    //Set Color
    void setColor(Color color) { this->color = color.ToVector4(); }
    //Set Color
    void setColor(Vector4 color) { this->color = color; }
    //Set Intensity
    void setIntensity(float intensity) { this->intensity = intensity; }
    //Set isWithShadows
    void setIsWithShadows(bool shadows) { this->isWithShadows = shadows; }
    // #endregion

    //Constructor
    PointLight(GraphicsDevice& GraphicsDevice, Vector3 Position, float Radius, Vector4 Color, float Intensity,
               bool isWithShadows, int shadowMapResoloution);

    //Create World Matrix for Deferred Rendering Geometry
    Matrix World() const;

    // fxport: the seed makes the cube map in the constructor; here it is made the first time the
    // light's shadow map is drawn (see SpotLight::MakeShadowMap). Returns the map.
    RenderTargetCube& MakeShadowMap();

private:
    GraphicsDevice* graphicsDevice;
};

}  // namespace TheCansinDeferredRenderer::Lights
