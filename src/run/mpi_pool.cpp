// MPI evaluation ranks: the session (init, worker loop, stop, finalise) and
// rank 0's pool. Protocol and limits in mpi_pool.hpp and docs/mpi.md.
#ifdef CIC_HAVE_MPI

#include "cic/run/mpi_pool.hpp"
#include "cic/io/experiment_types.hpp"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <thread>

#include "cic/run/worker_jobs.hpp"
#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::run {
namespace {

constexpr int kTagSettings = 1;
constexpr int kTagReady = 2;
constexpr int kTagJob = 3;
constexpr int kTagReply = 4;
constexpr int kTagStop = 5;

void send_text(const std::string& text, int to, int tag) {
    if (text.size() > static_cast<std::size_t>(INT_MAX))
        throw std::runtime_error("MPI message of " + std::to_string(text.size()) + " bytes is too long");
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

// MPI_Probe, without its busy wait: Open MPI spins a core while blocked, which
// would take CPU from the worker ranks sharing rank 0's machine, and from
// everything else while ranks idle (symbolic regression, or between
// generations). Polling with a short back-off costs at most ~2 ms per message.
MPI_Status probe(int source, int tag) {
    auto pause = std::chrono::microseconds(20);
    for (;;) {
        int found = 0;
        MPI_Status st;
        MPI_Iprobe(source, tag, MPI_COMM_WORLD, &found, &st);
        if (found) return st;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(2000));
    }
}

// Receives the message probe found (any size); returns its text.
std::string receive_text(const MPI_Status& probed) {
    int n = 0;
    MPI_Get_count(&probed, MPI_CHAR, &n);
    std::string text(static_cast<std::size_t>(n), '\0');
    MPI_Recv(text.data(), n, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return text;
}

std::string host_name() {
    char name[MPI_MAX_PROCESSOR_NAME];
    int n = 0;
    MPI_Get_processor_name(name, &n);
    return std::string(name, static_cast<std::size_t>(n));
}

// A worker rank's check of the settings before any job: everything a job would
// need (valid settings; for HyperGP, the robot file at the same path).
void check_settings(const std::string& text) {
    const io::Settings s = io::read_settings_string(text, "settings from rank 0");
    if (io::walks_a_robot(s) && io::genotype_form(s) == io::GenotypeForm::Trees) (void)hypergp::Model::from_settings(s);
}

int env_int(const char* name) {
    const char* v = std::getenv(name);
    return v && *v ? std::atoi(v) : 0;
}

} // namespace

int mpi_launch_size() {
    if (const int n = env_int("OMPI_COMM_WORLD_SIZE")) return n;
    if (const int n = env_int("PMI_SIZE")) return n;
    if (std::getenv("PMIX_RANK")) return -1;
    return 0;
}

int mpi_world_size() {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (!initialised || finalised) return 1;
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

MpiSession::MpiSession() {
    // All MPI calls come from the main thread, one at a time (the evolution
    // loop evaluates there); SERIALIZED leaves room for other threads to exist.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    if (rank_ == 0)
        for (int r = 1; r < size_; ++r) MPI_Send(nullptr, 0, MPI_CHAR, r, kTagStop, MPI_COMM_WORLD);
    MPI_Finalize();
}

int MpiSession::serve() {
    std::map<std::string, JobHandler> kinds = make_worker_job_kinds(WorkerContext{});
    for (;;) {
        const MPI_Status st = probe(0, MPI_ANY_TAG);
        std::string text = receive_text(st);
        if (st.MPI_TAG == kTagStop) return 0;
        if (st.MPI_TAG == kTagSettings) {
            std::string ready = "O";
            try {
                check_settings(text);
                WorkerContext context;
                context.settings_text = std::move(text);
                kinds = make_worker_job_kinds(context);
            } catch (const std::exception& e) {
                ready = "E(" + host_name() + ") " + e.what();
            }
            send_text(ready, 0, kTagReady);
            continue;
        }
        if (st.MPI_TAG != kTagJob) {
            std::cerr << "cic: MPI rank " << rank_ << ": unexpected message tag " << st.MPI_TAG << '\n';
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        std::string reply;
        try {
            reply = "O" + dispatch_worker_job(kinds, text);
        } catch (const std::exception& e) {
            reply = std::string("E") + e.what();
        } catch (...) {
            reply = "Eunknown exception";
        }
        send_text(reply, 0, kTagReply);
    }
}

MpiPool::MpiPool(const std::string& settings_text) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (rank != 0) throw std::logic_error("MpiPool: only rank 0 hands out jobs");
    if (size_ < 2) throw std::logic_error("MpiPool: needs at least 2 MPI ranks");
    for (int r = 1; r < size_; ++r) send_text(settings_text, r, kTagSettings);
    std::string problems;
    for (int r = 1; r < size_; ++r) {
        const MPI_Status st = probe(MPI_ANY_SOURCE, kTagReady);
        const std::string ready = receive_text(st);
        if (ready.empty() || ready[0] != 'O')
            problems += (problems.empty() ? "" : "; ") + std::string("MPI rank ") + std::to_string(st.MPI_SOURCE) +
                        ": " + (ready.empty() ? "empty answer" : ready.substr(1));
    }
    if (!problems.empty())
        throw InputError("worker ranks cannot use the settings (is every file at the same path on every machine?): " +
                         problems);
}

std::vector<JobResult> MpiPool::run(const std::vector<std::string>& jobs) {
    std::vector<JobResult> results(jobs.size());
    std::vector<long> busy(static_cast<std::size_t>(size_), -1);   // job index per rank, -1 = idle
    std::size_t next = 0, done = 0;
    while (done < jobs.size()) {
        for (int r = 1; r < size_ && next < jobs.size(); ++r) {
            if (busy[static_cast<std::size_t>(r)] >= 0) continue;
            send_text(jobs[next], r, kTagJob);
            busy[static_cast<std::size_t>(r)] = static_cast<long>(next);
            results[next].attempts = 1;
            ++next;
        }
        const MPI_Status st = probe(MPI_ANY_SOURCE, kTagReply);
        const std::string payload = receive_text(st);
        // The error text is the handler's, as with ProcessPool: it may land in
        // population.xml, which must not depend on where a job ran.
        long& job = busy[static_cast<std::size_t>(st.MPI_SOURCE)];
        if (job < 0) throw std::runtime_error("MPI rank " + std::to_string(st.MPI_SOURCE) + " replied without a job");
        JobResult& r = results[static_cast<std::size_t>(job)];
        r.ok = !payload.empty() && payload[0] == 'O';
        (r.ok ? r.output : r.error) = payload.empty() ? "empty reply" : payload.substr(1);
        job = -1;
        ++done;
    }
    return results;
}

} // namespace cic::run

#endif // CIC_HAVE_MPI
