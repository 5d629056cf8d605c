// SpriteEffect.fx: SpriteBatch's built-in effect, written the way XNA 4's stock SpriteEffect is
// (same parameter, sampler register, entry points, semantics and shader models), so that a custom
// pixel-shader-only effect given to SpriteBatch.Begin links against this vertex shader exactly as
// it does on XNA.
//
// SM2 on purpose: XNA ran it on Direct3D 9, and fxport gives vs_2_0 shaders D3D9's pixel centres.
// SpriteBatch puts into MatrixTransform what XNA puts there (the caller's transformMatrix times a
// half-pixel shift and the viewport's orthographic projection); see sprite_batch.h.
//
// Embedded into fxport_graphics at build time (sprite_effect.cmake) and compiled at run time as
// "<builtin>/SpriteEffect.fx".

float4x4 MatrixTransform;

sampler TextureSampler : register(s0);

void SpriteVertexShader(inout float4 color    : COLOR0,
                        inout float2 texCoord : TEXCOORD0,
                        inout float4 position : POSITION0)
{
    position = mul(position, MatrixTransform);
}

float4 SpritePixelShader(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : COLOR0
{
    return tex2D(TextureSampler, texCoord) * color;
}

technique SpriteBatch
{
    pass
    {
        VertexShader = compile vs_2_0 SpriteVertexShader();
        PixelShader  = compile ps_2_0 SpritePixelShader();
    }
}
