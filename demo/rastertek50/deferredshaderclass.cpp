////////////////////////////////////////////////////////////////////////////////
// Filename: deferredshaderclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/deferredshaderclass.h"

#include <cstdio>
#include <exception>
#include <fstream>

namespace Rastertek50 {

DeferredShaderClass::DeferredShaderClass()
{
	m_technique = 0;

	m_worldMatrixPtr = 0;
	m_viewMatrixPtr = 0;
	m_projectionMatrixPtr = 0;
	m_texturePtr = 0;
}


DeferredShaderClass::~DeferredShaderClass()
{
}


bool DeferredShaderClass::Initialize(fxport::GraphicsDevice* device, const std::string& hlslDir)
{
	bool result;


	// Initialize the shader that will be used.
	result = InitializeShader(device, hlslDir + "/rastertek/deferred.fx");
	if(!result)
	{
		return false;
	}

	return true;
}


void DeferredShaderClass::Shutdown()
{
	// Shutdown the shader effect.
	ShutdownShader();

	return;
}


void DeferredShaderClass::Render(fxport::GraphicsDevice* device, int indexCount, D3DXMATRIX worldMatrix, D3DXMATRIX viewMatrix, D3DXMATRIX projectionMatrix, 
				 fxport::Texture* texture)
{
	// Set the shader parameters that it will use for rendering.
	SetShaderParameters(worldMatrix, viewMatrix, projectionMatrix, texture);

	// Now render the prepared buffers with the shader.
	RenderShader(device, indexCount);

	return;
}


bool DeferredShaderClass::InitializeShader(fxport::GraphicsDevice* device, const std::string& filename)
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
	m_technique = m_effect->Techniques["DeferredTechnique"];
	if(!m_technique)
	{
		return false;
	}
	m_effect->CurrentTechnique = m_technique;

	// Now setup the layout of the data that goes into the shader: POSITION (R32G32B32_FLOAT),
	// TEXCOORD0 (R32G32_FLOAT), NORMAL (R32G32B32_FLOAT) - fxport: ModelClass::VertexDeclaration.

	// Get pointers to the three matrices inside the shader so we can update them from this class.
	m_worldMatrixPtr = &m_effect->Parameters["worldMatrix"];
	m_viewMatrixPtr = &m_effect->Parameters["viewMatrix"];
	m_projectionMatrixPtr = &m_effect->Parameters["projectionMatrix"];

	// Get pointer to the texture resource inside the shader.
	m_texturePtr = &m_effect->Parameters["shaderTexture"];

	return true;
}


void DeferredShaderClass::ShutdownShader()
{
	// Release the pointer to the texture in the shader file.
	m_texturePtr = 0;

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


void DeferredShaderClass::OutputShaderErrorMessage(const char* compileErrors, const std::string& shaderFilename)
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


void DeferredShaderClass::SetShaderParameters(D3DXMATRIX worldMatrix, D3DXMATRIX viewMatrix, D3DXMATRIX projectionMatrix, 
					      fxport::Texture* texture)
{
	// Set the world matrix variable inside the shader (fxport: D3DX and XNA matrices have the same
	// layout and convention, so SetMatrix((float*)&m) is SetValue(m), no transpose).
	m_worldMatrixPtr->SetValue(worldMatrix);

	// Set the view matrix variable inside the shader.
	m_viewMatrixPtr->SetValue(viewMatrix);

	// Set the projection matrix variable inside the shader.
	m_projectionMatrixPtr->SetValue(projectionMatrix);

	// Bind the texture.
	m_texturePtr->SetValue(texture);

	return;
}


void DeferredShaderClass::RenderShader(fxport::GraphicsDevice* device, int indexCount)
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
