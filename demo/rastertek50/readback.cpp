// ReadTexture (readback.h).
#include "rastertek50/readback.h"

#include <cstdio>
#include <cstring>

namespace Rastertek50 {

using namespace fxport::d3d10;

std::vector<unsigned char> ReadTexture(ID3D10Device* device, ID3D10Texture2D* texture, unsigned int bytesPerTexel)
{
	D3D10_TEXTURE2D_DESC desc;
	texture->GetDesc(&desc);
	desc.MipLevels = 1;
	desc.Usage = D3D10_USAGE_STAGING;
	desc.BindFlags = 0;
	desc.CPUAccessFlags = D3D10_CPU_ACCESS_READ;
	desc.MiscFlags = 0;
	ComPtr<ID3D10Texture2D> staging;
	if(FAILED(device->CreateTexture2D(&desc, NULL, staging.GetAddressOf())))
	{
		std::fprintf(stderr, "fxdemo rastertek50: read back: %s\n", GetLastErrorMessage());
		return {};
	}
	device->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, 0, NULL);
	D3D11_MAPPED_SUBRESOURCE mapped;
	if(FAILED(device->GetD3D11Context()->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped)))
	{
		std::fprintf(stderr, "fxdemo rastertek50: read back: %s\n", GetLastErrorMessage());
		return {};
	}
	const std::size_t row = std::size_t(desc.Width) * bytesPerTexel;
	std::vector<unsigned char> texels(row * desc.Height);
	for(UINT y = 0; y < desc.Height; y++)
	{
		std::memcpy(&texels[y * row], static_cast<const unsigned char*>(mapped.pData) + std::size_t(y) * mapped.RowPitch, row);
	}
	device->GetD3D11Context()->Unmap(staging.Get(), 0);
	return texels;
}

}  // namespace Rastertek50
