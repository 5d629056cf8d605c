#include "common/program_registry.h"

namespace fxdemo {

std::map<std::string, Program>& programs() {
    static std::map<std::string, Program> registry;
    return registry;
}

}  // namespace fxdemo
