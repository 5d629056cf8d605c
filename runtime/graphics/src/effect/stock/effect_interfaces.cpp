// IEffectLights::EnableDefaultLighting: XNA 4's key/fill/back light rig (the values XNA documents
// for its stock effects' EnableDefaultLighting).
#include "fxport/graphics/effect_interfaces.h"

namespace fxport {

void IEffectLights::EnableDefaultLighting() {
    LightingEnabled = true;
    AmbientLightColor = Vector3(0.05333332f, 0.09882354f, 0.1819608f);

    // Key light: warm, from above-right-front, with a matching highlight.
    DirectionalLight0.Direction = Vector3(-0.5265408f, -0.5735765f, -0.6275069f);
    DirectionalLight0.DiffuseColor = Vector3(1.0f, 0.9607844f, 0.8078432f);
    DirectionalLight0.SpecularColor = Vector3(1.0f, 0.9607844f, 0.8078432f);
    DirectionalLight0.Enabled = true;

    // Fill light: orange, from below-left-behind, no highlight.
    DirectionalLight1.Direction = Vector3(0.7198464f, 0.3420201f, 0.6040227f);
    DirectionalLight1.DiffuseColor = Vector3(0.9647059f, 0.7607844f, 0.4078432f);
    DirectionalLight1.SpecularColor = Vector3(0, 0, 0);
    DirectionalLight1.Enabled = true;

    // Back light: cool rim from behind.
    DirectionalLight2.Direction = Vector3(0.4545195f, -0.7660444f, 0.4545195f);
    DirectionalLight2.DiffuseColor = Vector3(0.3231373f, 0.3607844f, 0.3937255f);
    DirectionalLight2.SpecularColor = Vector3(0.3231373f, 0.3607844f, 0.3937255f);
    DirectionalLight2.Enabled = true;
}

}  // namespace fxport
