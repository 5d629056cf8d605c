// fxport addition: the procedural sprites of fxdemo lighting2d's scene (the seed draws whatever
// textures its game has; we generate them): a tiled floor for the background, and three shadow
// casters -- a box, a disc and an "L" bar that marks orientation (a flip would show). Shared by the
// demo and `fxdemo report`'s lighting2d sweep, so that both render the same scene.
#pragma once

#include <memory>

#include "fxport/graphics.h"

namespace _2DLightingSystem {

struct SceneSprites {
    std::unique_ptr<fxport::Texture2D> background, box, disc, bar;
};

SceneSprites MakeSceneSprites(fxport::GraphicsDevice& device);

}  // namespace _2DLightingSystem
