// Shared pieces of the runtime's pixel tests: one headless device per test process, the fixture
// effects, and a full-screen quad drawn with user primitives.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics.h"

namespace fxport::test {

// Created on first use (OSMesa, or $FXPORT_PLATFORM), kept until exit.
GraphicsDevice& testDevice();

// tests/fixtures/runtime/<name>.
std::string runtimeFixture(const std::string& name);

// Two triangles covering NDC [-1,1]^2 at depth z, UV (0,0) at NDC (-1,+1) and (1,1) at (+1,-1)
// (the seed's FullscreenQuad mapping). Clockwise as seen, so default culling keeps them.
std::vector<VertexPositionTexture> fullscreenQuad(float z = 0);
void drawQuad(GraphicsDevice& device, float z = 0);

// Reads a render target back as floats, 4 per texel (RGBA), top row first.
std::vector<float> readFloats(RenderTarget2D& target);

}  // namespace fxport::test
