#include "common/process_pool.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <map>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(const timeval& t) {
    return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
}

/// Starts `job` with its output appended to its log; returns the child's pid.
pid_t start(const PoolJob& job) {
    const int log = ::open(job.logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (log < 0) {
        throw std::runtime_error(
            fmt::format("{}: cannot open the log file: {}", job.logPath, std::strerror(errno)));
    }
    std::vector<char*> argv;
    for (const std::string& a : job.argv) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    const pid_t pool = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        ::close(log);
        throw std::runtime_error(fmt::format("cannot start a process: {}", std::strerror(e)));
    }
    if (pid == 0) {
        // The child: its own process group, so that a Ctrl-C at the terminal reaches the pool
        // only, and the pool decides what the runs get.
        ::setpgid(0, 0);
        // A run ends with its pool: a killed pool (kill -9) would otherwise leave the run going
        // as an orphan that still holds its run folder's lock and log. SIGTERM lets the run stop
        // at a step as on Ctrl-C. The signal is sent when the forking thread ends, so the pool
        // must be run from a thread that lives as long as its runs (ProcessPool::run blocks).
        // If the pool died before the prctl took effect, getppid() is no longer the pool's pid.
        if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != pool) {
            ::_exit(128 + SIGTERM);
        }
        ::dup2(log, STDOUT_FILENO);
        ::dup2(log, STDERR_FILENO);
        const int devnull = ::open("/dev/null", O_RDONLY);
        if (devnull >= 0) {
            ::dup2(devnull, STDIN_FILENO);
        }
        ::execv(argv[0], argv.data());
        const std::string message =
            fmt::format("cannot run {}: {}\n", job.argv.front(), std::strerror(errno));
        [[maybe_unused]] const auto written =
            ::write(STDERR_FILENO, message.data(), message.size());
        ::_exit(127);
    }
    ::close(log);
    return pid;
}

} // namespace

ProcessPool::ProcessPool(int maxJobs, int maxThreads)
    : maxJobs_(maxJobs < 1 ? 1 : maxJobs), maxThreads_(maxThreads < 1 ? 1 : maxThreads) {}

std::vector<PoolResult> ProcessPool::run(const std::vector<PoolJob>& jobs, const OnDone& onDone,
                                         const OnTick& onTick, const std::atomic<bool>* stop,
                                         double tick) {
    std::vector<PoolResult> results(jobs.size());
    struct Running {
        std::size_t job;
        Clock::time_point started;
    };
    std::map<pid_t, Running> running;
    std::size_t next = 0, ended = 0;
    int threads = 0; // of the running jobs
    bool stopping = false;
    auto lastTick = Clock::now();
    while (next < jobs.size() || !running.empty()) {
        if (!stopping && stop && stop->load()) {
            stopping = true;
            for (const auto& [pid, r] : running) {
                ::kill(pid, SIGINT);
            }
        }
        while (!stopping && next < jobs.size() && int(running.size()) < maxJobs_ &&
               (running.empty() || threads + jobs[next].threads <= maxThreads_)) {
            const pid_t pid = start(jobs[next]);
            threads += jobs[next].threads;
            results[next].started = true;
            running[pid] = {next, Clock::now()};
            ++next;
        }
        if (stopping && running.empty()) {
            break;
        }
        int status = 0;
        rusage usage{};
        const pid_t pid = ::wait4(-1, &status, WNOHANG, &usage);
        if (pid > 0) {
            const auto it = running.find(pid);
            if (it == running.end()) {
                continue; // not ours
            }
            PoolResult& r = results[it->second.job];
            r.wallSeconds =
                std::chrono::duration<double>(Clock::now() - it->second.started).count();
            r.cpuSeconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
            if (WIFEXITED(status)) {
                r.exitStatus = WEXITSTATUS(status);
            } else if (WIFSIGNALED(status)) {
                r.signal = WTERMSIG(status);
            }
            const std::size_t job = it->second.job;
            threads -= jobs[job].threads;
            running.erase(it);
            ++ended;
            if (onDone) {
                onDone(job, r);
            }
            continue;
        }
        if (pid < 0 && errno != EINTR && errno != ECHILD) {
            throw std::runtime_error(fmt::format("waiting for a run: {}", std::strerror(errno)));
        }
        const auto now = Clock::now();
        if (onTick && std::chrono::duration<double>(now - lastTick).count() >= tick) {
            onTick(ended, running.size());
            lastTick = now;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return results;
}

int processorCount() {
    const unsigned cores = std::thread::hardware_concurrency();
    return cores == 0 ? 1 : int(cores);
}

} // namespace grainlab
