// See tess_factor_intrinsics.h: D3D's ProcessTessFactors intrinsics as HLSL helpers.
#include "rewrite/tess_factor_intrinsics.h"

#include <algorithm>

namespace fxport::xlate {

namespace {

struct Intrinsic {
    const char* name;
    const char* helper;      // the helper that computes it (fxport_<name> calls it)
    int op;                  // 0 average, 1 maximum, 2 minimum (the helper's first argument); -1 none
    const char* parameters;  // the intrinsic's parameters
    const char* arguments;   // the same, as arguments
};

constexpr const char* kTri = "float3 raw, float scale, out float3 edges, out float inside, out float unrounded";
constexpr const char* kQuad = "float4 raw, float scale, out float4 edges, out float2 inside, out float2 unrounded";
constexpr const char* k2DQuad = "float4 raw, float2 scale, out float4 edges, out float2 inside, out float2 unrounded";
constexpr const char* kEdgeArguments = "raw, scale, edges, inside, unrounded";
constexpr const char* kIsoline = "float detail, float density, out float roundedDetail, out float roundedDensity";
constexpr const char* kIsolineArguments = "detail, density, roundedDetail, roundedDensity";

constexpr Intrinsic kIntrinsics[] = {
    {"ProcessTriTessFactorsAvg", "fxport_ProcessTriTessFactors", 0, kTri, kEdgeArguments},
    {"ProcessTriTessFactorsMax", "fxport_ProcessTriTessFactors", 1, kTri, kEdgeArguments},
    {"ProcessTriTessFactorsMin", "fxport_ProcessTriTessFactors", 2, kTri, kEdgeArguments},
    {"ProcessQuadTessFactorsAvg", "fxport_ProcessQuadTessFactors", 0, kQuad, kEdgeArguments},
    {"ProcessQuadTessFactorsMax", "fxport_ProcessQuadTessFactors", 1, kQuad, kEdgeArguments},
    {"ProcessQuadTessFactorsMin", "fxport_ProcessQuadTessFactors", 2, kQuad, kEdgeArguments},
    {"Process2DQuadTessFactorsAvg", "fxport_Process2DQuadTessFactors", 0, k2DQuad, kEdgeArguments},
    {"Process2DQuadTessFactorsMax", "fxport_Process2DQuadTessFactors", 1, k2DQuad, kEdgeArguments},
    {"Process2DQuadTessFactorsMin", "fxport_Process2DQuadTessFactors", 2, k2DQuad, kEdgeArguments},
    {"ProcessIsolineTessFactors", "fxport_isolineTessFactors", -1, kIsoline, kIsolineArguments},
};

// Clamp: [1, 64] (integer, pow2), [1, 63] (fractional_odd), [2, 64] (fractional_even).
// Round: integer up to a whole number; pow2 up to a power of two (a mantissa other than 0 bumps
// the exponent); fractional not at all. Combine: op over the edge factors, each at least 1.
// Inside: the scaled factor clamped and rounded; under fractional_odd, where it rounds below 3,
// the (unscaled) average or maximum clamped to at most 3 instead.
const char* kHelpers =
    "float4 fxport_tfClamp(float4 f) { return min(max(f, FXPORT_PARTITIONING == 3 ? 2.0 : 1.0), FXPORT_PARTITIONING == 2 ? 63.0 : 64.0); } "
    "float4 fxport_tfRound(float4 f) { if (FXPORT_PARTITIONING == 0) return ceil(f); "
    "if (FXPORT_PARTITIONING != 1) return f; uint4 b = asuint(f); "
    "return asfloat((b & 0x7f800000u) + min(b & 0x007fffffu, 1u) * 0x00800000u); } "
    "float fxport_tfOp(int op, float a, float b) { return op == 1 ? max(a, b) : op == 2 ? min(a, b) : a + b; } "
    "void fxport_tfInside(float4 scaled, float4 small, out float4 unrounded, out float4 rounded) { "
    "unrounded = fxport_tfClamp(scaled); rounded = fxport_tfRound(unrounded); "
    "if (FXPORT_PARTITIONING == 2) { bool4 lt = rounded < 3.0; float4 s = min(fxport_tfClamp(small), 3.0); "
    "unrounded = lt ? s : unrounded; rounded = lt ? s : rounded; } } "
    "void fxport_ProcessTriTessFactors(int op, float3 raw, float scale, out float3 edges, out float inside, out float unrounded) { "
    "edges = fxport_tfRound(fxport_tfClamp(raw.xyzz)).xyz; float3 c = max(raw, 1.0); "
    "float avg = (c.x + c.y + c.z) * (1.0 / 3.0); "
    "float f = op == 0 ? avg : fxport_tfOp(op, fxport_tfOp(op, c.x, c.y), c.z); "
    "float4 u, r; fxport_tfInside((f * min(max(scale, 0.0), 1.0)).xxxx, (op == 1 ? f : avg).xxxx, u, r); "
    "inside = r.x; unrounded = u.x; } "
    "void fxport_ProcessQuadTessFactors(int op, float4 raw, float scale, out float4 edges, out float2 inside, out float2 unrounded) { "
    "edges = fxport_tfRound(fxport_tfClamp(raw)); float4 c = max(raw, 1.0); "
    "float avg = ((c.x + c.y) + (c.z + c.w)) * 0.25; "
    "float f = op == 0 ? avg : fxport_tfOp(op, fxport_tfOp(op, c.x, c.y), fxport_tfOp(op, c.z, c.w)); "
    "float4 u, r; fxport_tfInside((f * min(max(scale, 0.0), 1.0)).xxxx, (op == 1 ? f : avg).xxxx, u, r); "
    "inside = r.xx; unrounded = u.xx; } "
    "void fxport_Process2DQuadTessFactors(int op, float4 raw, float2 scale, out float4 edges, out float2 inside, out float2 unrounded) { "
    "edges = fxport_tfRound(fxport_tfClamp(raw)); float4 c = max(raw, 1.0); "
    "float2 avg = float2(c.x + c.y, c.z + c.w) * 0.5; "
    "float2 f = op == 0 ? avg : float2(fxport_tfOp(op, c.x, c.y), fxport_tfOp(op, c.z, c.w)); "
    "float4 u, r; fxport_tfInside((f * min(max(scale, 0.0), 1.0)).xyxy, (op == 1 ? f : avg).xyxy, u, r); "
    "if (FXPORT_PARTITIONING == 2) { bool2 lt = u.xy < 3.0; "
    "float2 x = min(max(u.x, u.y), 3.0).xx, y = min(max(r.x, r.y), 3.0).xx; "
    "u.xy = lt ? x : u.xy; r.xy = lt ? y : r.xy; } "
    "inside = r.xy; unrounded = u.xy; } "
    "void fxport_isolineTessFactors(float detail, float density, out float roundedDetail, out float roundedDensity) { "
    "float4 r = fxport_tfRound(fxport_tfClamp(float4(detail, density, 1.0, 1.0))); "
    "roundedDetail = r.x; roundedDensity = r.y; } ";

const Intrinsic* intrinsicAt(const std::vector<Token>& t, size_t i) {
    if (!t[i].isIdent() || i + 1 >= t.size() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) return nullptr;
    for (const Intrinsic& in : kIntrinsics)
        if (t[i].text == in.name) return &in;
    return nullptr;
}

}  // namespace

int partitioningCode(const std::string& partitioning) {
    if (partitioning == "pow2") return 1;
    if (partitioning == "fractional_odd") return 2;
    if (partitioning == "fractional_even") return 3;
    return 0;
}

// Test: runtime D3D11 TessellationTest.ProcessTessFactors* (the factors as DXC computes them).
std::vector<TextEdit> tessFactorIntrinsics(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    if (syntax.functions.empty()) return edits;
    for (const Intrinsic& in : kIntrinsics)
        if (syntax.findFunction(in.name)) return edits;  // the effect's own: its calls are its own
    const std::vector<Token>& t = syntax.tokens;
    size_t first = syntax.functions.front().declaration.begin;
    for (const auto& f : syntax.functions) first = std::min(first, f.declaration.begin);
    for (size_t i = first; i + 1 < t.size(); ++i)
        if (intrinsicAt(t, i)) edits.push_back({t[i].offset, t[i].end, "fxport_" + t[i].text});
    if (edits.empty()) return edits;
    // Each intrinsic as a function of its own name, calling the helper with its operation.
    std::string helpers = kHelpers;
    for (const Intrinsic& in : kIntrinsics)
        helpers += std::string("void fxport_") + in.name + "(" + in.parameters + ") { " + in.helper + "(" +
                   (in.op >= 0 ? std::to_string(in.op) + ", " : "") + in.arguments + "); } ";
    edits.push_back({t[first].offset, t[first].offset, helpers});
    return edits;
}

}  // namespace fxport::xlate
