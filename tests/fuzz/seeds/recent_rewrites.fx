// A fuzz seed (tests/fuzz/make-corpus): one effect reaching the rewrites added last, so that the
// harnesses mutate them from the start: static initializers calling functions, quotes in a skipped
// #if group, min-precision matrix names, scalar ByteAddress stores, entry attributes in another
// case, gathers with four offsets, struct <-> array conversions, flat initializer lists with
// non-literal items, GetDimensions on a parameter and matrix products inside brackets.
#if 0
#error it's not valid anymore
#endif

float4x4 World;
float Scale;
Texture2D Tex;
SamplerState Linear;
RWByteAddressBuffer Output;

float twice(float x) { return x * 2; }
static float Doubled = twice(0.25) + 0.5;

struct Pair { float a; float b; };

struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; };

V VS(float4 p : POSITION, float2 uv : TEXCOORD0) {
    V o;
    o.p = mul(p, World);
    o.uv = uv;
    return o;
}

[MaxVertexCount(3)]
void GS(triangle V i[3], inout TriangleStream<V> s) {
    for (int k = 0; k < 3; ++k) s.Append(i[k]);
    s.RestartStrip();
}

float2 size(Texture2D t) {
    float w, h;
    t.GetDimensions(w, h);
    return float2(w, h);
}

float4 PS(V v) : SV_Target {
    min16float2x2 m = min16float2x2(1, 0, 0, 1);
    float2x2 n = float2x2(Scale, 1, 2, 3);
    float pick = (mul(m, n))[1][0];
    float2 both = float2(v.uv.x, Doubled);
    Pair pair = (Pair)both;
    float2 back = (float2)pair;
    float w[4] = { v.uv.x, v.uv.y, pick, back.y };
    float4 g = Tex.GatherRed(Linear, v.uv, int2(0, 0), int2(1, 0), int2(0, 1), int2(1, 1));
    return g + float4(w[0], w[1], w[2], w[3]) + size(Tex).xyxy * 0.001;
}

[NumThreads(1, 1, 1)]
void Broken() {}

[numthreads(4, 1, 1)]
void CS(uint3 id : SV_DispatchThreadID) {
    Output.Store2(id.x * 8, id.x);
    Output.Store(id.x * 8 + 4, asuint(Doubled));
}

technique11 Draw {
    pass P0 {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(CompileShader(gs_5_0, GS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}

technique11 Compute {
    pass P0 { SetComputeShader(CompileShader(cs_5_0, CS())); }
}
