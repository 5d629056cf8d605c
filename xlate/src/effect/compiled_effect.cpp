#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

bool CompiledEffect::hasErrors() const {
    for (const auto& d : diagnostics)
        if (d.severity == Severity::Error) return true;
    return false;
}

const Parameter* CompiledEffect::findParameter(const std::string& name) const {
    for (const auto& p : parameters)
        if (p.name == name) return &p;
    return nullptr;
}

int CompiledEffect::findTechnique(const std::string& name) const {
    for (size_t i = 0; i < techniques.size(); ++i)
        if (techniques[i].name == name) return static_cast<int>(i);
    return -1;
}

}  // namespace fxport::xlate
