// The example's post-process: a pixel-shader-only effect for SpriteBatch (XNA 4 style), which
// desaturates the scene a little and darkens its corners.
sampler TextureSampler : register(s0);

float Desaturation = 0.3;
float Vignette = 0.8;

float4 PixelShaderFunction(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : COLOR0
{
    float4 scene = tex2D(TextureSampler, texCoord);
    float grey = dot(scene.rgb, float3(0.299, 0.587, 0.114));
    float3 rgb = lerp(scene.rgb, grey.xxx, Desaturation);
    float2 fromCentre = texCoord - 0.5;
    rgb *= saturate(1 - Vignette * 2 * dot(fromCentre, fromCentre));
    // Alpha is left 0, as many XNA post effects leave it: a screen ignores it, and so does
    // SaveBackBufferAsPng.
    return float4(rgb, 0);
}

technique PostProcess
{
    pass Pass1
    {
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
