// The D3D11 session's translations of what the suite's blocks say into D3D11 descriptions, with no
// device (so runner_parts_test checks them): DXGI formats, sampler descriptions, input elements and
// their per-slot strides, primitive topologies. What D3D11 (or fxport's header) has no value for
// throws Unsupported with the reason.
#pragma once

#include <map>
#include <vector>

#include "fxport/d3d11.h"
#include "gpu_backend.h"

namespace conformance {

// The DXGI format the suite's format names ("r32g32-uint" -> DXGI_FORMAT_R32G32_UINT).
fxport::d3d11::DXGI_FORMAT dxgiFormat(const Format& format);
fxport::d3d11::D3D11_SAMPLER_DESC samplerDescOf(const SamplerDesc& sampler);

// An [input layout] as D3D11 input elements (each slot's elements packed in order, as vkd3d's
// runner does) and each slot's vertex stride. SemanticName points into `layout`, which must
// outlive the result.
struct InputElements {
    std::vector<fxport::d3d11::D3D11_INPUT_ELEMENT_DESC> elements;
    std::map<int, fxport::d3d11::UINT> strides;  // by input slot
};
InputElements inputElementsOf(const std::vector<InputElement>& layout);

fxport::d3d11::D3D11_PRIMITIVE_TOPOLOGY topologyOf(const DrawCall& call);
// Bytes of one texel (or vertex element) of a 32-bit-per-component format.
inline int texelBytes(const Format& format) { return 4 * format.components; }

}  // namespace conformance
