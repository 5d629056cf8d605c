// Everything of the runtime a ported XNA program uses: `#include "fxport/graphics.h"`.
//
// Where C# cannot be mirrored (docs/API.md): a property is a public member when the object only stores
// it, a const method when it is computed or fixed at creation (texture->Width()), a getter plus
// setName(value) when setting does work; a name lookup that XNA answers with null throws ArgumentError
// naming the key (find(name) returns nullptr for the C# null test); Nullable<T> is std::optional<T>.
#pragma once

#include "fxport/graphics/alpha_test_effect.h"
#include "fxport/graphics/animation_player.h"
#include "fxport/graphics/basic_effect.h"
#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/directional_light.h"
#include "fxport/graphics/dual_texture_effect.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/effect_interfaces.h"
#include "fxport/graphics/environment_map_effect.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/finite_check.h"
#include "fxport/graphics/fullscreen_quad.h"
#include "fxport/graphics/gpu_limits.h"
#include "fxport/graphics/gpu_timer.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/model.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/skinned_effect.h"
#include "fxport/graphics/skinning_data.h"
#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/structured_buffer.h"
#include "fxport/graphics/surface_format.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_1d.h"
#include "fxport/graphics/texture_2d_array.h"
#include "fxport/graphics/texture_3d.h"
#include "fxport/graphics/texture_processor.h"
#include "fxport/graphics/vertex_buffer.h"
#include "fxport/graphics/vertex_declaration.h"
#include "fxport/graphics/vertex_types.h"
#include "fxport/graphics/viewport.h"
#include "fxport/math.h"
