// DeviceOptimizations::withEnvironment: the FXPORT_* switches of the device's optimisation passes.
#include "fxport/graphics/device_optimizations.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace fxport {

namespace {

// $name=0 turns `value` off, 1 on; anything else but unset or empty is reported and ignored.
void applyOverride(const char* name, bool& value) {
    const char* set = std::getenv(name);
    if (!set || !*set) return;
    const std::string text = set;
    if (text == "0" || text == "1")
        value = text == "1";
    else
        std::cerr << "fxport: " << name << "='" << text << "' is not 1 or 0; DeviceOptimizations decides\n";
}

}  // namespace

DeviceOptimizations DeviceOptimizations::withEnvironment() const {
    DeviceOptimizations out = *this;
    applyOverride("FXPORT_DEFER_CLEARS", out.DeferClears);
    applyOverride("FXPORT_HONOUR_DISCARDS", out.HonourDiscards);
    applyOverride("FXPORT_LAZY_DEPTH", out.LazyDepthStorage);
    applyOverride("FXPORT_DROP_COVERED_CLEARS", out.DropCoveredClears);
    if (const char* compute = std::getenv("FXPORT_COMPUTE_PASSES"); compute && *compute) {
        bool on = out.ComputePasses.value_or(false);
        applyOverride("FXPORT_COMPUTE_PASSES", on);
        if (std::string(compute) == "0" || std::string(compute) == "1") out.ComputePasses = on;
    }
    return out;
}

}  // namespace fxport
