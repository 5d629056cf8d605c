////////////////////////////////////////////////////////////////////////////////
// Filename: d3dclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/d3dclass.h"

namespace Rastertek50 {

D3DClass::D3DClass()
{
	m_vsync_enabled = false;
}


D3DClass::~D3DClass()
{
}


bool D3DClass::Initialize(int screenWidth, int screenHeight, bool vsync, const std::string& platform, bool fullscreen,
			  float screenDepth, float screenNear)
{
	float fieldOfView, screenAspect;
	(void)fullscreen;  // fxport: windowed only


	// Store the vsync setting.
	m_vsync_enabled = vsync;

	// Create the swap chain, Direct3D device, and back buffer (fxport: the GraphicsDevice).
	fxport::PresentationParameters parameters;
	parameters.BackBufferWidth = screenWidth;
	parameters.BackBufferHeight = screenHeight;
	parameters.DepthStencilFormat = fxport::DepthFormat::Depth24Stencil8;
	parameters.platform = platform;
	parameters.windowTitle = "Rastertek DX10 Tutorial 50: Deferred Shading (fxport)";
	m_device = std::make_unique<fxport::GraphicsDevice>(parameters);

	// Set up the description of the stencil state (depth test on, LESS, writes on).
	m_depthStencilState.DepthBufferEnable = true;
	m_depthStencilState.DepthBufferWriteEnable = true;
	m_depthStencilState.DepthBufferFunction = fxport::CompareFunction::Less;

	// Set the depth stencil state.
	m_device->DepthStencilState = m_depthStencilState;

	// Setup the raster description which will determine how and what polygons will be drawn
	// (solid, back faces culled, clockwise front faces: XNA's CullCounterClockwise).
	m_rasterState = fxport::RasterizerState::CullCounterClockwise;

	// Now set the rasterizer state.
	m_device->RasterizerState = m_rasterState;

	// Setup the viewport for rendering.
	m_viewport = fxport::Viewport(0, 0, screenWidth, screenHeight);
	m_viewport.MinDepth = 0.0f;
	m_viewport.MaxDepth = 1.0f;

	// Create the viewport.
	m_device->Viewport = m_viewport;

	// Setup the projection matrix.
	fieldOfView = (float)D3DX_PI / 4.0f;
	screenAspect = (float)screenWidth / (float)screenHeight;

	// Create the projection matrix for 3D rendering.
	m_projectionMatrix = D3DXMatrixPerspectiveFovLH(fieldOfView, screenAspect, screenNear, screenDepth);

	// Initialize the world matrix to the identity matrix.
	m_worldMatrix = D3DXMATRIX::Identity;

	// Create an orthographic projection matrix for 2D rendering.
	m_orthoMatrix = D3DXMatrixOrthoLH((float)screenWidth, (float)screenHeight, screenNear, screenDepth);

	// Now create a second depth stencil state which turns off the Z buffer for 2D rendering.
	m_depthDisabledStencilState = m_depthStencilState;
	m_depthDisabledStencilState.DepthBufferEnable = false;

	return true;
}


void D3DClass::Shutdown()
{
	m_device.reset();
	return;
}


void D3DClass::BeginScene(float red, float green, float blue, float alpha)
{
	// Clear the back buffer and the depth buffer.
	m_device->Clear(fxport::ClearOptions::Target | fxport::ClearOptions::DepthBuffer | fxport::ClearOptions::Stencil,
			fxport::Vector4(red, green, blue, alpha), 1.0f, 0);
	return;
}


void D3DClass::EndScene()
{
	// Present the back buffer to the screen since rendering is complete.
	m_device->Present();
	return;
}


fxport::GraphicsDevice* D3DClass::GetDevice()
{
	return m_device.get();
}


void D3DClass::GetProjectionMatrix(D3DXMATRIX& projectionMatrix)
{
	projectionMatrix = m_projectionMatrix;
	return;
}


void D3DClass::GetWorldMatrix(D3DXMATRIX& worldMatrix)
{
	worldMatrix = m_worldMatrix;
	return;
}


void D3DClass::GetOrthoMatrix(D3DXMATRIX& orthoMatrix)
{
	orthoMatrix = m_orthoMatrix;
	return;
}


void D3DClass::TurnZBufferOn()
{
	m_device->DepthStencilState = m_depthStencilState;
	return;
}


void D3DClass::TurnZBufferOff()
{
	m_device->DepthStencilState = m_depthDisabledStencilState;
	return;
}


void D3DClass::SetBackBufferRenderTarget()
{
	// Bind the render target view and depth stencil buffer to the output render pipeline.
	m_device->SetRenderTarget(nullptr);
	return;
}


void D3DClass::ResetViewport()
{
	// Set the viewport.
	m_device->Viewport = m_viewport;
	return;
}

}  // namespace Rastertek50
