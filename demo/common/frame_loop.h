// The frame loop every fxdemo program runs: in a window, XNA's fixed 60 Hz steps until the window
// closes or `frames` is reached; headless, exactly `frames` (else `headlessDefault`) frames as fast
// as possible. After each frame the GPU timer's EndFrame(); at the end the device and the timer are
// finished so every pass time is in. `frame(index, lastHeadless)` returns false to stop early.
#pragma once

#include <functional>
#include <optional>

#include "fxport/graphics.h"

namespace fxport::demo {

// Returns the number of frames run.
int runFrameLoop(GraphicsDevice& device, GpuTimer& timer, bool windowed, std::optional<int> frames,
                 int headlessDefault, const std::function<bool(int index, bool lastHeadless)>& frame);

}  // namespace fxport::demo
