// DeviceOptimizations (fxport/graphics/device_optimizations.h): None() switches every pass off, and
// withEnvironment() is the one place the FXPORT_* switches are read: 0 and 1 override, anything else
// is reported and ignored. No GPU needed.
#include "fxport/graphics/device_optimizations.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace fxport;

namespace {

const char* kSwitches[] = {"FXPORT_DEFER_CLEARS", "FXPORT_HONOUR_DISCARDS", "FXPORT_LAZY_DEPTH",
                           "FXPORT_DROP_COVERED_CLEARS", "FXPORT_COMPUTE_PASSES"};

// Clears the switches for one test and puts back what the environment had.
struct CleanEnvironment {
    std::string saved[5];
    bool had[5] = {};
    CleanEnvironment() {
        for (int i = 0; i < 5; ++i) {
            if (const char* v = std::getenv(kSwitches[i])) had[i] = true, saved[i] = v;
            unsetenv(kSwitches[i]);
        }
    }
    ~CleanEnvironment() {
        for (int i = 0; i < 5; ++i)
            if (had[i]) setenv(kSwitches[i], saved[i].c_str(), 1);
            else unsetenv(kSwitches[i]);
    }
};

}  // namespace

TEST(DeviceOptimizations, DefaultsAreOnAndComputePassesUnset) {
    DeviceOptimizations o;
    EXPECT_TRUE(o.DeferClears && o.HonourDiscards && o.LazyDepthStorage && o.DropCoveredClears);
    EXPECT_FALSE(o.ComputePasses.has_value());
}

TEST(DeviceOptimizations, NoneSwitchesEveryPassOff) {
    DeviceOptimizations o = DeviceOptimizations::None();
    EXPECT_FALSE(o.DeferClears || o.HonourDiscards || o.LazyDepthStorage || o.DropCoveredClears);
    ASSERT_TRUE(o.ComputePasses.has_value());
    EXPECT_FALSE(*o.ComputePasses);
}

TEST(DeviceOptimizations, EnvironmentOverridesEachWay) {
    CleanEnvironment clean;
    setenv("FXPORT_DEFER_CLEARS", "0", 1);
    setenv("FXPORT_LAZY_DEPTH", "1", 1);
    setenv("FXPORT_COMPUTE_PASSES", "1", 1);
    DeviceOptimizations o = DeviceOptimizations::None();
    o.DeferClears = true;
    DeviceOptimizations e = o.withEnvironment();
    EXPECT_FALSE(e.DeferClears);
    EXPECT_TRUE(e.LazyDepthStorage);
    EXPECT_FALSE(e.HonourDiscards);  // not set: as given
    ASSERT_TRUE(e.ComputePasses.has_value());
    EXPECT_TRUE(*e.ComputePasses);
}

TEST(DeviceOptimizations, OtherValuesAreReportedAndIgnored) {
    CleanEnvironment clean;
    setenv("FXPORT_HONOUR_DISCARDS", "off", 1);
    setenv("FXPORT_COMPUTE_PASSES", "yes", 1);
    testing::internal::CaptureStderr();
    DeviceOptimizations e = DeviceOptimizations().withEnvironment();
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(e.HonourDiscards);
    EXPECT_FALSE(e.ComputePasses.has_value());
    EXPECT_NE(said.find("FXPORT_HONOUR_DISCARDS='off' is not 1 or 0"), std::string::npos) << said;
    EXPECT_NE(said.find("FXPORT_COMPUTE_PASSES='yes' is not 1 or 0"), std::string::npos) << said;
}
