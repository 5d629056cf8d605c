// fxdemo's debug sheet of the point-lights demo (not part of the seed): the G-buffer targets
// (colorRT rgb and alpha, normalRT rgb and alpha, depthRT), the light map (lightRT rgb = diffuse
// light, alpha = specular) and the final back buffer of the last frame on one labelled PNG.
#pragma once

#include <string>

namespace DeferredLighting {

class Game1;

void WriteDebugSheet(Game1& game, const std::string& path);

}  // namespace DeferredLighting
