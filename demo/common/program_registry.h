// The programs fxdemo can run besides `deferred`: each demo registers itself from its own .cpp,
//   FXDEMO_PROGRAM(lighting2d, "fxdemo lighting2d [--out DIR] ...", runLighting2d);
// so that adding a demo does not touch fxdemo_main.cpp. main() passes argv from the program name on.
#pragma once

#include <map>
#include <string>

namespace fxdemo {

using ProgramMain = int (*)(int argc, char** argv);  // argv[0] is the program name

struct Program {
    std::string usage;
    ProgramMain main = nullptr;
};

std::map<std::string, Program>& programs();

struct ProgramRegistration {
    ProgramRegistration(const char* name, const char* usage, ProgramMain main) { programs()[name] = {usage, main}; }
};

}  // namespace fxdemo

#define FXDEMO_PROGRAM(name, usage, main) \
    static const ::fxdemo::ProgramRegistration fxdemo_registration_##name(#name, usage, main)
