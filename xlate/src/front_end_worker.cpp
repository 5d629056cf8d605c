// fork + pipe + setrlimit: the worker writes framed records ('P' progress, 'R' result, 'M' out of
// memory) to a pipe; the parent reads them until the pipe closes and then reaps the child.
#include "front_end_worker.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

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

WorkerOutcome runInWorker(const std::function<std::string()>& work, const WorkerLimits& limits) {
    WorkerOutcome out;
    int fds[2];
    if (::pipe(fds) != 0) {
        out.payload = work();
        return out;
    }
    std::fflush(nullptr);  // nothing buffered is written twice
    pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        out.payload = work();
        return out;
    }
    if (pid == 0) {
        ::close(fds[0]);
        // A crash must end the worker with its signal, whatever handlers the host (or a sanitizer,
        // which would report and exit with a status instead) installed in the parent.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, SIG_DFL);
        workerMain(fds[1], work, limits);
    }
    ::close(fds[1]);
    // Read records until the child closes the pipe (it exits), with a wall-clock limit as well:
    // CPU time does not pass while a worker waits (a lock held by a thread that fork left behind).
    std::string bytes;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limits.cpuSeconds * 4 + 10);
    bool timedOut = false;
    char buf[65536];
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            timedOut = true;
            ::kill(pid, SIGKILL);
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buf, static_cast<size_t>(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    bool gotResult = false, outOfMemory = false;
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
    if (gotResult && !timedOut && WIFEXITED(status) && WEXITSTATUS(status) == 0) return out;
    if (outOfMemory) out.kind = WorkerOutcome::Kind::OutOfMemory;
    // SIGKILL is ours only when the wall-clock limit sent it; otherwise the OOM killer or a user.
    else if (timedOut || (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU))
        out.kind = WorkerOutcome::Kind::TimedOut;
    else out.kind = WorkerOutcome::Kind::Crashed;
    out.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return out;
}

}  // namespace fxport::xlate
