// The fixture most pixel tests of effects draw with: opaque blending, no depth test, no culling,
// and afterwards the back buffer as the target and no test texture left in a slot (the device is
// shared by every test of the process, testDevice()).
#pragma once

#include <gtest/gtest.h>

#include "fxport/graphics.h"
#include "runtime_test_support.h"

namespace fxport::test {

class OpaqueDrawTest : public ::testing::Test {
protected:
    void SetUp() override {
        device.BlendState = BlendState::Opaque;
        device.DepthStencilState = DepthStencilState::None;
        device.RasterizerState = RasterizerState::CullNone;
    }
    void TearDown() override {
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        for (int i = 0; i < kMaxTextureSlots; ++i) device.Textures[i] = nullptr;
    }
    static EffectOptions noCache() {
        EffectOptions o;
        o.useCache = false;
        return o;
    }
    GraphicsDevice& device = testDevice();
};

}  // namespace fxport::test
