////////////////////////////////////////////////////////////////////////////////
// Filename: deferredbuffersclass.h
////////////////////////////////////////////////////////////////////////////////
#pragma once

// The DeferredBufferClass is just the render to texture class re-written to handle an array of
// render to textures instead of just a single one. The outputs of the deferred shader will be
// writing to the texture buffers (render targets) of this class.


//////////////
// INCLUDES //
//////////////
#include <memory>

#include "fxport/graphics.h"

namespace Rastertek50 {

// The following define sets the number of rendering buffers in this class object.

/////////////
// DEFINES //
/////////////
const int BUFFER_COUNT = 2;


////////////////////////////////////////////////////////////////////////////////
// Class name: DeferredBuffersClass
////////////////////////////////////////////////////////////////////////////////
class DeferredBuffersClass
{
public:
	DeferredBuffersClass();
	DeferredBuffersClass(const DeferredBuffersClass&) = delete;
	~DeferredBuffersClass();

	// fxport: `format` is a knob of `fxdemo report` (the seed: DXGI_FORMAT_R32G32B32A32_FLOAT).
	bool Initialize(fxport::GraphicsDevice*, int, int, float, float,
	                fxport::SurfaceFormat format = fxport::SurfaceFormat::Vector4);
	void Shutdown();

	void SetRenderTargets(fxport::GraphicsDevice*);
	void ClearRenderTargets(fxport::GraphicsDevice*, float, float, float, float);

	// fxport: a RenderTarget2D is its own shader resource view.
	fxport::RenderTarget2D* GetShaderResourceView(int);

private:
	int m_textureWidth, m_textureHeight;

	// The render targets are now in an array instead of single pointers.
	// fxport: each RenderTarget2D is the texture, its render target view and its shader resource
	// view; the depth stencil buffer belongs to the first target (fxport binds the first target's
	// depth buffer with a set of targets, as XNA does).
	std::unique_ptr<fxport::RenderTarget2D> m_renderTargetTextureArray[BUFFER_COUNT];
	fxport::Viewport m_viewport;
};

}  // namespace Rastertek50
