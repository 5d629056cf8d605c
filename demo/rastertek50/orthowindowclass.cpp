////////////////////////////////////////////////////////////////////////////////
// Filename: orthowindowclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/orthowindowclass.h"

#include <cstddef>
#include <vector>

namespace Rastertek50 {

const fxport::VertexDeclaration OrthoWindowClass::VertexDeclaration(
	int(sizeof(VertexType)),
	{
		fxport::VertexElement(int(offsetof(VertexType, position)), fxport::VertexElementFormat::Vector3,
				      fxport::VertexElementUsage::Position, 0),
		fxport::VertexElement(int(offsetof(VertexType, texture)), fxport::VertexElementFormat::Vector2,
				      fxport::VertexElementUsage::TextureCoordinate, 0),
	});


OrthoWindowClass::OrthoWindowClass()
{
	m_vertexCount = 0;
	m_indexCount = 0;
}


OrthoWindowClass::~OrthoWindowClass()
{
}


bool OrthoWindowClass::Initialize(fxport::GraphicsDevice* device, int windowWidth, int windowHeight)
{
	bool result;


	// Initialize the vertex and index buffer that hold the geometry for the ortho window model.
	result = InitializeBuffers(device, windowWidth, windowHeight);
	if(!result)
	{
		return false;
	}

	return true;
}


void OrthoWindowClass::Shutdown()
{
	// Release the vertex and index buffers.
	ShutdownBuffers();

	return;
}


void OrthoWindowClass::Render(fxport::GraphicsDevice* device)
{
	// Put the vertex and index buffers on the graphics pipeline to prepare them for drawing.
	RenderBuffers(device);

	return;
}


int OrthoWindowClass::GetIndexCount()
{
	return m_indexCount;
}


int OrthoWindowClass::GetVertexCount()
{
	return m_vertexCount;
}


bool OrthoWindowClass::InitializeBuffers(fxport::GraphicsDevice* device, int windowWidth, int windowHeight)
{
	float left, right, top, bottom;
	int i;


	// Calculate the screen coordinates of the left side of the window.
	left = (float)((windowWidth / 2) * -1);

	// Calculate the screen coordinates of the right side of the window.
	right = left + (float)windowWidth;

	// Calculate the screen coordinates of the top of the window.
	top = (float)(windowHeight / 2);

	// Calculate the screen coordinates of the bottom of the window.
	bottom = top - (float)windowHeight;

	// Set the number of vertices in the vertex array.
	m_vertexCount = 6;

	// Set the number of indices in the index array.
	m_indexCount = m_vertexCount;

	// Create the vertex array.
	std::vector<VertexType> vertices(static_cast<std::size_t>(m_vertexCount));

	// Create the index array.
	std::vector<unsigned short> indices(static_cast<std::size_t>(m_indexCount));

	// Load the vertex array with data.
	// First triangle.
	vertices[0].position = D3DXVECTOR3(left, top, 0.0f);  // Top left.
	vertices[0].texture = D3DXVECTOR2(0.0f, 0.0f);

	vertices[1].position = D3DXVECTOR3(right, bottom, 0.0f);  // Bottom right.
	vertices[1].texture = D3DXVECTOR2(1.0f, 1.0f);

	vertices[2].position = D3DXVECTOR3(left, bottom, 0.0f);  // Bottom left.
	vertices[2].texture = D3DXVECTOR2(0.0f, 1.0f);

	// Second triangle.
	vertices[3].position = D3DXVECTOR3(left, top, 0.0f);  // Top left.
	vertices[3].texture = D3DXVECTOR2(0.0f, 0.0f);

	vertices[4].position = D3DXVECTOR3(right, top, 0.0f);  // Top right.
	vertices[4].texture = D3DXVECTOR2(1.0f, 0.0f);

	vertices[5].position = D3DXVECTOR3(right, bottom, 0.0f);  // Bottom right.
	vertices[5].texture = D3DXVECTOR2(1.0f, 1.0f);

	// Load the index array with data.
	for(i=0; i<m_indexCount; i++)
	{
		indices[i] = (unsigned short)i;
	}

	// Now create the vertex buffer.
	m_vertexBuffer = std::make_unique<fxport::VertexBuffer>(*device, VertexDeclaration, m_vertexCount,
								 fxport::BufferUsage::WriteOnly);
	m_vertexBuffer->SetData(vertices);

	// Create the index buffer.
	m_indexBuffer = std::make_unique<fxport::IndexBuffer>(*device, fxport::IndexElementSize::SixteenBits, m_indexCount,
							       fxport::BufferUsage::WriteOnly);
	m_indexBuffer->SetData(indices);

	return true;
}


void OrthoWindowClass::ShutdownBuffers()
{
	// Release the index buffer.
	m_indexBuffer.reset();

	// Release the vertex buffer.
	m_vertexBuffer.reset();

	return;
}


void OrthoWindowClass::RenderBuffers(fxport::GraphicsDevice* device)
{
	// Set the vertex buffer to active in the input assembler so it can be rendered.
	device->SetVertexBuffer(m_vertexBuffer.get());

	// Set the index buffer to active in the input assembler so it can be rendered.
	device->Indices = m_indexBuffer.get();

	// The primitive type (triangle list) is given to the draw call on fxport.

	return;
}

}  // namespace Rastertek50
