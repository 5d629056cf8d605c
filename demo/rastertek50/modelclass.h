////////////////////////////////////////////////////////////////////////////////
// Filename: modelclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses ModelClass but does not list it): the Rastertek DX10 ModelClass with
// position, texture and normal vertices. fxport: the model is generated content: LoadModel builds
// the cube of cube.txt (same faces, texture coordinates, normals and clockwise winding) as 24
// vertices and 36 indices instead of reading the file; the texture is TextureClass's generated one. The
// vertex and index buffers are ID3D10Buffers, the indices 32-bit (the tutorial's `unsigned long`).
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <vector>

#include "fxport/d3d10.h"
#include "rastertek50/d3dx_math.h"


///////////////////////
// MY CLASS INCLUDES //
///////////////////////
#include "rastertek50/textureclass.h"

namespace Rastertek50 {

using namespace fxport::d3d10;

////////////////////////////////////////////////////////////////////////////////
// Class name: ModelClass
////////////////////////////////////////////////////////////////////////////////
class ModelClass
{
public:
	struct VertexType
	{
		D3DXVECTOR3 position;
		D3DXVECTOR2 texture;
		D3DXVECTOR3 normal;
	};

	struct ModelType
	{
		float x, y, z;
		float tu, tv;
		float nx, ny, nz;
	};

public:
	ModelClass();
	ModelClass(const ModelClass&) = delete;
	~ModelClass();

	bool Initialize(ID3D10Device*, int textureSize);
	void Shutdown();
	void Render(ID3D10Device*);

	int GetIndexCount();
	int GetVertexCount();
	ID3D10ShaderResourceView* GetTexture();
	// fxport addition (--check): the generated texture's size.
	int GetTextureSize() const { return m_textureSize; }

	// The generated mesh (for tests).
	const std::vector<ModelType>& GetModel() const { return m_model; }
	const std::vector<unsigned short>& GetIndices() const { return m_indices; }


private:
	bool InitializeBuffers(ID3D10Device*);
	void ShutdownBuffers();
	void RenderBuffers(ID3D10Device*);

	bool LoadTexture(ID3D10Device*, int);
	void ReleaseTexture();

	bool LoadModel();
	void ReleaseModel();

private:
	ID3D10Buffer *m_vertexBuffer, *m_indexBuffer;
	int m_vertexCount, m_indexCount;
	int m_textureSize;  // fxport
	std::unique_ptr<TextureClass> m_Texture;
	std::vector<ModelType> m_model;
	std::vector<unsigned short> m_indices;
};

}  // namespace Rastertek50
