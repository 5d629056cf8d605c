// Draws D3D makes without colour: a depth-stencil view and no render target (a shadow map's pass),
// or no pixel shader. The device core draws into at least one colour target with a pixel shader,
// so such a draw gets a scratch target of the depth buffer's size and an empty pixel shader, with
// every colour write masked off (context_draw.cpp): what lands in the depth buffer is what D3D
// writes; the scratch target is never read. It stays for the next depth-only draw of that size.
#include "context.h"
#include "fxport/graphics/errors.h"

namespace fxport::d3d11 {

RenderTarget2D& Context::scratchTarget(int width, int height) {
    if (!scratch_ || scratch_->Width() != width || scratch_->Height() != height)
        scratch_ = std::make_unique<RenderTarget2D>(device_->core(), width, height, false, SurfaceFormat::R8, DepthFormat::None, 0,
                                                    RenderTargetUsage::PreserveContents);
    return *scratch_;
}

const PixelShader& Context::emptyPixelShader() {
    if (emptyPixelShader_) return *emptyPixelShader_.Get();
    static const char kSource[] = "void main() {}";
    ComPtr<ID3DBlob> code, errors;
    if (FAILED(D3DCompile(kSource, sizeof kSource - 1, "fxport-empty-pixel-shader.hlsl", nullptr, nullptr, "main", "ps_4_0", 0, 0,
                          code.GetAddressOf(), errors.GetAddressOf())))
        throw InvalidOperation(std::string("the empty pixel shader of a draw without one did not compile: ") + GetLastErrorMessage());
    ComPtr<ID3D11PixelShader> shader;
    if (FAILED(device_->CreatePixelShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf())))
        throw InvalidOperation(std::string("the empty pixel shader of a draw without one: ") + GetLastErrorMessage());
    emptyPixelShader_ = ComPtr<PixelShader>(static_cast<PixelShader*>(shader.Get()));
    return *emptyPixelShader_.Get();
}

}  // namespace fxport::d3d11
