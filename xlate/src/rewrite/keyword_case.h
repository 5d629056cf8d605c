// fxc reads the type keywords `matrix`, `vector` and `dword` in any case: the DirectX SDK's
// Soldier.fx (a vs_4_0 shader) declares `Matrix m = ...;`, Windows code `DWORD`. glslang knows only
// the lower-case words. A case
// variant used as a plain type (a name follows; fxc refuses `Matrix<float, 2, 2>` and
// `Vector<float, 2>`, as vkd3d's type-names pins) that the source does not declare itself
// (`struct Matrix`, `typedef ... Vector;`) is lower-cased. Runs on the preprocessed text, before
// the parser; the words keep their length, so every offset and line stays.
#pragma once

#include <string>

namespace fxport::xlate {

std::string typeKeywordsLowerCased(const std::string& preprocessed);

// fxc reads the texture keywords in any case too: `texture2D<float> t;` is a Texture2D (vkd3d's
// texture-load-typed L56). A DX9 texture takes no template, so a case variant of texture1D,
// texture2D, texture3D or textureCUBE followed by `<` is the DX10 object: spelled as glslang knows it
// (Texture2D, TextureCube). `TEXTURECUBE` keeps its length (`TextureCube`): offsets stay.
std::string textureTemplatesSpelledAsObjects(const std::string& preprocessed);

}  // namespace fxport::xlate
