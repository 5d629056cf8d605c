// Struct definitions written where a declaration also names variables, or inside another
// definition, split into what fxport's parser and glslang read: a named definition of its own and
// declarations that use the name. fxc takes all of these (vkd3d's struct-syntax, struct-semantics,
// static-initializer, struct-array and cbuffer tests pin them):
//  - `static struct { float4 x; } v;` and `struct apple { ... } a;` (a definition with declarators):
//    `struct N { ... }; static N v;`, N made up where the struct has no name (fxc's anonymous
//    struct);
//  - a struct defined in a struct's member list or in a cbuffer (`struct { float4 t : TEXCOORD; } m;`):
//    its definition goes before the outermost declaration around it, on that declaration's first
//    line, and the member becomes `N m;`;
//  - a struct defined in a function body (glslang takes definitions at file scope only; vkd3d's
//    state-block-syntax declares `struct {int a;} s;` in main): the definition goes before the
//    function, on its first line, and the declarators use the name.
// Runs on the preprocessed text, before the parser, and keeps every line where it was (a definition
// moved before its enclosing declaration joins that declaration's first line). A definition with no
// member or no declarator where it needs one (`struct { float a; };`) is left as written: fxc
// rejects it and so do we.
#pragma once

#include <string>

namespace fxport::xlate {

std::string splitStructDefinitions(const std::string& preprocessed);

}  // namespace fxport::xlate
