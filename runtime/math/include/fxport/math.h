// fxport's math library: XNA 4's math types with XNA's names and conventions (row vectors,
// right-handed, Direct3D [0, 1] depth), so C# host code ports line by line:
//
//   Matrix world = Matrix::CreateRotationY(angle) * Matrix::CreateTranslation(position);
//   Matrix view = Matrix::CreateLookAt({0, 0, 5}, Vector3::Zero, Vector3::Up);
//   Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, aspect, 1, 100);
//   device.Clear(Color::CornflowerBlue);
//
// Plain structs in namespace fxport; no GLM (nor any other library's) type appears in these headers.
// XNA's read-only properties are const methods (matrix.Translation()), settable ones that do work a
// getter plus setName (frustum.setMatrix); Nullable<float> results are std::optional (docs/API.md).
#pragma once

#include "fxport/math/bounding_box.h"
#include "fxport/math/bounding_frustum.h"
#include "fxport/math/bounding_sphere.h"
#include "fxport/math/color.h"
#include "fxport/math/math_helper.h"
#include "fxport/math/matrix.h"
#include "fxport/math/packed_vector.h"
#include "fxport/math/plane.h"
#include "fxport/math/quaternion.h"
#include "fxport/math/ray.h"
#include "fxport/math/rectangle.h"
#include "fxport/math/vector2.h"
#include "fxport/math/vector3.h"
#include "fxport/math/vector4.h"
