////////////////////////////////////////////////////////////////////////////////
// Filename: lightshaderclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/lightshaderclass.h"

#include <cstdio>
#include <exception>
#include <fstream>

namespace Rastertek50 {

LightShaderClass::LightShaderClass()
{
	m_technique = 0;

	m_worldMatrixPtr = 0;
	m_viewMatrixPtr = 0;
	m_projectionMatrixPtr = 0;

	m_colorTexturePtr = 0;
	m_normalTexturePtr = 0;

	m_lightDirectionPtr = 0;
}


LightShaderClass::~LightShaderClass()
{
}


bool LightShaderClass::Initialize(fxport::GraphicsDevice* device, const std::string& hlslDir)
{
	bool result;


	// Initialize the shader that will be used to render.
	result = InitializeShader(device, hlslDir + "/rastertek/light.fx");
	if(!result)
	{
		return false;
	}

	return true;
}


void LightShaderClass::Shutdown()
{
	// Shutdown the shader effect.
	ShutdownShader();

	return;
}


void LightShaderClass::Render(fxport::GraphicsDevice* device, int indexCount, D3DXMATRIX worldMatrix, D3DXMATRIX viewMatrix, D3DXMATRIX projectionMatrix, 
			      fxport::Texture* colorTexture, fxport::Texture* normalTexture, D3DXVECTOR3 lightDirection)
{
	// Set the shader parameters that it will use for rendering.
	SetShaderParameters(worldMatrix, viewMatrix, projectionMatrix, colorTexture, normalTexture, lightDirection);

	// Now render the prepared buffers with the shader.
	RenderShader(device, indexCount);

	return;
}


bool LightShaderClass::InitializeShader(fxport::GraphicsDevice* device, const std::string& filename)
{
	// Load the shader in from the file (fxport: compiled by xlate, cached).
	try
	{
		m_effect = std::make_unique<fxport::Effect>(*device, filename, m_effectOptions);
	}
	catch(const std::exception& error)
	{
		// If the shader failed to compile it should have writen something to the error message.
		OutputShaderErrorMessage(error.what(), filename);
		return false;
	}

	// Get a pointer to the technique inside the shader.
	m_technique = m_effect->Techniques["LightTechnique"];
	if(!m_technique)
	{
		return false;
	}
	m_effect->CurrentTechnique = m_technique;

	// The polygon layout now only requires position and texture coordinates since we are doing 2D
	// post processing (fxport: OrthoWindowClass::VertexDeclaration).

	// Get pointers to the three matrices inside the shader so we can update them from this class.
	m_worldMatrixPtr = &m_effect->Parameters["worldMatrix"];
	m_viewMatrixPtr = &m_effect->Parameters["viewMatrix"];
	m_projectionMatrixPtr = &m_effect->Parameters["projectionMatrix"];

	// The two new texture pointers are setup here.

	// Get pointers to the texture resources inside the shader.
	m_colorTexturePtr = &m_effect->Parameters["colorTexture"];
	m_normalTexturePtr = &m_effect->Parameters["normalTexture"];

	// Get pointers to the light direction and diffuse color variables inside the shader.
	m_lightDirectionPtr = &m_effect->Parameters["lightDirection"];

	return true;
}


void LightShaderClass::ShutdownShader()
{
	// Release the light pointers.
	m_lightDirectionPtr = 0;

	// Release the pointers to the textures in the shader file.
	m_colorTexturePtr = 0;
	m_normalTexturePtr = 0;

	// Release the pointers to the matrices inside the shader.
	m_worldMatrixPtr = 0;
	m_viewMatrixPtr = 0;
	m_projectionMatrixPtr = 0;

	// Release the pointer to the shader technique.
	m_technique = 0;

	// Release the pointer to the shader.
	m_effect.reset();

	return;
}


void LightShaderClass::OutputShaderErrorMessage(const char* compileErrors, const std::string& shaderFilename)
{
	std::ofstream fout;


	// Open a file to write the error message to.
	fout.open("shader-error.txt");

	// Write out the error message.
	fout << compileErrors;

	// Close the file.
	fout.close();

	// Notify the user (fxport: on stderr instead of a message box).
	std::fprintf(stderr, "%s: error compiling shader:\n%s\n", shaderFilename.c_str(), compileErrors);

	return;
}


void LightShaderClass::SetShaderParameters(D3DXMATRIX worldMatrix, D3DXMATRIX viewMatrix, D3DXMATRIX projectionMatrix, 
					   fxport::Texture* colorTexture, fxport::Texture* normalTexture, 
					   D3DXVECTOR3 lightDirection)
{
	// Set the world matrix variable inside the shader.
	m_worldMatrixPtr->SetValue(worldMatrix);

	// Set the view matrix variable inside the shader.
	m_viewMatrixPtr->SetValue(viewMatrix);

	// Set the projection matrix variable inside the shader.
	m_projectionMatrixPtr->SetValue(projectionMatrix);

	// The two deferred textures are set in the shader here.

	// Bind the textures.
	m_colorTexturePtr->SetValue(colorTexture);
	m_normalTexturePtr->SetValue(normalTexture);

	// Set the direction of the light inside the shader.
	m_lightDirectionPtr->SetValue(lightDirection);

	return;
}


void LightShaderClass::RenderShader(fxport::GraphicsDevice* device, int indexCount)
{
	int i;
	

	// Set the input layout (fxport: the vertex buffer's declaration).

	// Go through each pass in the technique (should be just one currently) and render the triangles.
	for(i=0; i<m_technique->Passes.Count(); ++i)
	{
		m_technique->Passes[i].Apply();
		device->DrawIndexedPrimitives(fxport::PrimitiveType::TriangleList, 0, 0, indexCount, 0, indexCount / 3);
	}

	return;
}

}  // namespace Rastertek50
