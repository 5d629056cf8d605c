////////////////////////////////////////////////////////////////////////////////
// Filename: lightshaderclass.h
////////////////////////////////////////////////////////////////////////////////
#pragma once

// The LightShaderClass has been re-written to handle deferred shading.


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <string>

#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: LightShaderClass
////////////////////////////////////////////////////////////////////////////////
class LightShaderClass
{
public:
	LightShaderClass();
	LightShaderClass(const LightShaderClass&) = delete;
	~LightShaderClass();

	// fxport: `hlslDir` is the folder holding rastertek/light.fx (the seed's "../Engine/").
	bool Initialize(fxport::GraphicsDevice*, const std::string& hlslDir);
	// fxport additions (issue 6, fxdemo --explain): the options the effect is compiled with (set
	// before Initialize; e.g. useCache = false so that compile times compare) and the effect itself.
	void SetEffectOptions(const fxport::EffectOptions& options) { m_effectOptions = options; }
	fxport::Effect* GetEffect() { return m_effect.get(); }
	void Shutdown();
	void Render(fxport::GraphicsDevice*, int, D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, fxport::Texture*, 
		    fxport::Texture*, D3DXVECTOR3);

private:
	bool InitializeShader(fxport::GraphicsDevice*, const std::string&);
	void ShutdownShader();
	void OutputShaderErrorMessage(const char*, const std::string&);

	void SetShaderParameters(D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, fxport::Texture*, 
				 fxport::Texture*, D3DXVECTOR3);
	void RenderShader(fxport::GraphicsDevice*, int);

private:
	std::unique_ptr<fxport::Effect> m_effect;
	fxport::EffectOptions m_effectOptions;
	fxport::EffectTechnique* m_technique;
	// fxport: the input layout is the vertex buffer's VertexDeclaration (OrthoWindowClass::VertexDeclaration).

	fxport::EffectParameter* m_worldMatrixPtr;
	fxport::EffectParameter* m_viewMatrixPtr;
	fxport::EffectParameter* m_projectionMatrixPtr;

	// Most importantly the shader now takes in two render to textures that contain the color and normal data.
	fxport::EffectParameter* m_colorTexturePtr;
	fxport::EffectParameter* m_normalTexturePtr;

	fxport::EffectParameter* m_lightDirectionPtr;
};

}  // namespace Rastertek50
