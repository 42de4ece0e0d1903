// Worker processes over socket pairs (one bidirectional pipe per worker).
// Frame = 8-byte little-endian length + payload. A reply payload starts with
// 'O' (ok) or 'E' (the handler threw; the rest is the message).
#include "cic/core/process_pool.hpp"
#include "cic/core/error.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <deque>
#include <utility>
#include <stdexcept>
#include <thread>

#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cic {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint64_t kMaxFrame = std::uint64_t{1} << 32;

bool write_all(int fd, const char* p, std::size_t n) {
    while (n > 0) {
        // send() with MSG_NOSIGNAL: a dead peer gives EPIPE, not SIGPIPE. Falls
        // back to write() when fd is not a socket (a worker on plain pipes).
        ssize_t k = ::send(fd, p, n, MSG_NOSIGNAL);
        if (k < 0 && errno == ENOTSOCK) k = ::write(fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        p += k;
        n -= static_cast<std::size_t>(k);
    }
    return true;
}

bool write_frame(int fd, const std::string& payload) {
    char len[8];
    std::uint64_t n = payload.size();
    for (int i = 0; i < 8; ++i) len[i] = static_cast<char>((n >> (8 * i)) & 0xff);
    return write_all(fd, len, 8) && write_all(fd, payload.data(), payload.size());
}

// Blocking read of exactly n bytes: 1 = ok, 0 = clean EOF before any byte, -1 = error/short.
int read_exact(int fd, char* p, std::size_t n) {
    std::size_t got = 0;
    while (got < n) {
        ssize_t k = ::read(fd, p + got, n - got);
        if (k < 0 && errno == EINTR) continue;
        if (k < 0) return -1;
        if (k == 0) return got == 0 ? 0 : -1;
        got += static_cast<std::size_t>(k);
    }
    return 1;
}

// Parses a complete frame from the front of buf, if there is one.
bool take_frame(std::string& buf, std::string& payload) {
    if (buf.size() < 8) return false;
    std::uint64_t n = 0;
    for (int i = 0; i < 8; ++i) n |= std::uint64_t(static_cast<unsigned char>(buf[static_cast<std::size_t>(i)])) << (8 * i);
    if (buf.size() < 8 + n) return false;
    payload = buf.substr(8, n);
    buf.erase(0, 8 + n);
    return true;
}

struct Worker {
    pid_t pid = -1;
    int fd = -1;          // our end of the socket pair
    long job = -1;        // job index being run, -1 = idle
    Clock::time_point started;
    std::string inbox;
};

} // namespace

struct ProcessPool::Impl {
    PoolOptions opt;
    std::vector<Worker> workers;
    int restarts = 0;
    std::vector<std::string> notes;   // trouble with no job to pin it on

    void spawn(Worker& w) {
        int sv[2];
        if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
            throw std::runtime_error(std::string("ProcessPool: socketpair: ") + std::strerror(errno));
        std::vector<char*> argv;
        for (const std::string& a : opt.argv) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        const pid_t pid = ::fork();
        if (pid < 0) {
            ::close(sv[0]);
            ::close(sv[1]);
            throw std::runtime_error(std::string("ProcessPool: fork: ") + std::strerror(errno));
        }
        if (pid == 0) {   // child: only async-signal-safe calls until exec
            // Ctrl-C reaches the whole process group, and a batch scheduler's SIGTERM
            // every process of the job; the parent decides when the run stops and
            // ends its workers, so they ignore both (SIG_IGN survives exec).
            ::signal(SIGINT, SIG_IGN);
            ::signal(SIGTERM, SIG_IGN);
            ::dup2(sv[1], 0);
            ::dup2(sv[1], 1);
            ::execv(argv[0], argv.data());
            ::_exit(127);
        }
        ::close(sv[1]);
        w = Worker{};
        w.pid = pid;
        w.fd = sv[0];
    }

    static void end(Worker& w, bool force) {
        if (w.fd >= 0) ::close(w.fd);
        w.fd = -1;
        if (w.pid <= 0) return;
        if (force) ::kill(w.pid, SIGKILL);
        // Closing the socket ends an idle worker; give it a moment, then insist.
        for (int i = 0; i < 60; ++i) {
            pid_t r = ::waitpid(w.pid, nullptr, WNOHANG);
            if (r == w.pid || (r < 0 && errno != EINTR)) { w.pid = -1; return; }
            std::this_thread::sleep_for(std::chrono::milliseconds(i < 20 ? 1 : 10));
        }
        ::kill(w.pid, SIGKILL);
        while (::waitpid(w.pid, nullptr, 0) < 0 && errno == EINTR) {}
        w.pid = -1;
    }

    void replace(Worker& w) {
        end(w, true);
        spawn(w);
        ++restarts;
    }
};

ProcessPool::ProcessPool(PoolOptions options) : impl_(new Impl) {
    impl_->opt = std::move(options);
    const PoolOptions& o = impl_->opt;
    try {
        if (o.workers < 1) throw std::invalid_argument("ProcessPool: workers must be >= 1");
        if (o.argv.empty()) throw std::invalid_argument("ProcessPool: empty worker command");
        if (!(o.timeout_seconds > 0)) throw std::invalid_argument("ProcessPool: timeout must be > 0");
        if (o.retries < 0) throw std::invalid_argument("ProcessPool: retries must be >= 0");
        if (::access(o.argv[0].c_str(), X_OK) != 0)
            throw std::runtime_error("ProcessPool: cannot execute worker '" + o.argv[0] + "'");
        impl_->workers.resize(static_cast<std::size_t>(o.workers));
        for (Worker& w : impl_->workers) impl_->spawn(w);
    } catch (...) {
        for (Worker& w : impl_->workers) Impl::end(w, true);
        delete impl_;
        throw;
    }
}

ProcessPool::~ProcessPool() {
    for (Worker& w : impl_->workers) Impl::end(w, w.job >= 0);
    delete impl_;
}

int ProcessPool::workers() const { return static_cast<int>(impl_->workers.size()); }
int ProcessPool::restarts() const { return impl_->restarts; }

std::vector<std::string> ProcessPool::take_notes() { return std::exchange(impl_->notes, {}); }

std::vector<int> ProcessPool::pids() const {
    std::vector<int> out;
    for (const Worker& w : impl_->workers) out.push_back(static_cast<int>(w.pid));
    return out;
}

std::vector<JobResult> ProcessPool::run(const std::vector<std::string>& jobs) {
    Impl& im = *impl_;
    std::vector<JobResult> results(jobs.size());
    std::deque<long> pending;
    for (std::size_t i = 0; i < jobs.size(); ++i) pending.push_back(static_cast<long>(i));
    std::size_t done = 0;
    const auto timeout = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(im.opt.timeout_seconds));

    // A job's attempt ended badly: retry it at the front of the queue, or give up.
    auto lost = [&](Worker& w, const std::string& why) {
        const long j = w.job;
        w.job = -1;
        im.replace(w);
        if (j < 0) {
            im.notes.push_back(why + "; worker replaced");
            return;
        }
        JobResult& r = results[static_cast<std::size_t>(j)];
        r.trouble.push_back("attempt " + std::to_string(r.attempts) + ": " + why + "; worker replaced");
        if (r.attempts <= im.opt.retries) {
            pending.push_front(j);
        } else {
            r.ok = false;
            r.error = why + " (after " + std::to_string(r.attempts) + " attempts)";
            ++done;
        }
    };

    // Workers ended by an interrupt come back for the next batch.
    for (Worker& w : im.workers)
        if (w.pid <= 0) im.spawn(w);
    while (done < jobs.size()) {
        if (im.opt.interrupted && im.opt.interrupted()) {
            for (Worker& w : im.workers) {
                Impl::end(w, true);
                w.job = -1;
            }
            throw Interrupted();
        }
        for (Worker& w : im.workers) {
            if (w.job >= 0 || pending.empty()) continue;
            const long j = pending.front();
            pending.pop_front();
            w.job = j;
            w.started = Clock::now();
            ++results[static_cast<std::size_t>(j)].attempts;
            if (!write_frame(w.fd, jobs[static_cast<std::size_t>(j)])) lost(w, "worker died before taking the job");
        }

        std::vector<pollfd> fds;
        for (const Worker& w : im.workers) fds.push_back({w.fd, POLLIN, 0});
        auto wait = std::chrono::milliseconds(im.opt.interrupted ? 50 : 1000);
        const auto now = Clock::now();
        for (const Worker& w : im.workers)
            if (w.job >= 0) {
                auto left = std::chrono::duration_cast<std::chrono::milliseconds>(w.started + timeout - now);
                wait = std::min(wait, std::max(left + std::chrono::milliseconds(1), std::chrono::milliseconds(0)));
            }
        const int n = ::poll(fds.data(), fds.size(), static_cast<int>(wait.count()));
        if (n < 0 && errno != EINTR) throw std::runtime_error(std::string("ProcessPool: poll: ") + std::strerror(errno));

        for (std::size_t i = 0; i < im.workers.size(); ++i) {
            Worker& w = im.workers[i];
            if (n > 0 && (fds[i].revents & (POLLIN | POLLHUP | POLLERR))) {
                char buf[65536];
                ssize_t k = ::read(w.fd, buf, sizeof buf);
                if (k < 0 && errno == EINTR) continue;
                if (k <= 0) {   // EOF or error: the worker is gone (crashed or killed)
                    lost(w, "worker process ended unexpectedly");
                    continue;
                }
                w.inbox.append(buf, static_cast<std::size_t>(k));
                std::string payload;
                if (w.job >= 0 && take_frame(w.inbox, payload)) {
                    JobResult& r = results[static_cast<std::size_t>(w.job)];
                    r.ok = !payload.empty() && payload[0] == 'O';
                    (r.ok ? r.output : r.error) = payload.empty() ? "empty reply" : payload.substr(1);
                    w.job = -1;
                    ++done;
                } else if (w.job < 0) {
                    lost(w, "worker wrote without a job");
                }
                continue;
            }
            if (w.job >= 0 && Clock::now() - w.started >= timeout)
                lost(w, "job timed out after " + std::to_string(im.opt.timeout_seconds) + " s");
        }
    }
    return results;
}

int serve_worker(int in_fd, int out_fd, const std::function<std::string(const std::string&)>& handler) {
    for (;;) {
        char len[8];
        const int h = read_exact(in_fd, len, 8);
        if (h == 0) return 0;   // end of input: the pool is done with us
        if (h < 0) return 1;
        std::uint64_t n = 0;
        for (int i = 0; i < 8; ++i) n |= std::uint64_t(static_cast<unsigned char>(len[i])) << (8 * i);
        if (n > kMaxFrame) return 1;
        std::string job(n, '\0');
        if (n > 0 && read_exact(in_fd, job.data(), n) != 1) return 1;
        std::string reply;
        try {
            reply = "O" + handler(job);
        } catch (const std::exception& e) {
            reply = std::string("E") + e.what();
        } catch (...) {
            reply = "Eunknown exception";
        }
        if (!write_frame(out_fd, reply)) return 1;
    }
}

} // namespace cic
