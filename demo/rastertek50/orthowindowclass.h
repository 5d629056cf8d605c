////////////////////////////////////////////////////////////////////////////////
// Filename: orthowindowclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses OrthoWindowClass but does not list it): the Rastertek full screen
// ortho window, two triangles of position + texture vertices centred on the origin.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>

#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: OrthoWindowClass
////////////////////////////////////////////////////////////////////////////////
class OrthoWindowClass
{
public:
	struct VertexType
	{
		D3DXVECTOR3 position;
		D3DXVECTOR2 texture;
	};

public:
	OrthoWindowClass();
	OrthoWindowClass(const OrthoWindowClass&) = delete;
	~OrthoWindowClass();

	bool Initialize(fxport::GraphicsDevice*, int, int);
	void Shutdown();
	void Render(fxport::GraphicsDevice*);

	int GetIndexCount();
	int GetVertexCount();

	// The input layout of the light shader (POSITION, TEXCOORD0).
	static const fxport::VertexDeclaration VertexDeclaration;

private:
	bool InitializeBuffers(fxport::GraphicsDevice*, int, int);
	void ShutdownBuffers();
	void RenderBuffers(fxport::GraphicsDevice*);

private:
	std::unique_ptr<fxport::VertexBuffer> m_vertexBuffer;
	std::unique_ptr<fxport::IndexBuffer> m_indexBuffer;
	int m_vertexCount, m_indexCount;
};

}  // namespace Rastertek50
