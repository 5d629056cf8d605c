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
#include <vector>

#include "fxport/d3d10.h"
#include "fxport/graphics.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

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
	bool Initialize(ID3D10Device*, int, int, float, float, DXGI_FORMAT format = DXGI_FORMAT_R32G32B32A32_FLOAT);
	void Shutdown();

	void SetRenderTargets(ID3D10Device*);
	void ClearRenderTargets(ID3D10Device*, float, float, float, float);

	ID3D10ShaderResourceView* GetShaderResourceView(int);

	// fxport additions for fxdemo (--explain, --check, debug.png): the targets' size and format,
	// and a target's texels read back as float4 (whatever its format), top row first.
	int GetTextureWidth() const { return m_textureWidth; }
	int GetTextureHeight() const { return m_textureHeight; }
	DXGI_FORMAT GetFormat() const { return m_format; }
	std::vector<fxport::Vector4> GetTargetData(ID3D10Device*, int);

private:
	int m_textureWidth, m_textureHeight;
	DXGI_FORMAT m_format;  // fxport

	// The render targets are now in an array instead of single pointers.
	ID3D10Texture2D* m_renderTargetTextureArray[BUFFER_COUNT];
	ID3D10RenderTargetView* m_renderTargetViewArray[BUFFER_COUNT];
	ID3D10ShaderResourceView* m_shaderResourceViewArray[BUFFER_COUNT];
	ID3D10Texture2D* m_depthStencilBuffer;
	ID3D10DepthStencilView* m_depthStencilView;
	D3D10_VIEWPORT m_viewport;
};

}  // namespace Rastertek50
