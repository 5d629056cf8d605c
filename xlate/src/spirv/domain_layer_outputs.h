// A domain shader's SV_RenderTargetArrayIndex / SV_ViewportArrayIndex output. glslang makes these
// Layer / ViewportIndex only in vertex and geometry shaders (its HLSL front end's rule); in a
// tessellation evaluation shader they stay user varyings, so a domain shader that feeds the
// rasteriser would send every primitive to layer and viewport 0. Each such output gets a twin
// built-in output that every store to it writes too: gl_Layer / gl_ViewportIndex when the domain
// shader is the last stage before the rasteriser (the extension lines are pre_raster_builtins.h's),
// the varying for a geometry shader after it (D3D11 compiles the stages apart).
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (unchanged) unless the module is a tessellation evaluation
// shader with such an output.
bool domainLayerOutputs(ParsedSpirv& m);

}  // namespace fxport::xlate
