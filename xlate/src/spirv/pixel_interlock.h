// A pixel shader that reads or writes a rasterizer-ordered view (rewrite/rasterizer_ordered_views.h)
// runs its body as one critical section in primitive order: SPV_EXT_fragment_shader_interlock's
// PixelInterlockOrderedEXT, OpBeginInvocationInterlockEXT after the entry function's variables
// and OpEndInvocationInterlockEXT before its return (legalisation leaves one). SPIRV-Cross writes
// it as GL_ARB_fragment_shader_interlock (or NV's), so a driver without either refuses the
// shader at link rather than run it unordered. D3D orders only the ROV accesses; ordering the
// whole body is what the GL extension can express, and gives the same values.
#pragma once

#include <string>
#include <vector>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h: false (unchanged) unless the module is a fragment shader in which a
// variable named in `views` is left.
bool pixelInterlockForOrderedViews(ParsedSpirv& m, const std::vector<std::string>& views);

}  // namespace fxport::xlate
