// Runs each (.shader_test file, shader model) in its own forked child process (which makes its own
// GL context), a few at a time. A compile or draw that takes the child down is counted as a crash
// of that section or draw, and the (file, model) is rerun with that line marked crashed, so the
// rest of the file still counts. Results come back over a pipe, one line each (results.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model_run.h"
#include "results.h"

namespace conformance {

struct FileOutcome {
    std::string path;
    std::string name;
    std::vector<ModelResult> results;  // one per model the file allows
    std::vector<Failure> failures;
    bool outOfScope = false;  // the file allows none of 2.0, 3.0, 4.0, 5.0
    std::string error;        // the file could not be parsed, or a child died where no rerun helps
};

struct PoolOptions {
    int jobs = 2;
    int timeoutSeconds = 300;  // per (file, model) child
};

// Runs every file; `done` is called in the parent as each file finishes (in completion order).
// `run.markerFd` and `run.crashLines` are set per child.
void runFiles(const std::vector<std::string>& paths, const RunOptions& run, const PoolOptions& pool,
              const std::function<void(const FileOutcome&)>& done);

}  // namespace conformance
