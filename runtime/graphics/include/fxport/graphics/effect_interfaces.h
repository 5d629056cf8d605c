// IEffectMatrices, IEffectLights, IEffectFog: XNA 4's interfaces for what several effects share, so
// that a host (or Model) sets matrices, lights or fog on any effect that has them:
//   if (auto* matrices = dynamic_cast<IEffectMatrices*>(part.Effect)) matrices->World = world;
//
// fxport's rule for C# properties: a property whose value is only read when the effect is applied
// is a public field (effect.World = m; reads and writes as in C#); the effect turns the fields into
// shader constants in Effect::OnApply. So these interfaces hold the fields themselves: the stock
// effects derive from them, and a user's Effect subclass may too (and read them in its OnApply).
#pragma once

#include "fxport/graphics/directional_light.h"
#include "fxport/math.h"

namespace fxport {

class IEffectMatrices {
public:
    Matrix World = Matrix::Identity;
    Matrix View = Matrix::Identity;
    Matrix Projection = Matrix::Identity;

protected:
    IEffectMatrices() = default;
    IEffectMatrices(const IEffectMatrices&) = default;
    IEffectMatrices& operator=(const IEffectMatrices&) = default;
    virtual ~IEffectMatrices() = default;
};

class IEffectLights {
public:
    DirectionalLight DirectionalLight0;
    DirectionalLight DirectionalLight1;
    DirectionalLight DirectionalLight2;
    Vector3 AmbientLightColor = Vector3(0, 0, 0);
    bool LightingEnabled = false;

    // XNA's three-light rig (key, fill and back light, all three enabled) and its ambient colour;
    // turns lighting on. The material's colours are left alone.
    virtual void EnableDefaultLighting();

protected:
    IEffectLights() = default;
    IEffectLights(const IEffectLights&) = default;
    IEffectLights& operator=(const IEffectLights&) = default;
    virtual ~IEffectLights() = default;
};

class IEffectFog {
public:
    // XNA's linear fog: factor = saturate((depth - FogStart) / (FogEnd - FogStart)), depth = the
    // vertex's distance in front of the camera (-z in view space), computed per vertex; the colour
    // becomes lerp(colour, FogColor * alpha, factor). FogStart == FogEnd fogs everything.
    bool FogEnabled = false;
    float FogStart = 0;
    float FogEnd = 1;
    Vector3 FogColor = Vector3(0, 0, 0);

protected:
    IEffectFog() = default;
    IEffectFog(const IEffectFog&) = default;
    IEffectFog& operator=(const IEffectFog&) = default;
    virtual ~IEffectFog() = default;
};

}  // namespace fxport
