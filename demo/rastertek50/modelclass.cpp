////////////////////////////////////////////////////////////////////////////////
// Filename: modelclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/modelclass.h"

#include <cstddef>

namespace Rastertek50 {

const fxport::VertexDeclaration ModelClass::VertexDeclaration(
	int(sizeof(VertexType)),
	{
		fxport::VertexElement(int(offsetof(VertexType, position)), fxport::VertexElementFormat::Vector3,
				      fxport::VertexElementUsage::Position, 0),
		fxport::VertexElement(int(offsetof(VertexType, texture)), fxport::VertexElementFormat::Vector2,
				      fxport::VertexElementUsage::TextureCoordinate, 0),
		fxport::VertexElement(int(offsetof(VertexType, normal)), fxport::VertexElementFormat::Vector3,
				      fxport::VertexElementUsage::Normal, 0),
	});


ModelClass::ModelClass()
{
	m_vertexCount = 0;
	m_indexCount = 0;
}


ModelClass::~ModelClass()
{
}


bool ModelClass::Initialize(fxport::GraphicsDevice* device, int textureSize)
{
	bool result;


	// Load in the model data.
	result = LoadModel();
	if(!result)
	{
		return false;
	}

	// Initialize the vertex and index buffer that hold the geometry for the model.
	result = InitializeBuffers(device);
	if(!result)
	{
		return false;
	}

	// Load the texture for this model.
	result = LoadTexture(device, textureSize);
	if(!result)
	{
		return false;
	}

	return true;
}


void ModelClass::Shutdown()
{
	// Release the model texture.
	ReleaseTexture();

	// Release the vertex and index buffers.
	ShutdownBuffers();

	// Release the model data.
	ReleaseModel();

	return;
}


void ModelClass::Render(fxport::GraphicsDevice* device)
{
	// Put the vertex and index buffers on the graphics pipeline to prepare them for drawing.
	RenderBuffers(device);

	return;
}


int ModelClass::GetIndexCount()
{
	return m_indexCount;
}


int ModelClass::GetVertexCount()
{
	return m_vertexCount;
}


fxport::Texture2D* ModelClass::GetTexture()
{
	return m_Texture->GetTexture();
}


bool ModelClass::InitializeBuffers(fxport::GraphicsDevice* device)
{
	std::vector<VertexType> vertices(static_cast<std::size_t>(m_vertexCount));
	int i;


	// Load the vertex array with data.
	for(i=0; i<m_vertexCount; i++)
	{
		vertices[i].position = D3DXVECTOR3(m_model[i].x, m_model[i].y, m_model[i].z);
		vertices[i].texture = D3DXVECTOR2(m_model[i].tu, m_model[i].tv);
		vertices[i].normal = D3DXVECTOR3(m_model[i].nx, m_model[i].ny, m_model[i].nz);
	}

	// Now finally create the vertex buffer.
	m_vertexBuffer = std::make_unique<fxport::VertexBuffer>(*device, VertexDeclaration, m_vertexCount,
								 fxport::BufferUsage::WriteOnly);
	m_vertexBuffer->SetData(vertices);

	// Create the index buffer.
	m_indexBuffer = std::make_unique<fxport::IndexBuffer>(*device, fxport::IndexElementSize::SixteenBits, m_indexCount,
							       fxport::BufferUsage::WriteOnly);
	m_indexBuffer->SetData(m_indices);

	return true;
}


void ModelClass::ShutdownBuffers()
{
	// Release the index buffer.
	m_indexBuffer.reset();

	// Release the vertex buffer.
	m_vertexBuffer.reset();

	return;
}


void ModelClass::RenderBuffers(fxport::GraphicsDevice* device)
{
	// Set the vertex buffer to active in the input assembler so it can be rendered.
	device->SetVertexBuffer(m_vertexBuffer.get());

	// Set the index buffer to active in the input assembler so it can be rendered.
	device->Indices = m_indexBuffer.get();

	// The primitive type (triangle list) is given to the draw call on fxport.

	return;
}


bool ModelClass::LoadTexture(fxport::GraphicsDevice* device, int textureSize)
{
	bool result;


	// Create the texture object.
	m_Texture = std::make_unique<TextureClass>();

	// Initialize the texture object.
	result = m_Texture->Initialize(device, textureSize);
	if(!result)
	{
		return false;
	}

	return true;
}


void ModelClass::ReleaseTexture()
{
	// Release the texture object.
	if(m_Texture)
	{
		m_Texture->Shutdown();
		m_Texture.reset();
	}

	return;
}


// fxport: cube.txt generated. Each face is listed as its top left, top right, bottom left and
// bottom right corner seen from outside the cube (texture coordinates (0,0), (1,0), (0,1), (1,1)),
// drawn as the triangles (TL, TR, BL) and (BL, TR, BR): clockwise, as in cube.txt.
bool ModelClass::LoadModel()
{
	struct Face { float n[3]; float c[4][3]; };
	static const Face faces[6] = {
		// front (-Z)
		{{0, 0, -1}, {{-1, 1, -1}, {1, 1, -1}, {-1, -1, -1}, {1, -1, -1}}},
		// right (+X)
		{{1, 0, 0}, {{1, 1, -1}, {1, 1, 1}, {1, -1, -1}, {1, -1, 1}}},
		// back (+Z)
		{{0, 0, 1}, {{1, 1, 1}, {-1, 1, 1}, {1, -1, 1}, {-1, -1, 1}}},
		// left (-X)
		{{-1, 0, 0}, {{-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}}},
		// top (+Y)
		{{0, 1, 0}, {{-1, 1, 1}, {1, 1, 1}, {-1, 1, -1}, {1, 1, -1}}},
		// bottom (-Y)
		{{0, -1, 0}, {{-1, -1, -1}, {1, -1, -1}, {-1, -1, 1}, {1, -1, 1}}},
	};
	static const float uv[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
	static const unsigned short corners[6] = {0, 1, 2, 2, 1, 3};

	// Set the vertex count and the index count.
	m_vertexCount = 24;
	m_indexCount = 36;

	// Create the model using the vertex count that was read in.
	m_model.clear();
	m_indices.clear();
	for(const Face& face : faces)
	{
		const unsigned short base = (unsigned short)m_model.size();
		for(int corner = 0; corner < 4; corner++)
		{
			ModelType v;
			v.x = face.c[corner][0]; v.y = face.c[corner][1]; v.z = face.c[corner][2];
			v.tu = uv[corner][0]; v.tv = uv[corner][1];
			v.nx = face.n[0]; v.ny = face.n[1]; v.nz = face.n[2];
			m_model.push_back(v);
		}
		for(unsigned short corner : corners) m_indices.push_back((unsigned short)(base + corner));
	}

	return true;
}


void ModelClass::ReleaseModel()
{
	m_model.clear();
	m_indices.clear();
	return;
}

}  // namespace Rastertek50
