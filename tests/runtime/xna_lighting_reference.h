// XNA's directional-light equations in double, shared by the stock-effect and Model pixel tests
// (written from XNA's documentation, independently of runtime/graphics/shaders).
#pragma once

#include <algorithm>
#include <cmath>

#include "cpu_raster.h"
#include "fxport/graphics/effect_interfaces.h"
#include "fxport/math.h"

namespace fxport::stock_test {

// Three directional lights (defaults: the tests' own rig, the third one off).
struct Lights {
    bool enabled[3] = {true, true, false};
    Vector3 direction[3] = {Vector3::Normalize(Vector3(-0.5f, -0.6f, -0.7f)), Vector3::Normalize(Vector3(0.8f, 0.2f, -0.3f)),
                            Vector3::Normalize(Vector3(0.1f, 0.9f, 0.2f))};
    Vector3 diffuse[3] = {Vector3(0.9f, 0.8f, 0.6f), Vector3(0.2f, 0.3f, 0.5f), Vector3(0.4f, 0.4f, 0.4f)};
    Vector3 specular[3] = {Vector3(0.7f, 0.7f, 0.6f), Vector3(0.3f, 0.2f, 0.1f), Vector3(1, 1, 1)};
};

struct Material {
    D3 diffuse{1, 1, 1}, emissive{0, 0, 0}, specular{1, 1, 1}, ambient{0, 0, 0};
    double specularPower = 16, alpha = 1;
};

struct LightResult {
    D3 diffuse, specular;
};

// Lambert + Blinn-Phong over the enabled lights; diffuse * material + emissive + ambient * diffuse,
// everything premultiplied by alpha (XNA's BasicEffect material).
// The highlight switches on where N.L crosses 0 (XNA's equations are discontinuous there): a
// pixel shaded within 2e-3 of that is reported through `nearTerminator` and left out.
inline LightResult light(const Lights& lights, const Material& m, D3 toEye, D3 normal, bool* nearTerminator = nullptr) {
    D3 diffuse, specular;
    for (int i = 0; i < 3; ++i) {
        if (!lights.enabled[i]) continue;
        const D3 toLight = -toD3(lights.direction[i]);
        const double nDotL = dot(normal, toLight);
        if (nearTerminator && std::fabs(nDotL) < 2e-3) *nearTerminator = true;
        if (nDotL < 0) continue;
        const double nDotH = std::max(dot(normal, normalize(toEye + toLight)), 0.0);
        diffuse = diffuse + toD3(lights.diffuse[i]) * nDotL;
        specular = specular + toD3(lights.specular[i]) * std::pow(nDotH, m.specularPower);
    }
    return {(diffuse * m.diffuse + m.emissive + m.ambient * m.diffuse) * m.alpha, specular * m.specular};
}

// Copies what an effect was given back into the reference's light list (EnableDefaultLighting).
inline Lights lightsOf(const IEffectLights& effect) {
    Lights l;
    const DirectionalLight* all[3] = {&effect.DirectionalLight0, &effect.DirectionalLight1, &effect.DirectionalLight2};
    for (int i = 0; i < 3; ++i) {
        l.enabled[i] = all[i]->Enabled;
        l.direction[i] = all[i]->Direction;
        l.diffuse[i] = all[i]->DiffuseColor;
        l.specular[i] = all[i]->SpecularColor;
    }
    return l;
}

}  // namespace fxport::stock_test
