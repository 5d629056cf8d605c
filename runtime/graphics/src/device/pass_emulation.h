// INTERNAL, GL-free: the D3D9 render states a pass sets that GL core lacks, as EffectPass::Apply()
// hands them to the device (effect/pass_states.cpp) without seeing the device's private state.
#pragma once

#include "fxport/graphics/graphics_device.h"

namespace fxport::xlate {
struct SourceLocation;
}

namespace fxport {

// D3D9 render states GL core lacks, as the last EffectPass::Apply() set them (off unless its pass
// says otherwise).
struct PassEmulation {
    // Set by each draw from GraphicsDevice::FixedFunction (fixed_function_draw.cpp): whether the
    // alpha test, or another emulated D3D9 fixed-function state, changes what the draw does.
    bool alphaTest = false;
    bool fixedFunction = false;
    bool srgbWrite = false;     // encode into sRGB targets (Backend::setSrgbWrite)
    const xlate::SourceLocation* srgbWriteAt = nullptr;  // where the pass set it (for the warning)
    bool* srgbWriteReported = nullptr;  // the applied effect's "said once" flag
    bool operator==(const PassEmulation&) const = default;
};

// What the next draws emulate: the last applied pass's states.
void setPassEmulation(GraphicsDevice& device, const PassEmulation& emulation);

}  // namespace fxport
