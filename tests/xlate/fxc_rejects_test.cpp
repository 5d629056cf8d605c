// HLSL that fxc rejects and glslang accepts: each rule of the fxc-check families added for
// issue 23 (effect_keywords, patch_objects, overload_ambiguity, overload_ties, ternary_shapes,
// uniform_initializers, uav_rules, operand_type_rules, declaration_limits, majority_modifiers,
// switch_labels, switch `continue`, the division by an unset static, unset static resources ...)
// must stop the compile with an FX2001 error at the offending line, and a valid twin of each case
// -- the same code one step away from the rule -- must still compile, so a rule that grew too wide fails here too. Sources follow vkd3d's conformance
// sections that pin the rules (named per case).
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

struct RejectCase {
    const char* name;
    const char* profile;  // loose shader profile; nullptr: compile as an effect
    std::string invalid;  // fxc refuses it
    int line;             // where the first error must point
    const char* word;     // a word the message must hold
    std::string valid;    // one step away: fxc compiles it
    const char* validProfile = nullptr;  // the twin's profile when the step is the profile itself
    const char* id = diag::kHlsl;        // the error's id (FX1204 for the element limit, docs/limits.md; FX1403 for entry attributes)
};

void PrintTo(const RejectCase& c, std::ostream* os) { *os << c.name; }

CompiledEffect compile(const std::string& source, const char* profile) {
    CompileOptions options;
    options.useCache = false;
    if (!profile) return compileEffectSource(source, "/tmp/fxc_rejects_case.fx", options);
    return compileShaderSource(source, "/tmp/fxc_rejects_case.hlsl", {{"/tmp/fxc_rejects_case.hlsl", "main", profile}}, options);
}


// A hull shader of a tri domain with the given output topology (hull-shader-attributes).
std::string hullOfTriangles(const char* topology) {
    return std::string("struct patch_constant_data\n{\n    float edges[3] : SV_TessFactor;\n    float inside : SV_InsideTessFactor;\n};\n\n"
                       "patch_constant_data patch_constant()\n{\n    return (patch_constant_data)0;\n}\n\n[domain(\"tri\")]\n"
                       "[outputcontrolpoints(3)]\n[partitioning(\"integer\")]\n[outputtopology(\"") +
           topology + "\")]\n[patchconstantfunc(\"patch_constant\")]\nfloat4 main() : POSITION\n{\n    return 0;\n}\n";
}

const char* kHullPrelude = R"(struct data { float4 val : VAL; };
struct patch_constant_data { float edges[2] : SV_TessFactor; };
)";

std::vector<RejectCase> cases() {
    return {
        // effect-technique-fx_4: `technique` in any case is a keyword; `teChnique10` is a name.
        {"TechniqueAsVariable", "ps_4_0", "float4 main() : sv_target\n{\n    float4 teChnique = 0;\n    return teChnique;\n}\n", 3, "keyword",
         "float4 main() : sv_target\n{\n    float4 teChnique10 = 0;\n    return teChnique10;\n}\n"},
        // effect-technique-fx_4: technique10 opens a technique in lower case only.
        {"Technique10UpperCase", nullptr, "float4 main() : sv_target { return 0; }\ntEchnique10\n{\n    pass { PixelShader = compile ps_4_0 main(); }\n}\n", 2,
         "lower case", "float4 main() : sv_target { return 0; }\ntechnique10\n{\n    pass { PixelShader = compile ps_4_0 main(); }\n}\n"},
        // strings: `String` is the string type.
        {"StringAsVariable", "ps_4_0", "float4 String;\n\nfloat4 main() : sv_target { return 0; }\n", 1, "String",
         "float4 sTring;\n\nfloat4 main() : sv_target { return 0; }\n"},
        // patch-syntax: a patch is read-only.
        {"PatchElementAssigned", "ps_4_0",
         "float data[2];\nfloat4 main() : SV_TARGET\n{\n    InputPatch<float, 2> patch = data;\n    patch[0] = 3;\n    return patch[0];\n}\n", 5,
         "read-only", "float data[2];\nfloat4 main() : SV_TARGET\n{\n    InputPatch<float, 2> patch = data;\n    return patch[0];\n}\n"},
        // patch-syntax: at least one control point.
        {"PatchOfNoPoints", "ps_4_0", "InputPatch<float, 0> patch;\nfloat4 main() : SV_TARGET { return 0; }\n", 1, "control point",
         "InputPatch<float, 2> patch;\nfloat4 main() : SV_TARGET { return 0; }\n"},
        // patch-syntax: a domain shader takes an OutputPatch, not an InputPatch.
        {"DomainInputPatch", "ds_5_0",
         std::string(kHullPrelude) + "[domain(\"isoline\")]\nfloat4 main(patch_constant_data input, InputPatch<data, 2> patch) : POSITION { return 0; }\n", 4,
         "InputPatch", std::string(kHullPrelude) + "[domain(\"isoline\")]\nfloat4 main(patch_constant_data input, OutputPatch<data, 2> patch) : POSITION { return 0; }\n"},
        // function-overload: f(float) and f(float1) are defined apart but called ambiguously.
        {"ScalarAndFloat1Overloads", "ps_4_0",
         "void func(float arg) {}\nvoid func(float1 arg) {}\nfloat4 main() : sv_target\n{\n    float x = 1.0;\n    func(x);\n    return 1.0;\n}\n", 6,
         "ambiguous", "void func(float arg) {}\nvoid func(float1 arg) {}\nfloat4 main() : sv_target\n{\n    float x = 1.0;\n    return x;\n}\n"},
        // ternary: a float3 condition cannot select between float4s.
        {"TernaryConditionShape", "ps_4_0",
         "uniform float3 cond;\nuniform float4 a, b;\nfloat4 main() : sv_target\n{\n    return (cond ? a : b);\n}\n", 5, "shape",
         "uniform float4 cond;\nuniform float4 a, b;\nfloat4 main() : sv_target\n{\n    return (cond ? a : b);\n}\n"},
        // switch: `continue` in a case of a switch inside a loop.
        {"ContinueInSwitchCase", "ps_4_0",
         "uint4 v;\nfloat4 main() : sv_target\n{\n    float4 c = 1;\n    for (uint i = 0; i < v.z; i++)\n    {\n        switch (v.x)\n        {\n"
         "            case 0:\n                c += 0.1f;\n                continue;\n            default:\n                break;\n        }\n    }\n    return c;\n}\n",
         11, "continue",
         "uint4 v;\nfloat4 main() : sv_target\n{\n    float4 c = 1;\n    for (uint i = 0; i < v.z; i++)\n    {\n        switch (v.x)\n        {\n"
         "            case 0:\n                for (uint j = 0; j < v.z; j++) { c += 1; if (v.w) continue; }\n                break;\n            default:\n"
         "                break;\n        }\n    }\n    return c;\n}\n"},
        // default-values: a uniform's initial value is a literal expression.
        {"UniformInitialValueReadsUniform", "ps_4_0", "float a = 7;\nfloat4 b = {1, 2, a, 4};\nfloat4 main() : sv_target { return b; }\n", 2, "literal",
         "float a = 7;\nfloat4 b = {1, 2, 7, 4};\nfloat4 main() : sv_target { return b * a; }\n"},
        // uav-atomics: Interlocked* returns nothing.
        {"InterlockedResultUsed", "cs_5_0",
         "RWBuffer<uint> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    uint err = InterlockedAdd(u[0], 1);\n}\n", 5, "void",
         "RWBuffer<uint> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    uint old;\n    InterlockedAdd(u[0], 1, old);\n}\n"},
        // uav-atomics: the destination is a scalar int or uint.
        {"InterlockedOnUint1", "cs_5_0", "RWBuffer<uint1> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    InterlockedAdd(u[0], 1);\n}\n", 5,
         "scalar", "RWBuffer<uint> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    InterlockedAdd(u[0], 1);\n}\n"},
        // uav-atomics: cs_4_x has no typed UAVs.
        {"TypedUavInCs4", "cs_4_0", "RWBuffer<uint> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    u[0] = 1;\n}\n", 1, "cs_5_0",
         "RWBuffer<uint> u : register(u1);\n[numthreads(3, 1, 1)]\nvoid main()\n{\n    u[0] = 1;\n}\n", "cs_5_0"},
        // uav-rwtexture: a pixel shader's UAVs begin above its render targets.
        {"PixelUavOverlapsTarget", "ps_5_0",
         "RWTexture2D<float4> u : register(u1);\nfloat4 main() : sv_target1\n{\n    u[uint2(0, 0)] = 0.5;\n    return 0;\n}\n", 1, "render target",
         "RWTexture2D<float4> u : register(u2);\nfloat4 main() : sv_target1\n{\n    u[uint2(0, 0)] = 0.5;\n    return 0;\n}\n"},
        // uav-rwstructuredbuffer: structured elements hold no objects.
        {"StructuredBufferOfTextures", "ps_5_0", "struct s { Texture2D t; };\nRWStructuredBuffer<s> u;\nfloat4 main() : sv_target1 { return 0; }\n", 2,
         "objects", "struct s { float4 t; };\nRWStructuredBuffer<s> u;\nfloat4 main() : sv_target1 { return 0; }\n"},
        // effect-compile: `compile` passes literals to uniform parameters only.
        {"CompileArgumentsBeyondUniforms", nullptr,
         "float4 fun(uniform float4 a, float4 b : TEXCOORD0, uniform float4 c) : COLOR\n{\n    return a + b + c;\n}\ntechnique\n{\n    pass\n    {\n"
         "        PixelShader = compile ps_2_0 fun(1, 2, 3);\n    }\n}\n",
         9, "uniform parameters",
         "float4 fun(uniform float4 a, float4 b : TEXCOORD0, uniform float4 c) : COLOR\n{\n    return a + b + c;\n}\ntechnique\n{\n    pass\n    {\n"
         "        PixelShader = compile ps_2_0 fun(1, 2);\n    }\n}\n"},
        // constructgswithso: 2 or 6 arguments.
        {"ConstructGSWithSOArgumentCount", "ps_4_0",
         "float4 main() : sv_target { return 0; }\nGeometryShader gs2 = ConstructGSWithSO(1, 2, 3);\n", 2, "ConstructGSWithSO",
         "float4 main() : sv_target { return 0; }\nGeometryShader gs2 = ConstructGSWithSO(\"foo\", \"bar\");\n"},
        // cbuffer: once an object is placed by register(), the numbers want packoffset().
        {"CbufferManualPackingWithObjects", "ps_4_0",
         "cbuffer buffer\n{\n    float4 foo;\n    Texture2D tex : register(t1);\n}\nfloat4 main() : sv_target { return foo; }\n", 3, "packoffset",
         "cbuffer buffer\n{\n    float4 foo : packoffset(c0);\n    Texture2D tex : register(t1);\n}\nfloat4 main() : sv_target { return foo; }\n"},
        // object-references: a texture array indexed by a uniform needs SM 5.1.
        {"TextureArrayIndexedByUniform", "ps_4_0", "Texture2D tex[3];\nuniform int n;\nfloat4 main() : sv_target\n{\n    return tex[n].Load(0);\n}\n", 5,
         "uniform", "Texture2D tex[3];\nuniform int n;\nfloat4 main() : sv_target\n{\n    return tex[1].Load(0) * n;\n}\n"},
        // vector-indexing: an index is a scalar, not an int1.
        {"VectorIndexOfInt1", "ps_4_0", "float4 main() : SV_TARGET\n{\n    float4 vec = {0, 1, 2, 3};\n    int1 idx = {3};\n    return vec[idx];\n}\n", 5,
         "scalar", "float4 main() : SV_TARGET\n{\n    float4 vec = {0, 1, 2, 3};\n    int2 idx = {1, 2};\n    return vec[idx.y];\n}\n"},
        // switch: below SM4 the selector of a switch is an integer.
        {"FloatSwitchSelectorInSm3", "ps_3_0",
         "float4 v;\nfloat4 main() : sv_target\n{\n    float4 c = 1;\n    switch (v.x)\n    {\n    case 2.1f:\n        c += 0.1f;\n        break;\n    }\n    return c;\n}\n", 5,
         "float",
         "uint4 v;\nfloat4 main() : sv_target\n{\n    float4 c = 1;\n    switch (v.x)\n    {\n    case 2.1f:\n        c += 0.1f;\n        break;\n    }\n    return c;\n}\n"},
        // asint: a bool has no bits to reinterpret.
        {"AsintOfBool", "ps_4_0", "float4 main() : sv_target\n{\n    bool b = true;\n    return asint(b);\n}\n", 4, "asint",
         "float4 main() : sv_target\n{\n    float b = 1;\n    return asint(b);\n}\n"},
        // asuint: nor a double (one argument).
        {"AsuintOfDouble", "ps_5_0", "float4 main() : sv_target\n{\n    double d = 1.0;\n    return asuint(d);\n}\n", 4, "asuint",
         "float4 main() : sv_target\n{\n    int d = 1;\n    return asuint(d);\n}\n"},
        // distance: dst takes scalars or 4-component vectors.
        {"DstOfFloat1", "ps_4_0", "float4 main() : SV_TARGET\n{\n    float1 bad_size = 0;\n    dst(bad_size, bad_size);\n    return 1;\n}\n", 4, "dst",
         "float4 main() : SV_TARGET\n{\n    float4 good_size = 0;\n    dst(good_size, good_size);\n    return 1;\n}\n"},
        // step: a matrix and a float1 do not convert to each other.
        {"StepOfMatrixAndFloat1", "ps_4_0",
         "float4 main() : sv_target\n{\n    float2x2 a = {1, 2, 3, 4};\n    float1 b = {3};\n    step(a, b);\n    return 0;\n}\n", 5, "float1",
         "float4 main() : sv_target\n{\n    float2x2 a = {1, 2, 3, 4};\n    float b = 3;\n    step(a, b);\n    return 0;\n}\n"},
        // bitwise: shifts take integers.
        {"ShiftByFloat", "ps_4_0", "float4 main() : SV_TARGET\n{\n    uint u = 5;\n    float f = 15.0;\n\n    return float4(u >> f, 0, 0, 0);\n}\n", 6,
         "int",
         "float4 main() : SV_TARGET\n{\n    uint u = 5;\n    int f = 15;\n\n    return float4(u >> f, 0, 0, 0);\n}\n"},
        // invalid: an array dimension is at most 65536.
        {"ArrayDimensionTooLarge", "ps_4_0", "float4 main() : sv_target\n{\n    float a[65537];\n    return 0;\n}\n", 3, "65536",
         "float4 main() : sv_target\n{\n    float a[65536];\n    return 0;\n}\n", nullptr, diag::kArrayTooLarge},
        // unroll: fxc gives up unrolling at 1024 iterations.
        {"UnrollOf1024Iterations", "ps_4_0",
         "float4 main() : sv_target\n{\n    int i;\n    [unroll]\n    for (i = 0; i < 1024; ++i);\n    return float4(i, 0, 0, 0);\n}\n", 4, "unroll",
         "float4 main() : sv_target\n{\n    int i;\n    [unroll]\n    for (i = 0; i < 1023; ++i);\n    return float4(i, 0, 0, 0);\n}\n"},
        // majority-pragma: a typedef keeps the pragma's majority; the other one contradicts it.
        {"MajorityContradictsTypedefPragma", "ps_4_0",
         "#pragma pack_matrix(row_major)\ntypedef float2x2 mat_t;\nuniform column_major mat_t m;\nfloat4 main() : sv_target { return m[0].xyxy; }\n", 3,
         "row_major",
         "#pragma pack_matrix(row_major)\ntypedef float2x2 mat_t;\n#pragma pack_matrix(column_major)\nuniform mat_t m;\nfloat4 main() : sv_target { return m[0].xyxy; }\n"},
        // function-overload: a bool is no closer to int than to float.
        {"OverloadTieOfBool", "ps_4_0",
         "float f(int x) { return 1.0; }\nfloat f(float x) { return 2.0; }\nfloat4 main() : sv_target\n{\n    return f(true);\n}\n", 5, "ambiguous",
         "float f(int x) { return 1.0; }\nfloat f(float x) { return 2.0; }\nfloat4 main() : sv_target\n{\n    return f(1.5);\n}\n"},
        // function-overload L44: an unsuffixed literal is int and uint alike; `3l` is an int.
        {"OverloadTieOfIntLiteral", "ps_4_0",
         "float func(int arg) { return 1.0; }\nfloat func(uint arg) { return 2.0; }\nfloat4 main() : sv_target\n{\n    return func(3);\n}\n", 5, "ambiguous",
         "float func(int arg) { return 1.0; }\nfloat func(uint arg) { return 2.0; }\nfloat4 main() : sv_target\n{\n    return func(3l);\n}\n"},
        // function-overload: a float4 argument ties float4 and float2x2.
        {"OverloadTieOfVectorAndMatrix", "ps_4_0",
         "float4 func(float2x2 x) { return 2.0; }\nfloat4 func(float4 x) { return 1.0; }\nfloat4 main() : sv_target\n{\n    return func(float4(0, 0, 0, 0));\n}\n",
         5, "ambiguous",
         "float4 func(float3x3 x) { return 2.0; }\nfloat4 func(float4 x) { return 1.0; }\nfloat4 main() : sv_target\n{\n    return func(float4(0, 0, 0, 0));\n}\n"},
        // swizzle-matrix: zero-based and one-based subscripts in one swizzle.
        {"MixedMatrixSubscripts", "ps_4_0",
         "float4 main() : sv_target\n{\n    float3x2 mat = {1, 2, 3, 4, 5, 6};\n    float2 p = mat._11_m00;\n    return p.xyxy;\n}\n", 4, "_11_m00",
         "float4 main() : sv_target\n{\n    float3x2 mat = {1, 2, 3, 4, 5, 6};\n    float2 p = mat._m10_m00;\n    return p.xyxy;\n}\n"},
        // GLSL's texture-coordinate swizzle set (s, t, p, q) is no HLSL; a struct's members so
        // named (struct-array's `colours[0].q`) are members.
        {"TextureCoordinateSwizzle", "ps_4_0", "float4 c;\nfloat4 main() : sv_target\n{\n    return c.q + c.st.x;\n}\n", 4, "'q'",
         "struct pair { float p, q; };\nfloat4 c;\nfloat4 main() : sv_target\n{\n    pair v = {c.x, c.y};\n    return v.q + c.a;\n}\n"},
        // function-cast: one value is not written back into a float4.
        {"ScalarOutParameterOfAVector", "ps_4_0",
         "void fun(out float f) { f = 1; }\nfloat4 main() : sv_target\n{\n    float4 p = {-1, -2, -3, -4};\n    fun(p);\n    return p;\n}\n", 5, "out parameter",
         "void fun(out float f) { f = 1; }\nfloat4 main() : sv_target\n{\n    float4 p = {-1, -2, -3, -4};\n    fun(p.y);\n    return p;\n}\n"},
        // static-initializer: a static starts at zero, so `1 / i` divides by the constant 0.
        {"DivisionByUnsetStatic", "ps_4_0", "static uint i;\n\nfloat4 main() : sv_target\n{\n    return 1 / i;\n}\n", 3, "division by zero",
         "static uint i = 2;\n\nfloat4 main() : sv_target\n{\n    return 1 / i;\n}\n"},
        // static-initializer: a static that a uniform sets is no constant.
        {"DivisionByStaticSetFromUniform", "ps_4_0", "uint u;\nstatic uint i;\n\nfloat4 main() : sv_target\n{\n    return 1 / i;\n}\n", 4,
         "division by zero", "uint u;\nstatic uint i;\n\nfloat4 main() : sv_target\n{\n    i = u;\n    return 1 / i;\n}\n"},
        // static-initializer: a static texture read with no value; given one, it compiles.
        {"StaticTextureWithoutValue", "ps_4_0",
         "static Texture2D tex;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    return tex.Sample(sam, float2(0, 0));\n}\n", 1, "never given a value",
         "Texture2D real_tex;\nstatic Texture2D tex = real_tex;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    return tex.Sample(sam, float2(0, 0));\n}\n"},
        // A local texture array indexed by a uniform holds no one known texture (fxc: SM5.0 indexes
        // resource arrays by literals only); stored at an index that folds to a constant (vkd3d's
        // object-references), the copies are traced and it compiles.
        {"LocalTextureArrayIndexedByAUniform", "ps_5_0",
         "Texture2D t1, t2;\nuint u;\n\nfloat4 main() : sv_target\n{\n    Texture2D b[2];\n    b[0] = t1;\n    b[1] = t2;\n    return b[u].Load(int3(0, 0, 0));\n}\n", 6,
         "local resource variable",
         "Texture2D t1, t2;\nuint u;\n\nfloat4 main() : sv_target\n{\n    Texture2D b[2];\n    int4 co = {0, 0, 0, 0};\n    b[(int)co.x + (int)co.y] = t1;\n"
         "    b[1] = t2;\n    return b[0].Load(int3(0, 0, 0)) + b[1].Load(int3(0, 0, 0));\n}\n"},
        // static-initializer: through a function's static copy; a read in dead code does not count.
        {"StaticTextureCopiedWithoutValue", "ps_4_0",
         "static Texture2D tex1;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    static Texture2D tex2 = tex1;\n    return tex2.Sample(sam, float2(0, 0));\n}\n",
         1, "'tex1'",
         "static Texture2D tex1;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    if (0)\n        return tex1.Sample(sam, float2(0, 0));\n"
         "    float4 unused = tex1.Sample(sam, float2(0, 0));\n    return 1;\n}\n"},
        // static-initializer: assigned in the function before the read.
        {"StaticTextureAssignedLater", "ps_4_0",
         "Texture2D real_tex;\nstatic Texture2D tex;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    return tex.Sample(sam, float2(0, 0));\n}\n", 2,
         "'tex'",
         "Texture2D real_tex;\nstatic Texture2D tex;\nsampler sam;\n\nfloat4 main() : sv_target\n{\n    tex = real_tex;\n    return tex.Sample(sam, float2(0, 0));\n}\n"},
        // vector-indexing: a vector's component is written only at a constant index; read at any.
        {"VectorWrittenAtUniformIndex", "ps_4_0", "float4 v;\nfloat i;\n\nfloat4 main() : sv_target\n{\n    float4 p = v;\n    p[i] = 2.0;\n    return p;\n}\n", 7,
         "written at index", "float4 v;\nfloat i;\n\nfloat4 main() : sv_target\n{\n    float4 p = v;\n    p[1] = p[i];\n    return p;\n}\n"},
        {"VectorWrittenInUnrolledLoop", "ps_4_0", "float4 v;\nint i;\n\nfloat4 main() : sv_target\n{\n    float4 p = v;\n    p[i] += 1;\n    return p;\n}\n", 7,
         "written at index", "float4 v;\nint i;\n\nfloat4 main() : sv_target\n{\n    float4 p = v;\n    for (int k = 0; k < 4; k++)\n        p[k] += 1;\n    return p;\n}\n"},
        // entry-point-semantics: a row_major matrix's rows are no vectors on a shared input semantic.
        {"RowMajorRowsBesideVectorInput", "ps_4_0",
         "float4 main(in float2 a : TEXCOORD0, row_major float1x2 b : TEXCOORD0) : sv_target\n{\n    return 0.0;\n}\n", 1, "layouts",
         "float4 main(in float2 a : TEXCOORD0, float2x1 b : TEXCOORD0) : sv_target\n{\n    return 0.0;\n}\n"},
        {"RowMajorRowsBesideVector4Input", "ps_4_0",
         "float4 main(in float4 a : TEXCOORD0, row_major float1x4 b : TEXCOORD0) : sv_target\n{\n    return 0.0;\n}\n", 1, "layouts",
         "float4 main(in float4 a : TEXCOORD0, row_major float1x4 b : TEXCOORD0) : sv_target\n{\n    return 0.0;\n}\n", "ps_3_0"},
        // fxgroup-syntax: an fxgroup holds technique10/technique11 only.
        {"UnversionedTechniqueInGroup", "ps_4_0", "fxgroup group1\n{\n    technique\n    {\n    }\n}\n\nfloat4 main() : sv_target { return 0; }\n", 3, "fxgroup",
         "fxgroup group1\n{\n    technique11\n    {\n    }\n}\n\nfloat4 main() : sv_target { return 0; }\n"},
        // sm1-const-folding: 3000000000 is a negative int to fxc; SM 1-3 refuse it as a uint.
        {"NegativeIntLiteralAsUintSm2", "ps_2_0", "float4 main() : SV_TARGET\n{\n    uint x = 3000000000 + 3000000000;\n    return float4(x, 0.0, 0.0, 0.0);\n}\n", 3,
         "negative int", "float4 main() : SV_TARGET\n{\n    uint x = 3000000000u + 3000000000u;\n    return float4(x, 0.0, 0.0, 0.0);\n}\n"},
        {"NegativeIntLiteralAsUintSm4", "ps_3_0", "float4 main() : SV_TARGET\n{\n    uint x = 3000000000;\n    return float4(x, 0.0, 0.0, 0.0);\n}\n", 3,
         "negative int", "float4 main() : SV_TARGET\n{\n    uint x = 3000000000;\n    return float4(x, 0.0, 0.0, 0.0);\n}\n", "ps_4_0"},
        // cast-to-int: a hexadecimal literal is not read as a negative int there.
        {"DecimalNotHexLiteralAsUint", "ps_2_0", "float4 main() : SV_TARGET\n{\n    uint u = 4294967294;\n    return float4(u, 0.0, 0.0, 0.0);\n}\n", 3,
         "negative int", "float4 main() : SV_TARGET\n{\n    uint u = 0xfffffffe;\n    return float4(u, 0.0, 0.0, 0.0);\n}\n"},
        // bitwise-assignment: `<<=` needs integers too.
        {"FloatShiftAssignment", "ps_4_0", "float4 main() : SV_TARGET\n{\n    float x = 5.0, y = 15.0;\n    x <<= y;\n    return float4(x, y, 0, 0);\n}\n", 4, "<<=",
         "float4 main() : SV_TARGET\n{\n    int x = 5, y = 15;\n    x <<= y;\n    return float4(x, y, 0, 0);\n}\n"},
        // texture-load-offset: an immediate texel offset is -8..7.
        {"TexelOffsetOutOfRange", "ps_4_0",
         "Texture2D t;\n\nfloat4 main(float4 pos : sv_position) : sv_target\n{\n    return t.Load(int3(pos.xy, 0), int2(8, 1));\n}\n", 5, "-8 to 7",
         "Texture2D t;\n\nfloat4 main(float4 pos : sv_position) : sv_target\n{\n    return t.Load(int3(pos.xy, 0), int2(-8, 7));\n}\n"},
        {"SampleOffsetOutOfRange", "ps_4_0",
         "Texture2D t;\nsampler s;\n\nfloat4 main(float4 pos : sv_position) : sv_target\n{\n    return t.Sample(s, pos.xy, int2(0, -9));\n}\n", 6, "-8 to 7",
         "Texture2D t;\nsampler s;\n\nfloat4 main(float4 pos : sv_position) : sv_target\n{\n    return t.Sample(s, pos.xy, int2(0, -8));\n}\n"},
        // load-level: a Texture2D's subscript takes two coordinates (a Texture2DArray's three).
        {"TextureSubscriptOfWrongSize", "ps_4_0", "Texture2D t;\n\nfloat4 main() : sv_target\n{\n    return t[uint3(0, 0, 0)];\n}\n", 5, "2 coordinates",
         "Texture2DArray t;\n\nfloat4 main() : sv_target\n{\n    return t[uint3(0, 0, 0)];\n}\n"},
        // tgsm: at cs_4_x groupshared is an array of one element per thread, written at SV_GroupIndex.
        {"GroupSharedScalarCs4", "cs_4_0",
         "RWByteAddressBuffer u : register(u0);\ngroupshared uint m;\n\n[numthreads(4, 1, 1)]\nvoid main(uint local_idx : SV_GroupIndex)\n{\n"
         "    if (local_idx == 0)\n        m = 0;\n    GroupMemoryBarrierWithGroupSync();\n    u.Store(4 * local_idx, m);\n}\n",
         2, "array of 4",
         "RWByteAddressBuffer u : register(u0);\ngroupshared uint m;\n\n[numthreads(4, 1, 1)]\nvoid main(uint local_idx : SV_GroupIndex)\n{\n"
         "    if (local_idx == 0)\n        m = 0;\n    GroupMemoryBarrierWithGroupSync();\n    u.Store(4 * local_idx, m);\n}\n",
         "cs_5_0"},
        {"GroupSharedStoreElsewhereCs4", "cs_4_0",
         "RWByteAddressBuffer u : register(u0);\ngroupshared uint m[4];\n\n[numthreads(4, 1, 1)]\nvoid main(uint local_idx : SV_GroupIndex)\n{\n"
         "    if (local_idx == 0)\n        m[0] = 0;\n    GroupMemoryBarrierWithGroupSync();\n    u.Store(4 * local_idx, m[0]);\n}\n",
         8, "SV_GroupIndex",
         "RWByteAddressBuffer u : register(u0);\ngroupshared uint m[4];\n\n[numthreads(4, 1, 1)]\nvoid main(uint local_idx : SV_GroupIndex)\n{\n"
         "    m[local_idx] = 0;\n    GroupMemoryBarrierWithGroupSync();\n    u.Store(4 * local_idx, m[0]);\n}\n"},
        // effect-shader-objects: VertexShader names the type, vertexshadeR is a name.
        {"VertexShaderAsVariable", "ps_4_0", "float4 VertexShader;\n\nfloat4 main() : sv_target\n{\n    return 0;\n}\n", 1, "shader object type",
         "float4 vertexshadeR;\nfloat4 geometryshader;\n\nfloat4 main() : sv_target\n{\n    return 0;\n}\n"},
        {"LowerCaseVertexShaderAsVariable", "ps_2_0", "float4 vertexshader;\n\nfloat4 main() : sv_target\n{\n    return 0;\n}\n", 1, "shader object type",
         "float4 main() : sv_target\n{\n    return 0;\n}\n\ntechnique t\n{\n    pass p\n    {\n        VertexShader = NULL;\n        PixelShader = compile ps_2_0 main();\n    }\n}\n"},
        // invalid: a static struct of a sampler and numbers needs an initial value.
        {"StaticStructOfObjectAndNumbers", "ps_4_0",
         "struct apple\n{\n    sampler sam;\n    float4 aa;\n};\n\nstatic struct apple a;\n\nfloat4 main() : sv_target\n{\n    return 1.0;\n}\n", 7, "both an object and numbers",
         "struct apple\n{\n    float4 bb;\n    float4 aa;\n};\n\nstatic struct apple a;\n\nfloat4 main() : sv_target\n{\n    return 1.0;\n}\n"},
        // numthreads: a thread-group dimension is a scalar.
        {"NumthreadsOfAVector", "cs_5_0", "[numthreads(uint1(1), 1, 1)]\nvoid main() {}\n", 2, "vector", "[numthreads(uint(1), 1, 1)]\nvoid main() {}\n", nullptr,
         diag::kBadEntrySignature},
        // hull-shader-attributes: lines come from an isoline domain only.
        {"LineTopologyOfTriangles", "hs_5_0", hullOfTriangles("line"), 17, "isoline", hullOfTriangles("triangle_cw"), nullptr, diag::kBadEntrySignature},
        // rt-format-mismatch: no double output.
        {"DoubleOutput", "ps_4_0", "double2 main() : sv_target\n{\n    return 0;\n}\n", 1, "double", "float2 main() : sv_target\n{\n    return 0;\n}\n"},
        // nointerpolation: a constant value has no centroid.
        {"NointerpolationCentroid", "vs_4_0",
         "struct ps_input\n{\n    nointerpolation centroid float4 t : texcoord;\n};\n\nvoid main(uint id : sv_vertexid, inout ps_input input, out float4 pos : sv_position)\n{\n    pos = 0;\n}\n",
         3, "exclude",
         "struct ps_input\n{\n    nointerpolation float4 t : texcoord;\n};\n\nvoid main(uint id : sv_vertexid, inout centroid ps_input input, out float4 pos : sv_position)\n{\n    pos = 0;\n}\n"},
        // arithmetic-int-uniform: no signed division of minimum precision; min16uint divides.
        {"SignedMinPrecisionDivision", "ps_4_0",
         "uniform min16int4 u;\n\nint4 main() : sv_target\n{\n    min16int i = 32767;\n    return int4(u.x / i, 0, 0, 0);\n}\n", 6, "minimum-precision",
         "uniform min16uint4 u;\n\nint4 main() : sv_target\n{\n    min16uint i = 32767;\n    return int4(u.x / i, 0, 0, 0);\n}\n"},
        // effect-compile: a shader variable's value is a literal expression, no other variable.
        // hard-copy-prop: a constant index past an array's end is refused in code that runs, and
        // compiles in dead code (rewrite/out_of_range_indices.h).
        {"ConstantIndexPastTheEndInLiveCode", "ps_4_0",
         "float4 main() : sv_target\n{\n    static float4 arr[4];\n    return arr[5];\n}\n", 4, "out of range",
         "float4 main() : sv_target\n{\n    static float4 arr[4];\n    bool x = false;\n    if (x) return arr[5];\n    return arr[3];\n}\n"},
        {"ShaderVariableFromVariable", "ps_4_0",
         "float4 main() : sv_target { return 0; }\n\nPixelShader ps1 = CompileShader(ps_2_0, main());\nPixelShader ps2 = ps1;\n", 4, "literal expression",
         "float4 main() : sv_target { return 0; }\n\nPixelShader ps1 = CompileShader(ps_2_0, main());\nPixelShader ps2 = NULL;\n"},
    };
}

class FxcRejects : public ::testing::TestWithParam<RejectCase> {};

TEST_P(FxcRejects, InvalidStopsAtItsLine) {
    const RejectCase& c = GetParam();
    try {
        compile(c.invalid, c.profile);
        FAIL() << c.name << " compiled, but fxc rejects it";
    } catch (const CompileError& e) {
        const Diagnostic* first = nullptr;
        for (const auto& d : e.diagnostics())
            if (d.severity == Severity::Error && !first) first = &d;
        ASSERT_NE(first, nullptr) << e.what();
        EXPECT_EQ(first->id, std::string(c.id)) << e.what();
        EXPECT_EQ(first->location.line, c.line) << e.what();
        EXPECT_NE(first->message.find(c.word), std::string::npos) << e.what();
    }
}

TEST_P(FxcRejects, ValidTwinCompiles) {
    const RejectCase& c = GetParam();
    try {
        compile(c.valid, c.validProfile ? c.validProfile : c.profile);
    } catch (const CompileError& e) {
        FAIL() << c.name << ": the valid twin was refused: " << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Rules, FxcRejects, ::testing::ValuesIn(cases()), [](const auto& p) { return std::string(p.param.name); });

}  // namespace
