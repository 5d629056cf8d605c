// Colour grading shared by the example's post effects: desaturation and a vignette.
float Desaturation = 0.3;
float Vignette = 0.8;

float3 Desaturate(float3 rgb)
{
    float grey = dot(rgb, float3(0.299, 0.587, 0.114));
    return lerp(rgb, grey.xxx, Desaturation);
}

// 1 at the centre of the screen, darker towards the corners.
float VignetteFactor(float2 texCoord)
{
    float2 fromCentre = texCoord - 0.5;
    return saturate(1 - Vignette * 2 * dot(fromCentre, fromCentre));
}
