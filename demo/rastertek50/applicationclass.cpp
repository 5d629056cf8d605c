////////////////////////////////////////////////////////////////////////////////
// Filename: applicationclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/applicationclass.h"

#include <cstdio>

#include "common/pass_timer.h"

namespace Rastertek50 {

using fxport::demo::PassTimer;

namespace {
// fxport: MessageBox(hwnd, text, L"Error", MB_OK) -> stderr.
void MessageBox(const char* text) { std::fprintf(stderr, "fxdemo rastertek50: %s\n", text); }
}  // namespace


ApplicationClass::ApplicationClass()
{
	m_rotation = 0.0f;
	m_gpuTimer = 0;
}


ApplicationClass::~ApplicationClass()
{
}


void ApplicationClass::SetDefines(const std::vector<std::pair<std::string, std::string>>& defines)
{
	m_defineText = defines;
	m_defines.clear();
	for(const auto& define : m_defineText)
	{
		D3D10_SHADER_MACRO macro;
		macro.Name = define.first.c_str();
		macro.Definition = define.second.c_str();
		m_defines.push_back(macro);
	}
	if(!m_defines.empty()) m_defines.push_back(D3D10_SHADER_MACRO());  // the terminator
}


bool ApplicationClass::Initialize(const std::string& platform, const std::string& hlslDir, int screenWidth, int screenHeight)
{
	bool result;

	
	// Create the input object.  This object will be used to handle reading the keyboard input from the user.
	m_Input = std::make_unique<InputClass>();

	// Initialize the input object.
	result = m_Input->Initialize(screenWidth, screenHeight);
	if(!result)
	{
		MessageBox("Could not initialize the input object.");
		return false;
	}

	// Create the Direct3D object.
	m_D3D = std::make_unique<D3DClass>();

	// Initialize the Direct3D object.
	result = m_D3D->Initialize(screenWidth, screenHeight, VSYNC_ENABLED, platform, FULL_SCREEN, SCREEN_DEPTH, SCREEN_NEAR);
	if(!result)
	{
		MessageBox("Could not initialize Direct3D.");
		return false;
	}

	// Create the camera object.
	m_Camera = std::make_unique<CameraClass>();

	// Set the initial position of the camera and build the matrices needed for rendering.
	m_Camera->SetPosition(0.0f, 0.0f, -10.0f);
	m_Camera->Render();
	m_Camera->RenderBaseViewMatrix();

	// Create the light object.
	m_Light = std::make_unique<LightClass>();

	// Initialize the light object.
	m_Light->SetDiffuseColor(1.0f, 1.0f, 1.0f, 1.0f);
	m_Light->SetDirection(0.0f, 0.0f, 1.0f);

	// Create the model object.
	m_Model = std::make_unique<ModelClass>();

	// Initialize the model object (fxport: cube.txt and seafloor.dds are generated, 256x256 texture).
	result = m_Model->Initialize(m_D3D->GetDevice(), 256);
	if(!result)
	{
		MessageBox("Could not initialize the model object.");
		return false;
	}

	// Create the full screen ortho window object.
	m_FullScreenWindow = std::make_unique<OrthoWindowClass>();

	// Initialize the full screen ortho window object.
	result = m_FullScreenWindow->Initialize(m_D3D->GetDevice(), screenWidth, screenHeight);
	if(!result)
	{
		MessageBox("Could not initialize the full screen ortho window object.");
		return false;
	}

	// Create the deferred buffers object.
	m_DeferredBuffers = std::make_unique<DeferredBuffersClass>();

	// Initialize the deferred buffers object.
	result = m_DeferredBuffers->Initialize(m_D3D->GetDevice(), screenWidth, screenHeight, SCREEN_DEPTH, SCREEN_NEAR, m_gbufferFormat);
	if(!result)
	{
		MessageBox("Could not initialize the deferred buffers object.");
		return false;
	}

	// Create the deferred shader object.
	m_DeferredShader = std::make_unique<DeferredShaderClass>();
	m_DeferredShader->SetDefines(m_defines.empty() ? NULL : m_defines.data());  // fxport

	// Initialize the deferred shader object.
	result = m_DeferredShader->Initialize(m_D3D->GetDevice(), hlslDir);
	if(!result)
	{
		MessageBox("Could not initialize the deferred shader object.");
		return false;
	}

	// Create the light shader object.
	m_LightShader = std::make_unique<LightShaderClass>();
	m_LightShader->SetDefines(m_defines.empty() ? NULL : m_defines.data());  // fxport

	// Initialize the light shader object.
	result = m_LightShader->Initialize(m_D3D->GetDevice(), hlslDir);
	if(!result)
	{
		MessageBox("Could not initialize the light shader object.");
		return false;
	}

	return true;
}


void ApplicationClass::Shutdown()
{
	// Release the light shader object.
	if(m_LightShader)
	{
		m_LightShader->Shutdown();
		m_LightShader.reset();
	}

	// Release the deferred shader object.
	if(m_DeferredShader)
	{
		m_DeferredShader->Shutdown();
		m_DeferredShader.reset();
	}

	// Release the deferred buffers object.
	if(m_DeferredBuffers)
	{
		m_DeferredBuffers->Shutdown();
		m_DeferredBuffers.reset();
	}

	// Release the full screen ortho window object.
	if(m_FullScreenWindow)
	{
		m_FullScreenWindow->Shutdown();
		m_FullScreenWindow.reset();
	}

	// Release the model object.
	if(m_Model)
	{
		m_Model->Shutdown();
		m_Model.reset();
	}

	// Release the light object.
	m_Light.reset();

	// Release the camera object.
	m_Camera.reset();

	// Release the D3D object.
	if(m_D3D)
	{
		m_D3D->Shutdown();
		m_D3D.reset();
	}

	// Release the input object.
	if(m_Input)
	{
		m_Input->Shutdown();
		m_Input.reset();
	}

	return;
}


bool ApplicationClass::Frame()
{
	bool result;


	// Do the input frame processing.
	result = m_Input->Frame();
	if(!result)
	{
		return false;
	}
	
	// Check if the user pressed escape and wants to exit the application.
	if(m_Input->IsEscapePressed() == true)
	{
		return false;
	}

	// Render the graphics.
	result = Render();
	if(!result)
	{
		return false;
	}

	return true;
}


bool ApplicationClass::Render()
{
	D3DXMATRIX worldMatrix, baseViewMatrix, orthoMatrix;

	// First thing we need to do is render the scene using the deferred shader. This is done in the
	// RenderSceneToTexture function.

	// Render the scene to the render buffers.
	{
		PassTimer timed(m_gpuTimer, "Deferred");
		RenderSceneToTexture();
	}

	PassTimer timed(m_gpuTimer, "Light");

	// Clear the scene.
	m_D3D->BeginScene(0.0f, 0.0f, 0.0f, 1.0f);

	// Setup the scene for 2D rendering.

	// Get the matrices.
	m_D3D->GetWorldMatrix(worldMatrix);
	m_Camera->GetBaseViewMatrix(baseViewMatrix);
	m_D3D->GetOrthoMatrix(orthoMatrix);

	// Turn off the Z buffer to begin all 2D rendering.
	m_D3D->TurnZBufferOff();

	// Put the full screen ortho window vertex and index buffers on the graphics pipeline to prepare them for drawing.
	m_FullScreenWindow->Render(m_D3D->GetDevice());

	// Now that the scene was rendered with the deferred shader we can use the render to texture
	// buffers to render the directional light. We use the re-written light shader as a 2D post
	// processing operation.

	// Render the full screen ortho window using the deferred light shader and the render buffers.
	m_LightShader->Render(m_D3D->GetDevice(), m_FullScreenWindow->GetIndexCount(), worldMatrix, baseViewMatrix, orthoMatrix, 
			      m_DeferredBuffers->GetShaderResourceView(0), m_DeferredBuffers->GetShaderResourceView(1), 
			      m_Light->GetDirection());

	// Turn the Z buffer back on now that all 2D rendering has completed.
	m_D3D->TurnZBufferOn();
	
	// Present the rendered scene to the screen.
	m_D3D->EndScene();

	return true;
}


void ApplicationClass::RenderSceneToTexture()
{
	D3DXMATRIX worldMatrix, viewMatrix, projectionMatrix;

	// Set the deferred render to texture buffers as the render target and then clear them before rendering.

	// Set the render buffers to be the render target.
	m_DeferredBuffers->SetRenderTargets(m_D3D->GetDevice());

	// Clear the render buffers.
	m_DeferredBuffers->ClearRenderTargets(m_D3D->GetDevice(), 0.0f, 0.0f, 0.0f, 1.0f);

	// Render the scene of the spinning cube using the deferred shader.

	// Get the matrices from the camera and d3d objects.
	m_D3D->GetWorldMatrix(worldMatrix);
	m_Camera->GetViewMatrix(viewMatrix);
	m_D3D->GetProjectionMatrix(projectionMatrix);

	// Update the rotation variable each frame.
	m_rotation += (float)D3DX_PI * 0.01f;
	if(m_rotation > 360.0f)
	{
		m_rotation -= 360.0f;
	}
	if(m_fixedRotation) m_rotation = *m_fixedRotation;  // fxport: SetFixedRotation

	// Rotate the world matrix by the rotation value so that the cube will spin.
	worldMatrix = D3DXMatrixRotationY(m_rotation);

	// Put the model vertex and index buffers on the graphics pipeline to prepare them for drawing.
	m_Model->Render(m_D3D->GetDevice());

	// Render the model using the deferred shader.
	m_DeferredShader->Render(m_D3D->GetDevice(), m_Model->GetIndexCount(), worldMatrix, viewMatrix, projectionMatrix, m_Model->GetTexture());

	// Set the render target back to the back buffer.

	// Reset the render target back to the original back buffer and not the render buffers anymore.
	m_D3D->SetBackBufferRenderTarget();

	// Reset the viewport back to the original.
	m_D3D->ResetViewport();

	return;
}

}  // namespace Rastertek50
