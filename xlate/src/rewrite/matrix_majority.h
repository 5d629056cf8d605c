// `#pragma pack_matrix(row_major)` / `(column_major)` as fxc applies it: every matrix declared
// after the pragma (globals, cbuffer and struct members, parameters) without a majority of its
// own takes the one the latest pragma named. glslang 12 keeps the first pragma's majority for the
// rest of the file, so a matrix after `#pragma pack_matrix(column_major)` came out row-major
// (transposed on upload). The pragmas are blanked and each such declaration gets the modifier
// written out; a matrix typedef declared after a pragma keeps that pragma's majority at every use
// (fxc), so the uses get it. Function bodies are left alone: a local matrix's majority is not observable.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// `defaultMajority` (CompileOptions::defaultMatrixMajority) holds until the first pragma.
std::vector<TextEdit> spellOutPackMatrixPragmas(const EffectSyntax& syntax, const std::string& defaultMajority = {});

}  // namespace fxport::xlate
