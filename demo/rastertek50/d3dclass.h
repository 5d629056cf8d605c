////////////////////////////////////////////////////////////////////////////////
// Filename: d3dclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses D3DClass but does not list it): the Rastertek DX10 D3DClass, reduced
// to what tutorial 50 calls, on fxport's D3D10 front end (fxport/d3d10.h). fxport: the swap chain is
// headless (its back buffer is a texture, nothing is shown), so a platform name (osmesa, egl)
// replaces the HWND and the full screen flag, and the adapter and display-mode enumeration (refresh
// rate, video card name) is left out -- the port's only deviation from the tutorial's calls.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <string>
#include <vector>

#include "fxport/d3d10.h"
#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

////////////////////////////////////////////////////////////////////////////////
// Class name: D3DClass
////////////////////////////////////////////////////////////////////////////////
class D3DClass
{
public:
	D3DClass();
	D3DClass(const D3DClass&) = delete;
	~D3DClass();

	// fxport: `platform` (osmesa, egl) replaces the HWND and the full screen flag.
	bool Initialize(int, int, bool, const std::string& platform, bool, float, float);
	void Shutdown();

	void BeginScene(float, float, float, float);
	void EndScene();

	ID3D10Device* GetDevice();

	void GetProjectionMatrix(D3DXMATRIX&);
	void GetWorldMatrix(D3DXMATRIX&);
	void GetOrthoMatrix(D3DXMATRIX&);

	void TurnZBufferOn();
	void TurnZBufferOff();

	void SetBackBufferRenderTarget();
	void ResetViewport();

	// fxport additions for fxdemo: the device core under the D3D10 device (GpuTimer, --explain,
	// the images' PNG encoder) and the back buffer read back (8-bit RGBA, top row first).
	fxport::GraphicsDevice& GetCoreDevice();
	std::vector<fxport::Color> GetBackBufferData();

private:
	bool m_vsync_enabled;
	IDXGISwapChain* m_swapChain;
	ID3D10Device* m_device;
	ID3D10RenderTargetView* m_renderTargetView;
	ID3D10Texture2D* m_depthStencilBuffer;
	ID3D10DepthStencilState* m_depthStencilState;
	ID3D10DepthStencilView* m_depthStencilView;
	ID3D10RasterizerState* m_rasterState;
	D3D10_VIEWPORT m_viewport;
	D3DXMATRIX m_projectionMatrix;
	D3DXMATRIX m_worldMatrix;
	D3DXMATRIX m_orthoMatrix;
	ID3D10DepthStencilState* m_depthDisabledStencilState;
};

}  // namespace Rastertek50
