// The object a method is called on (`t.GetDimensions(...)`, `t[2].Load(...)`, `s.tex.Sample(...)`),
// read back from the '.' before the method's name in a function body: a variable (a local, a
// parameter, a global texture or struct) followed by element subscripts and struct members. Its
// type is the declared one with the subscripts and members applied, so a rewrite keyed on the
// object's type (mixed_dimension_outputs.h) treats `T[0]`, a texture parameter and a struct's
// texture member as it treats a plain global texture. Nothing where the receiver is anything else
// (a call's result, a cast) or its declaration is not evident from the tokens.
#pragma once

#include <optional>
#include <string>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

struct MethodReceiver {
    size_t begin = 0;  // the receiver's first token
    std::string type;  // as declared, typedefs resolved: "Texture2D< float4 >", "Texture2DArray"
};

// `dot`: the token index of the '.' before the method's name, inside f's body.
std::optional<MethodReceiver> methodReceiver(const EffectSyntax& syntax, const FxFunction& f, size_t dot);

}  // namespace fxport::xlate
