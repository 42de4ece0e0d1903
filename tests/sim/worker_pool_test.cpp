// Evaluations in `cic worker` processes (the real binary, at env CIC_BINARY):
// bit-identical to in-process evaluation whatever the number of workers, and
// surviving killed and hung workers.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "cic/core/process_pool.hpp"
#include "cic/core/rng.hpp"
#include "cic/sim/job_text.hpp"

using namespace cic;
using namespace cic::sim;

namespace {

std::string cic_binary() {
    const char* env = std::getenv("CIC_BINARY");
    return env && *env ? env : CIC_BINARY;
}

PoolOptions worker_pool(int workers) {
    PoolOptions o;
    o.workers = workers;
    o.argv = {cic_binary(), "worker"};
    o.timeout_seconds = 60;
    return o;
}

// cic_test_worker (tests/support/test_worker.cpp): the real sine evaluation
// plus test-only job kinds.
PoolOptions test_worker_pool(int workers, double timeout_seconds) {
    PoolOptions o;
    o.workers = workers;
    o.argv = {CIC_TEST_WORKER};
    o.timeout_seconds = timeout_seconds;
    return o;
}

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

SimConfig short_config() {
    SimConfig c;
    c.sample_to = 3.0;
    c.delayed_start = 1.0;
    return c;
}

std::vector<std::vector<SineJoint>> random_controllers(int count, std::size_t joints) {
    Rng rng(2024);
    std::vector<std::vector<SineJoint>> out;
    for (int i = 0; i < count; ++i) {
        std::vector<SineJoint> g;
        for (std::size_t j = 0; j < joints; ++j)
            g.push_back({rng.uniform(0.0, 1.5), rng.uniform(0.1, 1.5), rng.uniform(0.0, 2 * std::numbers::pi)});
        out.push_back(g);
    }
    return out;
}

std::vector<double> fitnesses(const std::vector<JobResult>& results) {
    std::vector<double> f;
    for (const JobResult& r : results) {
        EXPECT_TRUE(r.ok) << r.error;
        f.push_back(r.ok ? parse_eval_reply(r.output).fitness : std::nan(""));
    }
    return f;
}

} // namespace

TEST(WorkerPool, SameFitnessBitsWithOneOrTwoWorkersAndInProcess) {
    const RobotSpec robot = preset(1, false);
    const SimConfig cfg = short_config();
    const auto controllers = random_controllers(20, robot.actuated().size());
    std::vector<std::string> jobs;
    for (const auto& c : controllers) jobs.push_back(make_sine_job(robot, cfg, c));

    std::vector<double> one, two;
    {
        ProcessPool pool(worker_pool(1));
        one = fitnesses(pool.run(jobs));
    }
    {
        ProcessPool pool(worker_pool(2));
        two = fitnesses(pool.run(jobs));
    }
    ASSERT_EQ(one.size(), 20u);
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        EXPECT_EQ(bits(one[i]), bits(two[i])) << i;
        // In this process, after all the evaluations before it, still the same bits.
        SineController c(controllers[i]);
        EXPECT_EQ(bits(evaluate(robot, c, cfg).fitness), bits(one[i])) << i;
    }
}

// Worker 0 is killed while it holds a job (cic_test_worker's "once" job tells
// us its pid only once it runs): the job is retried on a fresh worker, and the
// evaluations around it keep their bits. No sleeps, no timing assumptions.
TEST(WorkerPool, KilledWorkerIsSurvived) {
    const RobotSpec robot = preset(2, false);
    const SimConfig cfg = short_config();
    const auto marker = std::filesystem::temp_directory_path() / ("cic-once-" + std::to_string(::getpid()));
    std::filesystem::remove(marker);
    std::vector<std::string> jobs = {"once\n" + marker.string()};
    for (const auto& c : random_controllers(6, 12)) jobs.push_back(make_sine_job(robot, cfg, c));

    ProcessPool pool(test_worker_pool(2, 60));
    std::thread killer([&marker] {
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (!std::filesystem::exists(marker) && std::chrono::steady_clock::now() < give_up)
            std::this_thread::yield();
        int pid = 0;
        std::ifstream(marker) >> pid;
        if (pid > 0) ::kill(pid, SIGKILL);
    });
    const auto results = pool.run(jobs);
    killer.join();
    std::filesystem::remove(marker);
    EXPECT_EQ(pool.restarts(), 1);
    EXPECT_TRUE(results[0].ok) << results[0].error;
    EXPECT_EQ(results[0].attempts, 2);
    EXPECT_EQ(results[0].output, "retried");
    ProcessPool fresh(worker_pool(1));
    const auto reference = fitnesses(fresh.run({jobs.begin() + 1, jobs.end()}));
    for (std::size_t i = 1; i < jobs.size(); ++i)
        EXPECT_EQ(bits(parse_eval_reply(results[i].output).fitness), bits(reference[i - 1])) << i;
}

// A job that never answers is retried once on a fresh worker, then reported
// failed; the next job runs on yet another fresh worker. The timeout is far
// above what the small evaluation needs, even under a sanitizer.
TEST(WorkerPool, HungJobIsRetriedThenFailedAndTheRunGoesOn) {
    ProcessPool pool(test_worker_pool(1, 3.0));
    const auto results = pool.run({"hang", make_sine_job(preset(0, false), short_config(), {{0.5, 0.5, 0}})});
    EXPECT_FALSE(results[0].ok);
    EXPECT_EQ(results[0].attempts, 2);
    EXPECT_NE(results[0].error.find("timed out"), std::string::npos);
    EXPECT_TRUE(results[1].ok) << results[1].error;
    EXPECT_EQ(results[1].attempts, 1);
    EXPECT_EQ(pool.restarts(), 2);
}

TEST(WorkerPool, BadJobsAreErrorsNotCrashes) {
    ProcessPool pool(worker_pool(1));
    const auto results = pool.run({"nonsense\n", "sine\nrobot 1 0 q x\n"});
    EXPECT_FALSE(results[0].ok);
    EXPECT_NE(results[0].error.find("unknown job kind 'nonsense'"), std::string::npos) << results[0].error;
    EXPECT_FALSE(results[1].ok);
    EXPECT_EQ(results[1].attempts, 1);
    EXPECT_EQ(pool.restarts(), 0);
}
