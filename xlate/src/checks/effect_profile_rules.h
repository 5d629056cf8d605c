// Rules that depend on the effect profile fxc's /T names (CompileOptions::effectProfile):
//  - fx_4_0, fx_4_1 and fx_5_0 take an effect without a technique (variables and functions, as an
//    effect pool holds); fx_2_0 and the empty profile (XNA's effects) need one (FX1003);
//  - fx_4_0 and later refuse a variable of a struct that holds an object (a Texture member):
//    effect-variables-fx_4/fx_5 pin it; the struct's declaration alone is fine.
// An unknown profile is FX1401.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "fx/source_map.h"

namespace fxport::xlate {

// Whether the profile takes an effect without a technique; throws CompileError (FX1401, located
// at `displayPath`) for a profile fxc does not have.
bool allowsTechniqueless(const std::string& effectProfile, const std::string& displayPath);

// The profile's errors in the parsed effect, located; empty when there are none.
std::vector<Diagnostic> checkEffectProfile(const EffectSyntax& syntax, const SourceMap& map, const std::string& effectProfile);

}  // namespace fxport::xlate
