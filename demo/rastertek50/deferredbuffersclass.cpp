////////////////////////////////////////////////////////////////////////////////
// Filename: deferredbuffersclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/deferredbuffersclass.h"

#include <cstring>

#include "rastertek50/readback.h"

namespace Rastertek50 {


DeferredBuffersClass::DeferredBuffersClass()
{
	int i;

	for(i=0; i<BUFFER_COUNT; i++)
	{
		m_renderTargetTextureArray[i] = 0;
		m_renderTargetViewArray[i] = 0;
		m_shaderResourceViewArray[i] = 0;
	}

	m_depthStencilBuffer = 0;
	m_depthStencilView = 0;
	m_textureWidth = 0;
	m_textureHeight = 0;
	m_format = DXGI_FORMAT_R32G32B32A32_FLOAT;
}


DeferredBuffersClass::~DeferredBuffersClass()
{
}


bool DeferredBuffersClass::Initialize(ID3D10Device* device, int textureWidth, int textureHeight, float screenDepth, float screenNear,
				      DXGI_FORMAT format)
{
	D3D10_TEXTURE2D_DESC textureDesc;
	HRESULT result;
	D3D10_RENDER_TARGET_VIEW_DESC renderTargetViewDesc;
	D3D10_SHADER_RESOURCE_VIEW_DESC shaderResourceViewDesc;
	D3D10_TEXTURE2D_DESC depthBufferDesc;
	D3D10_DEPTH_STENCIL_VIEW_DESC depthStencilViewDesc;
	int i;
	(void)screenDepth;  // unused, as in the seed
	(void)screenNear;

	// Store the width and height of the render texture.
	m_textureWidth = textureWidth;
	m_textureHeight = textureHeight;
	m_format = format;  // fxport

	// Initialize the render target texture description.
	textureDesc = D3D10_TEXTURE2D_DESC();  // fxport: ZeroMemory (the fields below are all set)

	// Setup the render target texture description.
	textureDesc.Width = textureWidth;
	textureDesc.Height = textureHeight;
	textureDesc.MipLevels = 1;
	textureDesc.ArraySize = 1;
	textureDesc.Format = format;  // the seed: DXGI_FORMAT_R32G32B32A32_FLOAT
	textureDesc.SampleDesc.Count = 1;
	textureDesc.Usage = D3D10_USAGE_DEFAULT;
	textureDesc.BindFlags = D3D10_BIND_RENDER_TARGET | D3D10_BIND_SHADER_RESOURCE;
	textureDesc.CPUAccessFlags = 0;
	textureDesc.MiscFlags = 0;

	// We now create an array of render target textures for the deferred shader to write to.
	// Create the render target textures.
	for(i=0; i<BUFFER_COUNT; i++)
	{
		result = device->CreateTexture2D(&textureDesc, NULL, &m_renderTargetTextureArray[i]);
		if(FAILED(result))
		{
			return false;
		}
	}

	// Setup the description of the render target view.
	renderTargetViewDesc.Format = textureDesc.Format;
	renderTargetViewDesc.ViewDimension = D3D10_RTV_DIMENSION_TEXTURE2D;
	renderTargetViewDesc.Texture2D.MipSlice = 0;

	// We also create an array of render target views to access the render target textures through.
	// Create the render target views.
	for(i=0; i<BUFFER_COUNT; i++)
	{
		result = device->CreateRenderTargetView(m_renderTargetTextureArray[i], &renderTargetViewDesc, &m_renderTargetViewArray[i]);
		if(FAILED(result))
		{
			return false;
		}
	}

	// Setup the description of the shader resource view.
	shaderResourceViewDesc.Format = textureDesc.Format;
	shaderResourceViewDesc.ViewDimension = D3D10_SRV_DIMENSION_TEXTURE2D;
	shaderResourceViewDesc.Texture2D.MostDetailedMip = 0;
	shaderResourceViewDesc.Texture2D.MipLevels = 1;

	// We also create an array of shader resource views for the shaders to access the render target
	// textures.
	// Create the shader resource views.
	for(i=0; i<BUFFER_COUNT; i++)
	{
		result = device->CreateShaderResourceView(m_renderTargetTextureArray[i], &shaderResourceViewDesc, &m_shaderResourceViewArray[i]);
		if(FAILED(result))
		{
			return false;
		}
	}

	// Initialize the description of the depth buffer.
	depthBufferDesc = D3D10_TEXTURE2D_DESC();  // fxport: ZeroMemory

	// Set up the description of the depth buffer.
	depthBufferDesc.Width = textureWidth;
	depthBufferDesc.Height = textureHeight;
	depthBufferDesc.MipLevels = 1;
	depthBufferDesc.ArraySize = 1;
	depthBufferDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
	depthBufferDesc.SampleDesc.Count = 1;
	depthBufferDesc.SampleDesc.Quality = 0;
	depthBufferDesc.Usage = D3D10_USAGE_DEFAULT;
	depthBufferDesc.BindFlags = D3D10_BIND_DEPTH_STENCIL;
	depthBufferDesc.CPUAccessFlags = 0;
	depthBufferDesc.MiscFlags = 0;

	// Create the texture for the depth buffer using the filled out description.
	result = device->CreateTexture2D(&depthBufferDesc, NULL, &m_depthStencilBuffer);
	if(FAILED(result))
	{
		return false;
	}

	// Initailze the depth stencil view description.
	depthStencilViewDesc = D3D10_DEPTH_STENCIL_VIEW_DESC();  // fxport: ZeroMemory

	// Set up the depth stencil view description.
	depthStencilViewDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
	depthStencilViewDesc.ViewDimension = D3D10_DSV_DIMENSION_TEXTURE2D;
	depthStencilViewDesc.Texture2D.MipSlice = 0;

	// Create the depth stencil view.
	result = device->CreateDepthStencilView(m_depthStencilBuffer, &depthStencilViewDesc, &m_depthStencilView);
	if(FAILED(result))
	{
		return false;
	}

	// Setup the viewport for rendering.
	m_viewport.Width = textureWidth;
	m_viewport.Height = textureHeight;
	m_viewport.MinDepth = 0.0f;
	m_viewport.MaxDepth = 1.0f;
	m_viewport.TopLeftX = 0;
	m_viewport.TopLeftY = 0;

	return true;
}


void DeferredBuffersClass::Shutdown()
{
	int i;

	if(m_depthStencilView)
	{
		m_depthStencilView->Release();
		m_depthStencilView = 0;
	}

	if(m_depthStencilBuffer)
	{
		m_depthStencilBuffer->Release();
		m_depthStencilBuffer = 0;
	}

	for(i=0; i<BUFFER_COUNT; i++)
	{
		if(m_shaderResourceViewArray[i])
		{
			m_shaderResourceViewArray[i]->Release();
			m_shaderResourceViewArray[i] = 0;
		}

		if(m_renderTargetViewArray[i])
		{
			m_renderTargetViewArray[i]->Release();
			m_renderTargetViewArray[i] = 0;
		}

		if(m_renderTargetTextureArray[i])
		{
			m_renderTargetTextureArray[i]->Release();
			m_renderTargetTextureArray[i] = 0;
		}
	}
	
	return;
}


// This function now sets all of the render targets in the array as the location for the shaders to
// write to (instead of writing to the back buffer or a single render texture target).
void DeferredBuffersClass::SetRenderTargets(ID3D10Device* device)
{
	// Bind the render target view array and depth stencil buffer to the output render pipeline.
	device->OMSetRenderTargets(BUFFER_COUNT, m_renderTargetViewArray, m_depthStencilView);

	// Set the viewport.
	device->RSSetViewports(1, &m_viewport);

	return;
}


// The following function clears all of the render target buffers in the class object.
void DeferredBuffersClass::ClearRenderTargets(ID3D10Device* device, float red, float green, float blue, float alpha)
{
	float color[4];
	int i;

	// Setup the color to clear the buffer to.
	color[0] = red;
	color[1] = green;
	color[2] = blue;
	color[3] = alpha;

	// Clear the render target buffers.
	for(i=0; i<BUFFER_COUNT; i++)
	{
		device->ClearRenderTargetView(m_renderTargetViewArray[i], color);
	}
    
	// Clear the depth buffer.
	device->ClearDepthStencilView(m_depthStencilView, D3D10_CLEAR_DEPTH, 1.0f, 0);

	return;
}


// GetShaderResourceView provides calling functions a pointer to a specific shader resource out of
// the array of render textures.
ID3D10ShaderResourceView* DeferredBuffersClass::GetShaderResourceView(int view)
{
	return m_shaderResourceViewArray[view];
}


namespace {

// IEEE half to float (R16G16B16A16_FLOAT targets of `fxdemo report`).
float HalfToFloat(unsigned short h)
{
	const unsigned int sign = (unsigned int)(h >> 15) << 31, exponent = (h >> 10) & 0x1F, mantissa = h & 0x3FF;
	unsigned int bits;
	if(exponent == 0)
	{
		float f = (float)mantissa / 1024.0f / 16384.0f;  // subnormal: mantissa * 2^-24
		return sign ? -f : f;
	}
	if(exponent == 31) bits = sign | 0x7F800000u | (mantissa << 13);
	else bits = sign | ((exponent + 112) << 23) | (mantissa << 13);
	float f;
	std::memcpy(&f, &bits, sizeof f);
	return f;
}

}  // namespace


std::vector<fxport::Vector4> DeferredBuffersClass::GetTargetData(ID3D10Device* device, int view)
{
	const unsigned int bytesPerTexel = m_format == DXGI_FORMAT_R32G32B32A32_FLOAT ? 16 : m_format == DXGI_FORMAT_R16G16B16A16_FLOAT ? 8 : 4;
	const std::vector<unsigned char> bytes = ReadTexture(device, m_renderTargetTextureArray[view], bytesPerTexel);
	std::vector<fxport::Vector4> texels(bytes.size() / bytesPerTexel);
	for(std::size_t i = 0; i < texels.size(); i++)
	{
		const unsigned char* p = &bytes[i * bytesPerTexel];
		float c[4];
		for(int k = 0; k < 4; k++)
		{
			if(bytesPerTexel == 16) std::memcpy(&c[k], p + 4 * k, 4);
			else if(bytesPerTexel == 8) { unsigned short h; std::memcpy(&h, p + 2 * k, 2); c[k] = HalfToFloat(h); }
			else c[k] = p[k] / 255.0f;
		}
		texels[i] = fxport::Vector4(c[0], c[1], c[2], c[3]);
	}
	return texels;
}

}  // namespace Rastertek50
