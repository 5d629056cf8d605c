// The hull, patch-constant, domain and pixel stages of one quad patch, shared by the tessellation tests
// of the translator (tests/xlate), the XNA runtime (tests/runtime) and the D3D11 front end (tests/d3d11).
// Each test writes its own declarations before it (ControlPoint, PatchConstants, DomainOut, Factor and a
// VS), since the three front ends feed the patch differently: a `float Factor` global or a cbuffer, a
// POSITION or TEXCOORD0 control point. The domain shader's colour (u, v, u*v) is what their CPU checks
// compute; u*v is only within bounds when the hull's factor reached the tessellator.
#pragma once

namespace fxport::test {

// Struct and constant declarations the runtime and translator tests put before kQuadPatchStages.
inline const char* const kQuadPatchDeclarations = R"(struct ControlPoint { float3 pos : POSITION; };
struct PatchConstants { float edges[4] : SV_TessFactor; float inside[2] : SV_InsideTessFactor; };
struct DomainOut { float4 pos : SV_Position; float4 color : COLOR0; };
float Factor;

ControlPoint VS(float3 pos : POSITION) { ControlPoint o; o.pos = pos; return o; }
)";

inline const char* const kQuadPatchStages = R"(
PatchConstants Constants(InputPatch<ControlPoint, 4> patch)
{
    PatchConstants o;
    o.edges[0] = o.edges[1] = o.edges[2] = o.edges[3] = Factor;
    o.inside[0] = o.inside[1] = Factor;
    return o;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("Constants")]
ControlPoint HS(InputPatch<ControlPoint, 4> patch, uint i : SV_OutputControlPointID) { return patch[i]; }

[domain("quad")]
DomainOut DS(PatchConstants pc, float2 uv : SV_DomainLocation, const OutputPatch<ControlPoint, 4> patch)
{
    DomainOut o;
    o.pos = float4(lerp(lerp(patch[0].pos, patch[1].pos, uv.x), lerp(patch[3].pos, patch[2].pos, uv.x), uv.y), 1);
    o.color = float4(uv, uv.x * uv.y, 1);
    return o;
}

float4 PS(DomainOut i) : SV_Target { return i.color; }
)";

}  // namespace fxport::test
