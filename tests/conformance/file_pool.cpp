// Child processes per (file, shader model), rerun past crashes (see file_pool.h).
#include "file_pool.h"

#include "session_choice.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <iostream>
#include <map>

namespace conformance {

namespace {

constexpr int kMaxCrashesPerRun = 40;  // reruns of one (file, model) past crashing lines

struct Job {
    std::string path;
    std::string name;
    int model = 0;
    std::set<int> crashLines;
    std::vector<Failure> crashFailures;  // one per crash line, with the signal
};

void writeLine(int fd, const std::string& line) {
    std::string text = line + "\n";
    const char* p = text.data();
    std::size_t left = text.size();
    while (left) {
        ssize_t n = ::write(fd, p, left);
        if (n <= 0) return;
        p += n;
        left -= std::size_t(n);
    }
}

// In the child: the file at one model; "F" lines for failures, then one "R" line.
[[noreturn]] void childMain(const Job& job, RunOptions run, int fd) {
    int status = 0;
    try {
        ShaderTestFile file = parseShaderTestFile(job.path);
        // Its own folder for the section files: children running other models of the same file
        // write files of the same names.
        // A pid the system reused during a long run finds an earlier child's folder: a suffix then.
        std::string base = run.tempDir + "/" + std::to_string(::getpid());
        run.tempDir = base;
        for (int k = 1; ::mkdir(run.tempDir.c_str(), 0700) != 0; ++k) {
            if (errno != EEXIST || k > 100) throw std::runtime_error("cannot make " + run.tempDir);
            run.tempDir = base + "-" + std::to_string(k);
        }
        run.markerFd = fd;
        run.crashLines = job.crashLines;
        ModelOutcome outcome = runModel(file, job.model, run);
        for (const Failure& f : outcome.failures) writeLine(fd, "F\t" + f.encode());
        writeLine(fd, "R\t" + outcome.result.encode());
    } catch (const std::exception& e) {
        writeLine(fd, std::string("E\t") + e.what());
        status = 1;
    }
    std::cout.flush();
    ::_exit(status);
}

struct Child {
    Job job;
    pid_t pid = -1;
    int fd = -1;
    std::string buffer;
    int lastMarker = 0;
    bool haveResult = false;
    ModelResult result;
    std::vector<Failure> failures;
    std::string error;
    std::chrono::steady_clock::time_point started;
};

void consumeLine(Child& c, const std::string& line) {
    if (line.rfind("M\t", 0) == 0) c.lastMarker = std::stoi(line.substr(2));
    else if (line.rfind("F\t", 0) == 0) c.failures.push_back(Failure::decode(line.substr(2)));
    else if (line.rfind("R\t", 0) == 0) { c.result = ModelResult::decode(line.substr(2)); c.haveResult = true; }
    else if (line.rfind("E\t", 0) == 0) c.error = line.substr(2);
}

void drain(Child& c) {
    char buf[65536];
    ssize_t n;
    while ((n = ::read(c.fd, buf, sizeof buf)) > 0) c.buffer.append(buf, std::size_t(n));
    std::size_t nl;
    while ((nl = c.buffer.find('\n')) != std::string::npos) {
        consumeLine(c, c.buffer.substr(0, nl));
        c.buffer.erase(0, nl + 1);
    }
}

Child start(const Job& job, const RunOptions& run) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::cout.flush();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        ::close(fds[0]);
        childMain(job, run, fds[1]);
    }
    ::close(fds[1]);
    ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
    Child c;
    c.job = job;
    c.pid = pid;
    c.fd = fds[0];
    c.started = std::chrono::steady_clock::now();
    return c;
}

// Why the child ended badly ("" when it exited normally with a result).
std::string reap(Child& c) {
    drain(c);
    ::close(c.fd);
    int status = 0;
    ::waitpid(c.pid, &status, 0);
    if (WIFSIGNALED(status))
        return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    if (!c.haveResult) return c.error.empty() ? "exited without a result" : c.error;
    return "";
}

std::string fileNameOf(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
    if (name.ends_with(".shader_test")) name.resize(name.size() - 12);
    return name;
}

// The jobs of every file (one per model it allows); files allowing none are out of scope.
std::deque<Job> jobsFor(const std::vector<std::string>& paths, std::map<std::string, FileOutcome>& files) {
    std::deque<Job> jobs;
    for (const std::string& path : paths) {
        FileOutcome& f = files[path];
        f.path = path;
        f.name = fileNameOf(path);
        try {
            ShaderTestFile file = parseShaderTestFile(path);
            for (int model : kModels)
                if (fileAllowsModel(file, model)) jobs.push_back(Job{path, f.name, model, {}, {}});
            f.outOfScope = jobs.empty() || jobs.back().path != path;
        } catch (const std::exception& e) {
            f.error = e.what();
        }
    }
    return jobs;
}

// A finished child: its result, or a rerun past the line it crashed on.
void settle(Child& c, std::deque<Job>& jobs, std::map<std::string, FileOutcome>& files) {
    std::string why = reap(c);
    FileOutcome& f = files[c.job.path];
    if (why.empty()) {
        for (const Failure& x : c.job.crashFailures) c.failures.push_back(x);
        f.results.push_back(c.result);
        f.failures.insert(f.failures.end(), c.failures.begin(), c.failures.end());
        return;
    }
    bool canRerun = c.lastMarker > 0 && !c.job.crashLines.count(c.lastMarker) &&
                    int(c.job.crashLines.size()) < kMaxCrashesPerRun;
    if (canRerun) {
        Job again = c.job;
        again.crashLines.insert(c.lastMarker);
        again.crashFailures.push_back({c.job.name, c.job.model, c.lastMarker, "crash", why});
        jobs.push_front(again);
        return;
    }
    ModelResult crashed;
    crashed.file = c.job.name;
    crashed.model = c.job.model;
    crashed.crashed = int(c.job.crashLines.size()) + 1;
    f.results.push_back(crashed);
    f.failures.push_back({c.job.name, c.job.model, c.lastMarker, "crash", why + " (no rerun possible)"});
    f.error = why;
}

}  // namespace

void runFiles(const std::vector<std::string>& paths, const RunOptions& run, const PoolOptions& pool,
              const std::function<void(const FileOutcome&)>& done) {
    std::map<std::string, FileOutcome> files;
    std::deque<Job> jobs = jobsFor(paths, files);
    std::map<std::string, int> pendingJobs;
    for (const Job& j : jobs) ++pendingJobs[j.path];
    for (auto& [path, f] : files)
        if (!pendingJobs.count(path)) done(f);
    std::vector<Child> running;
    while (!jobs.empty() || !running.empty()) {
        while (!jobs.empty() && int(running.size()) < std::max(1, pool.jobs)) {
            running.push_back(start(jobs.front(), run));
            jobs.pop_front();
        }
        std::vector<pollfd> fds;
        for (const Child& c : running) fds.push_back({c.fd, POLLIN, 0});
        ::poll(fds.data(), fds.size(), 1000);
        for (std::size_t i = running.size(); i-- > 0;) {
            Child& c = running[i];
            bool ended = fds[i].revents & (POLLHUP | POLLERR);
            if (fds[i].revents & POLLIN) drain(c);
            if (!ended && std::chrono::steady_clock::now() - c.started > std::chrono::seconds(pool.timeoutSeconds)) {
                ::kill(c.pid, SIGKILL);
                ended = true;
            }
            if (!ended) continue;
            std::size_t before = jobs.size();
            settle(c, jobs, files);
            if (jobs.size() == before && --pendingJobs[c.job.path] == 0) done(files[c.job.path]);
            running.erase(running.begin() + std::ptrdiff_t(i));
        }
    }
}

}  // namespace conformance
