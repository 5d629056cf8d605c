#include "rastertek50/d3dx_math.h"

#include <cmath>

namespace Rastertek50 {

using fxport::Matrix;
using fxport::Vector3;

Matrix D3DXMatrixLookAtLH(Vector3 eye, Vector3 at, Vector3 up) {
    const Vector3 zaxis = Vector3::Normalize(at - eye);
    const Vector3 xaxis = Vector3::Normalize(Vector3::Cross(up, zaxis));
    const Vector3 yaxis = Vector3::Cross(zaxis, xaxis);
    return Matrix(xaxis.X, yaxis.X, zaxis.X, 0.0f,
                  xaxis.Y, yaxis.Y, zaxis.Y, 0.0f,
                  xaxis.Z, yaxis.Z, zaxis.Z, 0.0f,
                  -Vector3::Dot(xaxis, eye), -Vector3::Dot(yaxis, eye), -Vector3::Dot(zaxis, eye), 1.0f);
}

Matrix D3DXMatrixPerspectiveFovLH(float fovY, float aspect, float zn, float zf) {
    const float yScale = 1.0f / std::tan(fovY / 2.0f);
    const float xScale = yScale / aspect;
    return Matrix(xScale, 0.0f, 0.0f, 0.0f,
                  0.0f, yScale, 0.0f, 0.0f,
                  0.0f, 0.0f, zf / (zf - zn), 1.0f,
                  0.0f, 0.0f, -zn * zf / (zf - zn), 0.0f);
}

Matrix D3DXMatrixOrthoLH(float w, float h, float zn, float zf) {
    return Matrix(2.0f / w, 0.0f, 0.0f, 0.0f,
                  0.0f, 2.0f / h, 0.0f, 0.0f,
                  0.0f, 0.0f, 1.0f / (zf - zn), 0.0f,
                  0.0f, 0.0f, zn / (zn - zf), 1.0f);
}

}  // namespace Rastertek50
