// DirectionalLight: one of the three lights of XNA 4's lit stock effects (BasicEffect,
// EnvironmentMapEffect, SkinnedEffect), a plain value the effect reads at each Apply:
//   effect.DirectionalLight0.Direction = Vector3::Normalize(Vector3(1, -1, -1));
//   effect.DirectionalLight0.Enabled = true;
// A disabled light contributes nothing (its colours are sent as zero). Direction is used as given
// (XNA does not normalise it either): it points from the light into the scene.
#pragma once

#include "fxport/math.h"

namespace fxport {

struct DirectionalLight {
    bool Enabled = false;
    Vector3 Direction = Vector3(0, 0, -1);
    Vector3 DiffuseColor = Vector3(1, 1, 1);
    Vector3 SpecularColor = Vector3(0, 0, 0);
};

}  // namespace fxport
