// See one_row_textures.h: DX9 tex1D* as tex2D* in the middle of a one-row texture.
#include "rewrite/one_row_textures.h"

#include <algorithm>
#include <string>

namespace fxport::xlate {

namespace {

// Helpers in DX9 syntax (the effect compiles in glslang's DX9 mode where it has DX9 samplers).
// A wider coordinate passed to tex1D is truncated to its x, as fxc converts it to the float the
// intrinsic takes (glslang converts no vector to a scalar argument).
constexpr const char* kHelpers =
    "float4 fxport_tex1D(sampler2D s, float u) { return tex2D(s, float2(u, 0.5)); }\n"
    "float4 fxport_tex1D(sampler2D s, float2 u) { return tex2D(s, float2(u.x, 0.5)); }\n"
    "float4 fxport_tex1D(sampler2D s, float3 u) { return tex2D(s, float2(u.x, 0.5)); }\n"
    "float4 fxport_tex1D(sampler2D s, float4 u) { return tex2D(s, float2(u.x, 0.5)); }\n"
    "float4 fxport_tex1D(sampler2D s, float u, float dx, float dy) { return tex2Dgrad(s, float2(u, 0.5), float2(dx, 0), float2(dy, 0)); }\n"
    "float4 fxport_tex1Dgrad(sampler2D s, float u, float dx, float dy) { return tex2Dgrad(s, float2(u, 0.5), float2(dx, 0), float2(dy, 0)); }\n"
    "float4 fxport_tex1Dlod(sampler2D s, float4 t) { return tex2Dlod(s, float4(t.x, 0.5, 0, t.w)); }\n"
    "float4 fxport_tex1Dbias(sampler2D s, float4 t) { return tex2Dbias(s, float4(t.x, 0.5, 0, t.w)); }\n"
    "float4 fxport_tex1Dproj(sampler2D s, float4 t) { return tex2Dproj(s, float4(t.x, 0.5 * t.w, 0, t.w)); }\n";

bool isOneDimensionalIntrinsic(const std::string& name) {
    return name == "tex1D" || name == "tex1Dlod" || name == "tex1Dbias" || name == "tex1Dproj" || name == "tex1Dgrad";
}

}  // namespace

std::vector<TextEdit> oneDimensionalSamplingAsRows(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const auto& t = syntax.tokens;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i)
            if (t[i].isIdent() && t[i + 1].is("(") && !(i > 0 && t[i - 1].is(".")) && isOneDimensionalIntrinsic(t[i].text) &&
                !syntax.findFunction(t[i].text))
                edits.push_back({t[i].offset, t[i].end, "fxport_" + t[i].text});
    if (edits.empty()) return edits;
    size_t first = syntax.functions.front().declaration.begin;
    for (const auto& f : syntax.functions) first = std::min(first, f.declaration.begin);
    edits.push_back({t[first].offset, t[first].offset, kHelpers});
    return edits;
}

}  // namespace fxport::xlate
