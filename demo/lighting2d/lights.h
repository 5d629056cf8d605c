// Light, PointLight, SpotLight: the seed's Light.cs / PointLight.cs / SpotLight.cs (seed 002, Part 3),
// with GetBiasedAngle from the public LightRenderer port (docs/lighting2d-host-notes.md).
#pragma once

#include <cmath>

#include "fxport/math.h"

namespace _2DLightingSystem {

using fxport::Color;
using fxport::Vector2;

class Light {
public:
    Vector2 Position;
    float Power = 0.f;
    Color color;
    float radius = 0.f;

    explicit Light(Vector2 pos) : Light(pos, 0.f, Color::White) {}
    Light(Vector2 pos, float power, Color color) : Position(pos), Power(power), color(color) {}
    virtual ~Light() = default;
};

class PointLight : public Light {
public:
    explicit PointLight(Vector2 pos) : Light(pos, 0.f, Color::White) {}
    PointLight(Vector2 pos, float power, float radius) : Light(pos, 0.f, Color::White) {
        // The seed passes 0 as the power here (it drops `power`); kept as written.
        (void)power;
        this->radius = radius;
    }
    PointLight(Vector2 pos, Color color) : Light(pos, 0.f, color) {}
    PointLight(Vector2 pos, float power, float radius, Color color) : Light(pos, power, color) { this->radius = radius; }
};

class SpotLight : public Light {
public:
    Vector2 direction;
    float innerAngle;
    float outerAngle;

    SpotLight(Vector2 pos, Vector2 dir, float inner, float outer, float power, float _radius, Color col)
        : Light(pos, power, col), direction(dir), innerAngle(inner), outerAngle(outer) {
        radius = _radius;
    }

    // 0 when the outer arc contains the downward direction (+y, angle 0), else 2*PI: added to
    // negative angles so that the arc's angles are continuous.
    float GetAngleBias() const {
        float diffAngle = std::acos(Vector2::Dot(direction, Vector2::UnitY));
        // acos of a dot product that rounds past +-1 is NaN: the seed's fallback (0 down, PI up).
        if (std::isnan(diffAngle)) diffAngle = float(((sign(-direction.Y) + 1) / 2.f) * M_PI);
        if (diffAngle - (outerAngle / 2.f) < 0) return 0;
        return fxport::MathHelper::Pi * 2.f;
    }

    // [port] acos(dot(dir, UnitY)) * Sign(dir.X), plus AngleBias if negative. fxport fix of the
    // port's host bug: Sign(0) == 0 made a light pointing straight up (0,-1) get angle 0 instead of
    // PI; here X == 0 counts as positive. The NaN case is handled as in GetAngleBias.
    float GetBiasedAngle() const {
        float angle = std::acos(std::fmax(-1.f, std::fmin(1.f, Vector2::Dot(direction, Vector2::UnitY))));
        angle *= direction.X < 0 ? -1.f : 1.f;
        if (angle < 0) angle += GetAngleBias();
        return angle;
    }

private:
    static int sign(float v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
};

}  // namespace _2DLightingSystem
