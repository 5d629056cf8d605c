// RECONSTRUCTED by fxport: Part 7 of the tutorial (spot light unwrap) is not
// in the source text. Rebuilt from Unwrap.fx (Part 4) and the parameters the
// LightRenderer sets; see fxport-changes/lighting2d.md.

#define PI 3.14159265

float2 LightPos;

float TextureWidth;

float TextureHeight;

float DiagonalLength;

float MinAngle;

float MaxAngle;

sampler shadowCastersSampler  : register(s0);

float4 PixelShaderFunction(float2 texCoord : TEXCOORD0) : COLOR0
{
    float rayAngle = lerp(MinAngle, MaxAngle, texCoord.x);

    float sinTheta, cosTheta;

    sincos(rayAngle, sinTheta, cosTheta);

    float2 norm1 = float2(sinTheta, cosTheta);

    float LightDist;

    if (cosTheta == 0)
        LightDist = abs((((sinTheta + 1) / 2.0) * TextureWidth) - LightPos.x);
    else if (sinTheta == 0)
        LightDist = abs((((cosTheta + 1) / 2.0) * TextureHeight) - LightPos.y);
    else
    {
        float4 hit = float4(-LightPos.y / cosTheta, -LightPos.x / sinTheta, (TextureHeight - LightPos.y) / cosTheta, (TextureWidth - LightPos.x) / sinTheta);

        hit = (hit < 0) ? 2 * TextureWidth : hit;

        LightDist = min(min(hit.x, hit.z), min(hit.y, hit.w));
    }

    LightDist = mul(LightDist, texCoord.y);

    norm1 = mul(norm1, LightDist);

    float4 sample1 = tex2D(shadowCastersSampler, float2((LightPos.x + norm1.x) / TextureWidth, (LightPos.y + norm1.y) / TextureHeight));

    return float4((sample1.a < 0.01) ? 1 : LightDist / DiagonalLength, 0, 0, 1);
}

technique Technique1
{
    pass Pass1
    {
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
