// The device's side of the fragment tally (diagnostics/fragment_tally.h): GraphicsDevice's
// tallyFragments calls and the per-draw hook flush() calls.
#include "device/device_impl.h"
#include "diagnostics/fragment_tally.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

void GraphicsDevice::tallyFragments(bool on) {
    if (on && !impl_->fragmentTally) impl_->fragmentTally = std::make_shared<FragmentRuns>(*impl_);
    if (!on) impl_->fragmentTally.reset();
}

std::size_t GraphicsDevice::fragmentTallyMark() { return impl_->fragmentTally ? impl_->fragmentTally->mark() : 0; }

std::vector<GraphicsDevice::FragmentTally> GraphicsDevice::fragmentTallies(std::size_t from, std::size_t to) {
    return impl_->fragmentTally ? impl_->fragmentTally->between(from, to) : std::vector<FragmentTally>{};
}

void GraphicsDevice::Impl::tallyDraw() {
    if (!fragmentTally || !shaders[1]) return;
    const ShaderProgram& pixel = *shaders[1];
    if (!pixel.textureFetches) pixel.textureFetches = pixel.shader ? xlate::countTextureFetches(pixel.shader->glsl) : xlate::TextureFetches{};
    fragmentTally->beforeDraw(*pixel.textureFetches);
}

}  // namespace fxport
