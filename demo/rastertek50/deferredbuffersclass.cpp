////////////////////////////////////////////////////////////////////////////////
// Filename: deferredbuffersclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/deferredbuffersclass.h"

namespace Rastertek50 {

DeferredBuffersClass::DeferredBuffersClass()
{
	m_textureWidth = 0;
	m_textureHeight = 0;
}


DeferredBuffersClass::~DeferredBuffersClass()
{
}


bool DeferredBuffersClass::Initialize(fxport::GraphicsDevice* device, int textureWidth, int textureHeight, float screenDepth, float screenNear,
                                      fxport::SurfaceFormat format)
{
	int i;
	(void)screenDepth;
	(void)screenNear;


	// Store the width and height of the render texture.
	m_textureWidth = textureWidth;
	m_textureHeight = textureHeight;

	// Setup the render target texture description: one level, DXGI_FORMAT_R32G32B32A32_FLOAT
	// (SurfaceFormat::Vector4), render target and shader resource. The first one also carries the
	// DXGI_FORMAT_D24_UNORM_S8_UINT depth buffer. PreserveContents: binding does not clear (D3D10).

	// We now create an array of render target textures for the deferred shader to write to.

	// Create the render target textures (with their render target views and shader resource views).
	for(i=0; i<BUFFER_COUNT; i++)
	{
		m_renderTargetTextureArray[i] = std::make_unique<fxport::RenderTarget2D>(
			*device, textureWidth, textureHeight, false, format,
			i == 0 ? fxport::DepthFormat::Depth24Stencil8 : fxport::DepthFormat::None, 0,
			fxport::RenderTargetUsage::PreserveContents);
		m_renderTargetTextureArray[i]->Name = i == 0 ? "colorTexture" : "normalTexture";  // fxport: for messages
	}

	// Setup the viewport for rendering.
	m_viewport = fxport::Viewport(0, 0, textureWidth, textureHeight);
	m_viewport.MinDepth = 0.0f;
	m_viewport.MaxDepth = 1.0f;

	return true;
}


void DeferredBuffersClass::Shutdown()
{
	int i;


	for(i=0; i<BUFFER_COUNT; i++)
	{
		m_renderTargetTextureArray[i].reset();
	}
	
	return;
}


// This function now sets all of the render targets in the array as the location for the shaders
// to write to (instead of writing to the back buffer or a single render texture target).
void DeferredBuffersClass::SetRenderTargets(fxport::GraphicsDevice* device)
{
	// Bind the render target view array and depth stencil buffer to the output render pipeline.
	device->SetRenderTargets({*m_renderTargetTextureArray[0], *m_renderTargetTextureArray[1]});

	// Set the viewport.
	device->Viewport = m_viewport;

	return;
}


// The following function clears all of the render target buffers in the class object.
void DeferredBuffersClass::ClearRenderTargets(fxport::GraphicsDevice* device, float red, float green, float blue, float alpha)
{
	// Clear the render target buffers (fxport: Clear clears every bound target) and the depth buffer.
	device->Clear(fxport::ClearOptions::Target | fxport::ClearOptions::DepthBuffer,
		      fxport::Vector4(red, green, blue, alpha), 1.0f, 0);

	return;
}


// GetShaderResourceView provides calling functions a pointer to a specific shader resource out of
// the array of render textures.
fxport::RenderTarget2D* DeferredBuffersClass::GetShaderResourceView(int view)
{
	return m_renderTargetTextureArray[view].get();
}

}  // namespace Rastertek50
