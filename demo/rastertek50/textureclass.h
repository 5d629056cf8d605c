////////////////////////////////////////////////////////////////////////////////
// Filename: textureclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed's ModelClass loads seafloor.dds through TextureClass, which it does not
// list). fxport: the texture is generated content, made in code with Texture2D::SetData (every mip
// level, box-filtered), since the sampler is MIN_MAG_MIP_LINEAR.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <vector>

#include "fxport/graphics.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: TextureClass
////////////////////////////////////////////////////////////////////////////////
class TextureClass
{
public:
	TextureClass();
	TextureClass(const TextureClass&) = delete;
	~TextureClass();

	// fxport: generates the texture instead of D3DX10CreateShaderResourceViewFromFile(filename).
	bool Initialize(fxport::GraphicsDevice*, int size);
	void Shutdown();

	fxport::Texture2D* GetTexture();

	// The generated texel at (x, y) of level 0, top row first (for tests).
	static fxport::Color Texel(int x, int y, int size);
	// fxport: every mip level of the generated texture, level 0 first, each top row first.
	static std::vector<std::vector<fxport::Color>> MipChain(int size);

private:
	std::unique_ptr<fxport::Texture2D> m_texture;
};

}  // namespace Rastertek50
