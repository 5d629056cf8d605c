// Runs the HLSL front end (glslang's preprocessor and compiler, spirv-opt, SPIRV-Cross) in a forked
// worker process with CPU-time and memory limits, so that no effect can crash or exhaust the
// process that asked for the compile (`fxport check`, a game's `Effect(...)`). glslang 12 crashes
// on some malformed HLSL (front_end_hazards.h catches the shapes known so far) and has no bounds on
// macro expansion; in the worker, either is a diagnostic. A cache hit never starts a worker.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fxport::xlate {

struct WorkerLimits {
    int cpuSeconds = 60;                           // RLIMIT_CPU of the worker ($FXPORT_WORKER_SECONDS)
    size_t memoryBytes = size_t{3} << 30;          // address space it may add ($FXPORT_WORKER_MEMORY_MB)
    static WorkerLimits fromEnvironment();
};

struct WorkerOutcome {
    enum class Kind {
        Done,         // the work returned: `payload` is what it returned
        Crashed,      // died of a signal (`signal`)
        TimedOut,     // ran past the CPU or wall-clock limit
        OutOfMemory,  // an allocation failed past the memory limit
    } kind = Kind::Done;
    std::string payload;
    std::string progress;  // the last reportWorkerProgress() text: where the worker was
    int signal = 0;
};

// Runs `work` in a child process (fork) and returns what it returned, or how it failed.
// Falls back to running `work` here when fork fails.
WorkerOutcome runInWorker(const std::function<std::string()>& work, const WorkerLimits& limits);

// How many workers run at once: $FXPORT_JOBS, else the CPUs this process may run on.
int workerJobs();

// Several workers at once, each with its own limits (a worker's limits are its own: a slow one
// does not shorten another's time). All are forked from the thread that uses the pool, which
// waits for them with poll(); nothing runs on other threads.
//   WorkerPool pool(limits, workerJobs());
//   pool.submit(0, work0); pool.submit(1, work1);
//   while (auto done = pool.next()) use(done->first, done->second);
class WorkerPool {
public:
    WorkerPool(const WorkerLimits& limits, int jobs);
    ~WorkerPool();  // kills and reaps the workers still running (an exception left the caller)
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // Starts `work` now if fewer than `jobs` run, else when one finishes. `id` comes back with it.
    void submit(size_t id, std::function<std::string()> work);
    // Waits for the next worker to finish: its id and outcome. nullopt when none runs or waits.
    std::optional<std::pair<size_t, WorkerOutcome>> next();

    struct Running;

private:
    void startQueued();
    WorkerLimits limits_;
    int jobs_;
    std::deque<std::pair<size_t, std::function<std::string()>>> queued_;
    std::vector<std::unique_ptr<Running>> running_;
    std::deque<std::pair<size_t, WorkerOutcome>> finished_;  // ran here: fork failed
};

// True in a worker process (a compile there runs in it, never in a worker of its own).
bool insideWorker();

// Inside a worker: records what it is about to do (the last record before a crash says where).
// Outside a worker: does nothing.
void reportWorkerProgress(std::string_view where);

}  // namespace fxport::xlate
