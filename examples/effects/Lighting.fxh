// Lighting shared by the example's effects: one directional light and an ambient term.
float3 LightDirection = float3(-0.5, -0.7, -0.5);  // where the light travels (normalised here)
float Ambient = 0.25;

float Lambert(float3 normal)
{
    return Ambient + (1 - Ambient) * saturate(dot(normal, -normalize(LightDirection)));
}
