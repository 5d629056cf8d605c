////////////////////////////////////////////////////////////////////////////////
// Filename: d3dclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses D3DClass but does not list it): the Rastertek DX10 D3DClass, reduced
// to what tutorial 50 calls, on fxport. The swap chain, back buffer view and depth buffer are the
// GraphicsDevice's back buffer; the depth stencil states are DepthStencilState values.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <string>

#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: D3DClass
////////////////////////////////////////////////////////////////////////////////
class D3DClass
{
public:
	D3DClass();
	D3DClass(const D3DClass&) = delete;
	~D3DClass();

	// fxport: `platform` (osmesa, egl, glfw) replaces the HWND and the full screen flag.
	bool Initialize(int, int, bool, const std::string& platform, bool, float, float);
	void Shutdown();

	void BeginScene(float, float, float, float);
	void EndScene();

	fxport::GraphicsDevice* GetDevice();

	void GetProjectionMatrix(D3DXMATRIX&);
	void GetWorldMatrix(D3DXMATRIX&);
	void GetOrthoMatrix(D3DXMATRIX&);

	void TurnZBufferOn();
	void TurnZBufferOff();

	void SetBackBufferRenderTarget();
	void ResetViewport();

private:
	bool m_vsync_enabled;
	std::unique_ptr<fxport::GraphicsDevice> m_device;
	fxport::DepthStencilState m_depthStencilState;
	fxport::DepthStencilState m_depthDisabledStencilState;
	fxport::RasterizerState m_rasterState;
	fxport::Viewport m_viewport;
	D3DXMATRIX m_projectionMatrix;
	D3DXMATRIX m_worldMatrix;
	D3DXMATRIX m_orthoMatrix;
};

}  // namespace Rastertek50
