// The example's last pass: every other row of the screen a little darker, like an old monitor.
sampler TextureSampler : register(s0);

float ScreenHeight;
float Strength = 0.15;

float4 PixelShaderFunction(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : COLOR0
{
    float4 image = tex2D(TextureSampler, texCoord);
    float oddRow = fmod(floor(texCoord.y * ScreenHeight), 2);
    return float4(image.rgb * (1 - Strength * oddRow), image.a);
}

technique Scanlines
{
    pass Pass1
    {
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
