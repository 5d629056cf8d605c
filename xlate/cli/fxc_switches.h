// fxc's switches that take no value (fxc /?), as build scripts pass them to `fxport compile`:
// /Zpr and /Zpc set the majority of matrices that name none (as D3DCompile's
// D3DCOMPILE_PACK_MATRIX_* flags do); the optimisation, debug-information, strip and logo
// switches change nothing fxport emits and are accepted; those that change what fxc computes or
// accepts, and fxport does not reproduce, are refused by name. Each may be spelled /X or -X.
#pragma once

#include <string>

namespace fxport::cli {

enum class FxcSwitchAction { NotASwitch, Ignore, RowMajor, ColumnMajor, Refuse };

struct FxcSwitch {
    FxcSwitchAction action = FxcSwitchAction::NotASwitch;
    std::string why;  // Refuse: what the switch does that fxport does not
};

// `name`: the switch without its '/' or '-' (case as typed: fxc's switches are case-sensitive).
FxcSwitch fxcSwitch(const std::string& name);

// Whether an argument starting with '/' is a switch rather than an absolute path: its first
// component (up to the next '/') is no entry at the root, so /tmp/x.hlsl stays a path.
bool isSlashSwitch(const std::string& argument);

}  // namespace fxport::cli
