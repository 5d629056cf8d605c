// fxport::PackedVector: XNA's bit layouts, with expectations worked out by hand from XNA's packing
// rules (clamp, scale by the field's maximum, round to nearest even; IEEE binary16 for halves), and
// the types moved through SetData/GetData of their SurfaceFormat and sampled by a shader.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "fxport/graphics.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using namespace PackedVector;

TEST(PackedVector, HalvesRoundToNearestEvenAndOverflowToInfinity) {
    EXPECT_EQ(packHalf(1.0f), 0x3C00);
    EXPECT_EQ(packHalf(-2.0f), 0xC000);
    EXPECT_EQ(packHalf(65504.0f), 0x7BFF);                // the largest half
    EXPECT_EQ(packHalf(65519.0f), 0x7BFF);                // below the midpoint to 65536
    EXPECT_EQ(packHalf(65520.0f), 0x7C00);                // the midpoint: ties to even, infinity
    EXPECT_EQ(packHalf(1.0f + 1.0f / 2048), 0x3C00);      // halfway between 1 and 1 + 2^-10: even 1
    EXPECT_EQ(packHalf(1.0f + 3.0f / 2048), 0x3C02);      // halfway between 0x3C01 and 0x3C02: even
    EXPECT_EQ(packHalf(std::ldexp(1.0f, -24)), 0x0001);   // the smallest subnormal
    EXPECT_EQ(packHalf(std::ldexp(1.0f, -25)), 0x0000);   // half of it: ties to even, zero
    EXPECT_EQ(packHalf(std::ldexp(3.0f, -26)), 0x0001);   // three quarters of it: up
    EXPECT_EQ(packHalf(-0.0f), 0x8000);
    EXPECT_EQ(packHalf(std::numeric_limits<float>::infinity()), 0x7C00);
    EXPECT_TRUE(std::isnan(unpackHalf(packHalf(std::numeric_limits<float>::quiet_NaN()))));
    EXPECT_EQ(unpackHalf(0x3555), 0.333251953125f);  // 1.0101010101b * 2^-2
    EXPECT_EQ(unpackHalf(0x0001), std::ldexp(1.0f, -24));
    EXPECT_EQ(unpackHalf(0xFBFF), -65504.0f);
}

TEST(PackedVector, LayoutsAndRoundingAreXnas) {
    // NormalizedByte4(1, -1, 0.5, 0): 127, -127 (0x81), 63.5 -> 64 (even), 0; x in the low byte.
    EXPECT_EQ(NormalizedByte4(1, -1, 0.5f, 0).PackedValue, 0x0040817Fu);
    EXPECT_EQ(NormalizedByte4(2, -3, 0, 0).PackedValue, 0x0000817Fu);  // clamped to [-1, 1]
    const Vector4 back = NormalizedByte4(1, -1, 0.5f, 0).ToVector4();
    EXPECT_EQ(back, Vector4(1, -1, 64.0f / 127, 0));
    NormalizedByte4 minimum;
    minimum.PackedValue = 0x80;  // -128 reads as -1
    EXPECT_EQ(minimum.ToVector4().X, -1.0f);
    EXPECT_EQ(NormalizedByte2(-0.5f, 1).PackedValue, 0x7FC0u);  // -63.5 -> -64 (even): 0xC0; 127
    EXPECT_EQ(HalfVector2(1, -2).PackedValue, 0xC0003C00u);
    EXPECT_EQ(HalfVector4(1, -2, 0.5f, 0).PackedValue, 0x00003800C0003C00ull);
    EXPECT_EQ(Bgra5551(1, 0, 0, 1).PackedValue, 0xFC00u);
    EXPECT_EQ(Bgra5551(0, 0, 1, 0.4f).PackedValue, 0x001Fu);  // alpha 0.4 rounds to 0
    EXPECT_EQ(Bgr565(0, 1, 0).PackedValue, 0x07E0u);
    EXPECT_EQ(Bgra4444(1, 0.5f, 0, 1).PackedValue, 0xFF80u);  // 7.5 -> 8 (even)
    EXPECT_EQ(Rgba1010102(1, 0, 0.5f, 1).PackedValue, 0xE00003FFu);  // 511.5 -> 512
    EXPECT_EQ(Rg32(1, 0.5f).PackedValue, 0x8000FFFFu);  // 32767.5 -> 32768 (even)
    EXPECT_EQ(Rgba64(0, 1, 0, 1).PackedValue, 0xFFFF0000FFFF0000ull);
    EXPECT_EQ(Short2(-40000, 1.5f).PackedValue, 0x00028000u);  // clamped to -32768; 1.5 -> 2
    EXPECT_EQ(Short2(-40000, 1.5f).ToVector2(), Vector2(-32768, 2));
    EXPECT_EQ(Short4(2.5f, -1, 0, 40000).PackedValue, 0x7FFF0000FFFF0002ull);  // 2.5 -> 2
    EXPECT_EQ(Byte4(300, -5, 127.5f, 1).PackedValue, 0x01800000u | 0xFFu);  // 255, 0, 128, 1
    EXPECT_EQ(Alpha8(0.5f).PackedValue, 128);  // 127.5 -> 128 (even)
    EXPECT_EQ(NormalizedShort2(1, -1).PackedValue, 0x80017FFFu);
    EXPECT_EQ(NormalizedShort4(0, 0, 0, 1).PackedValue, 0x7FFF000000000000ull);
    EXPECT_EQ(HalfSingle(std::numeric_limits<float>::quiet_NaN()).PackedValue & 0x7C00, 0x7C00);
    EXPECT_EQ(Rgba64(std::numeric_limits<float>::quiet_NaN(), 0, 0, 0).PackedValue, 0u);  // NaN packs as 0
}

// The types are what SetData of their SurfaceFormat takes: written, read back unchanged, and
// sampled as the values they stand for.
TEST(PackedVector, TexturesTakeThemAsTheirFormatsTexels) {
    GraphicsDevice& device = test::testDevice();
    Texture2D halves(device, 2, 1, false, SurfaceFormat::HalfVector4);
    const std::vector<HalfVector4> written = {HalfVector4(1, 0.5f, -2, 0.25f), HalfVector4(65504, 0, 1.0f / 3, 1)};
    halves.SetData(written);
    std::vector<HalfVector4> read(2);
    halves.GetData(read.data(), read.size());
    EXPECT_EQ(read, written);

    Texture2D bytes(device, 1, 1, false, SurfaceFormat::NormalizedByte4);
    const NormalizedByte4 texel(1, -1, 0.5f, 0);
    bytes.SetData(&texel, 1);
    NormalizedByte4 back;
    bytes.GetData(&back, 1);
    EXPECT_EQ(back, texel);

    Texture2D packed(device, 1, 1, false, SurfaceFormat::Bgra5551);
    const Bgra5551 red(1, 0, 0, 1);
    packed.SetData(&red, 1);
    Bgra5551 redBack;
    packed.GetData(&redBack, 1);
    EXPECT_EQ(redBack, red);
}

}  // namespace
}  // namespace fxport
