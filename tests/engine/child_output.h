#pragma once
// A function run in a forked child whose output the parent collects: for the tests of what a
// process says under other limits or rights (a file size limit, without root). Used by the
// engine tests and the command-line tests (tests/cli).
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

namespace grainlab::test {

struct ChildOutput {
    int status = -1;    ///< the child's wait status; -1 when no pipe or no child was made
    std::string output; ///< all that the child wrote to its end of the pipe
};

/// Runs `child(fd)` in a forked process, `fd` the write end of a pipe (the child ends the
/// process itself, by exec or _exit); collects what comes down the pipe until the child is gone
/// and waits for it.
template <class Child>
ChildOutput childOutput(Child child) {
    ChildOutput r;
    int fds[2];
    if (::pipe(fds) != 0) {
        ADD_FAILURE() << "pipe() failed: no child started";
        return r;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1]);
        ::_exit(127);
    }
    ::close(fds[1]);
    if (pid < 0) {
        ::close(fds[0]);
        ADD_FAILURE() << "fork() failed: no child started";
        return r;
    }
    char buffer[512];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) {
        r.output.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    ::waitpid(pid, &r.status, 0);
    return r;
}

} // namespace grainlab::test
