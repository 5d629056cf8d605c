// Block descriptions -> D3D11 descriptions (see d3d11_descs.h).
#include "d3d11_descs.h"

namespace conformance {

using namespace fxport::d3d11;

DXGI_FORMAT dxgiFormat(const Format& f) {
    // A depth texture sampled with comparison is made as D3D programs make shadow maps: R32_TYPELESS,
    // read through an R32_FLOAT view (d3d11_session_resources.cpp).
    if (f.shadow) return DXGI_FORMAT_R32_TYPELESS;
    struct Known { const char* name; DXGI_FORMAT format; };
    static const Known kKnown[] = {
        {"r32g32b32a32-float", DXGI_FORMAT_R32G32B32A32_FLOAT}, {"r32g32b32a32-uint", DXGI_FORMAT_R32G32B32A32_UINT},
        {"r32g32-float", DXGI_FORMAT_R32G32_FLOAT}, {"r32-float", DXGI_FORMAT_R32_FLOAT}, {"r32-uint", DXGI_FORMAT_R32_UINT},
        {"r32-typeless", DXGI_FORMAT_R32_TYPELESS}, {"r32g32b32a32-sint", DXGI_FORMAT_R32G32B32A32_SINT},
        {"r32g32-uint", DXGI_FORMAT_R32G32_UINT}, {"r32g32-sint", DXGI_FORMAT_R32G32_SINT}, {"r32-sint", DXGI_FORMAT_R32_SINT},
    };
    for (const Known& k : kKnown)
        if (f.name == k.name) return k.format;
    throw Unsupported("format " + f.name + " (no DXGI_FORMAT value in fxport's d3d11_types.h)");
}

namespace {

D3D11_TEXTURE_ADDRESS_MODE addressOf(Address a) {
    switch (a) {
    case Address::Wrap: return D3D11_TEXTURE_ADDRESS_WRAP;
    case Address::Mirror: return D3D11_TEXTURE_ADDRESS_MIRROR;
    case Address::Clamp: return D3D11_TEXTURE_ADDRESS_CLAMP;
    case Address::Border: return D3D11_TEXTURE_ADDRESS_BORDER;
    case Address::MirrorOnce: return D3D11_TEXTURE_ADDRESS_MIRROR_ONCE;
    }
    return D3D11_TEXTURE_ADDRESS_CLAMP;
}

D3D11_COMPARISON_FUNC comparisonOf(const std::string& name) {
    static const struct { const char* name; D3D11_COMPARISON_FUNC func; } kFuncs[] = {
        {"never", D3D11_COMPARISON_NEVER}, {"less equal", D3D11_COMPARISON_LESS_EQUAL}, {"less", D3D11_COMPARISON_LESS},
        {"equal", D3D11_COMPARISON_EQUAL}, {"greater equal", D3D11_COMPARISON_GREATER_EQUAL}, {"greater", D3D11_COMPARISON_GREATER},
        {"not equal", D3D11_COMPARISON_NOT_EQUAL}, {"always", D3D11_COMPARISON_ALWAYS},
    };
    std::string n = name;
    n.erase(0, n.find_first_not_of(' '));
    n.erase(n.find_last_not_of(" \r") + 1);
    for (const auto& f : kFuncs)
        if (n == f.name) return f.func;
    throw Unsupported("sampler comparison function '" + name + "'");
}

// An input-layout element's format: the vertex formats beside dxgiFormat's texture ones.
DXGI_FORMAT vertexDxgiFormat(const Format& f) {
    static const struct { const char* name; DXGI_FORMAT format; } kVertex[] = {
        {"r32g32b32a32-sint", DXGI_FORMAT_R32G32B32A32_SINT}, {"r32g32b32-float", DXGI_FORMAT_R32G32B32_FLOAT},
        {"r32g32b32-uint", DXGI_FORMAT_R32G32B32_UINT}, {"r32g32b32-sint", DXGI_FORMAT_R32G32B32_SINT},
        {"r32g32-uint", DXGI_FORMAT_R32G32_UINT}, {"r32g32-sint", DXGI_FORMAT_R32G32_SINT}, {"r32-sint", DXGI_FORMAT_R32_SINT},
    };
    for (const auto& k : kVertex)
        if (f.name == k.name) return k.format;
    return dxgiFormat(f);
}

}  // namespace

D3D11_SAMPLER_DESC samplerDescOf(const SamplerDesc& s) {
    D3D11_SAMPLER_DESC d;
    // D3D11_FILTER's bits: min linear 0x10, mag linear 0x4, mip linear 0x1, comparison 0x80.
    UINT filter = (s.min == Filter::Linear ? 0x10u : 0u) | (s.mag == Filter::Linear ? 0x4u : 0u) | (s.mip == Filter::Linear ? 0x1u : 0u);
    if (s.comparison) {
        filter |= 0x80u;
        d.ComparisonFunc = comparisonOf(s.comparisonFunc);
    }
    d.Filter = D3D11_FILTER(filter);
    d.AddressU = addressOf(s.u);
    d.AddressV = addressOf(s.v);
    d.AddressW = addressOf(s.w);
    // vkd3d's runner leaves the border colour 0 and the LOD range open.
    for (float& c : d.BorderColor) c = 0.0f;
    return d;
}

InputElements inputElementsOf(const std::vector<InputElement>& layout) {
    InputElements out;
    for (const InputElement& e : layout) {
        D3D11_INPUT_ELEMENT_DESC d;
        d.SemanticName = e.semantic.c_str();
        d.SemanticIndex = UINT(e.index);
        d.Format = vertexDxgiFormat(e.format);
        if (e.slot < 0 || UINT(e.slot) >= D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT)
            throw std::runtime_error("input layout slot " + std::to_string(e.slot) + " (D3D11 has 0..31)");
        d.InputSlot = UINT(e.slot);
        d.AlignedByteOffset = out.strides[e.slot];
        out.strides[e.slot] += UINT(texelBytes(e.format));
        out.elements.push_back(d);
    }
    return out;
}

D3D11_PRIMITIVE_TOPOLOGY topologyOf(const DrawCall& call) {
    if (call.topology == "triangle list") return D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
    if (call.topology == "triangle strip") return D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP;
    if (call.topology == "point list") return D3D11_PRIMITIVE_TOPOLOGY_POINTLIST;
    if (call.topology == "patch list" && call.controlPoints >= 1 && call.controlPoints <= 32)
        return D3D11_PRIMITIVE_TOPOLOGY(UINT(D3D11_PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST) + UINT(call.controlPoints) - 1);
    throw Unsupported("primitive topology " + call.topology);
}

}  // namespace conformance
