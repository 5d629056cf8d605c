// Lights.DirectionalLight (seed 000, chapter 3): a direction, a colour and an intensity.
#pragma once

#include "deferred/xna.h"

namespace TheCansinDeferredRenderer::Lights {

class DirectionalLight {
    //Direction
    Vector3 direction;
    //Color
    Vector4 color;
    //Intensity
    float intensity;

public:
    // #region Get Functions
    //Get Direction
    Vector3 getDirection() const { return direction; }
    //Get Color
    Vector4 getColor() const { return color; }
    //Get Intensity
    float getIntensity() const { return intensity; }
    // #endregion

    // #region Set Functions
    //Set Direction
    void setDirection(Vector3 dir) { dir.Normalize(); this->direction = dir; }
    //Set Color
    void setColor(Vector4 color) { this->color = color; }
    //Set Color
    void setColor(Color color) { this->color = color.ToVector4(); }
    //Set Intensity
    void setIntensity(float intensity) { this->intensity = intensity; }
    // #endregion

    //Constructor
    DirectionalLight(Vector3 Direction, Vector4 Color, float Intensity);
    //Constructor
    DirectionalLight(Vector3 Direction, Color Color, float Intensity);
};

}  // namespace TheCansinDeferredRenderer::Lights
