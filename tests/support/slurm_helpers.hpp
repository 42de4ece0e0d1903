#pragma once
// What the Slurm tests share (tests/study/slurm_test.cpp, slurm_cluster_test.cpp):
// a shell command's output, waiting for a job name to leave the queue, and
// one Slurm test at a time.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace cic::testing {

// The standard output of `cmd`, run by the shell.
inline std::string shell(const std::string& cmd) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return out;
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    pclose(p);
    return out;
}

// Waits until no job named `name` is queued or running (at most `seconds`).
inline bool wait_for_jobs(const std::string& name, int seconds) {
    for (int i = 0; i < seconds * 2; ++i) {
        if (shell("squeue -h -n " + name + " 2>/dev/null").empty()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    return false;
}

// One Slurm test at a time (ctest -j runs test processes in parallel): they
// share the local cluster, whose job slots they count on, and one of them
// loses a node.
class SlurmTestLock {
public:
    SlurmTestLock() : fd_(::open("/tmp/cic-slurm-tests.lock", O_CREAT | O_RDWR | O_CLOEXEC, 0666)) {
        if (fd_ >= 0) ::flock(fd_, LOCK_EX);
    }
    ~SlurmTestLock() {
        if (fd_ >= 0) ::close(fd_);
    }
    SlurmTestLock(const SlurmTestLock&) = delete;
    SlurmTestLock& operator=(const SlurmTestLock&) = delete;

private:
    int fd_;
};

} // namespace cic::testing
