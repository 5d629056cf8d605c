// DirectDraw Surface (.dds) files -> RGBA8 levels (internal to fxport_graphics; Texture2D::FromFile
// uses it). Block-compressed BC1/BC2/BC3 (DXT1/DXT3/DXT5) are decoded here as D3D's block rules
// define them (BC1's 3-colour mode with transparent black included); uncompressed files are read
// through their channel masks (A8R8G8B8, X8R8G8B8, A8B8G8R8, R5G6B5, A1R5G5B5, A4R4G4B4, L8, A8,
// A8L8) or their DX10 DXGI format (R8G8B8A8, B8G8R8A8/X8, BC1-BC3, sRGB variants as stored).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport::detail {

struct DdsImage {
    int width = 0;
    int height = 0;
    bool cube = false;                        // six faces (+X, -X, +Y, -Y, +Z, -Z), each with `levels`
    bool volume = false;                      // a volume (DDSCAPS2_VOLUME / DX10 TEXTURE3D): `depth` slices
    int depth = 1;                            // each level holds max(1, depth >> level) slices, front to back
    std::vector<std::vector<Color>> levels;   // face-major: face 0's levels, then face 1's ...
    int levelCount = 1;                       // mip levels per face, as stored
};

// Throws ArgumentError naming `path` and what is wrong (truncated data, a format not listed above,
// a header that does not add up).
DdsImage readDds(const std::string& path);
// The same from bytes already read; `name` is for messages.
DdsImage decodeDds(std::span<const std::uint8_t> bytes, const std::string& name);

// One BC1/BC2/BC3 block of 16 texels (row by row) from its 8 or 16 bytes.
void decodeBc1Block(const std::uint8_t* block, Color out[16]);
void decodeBc2Block(const std::uint8_t* block, Color out[16]);
void decodeBc3Block(const std::uint8_t* block, Color out[16]);

}  // namespace fxport::detail
