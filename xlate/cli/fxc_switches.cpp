// See fxc_switches.h. What each switch does is fxc's documentation (fxc /? and learn.microsoft.com's
// "Syntax" page of FXC.exe) beside the D3DCOMPILE_* flag it sets.
#include "fxc_switches.h"

#include <filesystem>

namespace fxport::cli {

namespace {

struct Known {
    const char* name;
    FxcSwitchAction action;
    const char* why;
};

const Known kKnown[] = {
    {"Zpr", FxcSwitchAction::RowMajor, ""},
    {"Zpc", FxcSwitchAction::ColumnMajor, ""},
    // Optimisation levels, debug information, stripped reflection/debug data, the banner: fxc's
    // code and blob, never what a shader computes.
    {"Od", FxcSwitchAction::Ignore, ""},
    {"O0", FxcSwitchAction::Ignore, ""},
    {"O1", FxcSwitchAction::Ignore, ""},
    {"O2", FxcSwitchAction::Ignore, ""},
    {"O3", FxcSwitchAction::Ignore, ""},
    {"Zi", FxcSwitchAction::Ignore, ""},
    {"nologo", FxcSwitchAction::Ignore, ""},
    {"Qstrip_reflect", FxcSwitchAction::Ignore, ""},
    {"Qstrip_debug", FxcSwitchAction::Ignore, ""},
    // Strict mode refuses deprecated syntax, IEEE strictness forbids fxc's unsafe float
    // optimisations: neither changes the value of a shader fxc compiles under it.
    {"Ges", FxcSwitchAction::Ignore, ""},
    {"Gis", FxcSwitchAction::Ignore, ""},
    {"Gec", FxcSwitchAction::Refuse, "is fxc's backwards-compatibility mode (legacy syntax compiled for SM4/5 targets), which fxport does not reproduce"},
    {"Gfa", FxcSwitchAction::Refuse, "makes fxc avoid flow control (both sides of a branch run, gradients inside it defined), which fxport does not reproduce"},
    {"Gfp", FxcSwitchAction::Refuse, "makes fxc prefer flow control (branches kept, gradients inside them undefined), which fxport does not reproduce"},
    {"Gpp", FxcSwitchAction::Refuse, "makes fxc compute at partial precision, which fxport does not reproduce (GL computes at full precision)"},
};

}  // namespace

FxcSwitch fxcSwitch(const std::string& name) {
    for (const auto& k : kKnown)
        if (name == k.name) return {k.action, k.why};
    return {};
}

bool isSlashSwitch(const std::string& argument) {
    if (argument.size() < 2 || argument[0] != '/') return false;
    std::error_code ec;
    return !std::filesystem::exists(std::filesystem::path("/") / argument.substr(1, argument.find('/', 1) - 1), ec);
}

}  // namespace fxport::cli
