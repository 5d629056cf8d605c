// fxdemo's debug sheet of the deferred demo (not part of the seed): every intermediate target of
// the last frame on one PNG, labelled - G-buffer channels, light map, the spot light's shadow map,
// the six faces of the point light's cube shadow map, the scene before SSAO, SSAO raw and blurred,
// and the final back buffer. Targets are read back with GetData and turned into viewable colours on
// the CPU (float depths and exponential shadow maps stretched to [0, 1], see the labels), then drawn
// at tile size with SpriteBatch into a render target, and the labels with the debug font.
#pragma once

#include <string>

namespace TheCansinDeferredRenderer {

class Game1;

// Writes the sheet to `path`; with `fullSizeDir` non-empty also each tile at full size there.
void WriteDebugSheet(Game1& game, const std::string& path, const std::string& fullSizeDir);

}  // namespace TheCansinDeferredRenderer
