// Builders that append closed or open surfaces to a Primitive, each with exact (analytic)
// normals and tangents, counter-clockwise front faces and the uv conventions of mesh.h.
#pragma once

#include "mesh.h"

namespace fxport::content {

// A flat rectangle. Its normal is cross(axisU, axisUp); u grows along axisU, v grows against
// axisUp, so the image appears unmirrored seen from the front with axisUp as "up".
struct PatchDesc {
    Vec3 center;
    Vec3 axisU{1, 0, 0};   // unit
    Vec3 axisUp{0, 1, 0};  // unit, perpendicular to axisU
    float sizeU = 1;
    float sizeUp = 1;
    int cellsU = 1;  // subdivisions
    int cellsUp = 1;
    Vec2 uvTopLeft{0, 0};
    Vec2 uvBottomRight{1, 1};
};
void AddPatch(Primitive& out, const PatchDesc& desc);

// An axis-aligned box of six patches (side faces upright; top and bottom read from the +Z side).
struct BoxDesc {
    Vec3 center;
    Vec3 size{1, 1, 1};
    // 0: every face maps the whole texture (0..1); > 0: world-space mapping, one texture repeat
    // per this many units (so neighbouring boxes share texel density).
    float unitsPerRepeat = 0;
    // 0: one quad per face; > 0: faces split into cells of about this size.
    float cellSize = 0;
};
void AddBox(Primitive& out, const BoxDesc& desc);

// The side of an upright cylinder (no caps), base centre at `base`.
struct CylinderDesc {
    Vec3 base;
    float radius = 1;
    float height = 1;
    int segments = 24;
    int rings = 1;
    float uRepeats = 1;          // texture repeats around the circumference
    float unitsPerRepeatV = 1;   // world units per texture repeat along the height
};
void AddCylinderSide(Primitive& out, const CylinderDesc& desc);

// A UV sphere; the poles are on the Y axis, u runs around Y (uRepeats times), v from the north
// pole (v = 0) to the south pole (v = vRepeats).
struct SphereDesc {
    Vec3 center;
    float radius = 1;
    int segments = 32;
    int rings = 16;
    float uRepeats = 2;
    float vRepeats = 1;
};
void AddUvSphere(Primitive& out, const SphereDesc& desc);

// A closed cone with its apex at the origin, its axis along -Z, its base (a flat cap) at z = -1
// with base-polygon vertices at `baseRadius`. The spot-light volume; no tangents are needed.
void AddLightCone(Primitive& out, int segments, float baseRadius);

}  // namespace fxport::content
