////////////////////////////////////////////////////////////////////////////////
// Filename: modelclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses ModelClass but does not list it): the Rastertek DX10 ModelClass with
// position, texture and normal vertices. fxport: the model is generated content: LoadModel builds
// the cube of cube.txt (same faces, texture coordinates, normals and clockwise winding) as 24
// vertices and 36 indices instead of reading the file; the texture is TextureClass's generated one.
#pragma once


//////////////
// INCLUDES //
//////////////
#include <memory>
#include <vector>

#include "fxport/graphics.h"
#include "rastertek50/d3dx_math.h"


///////////////////////
// MY CLASS INCLUDES //
///////////////////////
#include "rastertek50/textureclass.h"

namespace Rastertek50 {

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

	bool Initialize(fxport::GraphicsDevice*, int textureSize);
	void Shutdown();
	void Render(fxport::GraphicsDevice*);

	int GetIndexCount();
	int GetVertexCount();
	fxport::Texture2D* GetTexture();

	// The generated mesh (for tests).
	const std::vector<ModelType>& GetModel() const { return m_model; }
	const std::vector<unsigned short>& GetIndices() const { return m_indices; }

	// The input layout of the deferred shader (POSITION, TEXCOORD0, NORMAL).
	static const fxport::VertexDeclaration VertexDeclaration;

private:
	bool InitializeBuffers(fxport::GraphicsDevice*);
	void ShutdownBuffers();
	void RenderBuffers(fxport::GraphicsDevice*);

	bool LoadTexture(fxport::GraphicsDevice*, int);
	void ReleaseTexture();

	bool LoadModel();
	void ReleaseModel();

private:
	std::unique_ptr<fxport::VertexBuffer> m_vertexBuffer;
	std::unique_ptr<fxport::IndexBuffer> m_indexBuffer;
	int m_vertexCount, m_indexCount;
	std::unique_ptr<TextureClass> m_Texture;
	std::vector<ModelType> m_model;
	std::vector<unsigned short> m_indices;
};

}  // namespace Rastertek50
