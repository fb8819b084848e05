#pragma once
/// A process id that names no running process: for tests of the clean-up of files and folders
/// that dead runs leave behind, named after their process.
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace freestand::test {

/// The id of a process that has exited and been reaped.
inline pid_t dead_pid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    return pid;
}

}  // namespace freestand::test
