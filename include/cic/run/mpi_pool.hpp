#pragma once
// MPI evaluation ranks (docs/mpi.md): `mpirun -np N cic --settings F` runs the
// evolution on rank 0 and evaluation jobs on ranks 1..N-1, which may sit on
// other machines. Only built with CIC_HAVE_MPI (CMake option CIC_WITH_MPI).
//
// Messages on MPI_COMM_WORLD, all text (MPI_CHAR):
//   rank 0 -> k  kTagSettings  effective settings XML; k answers kTagReady
//   k -> 0       kTagReady     "O" or "E" + why the settings cannot be used there
//   rank 0 -> k  kTagJob       a job (first line = kind, see worker_jobs.hpp)
//   k -> 0       kTagReply     "O" + reply, or "E" + the handler's error
//   rank 0 -> k  kTagStop      empty; k leaves its loop and finalises
#ifdef CIC_HAVE_MPI

#include <string>
#include <vector>

#include "cic/core/job_runner.hpp"

namespace cic::run {

// What the launcher says in the environment, without touching MPI:
// the world size from OMPI_COMM_WORLD_SIZE or PMI_SIZE; -1 when only PMIX_RANK
// is set (a launcher, size unknown until MPI_Init); 0 when not under a launcher.
int mpi_launch_size();

// Size of MPI_COMM_WORLD when MPI is initialised (and not finalised), else 1.
int mpi_world_size();

// MPI for one `cic` process. The constructor calls MPI_Init_thread; the
// destructor, on rank 0, tells every other rank to stop, then (on all ranks)
// calls MPI_Finalize. Only one per process.
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }

    // Ranks > 0: serve rank 0's settings and jobs until it says stop. Writes no
    // files. Returns the process exit code (0).
    int serve();

private:
    int rank_ = 0;
    int size_ = 1;
};

// Rank 0's side: hands jobs to ranks 1..size-1, one job per rank at a time, in
// job order; results come back in job order, so a run gives the same bits as
// with one worker. No timeout and no retry: a rank that dies ends the whole MPI
// job (MPI's default error handler), see docs/mpi.md.
class MpiPool final : public JobRunner {
public:
    // Sends the effective settings to every worker rank and waits until each
    // has checked them (read, validated, robot file loaded). Throws
    // cic::InputError naming the rank and host when one cannot use them, and
    // std::logic_error when called on a rank other than 0 or with size < 2.
    explicit MpiPool(const std::string& settings_text);

    std::vector<JobResult> run(const std::vector<std::string>& jobs) override;
    int workers() const override { return size_ - 1; }

private:
    int size_ = 1;
};

} // namespace cic::run

#endif // CIC_HAVE_MPI
