// DirectDraw Surface (.dds) files (internal to the runtime; Texture2D/TextureCube/Texture3D::FromFile
// and the D3D11 front end's D3DX11/DirectXTK loaders read them). The header is read by DirectXTK's
// DDSTextureLoader rules: the legacy pixel format (FourCC DXT1-DXT5, ATI1/BC4U/BC4S, ATI2/BC5U/
// BC5S, D3DX9's D3DFMT numbers 36 and 110-116, or channel masks) or the DX10 header's DXGI format
// (any D3D11 samples, BC1-BC7 and sRGB included), cube maps (all six faces), volumes, DX10 arrays.
// Two ways to read the texels:
//   Decoded: 8-bit RGBA levels (`levels`), for XNA's Texture classes. BC1/BC2/BC3 are decoded as
//     D3D's block rules define them (BC1's 3-colour mode with transparent black included), 8-bit
//     RGBA/BGRA and the channel-mask formats through their masks; other formats, arrays and 1D
//     textures are refused.
//   Stored: each subresource's bytes as the file stores them (`stored`) in `dxgiFormat`; a legacy
//     channel-mask format no DXGI format matches (24-bit RGB, X8B8G8R8 ...) is decoded instead
//     (`levels`, dxgiFormat 0).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport {
class GraphicsDevice;
class Texture2D;
class TextureCube;
}  // namespace fxport

namespace fxport::detail {

enum class DdsContent { Decoded, Stored };

struct DdsImage {
    int width = 0;
    int height = 0;
    bool cube = false;                        // six faces (+X, -X, +Y, -Y, +Z, -Z), each with `levels`
    bool volume = false;                      // a volume (DDSCAPS2_VOLUME, DDSD_DEPTH, DX10 TEXTURE3D): `depth` slices
    bool oneDimensional = false;              // DX10 TEXTURE1D (height 1); Stored only
    int depth = 1;                            // each level holds max(1, depth >> level) slices, front to back
    int arraySize = 1;                        // DX10 array items (each of 6 faces for a cube); Stored only
    int levelCount = 1;                       // mip levels per face, as stored (clamped to the full chain)
    std::uint32_t dxgiFormat = 0;             // the DXGI_FORMAT value of the stored texels (0: none matches)
    bool decodable = false;                   // the texels decode to 8-bit RGBA (DdsContent::Decoded reads them)
    int alphaMode = 0;                        // DDS_ALPHA_MODE: 0 unknown, 1 straight, 2 premultiplied (DXT2/4), 3 opaque, 4 custom
    std::vector<std::vector<Color>> levels;   // decoded: face-major (face 0's levels, then face 1's ...); a volume level's slices together
    std::vector<std::vector<std::uint8_t>> stored;  // Stored: item-major, then face, then level; a volume level's slices together
};

// Throws ArgumentError naming `path` and what is wrong (truncated data, a format not listed above,
// a header that does not add up); sizes are checked against the file before anything is copied.
DdsImage readDds(const std::string& path, DdsContent content = DdsContent::Decoded);
// The same from bytes already read; `name` is for messages.
DdsImage decodeDds(std::span<const std::uint8_t> bytes, const std::string& name, DdsContent content = DdsContent::Decoded);

// The DDS file at `path` as Texture2D::FromFile loads a .dds (decoded, a partial chain completed by
// 2x2 averages), whatever the file's name (texture.cpp).
std::unique_ptr<Texture2D> texture2DFromDds(GraphicsDevice& device, const std::string& path);
// The same with a BC1/BC2/BC3 (DXT1-5) file's blocks kept compressed: SurfaceFormat::Dxt1/Dxt3/
// Dxt5, its levels as stored (a partial chain completed by 2x2 averages encoded again); any other
// file as texture2DFromDds / TextureCube::FromFile load it (dds_stored_textures.cpp). What
// TextureProcessor's NoChange and DxtCompressed outputs load a .dds as.
std::unique_ptr<Texture2D> texture2DFromDdsAsStored(GraphicsDevice& device, const std::string& path);
std::unique_ptr<TextureCube> textureCubeFromDdsAsStored(GraphicsDevice& device, const std::string& path);

// One BC1/BC2/BC3 block of 16 texels (row by row) from its 8 or 16 bytes.
void decodeBc1Block(const std::uint8_t* block, Color out[16]);
void decodeBc2Block(const std::uint8_t* block, Color out[16]);
void decodeBc3Block(const std::uint8_t* block, Color out[16]);

}  // namespace fxport::detail
