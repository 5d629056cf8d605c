// INTERNAL, GL-free: what a SurfaceFormat's texels hold beyond their size (bytesPerPixel,
// surface_format.h); all of them read the one format table (gl/gl_formats.cpp).
#pragma once

#include "fxport/graphics/surface_format.h"

namespace fxport {

int channelCount(SurfaceFormat format);  // 1..4
bool isFloatFormat(SurfaceFormat format);  // float or half texels

}  // namespace fxport
