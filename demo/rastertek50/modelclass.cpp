////////////////////////////////////////////////////////////////////////////////
// Filename: modelclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/modelclass.h"

#include <vector>

namespace Rastertek50 {

ModelClass::ModelClass()
{
	m_vertexBuffer = 0;
	m_indexBuffer = 0;
	m_vertexCount = 0;
	m_indexCount = 0;
	m_textureSize = 0;
}


ModelClass::~ModelClass()
{
}


bool ModelClass::Initialize(ID3D10Device* device, int textureSize)
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


void ModelClass::Render(ID3D10Device* device)
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


ID3D10ShaderResourceView* ModelClass::GetTexture()
{
	return m_Texture->GetTexture();
}


bool ModelClass::InitializeBuffers(ID3D10Device* device)
{
	std::vector<VertexType> vertices(static_cast<std::size_t>(m_vertexCount));
	std::vector<unsigned int> indices(static_cast<std::size_t>(m_indexCount));
	D3D10_BUFFER_DESC vertexBufferDesc, indexBufferDesc;
	D3D10_SUBRESOURCE_DATA vertexData, indexData;
	HRESULT result;
	int i;


	// Load the vertex array with data.
	for(i=0; i<m_vertexCount; i++)
	{
		vertices[i].position = D3DXVECTOR3(m_model[i].x, m_model[i].y, m_model[i].z);
		vertices[i].texture = D3DXVECTOR2(m_model[i].tu, m_model[i].tv);
		vertices[i].normal = D3DXVECTOR3(m_model[i].nx, m_model[i].ny, m_model[i].nz);
	}

	// Load the index array with data (fxport: the generated cube's, see LoadModel).
	for(i=0; i<m_indexCount; i++)
	{
		indices[i] = m_indices[i];
	}

	// Set up the description of the vertex buffer.
	vertexBufferDesc.Usage = D3D10_USAGE_DEFAULT;
	vertexBufferDesc.ByteWidth = sizeof(VertexType) * m_vertexCount;
	vertexBufferDesc.BindFlags = D3D10_BIND_VERTEX_BUFFER;
	vertexBufferDesc.CPUAccessFlags = 0;
	vertexBufferDesc.MiscFlags = 0;

	// Give the subresource structure a pointer to the vertex data.
	vertexData.pSysMem = vertices.data();

	// Now finally create the vertex buffer.
	result = device->CreateBuffer(&vertexBufferDesc, &vertexData, &m_vertexBuffer);
	if(FAILED(result))
	{
		return false;
	}

	// Set up the description of the index buffer (fxport: 32-bit `unsigned int` indices, the
	// tutorial's `unsigned long` on Windows, DXGI_FORMAT_R32_UINT).
	indexBufferDesc.Usage = D3D10_USAGE_DEFAULT;
	indexBufferDesc.ByteWidth = sizeof(unsigned int) * m_indexCount;
	indexBufferDesc.BindFlags = D3D10_BIND_INDEX_BUFFER;
	indexBufferDesc.CPUAccessFlags = 0;
	indexBufferDesc.MiscFlags = 0;

	// Give the subresource structure a pointer to the index data.
	indexData.pSysMem = indices.data();

	// Create the index buffer.
	result = device->CreateBuffer(&indexBufferDesc, &indexData, &m_indexBuffer);
	if(FAILED(result))
	{
		return false;
	}

	return true;
}


void ModelClass::ShutdownBuffers()
{
	// Release the index buffer.
	if(m_indexBuffer)
	{
		m_indexBuffer->Release();
		m_indexBuffer = 0;
	}

	// Release the vertex buffer.
	if(m_vertexBuffer)
	{
		m_vertexBuffer->Release();
		m_vertexBuffer = 0;
	}

	return;
}


void ModelClass::RenderBuffers(ID3D10Device* device)
{
	unsigned int stride;
	unsigned int offset;


	// Set vertex buffer stride and offset.
	stride = sizeof(VertexType); 
	offset = 0;
    
	// Set the vertex buffer to active in the input assembler so it can be rendered.
	device->IASetVertexBuffers(0, 1, &m_vertexBuffer, &stride, &offset);

	// Set the index buffer to active in the input assembler so it can be rendered.
	device->IASetIndexBuffer(m_indexBuffer, DXGI_FORMAT_R32_UINT, 0);

	// Set the type of primitive that should be rendered from this vertex buffer, in this case triangles.
	device->IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST);

	return;
}


bool ModelClass::LoadTexture(ID3D10Device* device, int textureSize)
{
	bool result;


	// Create the texture object.
	m_Texture = std::make_unique<TextureClass>();

	// Initialize the texture object.
	m_textureSize = textureSize;  // fxport
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
