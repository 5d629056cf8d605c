// DepthStencilState: an immutable description with XNA's names and presets (Default, DepthRead, None).
#pragma once

#include <cstdint>

namespace fxport {

enum class CompareFunction : std::uint8_t { Always, Never, Less, LessEqual, Equal, GreaterEqual, Greater, NotEqual };
enum class StencilOperation : std::uint8_t {
    Keep, Zero, Replace, Increment, Decrement, IncrementSaturation, DecrementSaturation, Invert,
};

struct DepthStencilState {
    bool DepthBufferEnable = true;
    bool DepthBufferWriteEnable = true;
    CompareFunction DepthBufferFunction = CompareFunction::LessEqual;
    bool StencilEnable = false;
    CompareFunction StencilFunction = CompareFunction::Always;
    StencilOperation StencilPass = StencilOperation::Keep;
    StencilOperation StencilFail = StencilOperation::Keep;
    StencilOperation StencilDepthBufferFail = StencilOperation::Keep;
    bool TwoSidedStencilMode = false;
    CompareFunction CounterClockwiseStencilFunction = CompareFunction::Always;
    StencilOperation CounterClockwiseStencilPass = StencilOperation::Keep;
    StencilOperation CounterClockwiseStencilFail = StencilOperation::Keep;
    StencilOperation CounterClockwiseStencilDepthBufferFail = StencilOperation::Keep;
    int ReferenceStencil = 0;
    int StencilMask = -1;
    int StencilWriteMask = -1;

    bool operator==(const DepthStencilState&) const = default;

    static const DepthStencilState Default;    // test and write, LessEqual
    static const DepthStencilState DepthRead;  // test, no write
    static const DepthStencilState None;       // no test, no write
};

}  // namespace fxport
