////////////////////////////////////////////////////////////////////////////////
// Filename: cameraclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses CameraClass but does not list it): the Rastertek DX10 CameraClass
// with RenderBaseViewMatrix, on fxport math.
#pragma once


//////////////
// INCLUDES //
//////////////
#include "rastertek50/d3dx_math.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: CameraClass
////////////////////////////////////////////////////////////////////////////////
class CameraClass
{
public:
	CameraClass();
	CameraClass(const CameraClass&) = delete;
	~CameraClass();

	void SetPosition(float, float, float);
	void SetRotation(float, float, float);

	D3DXVECTOR3 GetPosition();
	D3DXVECTOR3 GetRotation();

	void Render();
	void GetViewMatrix(D3DXMATRIX&);

	void RenderBaseViewMatrix();
	void GetBaseViewMatrix(D3DXMATRIX&);

private:
	D3DXMATRIX BuildViewMatrix();

	float m_positionX, m_positionY, m_positionZ;
	float m_rotationX, m_rotationY, m_rotationZ;
	D3DXMATRIX m_viewMatrix, m_baseViewMatrix;
};

}  // namespace Rastertek50
