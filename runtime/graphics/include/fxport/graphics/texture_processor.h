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
// .dds files are taken as authored (their own mips and alpha), as MonoGame's processor leaves
// compressed input alone.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;

struct TextureProcessor {
    Color ColorKeyColor = Color(255, 0, 255, 255);
    bool ColorKeyEnabled = true;
    bool GenerateMipmaps = false;
    bool PremultiplyAlpha = true;
    bool ResizeToPowerOfTwo = false;
    bool MakeSquare = false;  // MonoGame's: pad nothing, resize to the larger side

    // Every step off: the image as the file has it.
    static TextureProcessor None() { return {Color(255, 0, 255, 255), false, false, false, false, false}; }

    struct Output {
        int width = 0;
        int height = 0;
        std::vector<std::vector<Color>> levels;  // levels[0] is width x height, then its mip chain
    };
    // `pixels` is width x height, top row first. Throws ArgumentError when the sizes disagree.
    Output Process(std::vector<Color> pixels, int width, int height) const;
    // Loads an image file (.png .jpg .jpeg .bmp .tga; .dds as authored) and processes it.
    std::unique_ptr<Texture2D> Load(GraphicsDevice& device, const std::string& path) const;
};

}  // namespace fxport
