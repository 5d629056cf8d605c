// RasterizerState: an immutable description with XNA's names and presets.
#pragma once

#include <cstdint>

namespace fxport {

// Which winding (as seen in the final image) is culled. XNA's front faces are clockwise, so the
// default CullCounterClockwiseFace keeps clockwise triangles.
enum class CullMode : std::uint8_t { None, CullClockwiseFace, CullCounterClockwiseFace };
enum class FillMode : std::uint8_t { Solid, WireFrame };

struct RasterizerState {
    // Qualified type names: the members are named like their types, as in XNA.
    fxport::CullMode CullMode = fxport::CullMode::CullCounterClockwiseFace;
    fxport::FillMode FillMode = fxport::FillMode::Solid;
    // D3D semantics: DepthBias is added to depth in [0,1] units; SlopeScaleDepthBias scales the
    // depth slope.
    float DepthBias = 0;
    float SlopeScaleDepthBias = 0;
    bool MultiSampleAntiAlias = true;
    bool ScissorTestEnable = false;
    // Not XNA's (XNA code leaves it false): D3D10/11's FrontCounterClockwise, set by the D3D11
    // front end. Counter-clockwise triangles are then the front ones -- what SV_IsFrontFace reads
    // and which stencil ops (the main or the CounterClockwise set) a triangle takes. CullMode still
    // names the winding as seen that is culled.
    bool FrontCounterClockwise = false;

    bool operator==(const RasterizerState&) const = default;

    static const RasterizerState CullClockwise;
    static const RasterizerState CullCounterClockwise;
    static const RasterizerState CullNone;
};

}  // namespace fxport
