////////////////////////////////////////////////////////////////////////////////
// Filename: applicationclass.h
////////////////////////////////////////////////////////////////////////////////
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fxport/graphics.h"


/////////////
// GLOBALS //
/////////////
namespace Rastertek50 {

const bool FULL_SCREEN = true;
const bool VSYNC_ENABLED = true;
const float SCREEN_DEPTH = 1000.0f;
const float SCREEN_NEAR = 0.1f;

}  // namespace Rastertek50


///////////////////////
// MY CLASS INCLUDES //
///////////////////////
#include "rastertek50/inputclass.h"
#include "rastertek50/d3dclass.h"
#include "rastertek50/cameraclass.h"
#include "rastertek50/lightclass.h"
#include "rastertek50/modelclass.h"
#include "rastertek50/orthowindowclass.h"
#include "rastertek50/deferredbuffersclass.h"
#include "rastertek50/deferredshaderclass.h"
#include "rastertek50/lightshaderclass.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: ApplicationClass
////////////////////////////////////////////////////////////////////////////////
class ApplicationClass
{
public:
	ApplicationClass();
	ApplicationClass(const ApplicationClass&) = delete;
	~ApplicationClass();

	// fxport: `platform` (osmesa, egl, glfw) and the effects' folder replace HINSTANCE and HWND.
	bool Initialize(const std::string& platform, const std::string& hlslDir, int, int);
	void Shutdown();
	bool Frame();

	// fxport additions: the passes are timed when a GpuTimer is attached; access for fxdemo.
	void SetGpuTimer(fxport::GpuTimer* timer) { m_gpuTimer = timer; }
	// fxport addition (a knob of `fxdemo report`): the G-buffer targets' format, set before
	// Initialize. The seed's is R32G32B32A32_FLOAT; R16G16B16A16_FLOAT and R8G8B8A8_UNORM (which
	// clamps the signed normals the seed writes) are the cheaper ones.
	void SetGBufferFormat(DXGI_FORMAT format) { m_gbufferFormat = format; }
	// fxport addition (fxdemo --define NAME=VALUE): macros both effects are compiled with, set
	// before Initialize.
	void SetDefines(const std::vector<std::pair<std::string, std::string>>& defines);
	D3DClass* GetD3D() { return m_D3D.get(); }
	DeferredShaderClass* GetDeferredShader() { return m_DeferredShader.get(); }
	LightShaderClass* GetLightShader() { return m_LightShader.get(); }
	DeferredBuffersClass* GetDeferredBuffers() { return m_DeferredBuffers.get(); }
	ModelClass* GetModel() { return m_Model.get(); }
	// The cube's rotation (radians) of the last frame rendered.
	float GetRotation() const { return m_rotation; }
	// fxport addition (`fxdemo report`): every frame draws the cube at this rotation instead of
	// turning it, so that settings timed over different numbers of frames show the same image.
	void SetFixedRotation(float radians) { m_fixedRotation = radians; }

private:
	bool Render();
	void RenderSceneToTexture();

private:
	std::unique_ptr<InputClass> m_Input;
	std::unique_ptr<D3DClass> m_D3D;
	std::unique_ptr<CameraClass> m_Camera;

	// We have a regular directional light object.
	std::unique_ptr<LightClass> m_Light;

	// We have the cube model that we will be rendering.
	std::unique_ptr<ModelClass> m_Model;

	// This is the 2D window that will be used to do the post processing on with the new deferred light shader.
	std::unique_ptr<OrthoWindowClass> m_FullScreenWindow;

	// This is the deferred buffers object that will contain the two render to textures containing
	// the deferred rendering information for the colors and the normals.
	std::unique_ptr<DeferredBuffersClass> m_DeferredBuffers;

	// And we have our deferred shader and the re-written directional light shader.
	std::unique_ptr<DeferredShaderClass> m_DeferredShader;
	std::unique_ptr<LightShaderClass> m_LightShader;

	// fxport: the seed's `static float rotation` in RenderSceneToTexture, as a member so that it
	// starts from 0 for each ApplicationClass (the rotation is a function of the frame number).
	float m_rotation;
	std::optional<float> m_fixedRotation;  // fxport
	fxport::GpuTimer* m_gpuTimer;
	DXGI_FORMAT m_gbufferFormat = DXGI_FORMAT_R32G32B32A32_FLOAT;
	std::vector<std::pair<std::string, std::string>> m_defineText;  // fxport: SetDefines
	std::vector<D3D10_SHADER_MACRO> m_defines;                      // over m_defineText, NULL-terminated
};

}  // namespace Rastertek50
