////////////////////////////////////////////////////////////////////////////////
// Filename: deferredshaderclass.h
////////////////////////////////////////////////////////////////////////////////
#pragma once

// This is the class that encapsulates the functionality of the deferred shader. It doesn't vary
// much from the regular shaders.


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <string>

#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: DeferredShaderClass
////////////////////////////////////////////////////////////////////////////////
class DeferredShaderClass
{
public:
	DeferredShaderClass();
	DeferredShaderClass(const DeferredShaderClass&) = delete;
	~DeferredShaderClass();

	// fxport: `hlslDir` is the folder holding rastertek/deferred.fx (the seed's "../Engine/").
	bool Initialize(fxport::GraphicsDevice*, const std::string& hlslDir);
	// fxport additions (issue 6, fxdemo --explain): the options the effect is compiled with (set
	// before Initialize; e.g. useCache = false so that compile times compare) and the effect itself.
	void SetEffectOptions(const fxport::EffectOptions& options) { m_effectOptions = options; }
	fxport::Effect* GetEffect() { return m_effect.get(); }
	void Shutdown();
	void Render(fxport::GraphicsDevice*, int, D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, fxport::Texture*);

private:
	bool InitializeShader(fxport::GraphicsDevice*, const std::string&);
	void ShutdownShader();
	void OutputShaderErrorMessage(const char*, const std::string&);

	void SetShaderParameters(D3DXMATRIX, D3DXMATRIX, D3DXMATRIX, fxport::Texture*);
	void RenderShader(fxport::GraphicsDevice*, int);

private:
	std::unique_ptr<fxport::Effect> m_effect;
	fxport::EffectOptions m_effectOptions;
	fxport::EffectTechnique* m_technique;
	// fxport: the input layout is the vertex buffer's VertexDeclaration (ModelClass::VertexDeclaration),
	// matched to the vertex shader's semantics at each draw.

	fxport::EffectParameter* m_worldMatrixPtr;
	fxport::EffectParameter* m_viewMatrixPtr;
	fxport::EffectParameter* m_projectionMatrixPtr;
	fxport::EffectParameter* m_texturePtr;
};

}  // namespace Rastertek50
