////////////////////////////////////////////////////////////////////////////////
// Filename: textureclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed's ModelClass loads seafloor.dds through TextureClass, which it does not
// list): the Rastertek DX10 TextureClass, D3DX10CreateShaderResourceViewFromFile. fxport: the
// texture is generated content (Texel), written to a BMP file that the same call loads; D3DX10
// gives it the full mip chain (each level the 2x2 box average of the one above, as MipChain makes
// it), which the sampler's MIN_MAG_MIP_LINEAR uses.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <vector>

#include "fxport/d3d10.h"
#include "fxport/graphics.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

////////////////////////////////////////////////////////////////////////////////
// Class name: TextureClass
////////////////////////////////////////////////////////////////////////////////
class TextureClass
{
public:
	TextureClass();
	TextureClass(const TextureClass&) = delete;
	~TextureClass();

	// fxport: `size` (the generated texture's) replaces the file name (seafloor.dds).
	bool Initialize(ID3D10Device*, int size);
	void Shutdown();

	ID3D10ShaderResourceView* GetTexture();

	// The generated texel at (x, y) of level 0, top row first (for tests).
	static fxport::Color Texel(int x, int y, int size);
	// fxport: every mip level of the generated texture, level 0 first, each top row first.
	static std::vector<std::vector<fxport::Color>> MipChain(int size);

private:
	ID3D10ShaderResourceView* m_texture;
};

}  // namespace Rastertek50
