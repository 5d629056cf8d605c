// DXGI formats an input layout may give a vertex element -> the device core's VertexFormat. D3D11
// reads any R32/R16/R8 layout of one to four components as floats, normalised integers or integers
// (an int/uint shader input reads the integers themselves, a float input their bits: D3D10 converts
// nothing); formats.cpp has the texture formats.
#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {

struct VertexFormatOf {
    DXGI_FORMAT format;
    VertexFormat vertex;
};

using C = VertexComponent;
const VertexFormatOf kVertexFormats[] = {
    {DXGI_FORMAT_R32G32B32A32_FLOAT, {C::Float32, 4, false}},
    {DXGI_FORMAT_R32G32B32A32_UINT, {C::UInt32, 4, false}},
    {DXGI_FORMAT_R32G32B32A32_SINT, {C::SInt32, 4, false}},
    {DXGI_FORMAT_R32G32B32_FLOAT, {C::Float32, 3, false}},
    {DXGI_FORMAT_R32G32B32_UINT, {C::UInt32, 3, false}},
    {DXGI_FORMAT_R32G32B32_SINT, {C::SInt32, 3, false}},
    {DXGI_FORMAT_R16G16B16A16_FLOAT, {C::Float16, 4, false}},
    {DXGI_FORMAT_R16G16B16A16_UNORM, {C::UInt16, 4, true}},
    {DXGI_FORMAT_R16G16B16A16_UINT, {C::UInt16, 4, false}},
    {DXGI_FORMAT_R16G16B16A16_SNORM, {C::SInt16, 4, true}},
    {DXGI_FORMAT_R16G16B16A16_SINT, {C::SInt16, 4, false}},
    {DXGI_FORMAT_R32G32_FLOAT, {C::Float32, 2, false}},
    {DXGI_FORMAT_R32G32_UINT, {C::UInt32, 2, false}},
    {DXGI_FORMAT_R32G32_SINT, {C::SInt32, 2, false}},
    {DXGI_FORMAT_R10G10B10A2_UNORM, {C::UInt1010102, 4, true}},
    {DXGI_FORMAT_R11G11B10_FLOAT, {C::UFloat111110, 3, false}},
    {DXGI_FORMAT_B8G8R8A8_UNORM, {C::UInt8Bgra, 4, true}},
    {DXGI_FORMAT_R8G8B8A8_UNORM, {C::UInt8, 4, true}},
    {DXGI_FORMAT_R8G8B8A8_UINT, {C::UInt8, 4, false}},
    {DXGI_FORMAT_R8G8B8A8_SNORM, {C::SInt8, 4, true}},
    {DXGI_FORMAT_R8G8B8A8_SINT, {C::SInt8, 4, false}},
    {DXGI_FORMAT_R16G16_FLOAT, {C::Float16, 2, false}},
    {DXGI_FORMAT_R16G16_UNORM, {C::UInt16, 2, true}},
    {DXGI_FORMAT_R16G16_UINT, {C::UInt16, 2, false}},
    {DXGI_FORMAT_R16G16_SNORM, {C::SInt16, 2, true}},
    {DXGI_FORMAT_R16G16_SINT, {C::SInt16, 2, false}},
    {DXGI_FORMAT_R32_FLOAT, {C::Float32, 1, false}},
    {DXGI_FORMAT_R32_UINT, {C::UInt32, 1, false}},
    {DXGI_FORMAT_R32_SINT, {C::SInt32, 1, false}},
    {DXGI_FORMAT_R8G8_UNORM, {C::UInt8, 2, true}},
    {DXGI_FORMAT_R8G8_UINT, {C::UInt8, 2, false}},
    {DXGI_FORMAT_R8G8_SNORM, {C::SInt8, 2, true}},
    {DXGI_FORMAT_R8G8_SINT, {C::SInt8, 2, false}},
    {DXGI_FORMAT_R16_FLOAT, {C::Float16, 1, false}},
    {DXGI_FORMAT_R16_UNORM, {C::UInt16, 1, true}},
    {DXGI_FORMAT_R16_UINT, {C::UInt16, 1, false}},
    {DXGI_FORMAT_R16_SNORM, {C::SInt16, 1, true}},
    {DXGI_FORMAT_R16_SINT, {C::SInt16, 1, false}},
    {DXGI_FORMAT_R8_UNORM, {C::UInt8, 1, true}},
    {DXGI_FORMAT_R8_UINT, {C::UInt8, 1, false}},
    {DXGI_FORMAT_R8_SNORM, {C::SInt8, 1, true}},
    {DXGI_FORMAT_R8_SINT, {C::SInt8, 1, false}},
};

}  // namespace

bool vertexFormat(DXGI_FORMAT f, VertexFormat& out) {
    for (const VertexFormatOf& v : kVertexFormats)
        if (v.format == f) {
            out = v.vertex;
            return true;
        }
    return false;
}

HRESULT readAsInputReads(VertexFormat& format, bool integerInput, DXGI_FORMAT dxgi, const std::string& at) {
    if (integerInput || format.normalized) return S_OK;
    switch (format.component) {
    case C::UInt32:
    case C::SInt32: format.component = C::Float32; return S_OK;  // the same 32 bits, unconverted
    case C::UInt16:
    case C::SInt16:
    case C::UInt8:
    case C::SInt8:
        return fail(E_NOTIMPL, at + "Format = " + formatName(dxgi) + " (" + std::to_string(dxgi) +
                                   ") feeds a float input: D3D hands the shader the integer's bits (a denormal float), which fxport "
                                   "can do for 32-bit integers only; declare the input uint/int and convert with asfloat() or (float)");
    default: return S_OK;
    }
}

}  // namespace fxport::d3d11
