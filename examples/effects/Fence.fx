// The fence game's lattice: a textured quad whose texels are wooden boards or holes. The holes are
// cut by the D3D9 alpha test in the pass (fxport emulates it with a pixel-shader variant that
// discards), so the quad needs no blending and no sorting, as XNA 3/4 games drew foliage and fences.
float4x4 World;
float4x4 View;
float4x4 Projection;
float3 Tint = float3(1, 1, 1);

texture FenceTexture;
sampler FenceSampler = sampler_state
{
    Texture = <FenceTexture>;
    MinFilter = Point;
    MagFilter = Point;
    MipFilter = None;
    AddressU = Clamp;
    AddressV = Clamp;
};

struct VertexShaderInput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
};

struct VertexShaderOutput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
};

VertexShaderOutput VertexShaderFunction(VertexShaderInput input)
{
    VertexShaderOutput output;
    float4 worldPosition = mul(input.Position, World);
    float4 viewPosition = mul(worldPosition, View);
    output.Position = mul(viewPosition, Projection);
    output.TexCoord = input.TexCoord;
    return output;
}

float4 PixelShaderFunction(VertexShaderOutput input) : COLOR0
{
    float4 color = tex2D(FenceSampler, input.TexCoord);
    return float4(color.rgb * Tint, color.a);
}

technique Fence
{
    pass Pass1
    {
        // Keep a pixel only where the texel's alpha is above 128/255: boards (255) and knots (192)
        // stay, holes (0) and knotholes (96) let the scene behind show.
        AlphaTestEnable = true;
        AlphaFunc = Greater;
        AlphaRef = 128;
        CullMode = None;

        VertexShader = compile vs_2_0 VertexShaderFunction();
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
