#pragma once
// One Slurm test at a time (ctest -j runs test processes in parallel): they
// share the local cluster, whose job slots they count on, and one of them
// loses a node (tests/study/slurm_cluster_test.cpp).
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace cic::testing {

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
