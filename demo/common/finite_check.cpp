#include "common/finite_check.h"

#include <cstdio>
#include <exception>

#include "common/pass_timer.h"

namespace fxport::demo {

NonFiniteError::NonFiniteError(const NonFiniteTarget& found)
    : std::runtime_error("--check-finite: " + found.describe()), first(found) {}

void throwIfNonFinite(const std::vector<NonFiniteTarget>& found) {
    if (!found.empty()) throw NonFiniteError(found.front());
}

FiniteCheckScope::FiniteCheckScope(GraphicsDevice* device, bool enabled) {
    if (!enabled || !device) return;
    check_ = std::make_unique<FiniteCheck>(*device);
    PassTimer::finiteCheck = check_.get();
}

FiniteCheckScope::~FiniteCheckScope() {
    if (!check_) return;
    PassTimer::finiteCheck = nullptr;
    if (std::uncaught_exceptions() == 0)
        std::printf("--check-finite: no NaN/Inf after %d passes (%d float/half targets scanned, %d unorm targets "
                    "skipped: they cannot hold NaN/Inf)\n",
                    check_->passesChecked(), check_->targetsScanned(), check_->targetsSkipped());
}

}  // namespace fxport::demo
