// RECONSTRUCTED by fxport: Part 8 of the tutorial (spot light light map) is
// not in the source text. Rebuilt from PointLight.fx (Part 5), the Part 8
// outline and the parameters the LightRenderer sets; see
// fxport-changes/lighting2d.md.

float2 ScreenDimensions;

float2 LightPos;

float DiagonalLength;

float Radius;

float LightPow;

float Bias;

float OuterMinAngle;

float OuterMaxAngle;

float CenterAngle;

float HalfInnerArc;

float HalfOuterArc;

float AngleBias;

sampler occlusionSampler : register(s0);

float4 PixelShaderFunction(float2 Texcoord : TEXCOORD0) : COLOR0
{
    float2 screenCoords = float2(ScreenDimensions.x * Texcoord.x, ScreenDimensions.y * Texcoord.y);

    float2 lightToPix = screenCoords - LightPos;

    float pixDist = length(lightToPix);

    float pixAngle = acos(dot(float2(0, 1), normalize(lightToPix)));

    pixAngle = (lightToPix.x < 0) ? -pixAngle : pixAngle;

    pixAngle += (pixAngle < 0) ? AngleBias : 0;

    float occlusionU = (pixAngle - OuterMinAngle) / (OuterMaxAngle - OuterMinAngle);

    float4 occlusionDist = tex2D(occlusionSampler, float2(occlusionU, 0.5));

    occlusionDist.xyz = mul(occlusionDist.xyz, DiagonalLength);

    float dist = occlusionDist.r;

    float angleDiff = abs(pixAngle - CenterAngle);

    float3 lighting = (1 - (pixDist / Radius)) * LightPow;

    lighting *= (angleDiff < HalfInnerArc) ? 1 : saturate((HalfOuterArc - angleDiff) / (HalfOuterArc - HalfInnerArc));

    if (angleDiff < HalfOuterArc && pixDist - Bias < min(Radius, dist))
        return float4(lighting, 1);
    return float4(0, 0, 0, 1);
}

technique Technique1
{
    pass Pass1
    {
        PixelShader = compile ps_2_0 PixelShaderFunction();
    }
}
