////////////////////////////////////////////////////////////////////////////////
// Filename: orthowindowclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses OrthoWindowClass but does not list it): the Rastertek full screen
// ortho window, two triangles of position + texture vertices centred on the origin.
#pragma once


//////////////
// INCLUDES //
//////////////
#include "fxport/d3d10.h"
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

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

	bool Initialize(ID3D10Device*, int, int);
	void Shutdown();
	void Render(ID3D10Device*);

	int GetIndexCount();
	int GetVertexCount();


private:
	bool InitializeBuffers(ID3D10Device*, int, int);
	void ShutdownBuffers();
	void RenderBuffers(ID3D10Device*);

private:
	ID3D10Buffer *m_vertexBuffer, *m_indexBuffer;
	int m_vertexCount, m_indexCount;
};

}  // namespace Rastertek50
