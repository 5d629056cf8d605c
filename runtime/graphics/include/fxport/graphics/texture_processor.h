// TextureProcessor: what XNA's content pipeline did to every texture it built, with XNA's
// defaults. An XNA game's .xnb textures were processed at build time (magenta keyed out, colours
// premultiplied by alpha, which SpriteBatch's and BlendState::AlphaBlend's premultiplied blending
// assume); fxport loads the source images, so ContentManager applies the same processing at load
// (ContentManager::textureProcessor, per asset ContentManager::SetTextureProcessor).
//
// The steps, in this order so keyed texels stay out of the filtering: colour key (a texel equal to
// ColorKeyColor in all four channels becomes transparent black), resize to powers of two and/or
// square (bilinear, texel centres aligned; XNA does not document its filter), premultiply
// (rgb = round(rgb * a / 255)), mip chain (each level the rounded 2x2 average of the one above).
// .dds files are taken as authored (their own mips and alpha, no keying or premultiplying), as
// MonoGame's processor returns compressed input untouched ("it is already a compressed format, we
// cannot do anything else"; XNA's own processor source is not public).
//
// TextureFormat, XNA's TextureProcessorOutputFormat, picks the SurfaceFormat of the result:
//   Color (XNA's default): every texel decoded to SurfaceFormat::Color, as above.
//   NoChange: a DXT1/DXT3/DXT5 (BC1-3) .dds keeps its blocks (SurfaceFormat::Dxt1/Dxt3/Dxt5, its
//     levels as stored); other .dds files and images load as Color.
//   DxtCompressed: images are processed as above, then each level is block-compressed: Dxt5 when
//     any texel's alpha lies strictly between 0 and 255 (XNA's "fractional alpha values"), Dxt1
//     otherwise (alpha 0 kept as BC1's transparent black, which a keyed or premultiplied
//     transparent texel already is). A DXT .dds keeps its blocks; an uncompressed one is compressed.
//     The compressed size must be a multiple of 4 both ways (D3D's rule for block-compressed
//     textures, which XNA's HiDef and Reach profiles share): other sizes are refused with an
//     ArgumentError naming the file (ResizeToPowerOfTwo gives such sizes from 4 up).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;
class TextureCube;

// XNA's TextureProcessorOutputFormat (see TextureProcessor::TextureFormat).
enum class TextureProcessorOutputFormat { Color, DxtCompressed, NoChange };

struct TextureProcessor {
    Color ColorKeyColor = Color(255, 0, 255, 255);
    bool ColorKeyEnabled = true;
    bool GenerateMipmaps = false;
    bool PremultiplyAlpha = true;
    bool ResizeToPowerOfTwo = false;
    bool MakeSquare = false;  // MonoGame's: pad nothing, resize to the larger side
    TextureProcessorOutputFormat TextureFormat = TextureProcessorOutputFormat::Color;

    // Every step off: the image as the file has it.
    static TextureProcessor None() { return {Color(255, 0, 255, 255), false, false, false, false, false}; }

    struct Output {
        int width = 0;
        int height = 0;
        std::vector<std::vector<Color>> levels;  // levels[0] is width x height, then its mip chain
    };
    // `pixels` is width x height, top row first. Throws ArgumentError when the sizes disagree.
    Output Process(std::vector<Color> pixels, int width, int height) const;
    // Loads an image file (.png .jpg .jpeg .bmp .tga; .dds as authored) and processes it, in
    // TextureFormat's SurfaceFormat. TextureProcessor with TextureFormat NoChange is the way to load
    // a .dds with its DXT blocks as stored (Texture2D::FromFile, like XNA's, always decodes).
    std::unique_ptr<Texture2D> Load(GraphicsDevice& device, const std::string& path) const;
    // A .dds cube map (TextureCube::FromFile's files): NoChange and DxtCompressed keep a DXT cube's
    // blocks, Color decodes it; an uncompressed cube loads as Color under every TextureFormat. The
    // other steps do not apply: cube maps are taken as authored (ContentManager::Load<TextureCube>
    // uses this with the asset's processor).
    std::unique_ptr<TextureCube> LoadCube(GraphicsDevice& device, const std::string& path) const;
};

}  // namespace fxport
