// fxport addition (not in the seed): the D3DX10 math functions the seed's classes call, on
// fxport::Matrix. D3DX matrices are row-major and used as mul(v, M) in HLSL; XNA's Matrix has the
// same layout and the same convention (mul(v, M) == Vector4::Transform(v, M)), so the seed's
// SetMatrix((float*)&m) becomes Parameters[...].SetValue(m) with no transpose. XNA builds only
// right-handed view/projection matrices; the seed uses the left-handed D3DX ones, written out here
// from the D3DX documentation's formulas.
#pragma once

#include "fxport/math.h"

namespace Rastertek50 {

using D3DXMATRIX = fxport::Matrix;
using D3DXVECTOR2 = fxport::Vector2;
using D3DXVECTOR3 = fxport::Vector3;
using D3DXVECTOR4 = fxport::Vector4;

constexpr float D3DX_PI = 3.141592654f;  // d3dx10math.h's value

// zaxis = normal(At - Eye), xaxis = normal(cross(Up, zaxis)), yaxis = cross(zaxis, xaxis).
fxport::Matrix D3DXMatrixLookAtLH(fxport::Vector3 eye, fxport::Vector3 at, fxport::Vector3 up);
// yScale = cot(fovY/2), xScale = yScale / aspect; z in [0,1] from zn to zf.
fxport::Matrix D3DXMatrixPerspectiveFovLH(float fovY, float aspect, float zn, float zf);
// 2/w, 2/h, 1/(zf-zn), zn/(zn-zf).
fxport::Matrix D3DXMatrixOrthoLH(float w, float h, float zn, float zf);
// D3DXMatrixRotationY has the same elements as XNA's CreateRotationY (M13 = -sin, M31 = sin).
inline fxport::Matrix D3DXMatrixRotationY(float angle) { return fxport::Matrix::CreateRotationY(angle); }
// Roll about Z, then pitch about X, then yaw about Y: the same as XNA's CreateFromYawPitchRoll.
inline fxport::Matrix D3DXMatrixRotationYawPitchRoll(float yaw, float pitch, float roll) {
    return fxport::Matrix::CreateFromYawPitchRoll(yaw, pitch, roll);
}

}  // namespace Rastertek50
