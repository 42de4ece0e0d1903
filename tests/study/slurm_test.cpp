// `cic sweep --slurm` against a real Slurm (scripts/slurm-local.sh, started by
// .ci/run with three namespace nodes; one node works as well): a 4-task job array runs to completion and the study
// aggregates; a task requeued mid-run resumes from its checkpoint and ends with
// the bytes of an uninterrupted run. Skipped when no Slurm answers here.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "support/run_helpers.hpp"
#include "support/slurm_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

bool slurm_up() { return std::system("timeout 10 sinfo -h -o %T 2>/dev/null | grep -q -E 'idle|mix|alloc'") == 0; }

// 2 configurations x 2 repeats of small HyperGP runs on R0.
std::string sweep_text(const fs::path& study, int generations) {
    return tiny_sweep_text("slurm", study, 8, generations, 4, "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 2);
}

TEST(Slurm, JobArrayRunsTheStudyAndItAggregates) {
    const SlurmTestLock lock;
    if (!slurm_up()) GTEST_SKIP() << "no Slurm here (start one with scripts/slurm-local.sh start)";
    const auto dir = temp_dir("slurm-array");
    write_text(dir / "s.xml", sweep_text(dir / "study", 3));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --slurm --jobs 2 --workers 1", dir / "log"), 0)
        << read_text(dir / "log");
    const std::string submitted = shell("sbatch --wait " + (dir / "study" / "slurm.sh").string() + " 2>&1");
    EXPECT_NE(submitted.find("Submitted batch job"), std::string::npos) << submitted;
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 5) << index;
    std::size_t done = 0;
    for (std::size_t p = index.find(",done,"); p != std::string::npos; p = index.find(",done,", p + 1)) ++done;
    EXPECT_EQ(done, 4u) << index;
    ASSERT_EQ(run_command("compare " + (dir / "study").string(), dir / "compare.log"), 0) << read_text(dir / "compare.log");
    EXPECT_NE(read_text(dir / "compare.log").find("| elitism=0 | 0 | 2 |"), std::string::npos)
        << read_text(dir / "compare.log");
    fs::remove_all(dir);
}

TEST(Slurm, RequeuedTaskResumesToTheSameBytes) {
    const SlurmTestLock lock;
    if (!slurm_up()) GTEST_SKIP() << "no Slurm here (start one with scripts/slurm-local.sh start)";
    const auto dir = temp_dir("slurm-requeue");
    // The reference: the same study run locally, uninterrupted.
    write_text(dir / "ref.xml", sweep_text(dir / "reference", 30));
    ASSERT_EQ(run_command("sweep " + (dir / "ref.xml").string() + " --jobs 2 --workers 1", dir / "ref.log"), 0)
        << read_text(dir / "ref.log");

    write_text(dir / "s.xml", sweep_text(dir / "study", 30));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --slurm --jobs 1 --workers 1", dir / "log"), 0);
    const std::string submitted = shell("sbatch --parsable " + (dir / "study" / "slurm.sh").string());
    const std::string job = submitted.substr(0, submitted.find_first_of(";\n"));
    ASSERT_FALSE(job.empty()) << submitted;
    // Task 0 writes checkpoints; requeue it once it has one and is not finished.
    const fs::path run0 = dir / "study" / "runs" / "elitism=0" / "s1";
    bool requeued = false;
    for (int i = 0; i < 600 && !requeued; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (fs::exists(run0 / "populations" / "gen-0003.xml") && !fs::exists(run0 / "summary.txt")) {
            requeued = std::system(("scontrol requeue " + job + "_0 > /dev/null 2>&1").c_str()) == 0;
            break;
        }
    }
    if (!requeued) {
        wait_for_jobs("cic-slurm", 300);
        GTEST_SKIP() << "task 0 finished before it could be requeued";
    }
    ASSERT_TRUE(wait_for_jobs("cic-slurm", 600)) << shell("squeue");
    const std::string log = read_text(run0 / "run.log");
    EXPECT_NE(log.find("resumed in place"), std::string::npos) << log;
    for (const auto& e : fs::recursive_directory_iterator(dir / "reference" / "runs")) {
        if (e.path().filename() != "population.xml") continue;
        const fs::path rel = fs::relative(e.path(), dir / "reference");
        EXPECT_EQ(read_text(dir / "study" / rel), read_text(e.path())) << rel;
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
