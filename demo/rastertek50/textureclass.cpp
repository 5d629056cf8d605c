////////////////////////////////////////////////////////////////////////////////
// Filename: textureclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/textureclass.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace Rastertek50 {

TextureClass::TextureClass()
{
	m_texture = 0;
}


TextureClass::~TextureClass()
{
}


// A sandy "sea floor" (stand-in for seafloor.dds): two sand tones in an 8x8 checker with ripples,
// and orientation marks: a red tile at texcoord (0,0) (top left) and a green tile at (1,0) (top
// right), so that a flip shows in the images.
fxport::Color TextureClass::Texel(int x, int y, int size)
{
	const int tile = size / 8;
	const int tx = x / tile, ty = y / tile;
	if(ty == 0 && tx == 0) return fxport::Color(220, 40, 30, 255);
	if(ty == 0 && tx == 7) return fxport::Color(40, 190, 60, 255);
	const float u = (x + 0.5f) / float(size), v = (y + 0.5f) / float(size);
	const float ripple = 0.5f + 0.5f * std::sin(6.2831853f * (6.0f * u + 2.0f * v));
	const bool dark = ((tx + ty) & 1) != 0;
	const float base = dark ? 0.55f : 0.85f;
	const float k = base * (0.85f + 0.15f * ripple);
	return fxport::Color(int(255.0f * k), int(230.0f * k), int(170.0f * k), 255);
}


std::vector<std::vector<fxport::Color>> TextureClass::MipChain(int size)
{
	std::vector<std::vector<fxport::Color>> chain;

	// Level 0.
	std::vector<fxport::Color> level(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
	for(int y = 0; y < size; y++)
		for(int x = 0; x < size; x++)
			level[std::size_t(y) * std::size_t(size) + std::size_t(x)] = Texel(x, y, size);
	chain.push_back(level);

	// The mip chain, each level the 2x2 box average of the one above.
	int levelSize = size;
	while(levelSize > 1)
	{
		const int next = levelSize / 2;
		std::vector<fxport::Color> smaller(static_cast<std::size_t>(next) * static_cast<std::size_t>(next));
		for(int y = 0; y < next; y++)
			for(int x = 0; x < next; x++)
			{
				int sum[4] = {0, 0, 0, 0};
				for(int dy = 0; dy < 2; dy++)
					for(int dx = 0; dx < 2; dx++)
					{
						const fxport::Color c = level[std::size_t(2 * y + dy) * std::size_t(levelSize) + std::size_t(2 * x + dx)];
						sum[0] += c.R; sum[1] += c.G; sum[2] += c.B; sum[3] += c.A;
					}
				smaller[std::size_t(y) * std::size_t(next) + std::size_t(x)] =
					fxport::Color((sum[0] + 2) / 4, (sum[1] + 2) / 4, (sum[2] + 2) / 4, (sum[3] + 2) / 4);
			}
		chain.push_back(smaller);
		level.swap(smaller);
		levelSize = next;
	}
	return chain;
}


namespace {

// fxport: level 0 of the generated texture as a 32-bit BMP (BITMAPINFOHEADER, bottom-up rows,
// BGRA bytes), for D3DX10CreateShaderResourceViewFromFile to load.
bool WriteBmp(const std::string& path, int size)
{
	std::vector<unsigned char> file(54 + std::size_t(size) * std::size_t(size) * 4, 0);
	auto put32 = [&](std::size_t at, std::uint32_t v) { for(int i = 0; i < 4; i++) file[at + std::size_t(i)] = (unsigned char)(v >> (8 * i)); };
	file[0] = 'B';
	file[1] = 'M';
	put32(2, std::uint32_t(file.size()));
	put32(10, 54);
	put32(14, 40);
	put32(18, std::uint32_t(size));
	put32(22, std::uint32_t(size));
	file[26] = 1;
	file[28] = 32;
	for(int y = 0; y < size; y++)
		for(int x = 0; x < size; x++)
		{
			const fxport::Color c = TextureClass::Texel(x, size - 1 - y, size);  // file rows bottom-up
			unsigned char* p = &file[54 + (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4];
			p[0] = c.B; p[1] = c.G; p[2] = c.R; p[3] = c.A;
		}
	std::ofstream out(path, std::ios::binary);
	out.write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
	return bool(out);
}

}  // namespace


bool TextureClass::Initialize(ID3D10Device* device, int size)
{
	HRESULT result;


	// fxport: the generated texture as a file (one per process, removed once loaded).
	const std::string filename = (std::filesystem::temp_directory_path() /
				      ("fxport-rastertek50-seafloor-" + std::to_string(getpid()) + ".bmp")).string();
	if(!WriteBmp(filename, size))
	{
		std::fprintf(stderr, "fxdemo rastertek50: cannot write %s\n", filename.c_str());
		return false;
	}

	// Load the texture in.
	result = D3DX10CreateShaderResourceViewFromFile(device, filename.c_str(), NULL, NULL, &m_texture, NULL);
	std::error_code ignored;
	std::filesystem::remove(filename, ignored);
	if(FAILED(result))
	{
		std::fprintf(stderr, "fxdemo rastertek50: %s\n", GetLastErrorMessage());
		return false;
	}

	return true;
}


void TextureClass::Shutdown()
{
	// Release the texture resource.
	if(m_texture)
	{
		m_texture->Release();
		m_texture = 0;
	}
	return;
}


ID3D10ShaderResourceView* TextureClass::GetTexture()
{
	return m_texture;
}

}  // namespace Rastertek50
