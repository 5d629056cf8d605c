// Viewport: the part of the render target drawn to, in pixels from the top-left corner, and the
// depth range; Project/Unproject map between object space and viewport pixels as XNA.
#pragma once

#include "fxport/math.h"

namespace fxport {

struct Viewport {
    int X = 0;
    int Y = 0;
    int Width = 0;
    int Height = 0;
    float MinDepth = 0;
    float MaxDepth = 1;

    Viewport() = default;
    Viewport(int x, int y, int width, int height) : X(x), Y(y), Width(width), Height(height) {}
    explicit Viewport(const Rectangle& r) : X(r.X), Y(r.Y), Width(r.Width), Height(r.Height) {}
    Rectangle Bounds() const { return Rectangle(X, Y, Width, Height); }
    float AspectRatio() const { return Height == 0 ? 0.0f : float(Width) / float(Height); }
    // XNA's Project: a point in object space to the viewport: x, y in pixels (y down from the top),
    // z in [MinDepth, MaxDepth] (D3D depth). Through world * view * projection, divided by w
    // unless w is within 1.192093e-7 of 1, as XNA.
    Vector3 Project(Vector3 source, const Matrix& projection, const Matrix& view, const Matrix& world) const {
        const Matrix m = world * view * projection;
        Vector3 v = Vector3::Transform(source, m);
        const float w = source.X * m.M14 + source.Y * m.M24 + source.Z * m.M34 + m.M44;
        if (!nearOne(w)) v = v / w;
        return {(v.X + 1.0f) * 0.5f * float(Width) + float(X), (-v.Y + 1.0f) * 0.5f * float(Height) + float(Y),
                v.Z * (MaxDepth - MinDepth) + MinDepth};
    }
    // XNA's Unproject: the inverse of Project (a pixel and depth back to object space).
    Vector3 Unproject(Vector3 source, const Matrix& projection, const Matrix& view, const Matrix& world) const {
        const Matrix m = Matrix::Invert(world * view * projection);
        const Vector3 ndc((source.X - float(X)) / float(Width) * 2.0f - 1.0f,
                          -((source.Y - float(Y)) / float(Height) * 2.0f - 1.0f),
                          (source.Z - MinDepth) / (MaxDepth - MinDepth));
        Vector3 v = Vector3::Transform(ndc, m);
        const float w = ndc.X * m.M14 + ndc.Y * m.M24 + ndc.Z * m.M34 + m.M44;
        if (!nearOne(w)) v = v / w;
        return v;
    }

    bool operator==(const Viewport&) const = default;

private:
    static bool nearOne(float w) { return w - 1.0f >= -1.192093e-7f && w - 1.0f <= 1.192093e-7f; }
};

}  // namespace fxport
