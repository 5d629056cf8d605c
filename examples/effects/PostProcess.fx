// The example's colour grading: a pixel-shader-only effect for SpriteBatch (XNA 4 style).
#include "Grading.fxh"

sampler TextureSampler : register(s0);

float4 PixelShaderFunction(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : COLOR0
{
    float4 scene = tex2D(TextureSampler, texCoord);
    // Alpha is left 0, as many XNA post effects leave it: a screen ignores it, and so does
    // SaveBackBufferAsPng.
    return float4(Desaturate(scene.rgb) * VignetteFactor(texCoord), 0);
}

technique PostProcess
{
    pass Pass1
    {
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
