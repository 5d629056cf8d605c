// The tutorial's "Scene" model (Content.Load<Model>("Scene"), seed 000 lines 641, 1850): a walled
// courtyard lit by the final chapter's lights (spot light at (0, 15, 0) pointing down, point light
// at (0, 5, 0) with radius 20; seed lines 2530-2539). See content/README.md for the layout.
#pragma once

#include <filesystem>

namespace fxport::content {

// Writes Scene.gltf, Scene.bin and the material textures (<Material>_{Albedo,Normal,Specular}.png).
void WriteScene(const std::filesystem::path& dir);

}  // namespace fxport::content
