////////////////////////////////////////////////////////////////////////////////
// Filename: lightshaderclass.h
////////////////////////////////////////////////////////////////////////////////
#pragma once

// The LightShaderClass is the directional light shader re-written for deferred shading: it lights
// the full screen window from the colour and normal render textures of the deferred buffers.


//////////////
// INCLUDES //
//////////////
#include <string>

#include "fxport/d3d10.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

////////////////////////////////////////////////////////////////////////////////
// Class name: LightShaderClass
////////////////////////////////////////////////////////////////////////////////
class LightShaderClass
{
public:
	LightShaderClass();
	LightShaderClass(const LightShaderClass&) = delete;
	~LightShaderClass();

	// fxport: `hlslDir` replaces the HWND (the effect is hlslDir/rastertek/light.fx).
	bool Initialize(ID3D10Device*, const std::string& hlslDir);
	void Shutdown();
	void Render(ID3D10Device*, int, D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, ID3D10ShaderResourceView*, 
		    ID3D10ShaderResourceView*, D3DXVECTOR3);

	// fxport addition (fxdemo --define): the macros the effect is compiled with (the seed passes
	// NULL), a NULL-terminated array that outlives Initialize; set before Initialize.
	void SetDefines(const D3D10_SHADER_MACRO* defines) { m_defines = defines; }
	// fxport addition (fxdemo --explain): the effect.
	ID3D10Effect* GetEffect() { return m_effect; }

private:
	bool InitializeShader(ID3D10Device*, const std::string&);
	void ShutdownShader();
	void OutputShaderErrorMessage(ID3D10Blob*, const std::string&);

	void SetShaderParameters(D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, ID3D10ShaderResourceView*, 
				 ID3D10ShaderResourceView*, D3DXVECTOR3);
	void RenderShader(ID3D10Device*, int);

private:
	ID3D10Effect* m_effect;
	const D3D10_SHADER_MACRO* m_defines;  // fxport
	ID3D10EffectTechnique* m_technique;
	ID3D10InputLayout* m_layout;

	ID3D10EffectMatrixVariable* m_worldMatrixPtr;
	ID3D10EffectMatrixVariable* m_viewMatrixPtr;
	ID3D10EffectMatrixVariable* m_projectionMatrixPtr;

	// Most importantly the shader now takes in two render to textures that contain the color and
	// normal data.
	ID3D10EffectShaderResourceVariable* m_colorTexturePtr;
	ID3D10EffectShaderResourceVariable* m_normalTexturePtr;

	ID3D10EffectVectorVariable* m_lightDirectionPtr;
};

}  // namespace Rastertek50
