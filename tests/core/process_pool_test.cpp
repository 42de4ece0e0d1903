// ProcessPool with ordinary programs as workers: /bin/cat echoes each frame
// back (a job "Ox" is answered ok with "x"), /bin/true dies at once, sleep hangs.
// The real `cic worker` is tested in tests/sim/worker_pool_test.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>

#include <sys/socket.h>
#include <unistd.h>

#include "cic/core/error.hpp"
#include "cic/core/process_pool.hpp"

using namespace cic;

namespace {

PoolOptions command(std::vector<std::string> argv, int workers = 1) {
    PoolOptions o;
    o.argv = std::move(argv);
    o.workers = workers;
    return o;
}

} // namespace

TEST(ProcessPool, ResultsComeInJobOrder) {
    for (int workers : {1, 2, 3}) {
        ProcessPool pool(command({"/bin/cat"}, workers));
        EXPECT_EQ(pool.workers(), workers);
        std::vector<std::string> jobs;
        for (int i = 0; i < 50; ++i) jobs.push_back("O" + std::string(static_cast<std::size_t>(i * 997), 'a' + i % 26));
        const auto results = pool.run(jobs);
        ASSERT_EQ(results.size(), jobs.size());
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            EXPECT_TRUE(results[i].ok);
            EXPECT_EQ(results[i].output, jobs[i].substr(1));
            EXPECT_EQ(results[i].attempts, 1);
        }
        EXPECT_EQ(pool.restarts(), 0);
        EXPECT_TRUE(pool.run({}).empty());
    }
}

TEST(ProcessPool, ErrorRepliesAreNotRetried) {
    ProcessPool pool(command({"/bin/cat"}));
    const auto r = pool.run({"Ebad input", "Ofine"});
    EXPECT_FALSE(r[0].ok);
    EXPECT_EQ(r[0].error, "bad input");
    EXPECT_EQ(r[0].attempts, 1);
    EXPECT_TRUE(r[1].ok);
}

TEST(ProcessPool, CrashingWorkerIsReplacedAndTheJobFailsAfterRetries) {
    PoolOptions o = command({"/bin/true"}, 2);
    o.retries = 1;
    ProcessPool pool(o);
    const auto r = pool.run({"Oa", "Ob", "Oc"});
    for (const JobResult& j : r) {
        EXPECT_FALSE(j.ok);
        EXPECT_EQ(j.attempts, 2);
        // /bin/true may exit before or after the job is written to it: both are crashes.
        const bool crashed = j.error.find("ended unexpectedly") != std::string::npos ||
                             j.error.find("died before taking the job") != std::string::npos;
        EXPECT_TRUE(crashed) << j.error;
    }
    EXPECT_GE(pool.restarts(), 6);
}

TEST(ProcessPool, HungWorkerTimesOut) {
    PoolOptions o = command({"/bin/sleep", "1000"});
    o.timeout_seconds = 0.2;
    o.retries = 1;
    ProcessPool pool(o);
    const auto r = pool.run({"Ox"});
    EXPECT_FALSE(r[0].ok);
    EXPECT_EQ(r[0].attempts, 2);
    EXPECT_NE(r[0].error.find("timed out"), std::string::npos) << r[0].error;
}

TEST(ProcessPool, KilledIdleWorkerIsReplaced) {
    ProcessPool pool(command({"/bin/cat"}, 2));
    const auto before = pool.pids();
    ::kill(before[0], SIGKILL);
    const auto r = pool.run({"Oa", "Ob", "Oc", "Od"});
    for (const JobResult& j : r) EXPECT_TRUE(j.ok) << j.error;
    EXPECT_EQ(pool.restarts(), 1);
    EXPECT_NE(pool.pids()[0], before[0]);
}

// An interrupt (Python's Ctrl-C) ends a batch of hung jobs at once: every
// worker is gone, run() throws, and the next batch starts fresh workers.
TEST(ProcessPool, InterruptEndsTheBatchAndItsWorkers) {
    PoolOptions o = command({"/bin/sh", "-c", "read line; exec sleep 1000"}, 2);
    std::atomic<int> asked{0};
    std::atomic<bool> stop{true};
    o.interrupted = [&] { return ++asked >= 4 && stop.load(); };
    ProcessPool pool(o);
    const auto before = pool.pids();
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_THROW(pool.run({"Oa", "Ob", "Oc"}), Interrupted);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
    for (int pid : before) EXPECT_NE(::kill(pid, 0), 0) << "worker " << pid << " still runs";
    stop = false;
    PoolOptions echo = command({"/bin/cat"}, 2);
    echo.interrupted = [&] { return stop.load(); };
    ProcessPool cats(echo);
    stop = true;
    EXPECT_THROW(cats.run({"Oa"}), Interrupted);
    stop = false;
    const auto r = cats.run({"Oa", "Ob"});   // new workers for the next batch
    EXPECT_TRUE(r[0].ok && r[1].ok);
    EXPECT_EQ(r[1].output, "b");
}

TEST(ProcessPool, BadArgumentsThrow) {
    EXPECT_THROW(ProcessPool(command({"/bin/cat"}, 0)), std::invalid_argument);
    EXPECT_THROW(ProcessPool(command({})), std::invalid_argument);
    EXPECT_THROW(ProcessPool(command({"/no/such/program"})), std::runtime_error);
    PoolOptions o = command({"/bin/cat"});
    o.timeout_seconds = 0;
    EXPECT_THROW(ProcessPool{o}, std::invalid_argument);
}

TEST(ServeWorker, AnswersFramesAndReportsHandlerErrors) {
    int sv[2];
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, sv), 0);
    int code = -1;
    std::thread worker([&] {
        code = serve_worker(sv[1], sv[1], [](const std::string& job) -> std::string {
            if (job == "throw") throw std::runtime_error("no good");
            return "<" + job + ">";
        });
        ::close(sv[1]);
    });
    auto frame = [](const std::string& s) {
        std::string f(8, '\0');
        for (int i = 0; i < 8; ++i) f[static_cast<std::size_t>(i)] = static_cast<char>((s.size() >> (8 * i)) & 0xff);
        return f + s;
    };
    const std::string out = frame("hi") + frame("throw") + frame("");
    ASSERT_EQ(::write(sv[0], out.data(), out.size()), static_cast<ssize_t>(out.size()));
    ::shutdown(sv[0], SHUT_WR);
    std::string got;
    char buf[256];
    for (ssize_t k; (k = ::read(sv[0], buf, sizeof buf)) > 0;) got.append(buf, static_cast<std::size_t>(k));
    worker.join();
    ::close(sv[0]);
    EXPECT_EQ(code, 0);
    EXPECT_EQ(got, frame("O<hi>") + frame("Eno good") + frame("O<>"));
}

