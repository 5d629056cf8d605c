// INTERNAL, GL-free: what the device core tells the effects, without reading an Effect's private
// state (effect/effect_impl.h): a texture was disposed, a warning was found while drawing.
#pragma once

#include <string>

namespace fxport {

class Effect;
class Texture;

// Hands `warning` to the handler SetEffectWarningHandler installed (stderr by default): for what is
// found only while drawing (an SRGBWriteEnable pass drawing into a target GL does not encode).
void reportEffectWarning(const std::string& warning);

// `texture` is disposed: `effect`'s texture parameters that hold it are left unset.
void forgetTexture(Effect& effect, const Texture* texture);

}  // namespace fxport
