// Runs the `fxport` command line from a test (FXPORT_CLI_PATH, set by tests/xlate/CMakeLists.txt)
// and captures what it printed: one helper for every xlate test that drives the CLI.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace fxport::test {

struct RunResult {
    bool exited = false;  // false: killed by a signal (a crash)
    int status = -1;      // exit status when exited, -1 otherwise
    std::string output;   // stdout and stderr
};

// `args` are already quoted for sh; `env` (e.g. "FXPORT_WORKER_SECONDS=2") goes before the command.
inline RunResult runCli(const std::string& args, const std::string& env = {}) {
    RunResult r;
    std::string command = env + " '" + FXPORT_CLI_PATH + "' " + args + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int wstatus = ::pclose(pipe);
    // popen runs `sh -c`; a child killed by a signal shows as the shell's status 128+signal.
    if (wstatus != -1 && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) < 128) {
        r.exited = true;
        r.status = WEXITSTATUS(wstatus);
    }
    return r;
}

}  // namespace fxport::test
