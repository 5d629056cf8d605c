// ModelMaterial.fx: the material of a ModelMeshPart loaded from glTF (see fxport/graphics/model.h).
//
// A Model gives each part an Effect made from this file, so that ported XNA code can read the
// part's textures the way the tutorials do:
//     GBuffer.Parameters["Texture"].SetValue(part.Effect->Parameters["Texture"].GetValueTexture2D());
// The three texture parameters are the point; the technique only makes it a complete, drawable
// effect (unlit: the albedo texture, with the specular map in alpha like GBuffer.fx).

float4x4 World;
float4x4 View;
float4x4 Projection;

// glTF baseColorTexture (default: 1x1 white)
texture Texture;
// glTF normalTexture (default: 1x1 flat normal (128, 128, 255))
texture NormalMap;
// KHR_materials_specular specularTexture, else extras.fxportSpecularMap (default: 1x1 black)
texture SpecularMap;

sampler AlbedoSampler = sampler_state
{
    texture = <Texture>;
    MINFILTER = LINEAR;
    MAGFILTER = LINEAR;
    MIPFILTER = LINEAR;
    ADDRESSU = WRAP;
    ADDRESSV = WRAP;
};

sampler NormalSampler = sampler_state
{
    texture = <NormalMap>;
    MINFILTER = LINEAR;
    MAGFILTER = LINEAR;
    MIPFILTER = LINEAR;
    ADDRESSU = WRAP;
    ADDRESSV = WRAP;
};

sampler SpecularSampler = sampler_state
{
    texture = <SpecularMap>;
    MINFILTER = LINEAR;
    MAGFILTER = LINEAR;
    MIPFILTER = LINEAR;
    ADDRESSU = WRAP;
    ADDRESSV = WRAP;
};

struct VSI
{
    float4 Position : POSITION0;
    float3 Normal : NORMAL0;
    float2 UV : TEXCOORD0;
    float3 Tangent : TANGENT0;
    float3 BiTangent : BINORMAL0;
};

struct VSO
{
    float4 Position : POSITION0;
    float2 UV : TEXCOORD0;
    float3 Normal : TEXCOORD1;
};

VSO VS(VSI input)
{
    VSO output;
    float4 worldPosition = mul(input.Position, World);
    float4 viewPosition = mul(worldPosition, View);
    output.Position = mul(viewPosition, Projection);
    output.UV = input.UV;
    output.Normal = mul(input.Normal, (float3x3)World);
    return output;
}

float4 PS(VSO input) : COLOR0
{
    float4 albedo = tex2D(AlbedoSampler, input.UV);
    // Read the other two maps too, so that every texture parameter is live in the shader.
    float3 normal = tex2D(NormalSampler, input.UV).xyz * 2.0f - 1.0f;
    float specular = tex2D(SpecularSampler, input.UV).x;
    albedo.rgb *= saturate(0.5f + 0.5f * normal.z);
    albedo.a = specular;
    return albedo;
}

technique Default
{
    pass p0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
