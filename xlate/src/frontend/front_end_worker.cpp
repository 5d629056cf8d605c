// fork + pipe + setrlimit: the worker writes framed records ('P' progress, 'R' result, 'M' out of
// memory) to a pipe; the parent reads them until the pipe closes and then reaps the child. A pool
// polls the pipes of several workers at once.
#include "frontend/front_end_worker.h"

#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>

namespace fxport::xlate {

namespace {

int g_workerFd = -1;  // the pipe to the parent, in a worker only

void writeAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        data += n;
        size -= static_cast<size_t>(n);
    }
}

void writeRecord(char kind, std::string_view text) {
    if (g_workerFd < 0) return;
    char header[9];
    header[0] = kind;
    uint64_t n = text.size();
    std::memcpy(header + 1, &n, 8);
    writeAll(g_workerFd, header, sizeof header);
    writeAll(g_workerFd, text.data(), text.size());
}

// Says "out of memory" before the allocation failure unwinds (or aborts inside glslang).
void outOfMemory() {
    std::set_new_handler(nullptr);
    writeRecord('M', {});
    throw std::bad_alloc();
}

size_t currentAddressSpace() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmSize:") {
            size_t kb = 0;
            status >> kb;
            return kb * 1024;
        }
        status.ignore(1 << 20, '\n');
    }
    return 0;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

[[noreturn]] void workerMain(int fd, const std::function<std::string()>& work, const WorkerLimits& limits) {
    // A worker's own worker (shaders compiled in parallel) lets go of its parent's pipe, so that
    // the parent's end closes when the parent exits.
    if (g_workerFd >= 0) ::close(g_workerFd);
    g_workerFd = fd;
    rlimit cpu{static_cast<rlim_t>(limits.cpuSeconds), static_cast<rlim_t>(limits.cpuSeconds) + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    // The address space it may ADD to what the parent had mapped (a game's GL driver may have
    // reserved gigabytes already). ASan reserves terabytes of shadow up front and maps more as it
    // goes, so under ASan the limit is the CPU time alone.
    if (!kAddressSanitizer) {
        rlim_t as = static_cast<rlim_t>(currentAddressSpace() + limits.memoryBytes);
        rlimit mem{as, as};
        ::setrlimit(RLIMIT_AS, &mem);
    }
    rlimit noCore{0, 0};  // a crash here is expected and reported; no core files
    ::setrlimit(RLIMIT_CORE, &noCore);
    std::set_new_handler(outOfMemory);
    try {
        writeRecord('R', work());
    } catch (const std::bad_alloc&) {
        writeRecord('M', {});
    } catch (...) {
        // work() turns everything it expects into its payload; anything else is a crash.
        ::_exit(3);
    }
    ::_exit(0);
}

}  // namespace

WorkerLimits WorkerLimits::fromEnvironment() {
    WorkerLimits l;
    if (const char* s = std::getenv("FXPORT_WORKER_SECONDS"); s && std::atoi(s) > 0) l.cpuSeconds = std::atoi(s);
    if (const char* m = std::getenv("FXPORT_WORKER_MEMORY_MB"); m && std::atoll(m) > 0)
        l.memoryBytes = static_cast<size_t>(std::atoll(m)) << 20;
    return l;
}

void reportWorkerProgress(std::string_view where) { writeRecord('P', where); }

bool insideWorker() { return g_workerFd >= 0; }

// One forked worker: its pipe, what it has sent so far and its wall-clock deadline.
struct WorkerPool::Running {
    size_t id = 0;
    pid_t pid = -1;
    int fd = -1;
    std::string bytes;
    std::chrono::steady_clock::time_point deadline;
    bool timedOut = false;
};

namespace {

// Forks a worker for `work`; nullptr when pipe or fork failed.
std::unique_ptr<WorkerPool::Running> startWorker(const std::function<std::string()>& work, const WorkerLimits& limits) {
    int fds[2];
    if (::pipe(fds) != 0) return nullptr;
    std::fflush(nullptr);  // nothing buffered is written twice
    pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return nullptr;
    }
    if (pid == 0) {
        ::close(fds[0]);
        // A crash must end the worker with its signal, whatever handlers the host (or a sanitizer,
        // which would report and exit with a status instead) installed in the parent.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, SIG_DFL);
        workerMain(fds[1], work, limits);
    }
    ::close(fds[1]);
    auto w = std::make_unique<WorkerPool::Running>();
    w->pid = pid;
    w->fd = fds[0];
    // CPU time does not pass while a worker waits (a lock held by a thread that fork left behind):
    // a wall-clock limit as well.
    w->deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limits.cpuSeconds * 4 + 10);
    return w;
}

// Reaps a worker whose pipe closed (or that was killed) and decodes its records.
WorkerOutcome finishWorker(WorkerPool::Running& w) {
    ::close(w.fd);
    int status = 0;
    while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
    WorkerOutcome out;
    bool gotResult = false, outOfMemory = false;
    const std::string& bytes = w.bytes;
    for (size_t at = 0; at + 9 <= bytes.size();) {
        char kind = bytes[at];
        uint64_t n = 0;
        std::memcpy(&n, bytes.data() + at + 1, 8);
        if (n > bytes.size() - at - 9) break;  // cut short by the crash
        std::string text = bytes.substr(at + 9, n);
        at += 9 + n;
        if (kind == 'P') out.progress = std::move(text);
        else if (kind == 'M') outOfMemory = true;
        else if (kind == 'R') out.payload = std::move(text), gotResult = true;
    }
    if (gotResult && !w.timedOut && WIFEXITED(status) && WEXITSTATUS(status) == 0) return out;
    if (outOfMemory) out.kind = WorkerOutcome::Kind::OutOfMemory;
    // SIGKILL is ours only when the wall-clock limit sent it; otherwise the OOM killer or a user.
    else if (w.timedOut || (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU))
        out.kind = WorkerOutcome::Kind::TimedOut;
    else out.kind = WorkerOutcome::Kind::Crashed;
    out.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return out;
}

}  // namespace

WorkerOutcome runInWorker(const std::function<std::string()>& work, const WorkerLimits& limits) {
    WorkerPool pool(limits, 1);
    pool.submit(0, work);
    return pool.next()->second;
}

int workerJobs() {
    if (const char* j = std::getenv("FXPORT_JOBS"); j && std::atoi(j) > 0) return std::min(std::atoi(j), 256);
    cpu_set_t set;
    if (::sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
    long n = ::sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? static_cast<int>(n) : 1;
}

WorkerPool::WorkerPool(const WorkerLimits& limits, int jobs) : limits_(limits), jobs_(std::max(jobs, 1)) {}

WorkerPool::~WorkerPool() {
    for (auto& w : running_) {
        ::kill(w->pid, SIGKILL);
        (void)finishWorker(*w);
    }
}

void WorkerPool::submit(size_t id, std::function<std::string()> work) {
    queued_.emplace_back(id, std::move(work));
    startQueued();
}

void WorkerPool::startQueued() {
    while (!queued_.empty() && static_cast<int>(running_.size()) < jobs_) {
        auto [id, work] = std::move(queued_.front());
        queued_.pop_front();
        if (auto w = startWorker(work, limits_)) {
            w->id = id;
            running_.push_back(std::move(w));
        } else {
            WorkerOutcome here;  // no process to spare: run it here, as before the worker existed
            here.payload = work();
            finished_.emplace_back(id, std::move(here));
        }
    }
}

std::optional<std::pair<size_t, WorkerOutcome>> WorkerPool::next() {
    char buf[65536];
    while (finished_.empty() && !running_.empty()) {
        auto now = std::chrono::steady_clock::now();
        long long wait = 1000;
        std::vector<pollfd> fds;
        for (auto& w : running_) {
            long long left = std::chrono::duration_cast<std::chrono::milliseconds>(w->deadline - now).count();
            if (left <= 0 && !w->timedOut) {
                w->timedOut = true;
                ::kill(w->pid, SIGKILL);  // its pipe closes: read below
            }
            if (!w->timedOut) wait = std::max(0LL, std::min(wait, left));
            fds.push_back({w->fd, POLLIN, 0});
        }
        int r = ::poll(fds.data(), fds.size(), static_cast<int>(wait));
        if (r <= 0) continue;  // EINTR or a deadline to check
        for (size_t i = 0; i < fds.size(); ++i) {
            if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            Running& w = *running_[i];
            ssize_t n = ::read(w.fd, buf, sizeof buf);
            if (n < 0 && errno == EINTR) continue;
            if (n > 0) {
                w.bytes.append(buf, static_cast<size_t>(n));
                continue;
            }
            finished_.emplace_back(w.id, finishWorker(w));  // the pipe closed: the worker exited
            running_[i].reset();
        }
        running_.erase(std::remove(running_.begin(), running_.end(), nullptr), running_.end());
        startQueued();
    }
    if (finished_.empty()) return std::nullopt;
    auto done = std::move(finished_.front());
    finished_.pop_front();
    return done;
}

}  // namespace fxport::xlate
