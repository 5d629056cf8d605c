/// <summary>
/// A Spot Light with shadows
/// </summary>
// Lights.SpotLight (seed 000, chapter 4).
#pragma once

#include <memory>

#include "deferred/xna.h"

namespace TheCansinDeferredRenderer::Lights {

class SpotLight {
    //Position
    Vector3 position;
    //Direction
    Vector3 direction;
    //Color
    Vector4 color;
    //Intensity
    float intensity;
    //NearPlane
    float nearPlane;
    //FarPlane
    float farPlane;
    //FOV
    float FOV;
    //Is this Light with Shadows?
    bool isWithShadows;
    //Shadow Map Resoloution
    int shadowMapResoloution;
    //DepthBias for the Shadowing... (1.0f / 2000.0f)
    float depthBias;
    //World(for geometry in LightMapping phase...)
    Matrix world;
    //View
    Matrix view;
    //Projection
    Matrix projection;
    //Shadow Map
    std::unique_ptr<RenderTarget2D> shadowMap;
    //Attenuation Texture
    Texture2D* attenuationTexture;

public:
    // #region Get Functions
    //Get Position
    Vector3 getPosition() const { return position; }
    //Get Direction
    Vector3 getDirection() const { return direction; }
    //Get Color
    Vector4 getColor() const { return color; }
    //Get Intensity
    float getIntensity() const { return intensity; }
    //Get NearPlane
    float getNearPlane() const { return nearPlane; }
    //Get FarPlane
    float getFarPlane() const { return farPlane; }
    //Get FOV
    float getFOV() const { return FOV; }
    //Get IsWithShadows
    bool getIsWithShadows() const { return isWithShadows; }
    //Get ShadowMapResoloution
    // fxport: the seed caps at 2048; the cap is 4096 here (XNA HiDef's largest texture) so that
    // DemoSettings::spotShadowMapSize can sweep up to it. The seed's 2048 is unchanged.
    int getShadowMapResoloution() const {
        if (shadowMapResoloution < 4096)
            return shadowMapResoloution;
        else
            return 4096;
    }
    //Get DepthBias
    float getDepthBias() const { return depthBias; }
    //Get World
    Matrix getWorld() const { return world; }
    //Get View
    Matrix getView() const { return view; }
    //Get Projection
    Matrix getProjection() const { return projection; }
    //Get ShadowMap
    // fxport: nullptr until the light's shadow map is first drawn (MakeShadowMap).
    RenderTarget2D* getShadowMap() const { return shadowMap.get(); }
    //Get Attenuation Texture
    Texture2D* getAttenuationTexture() const { return attenuationTexture; }
    // #endregion

    // #region Set Functions
    //Set Position
    void setPosition(Vector3 position) { this->position = position; }
    //Set Direction
    void setDirection(Vector3 direction) {
        direction.Normalize();
        this->direction = direction;
    }
    //Set Color
    void setColor(Vector4 color) { this->color = color; }
    void setColor(Color color) { this->color = color.ToVector4(); }
    //Set Intensity
    void setIntensity(float intensity) { this->intensity = intensity; }
    //Set isWithShadows
    void setIsWithShadows(bool iswith) { this->isWithShadows = iswith; }
    //Set DepthBias
    void setDepthBias(float bias) { this->depthBias = bias; }
    //Set Attenuation Texture
    void setAttenuationTexture(Texture2D* attenuationTexture) { this->attenuationTexture = attenuationTexture; }
    // #endregion

    //Constructor
    SpotLight(GraphicsDevice& GraphicsDevice, Vector3 Position, Vector3 Direction, Vector4 Color, float Intensity,
              bool isWithShadows, int ShadowMapResoloution, Texture2D* AttenuationTexture);

    //Calculate the Cosine of the LightAngle
    float LightAngleCos() const;

    //Update
    void Update();

    // fxport: the seed makes the shadow map in the constructor, for every spot light; here it is
    // made the first time a shadow map is drawn for the light (LightManager::DrawShadowMaps), so a
    // light that never casts shadows, or is never seen, has none. Returns the map.
    RenderTarget2D& MakeShadowMap();

private:
    GraphicsDevice* graphicsDevice;
};

}  // namespace TheCansinDeferredRenderer::Lights
