#include "common/frame_loop.h"

#include <chrono>
#include <thread>

#include "fxport/platform/graphics_context.h"

namespace fxport::demo {

int runFrameLoop(GraphicsDevice& device, GpuTimer& timer, bool windowed, std::optional<int> frames,
                 int headlessDefault, const std::function<bool(int index, bool lastHeadless)>& frame) {
    int count = 0;
    if (windowed) {
        using Clock = std::chrono::steady_clock;
        auto next = Clock::now();
        while (!device.context().shouldClose() && (!frames || count < *frames)) {
            if (!frame(count, false)) break;
            timer.EndFrame();
            ++count;
            next += std::chrono::microseconds(16667);
            auto now = Clock::now();
            if (next > now) std::this_thread::sleep_until(next);
            else next = now;
        }
    } else {
        const int n = frames.value_or(headlessDefault);
        for (; count < n; ++count) {
            if (!frame(count, count == n - 1)) break;
            timer.EndFrame();
        }
    }
    device.finish();
    timer.Finish();
    return count;
}

}  // namespace fxport::demo
