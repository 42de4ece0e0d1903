// Several machines for real, on one: a multi-node Slurm whose nodes are network
// namespaces (scripts/slurm-local.sh start --nodes 3, started by .ci/run).
//   - a study submitted with `cic sweep --slurm` runs on every node, and
//     `cic compare` gives the table of the same study run locally;
//   - a node lost mid-study (its slurmd and job processes killed, the node
//     DOWN): its tasks are requeued onto the other nodes, resume from their
//     checkpoints, and every population equals the local uninterrupted study's;
//   - mpirun with a hostfile of the namespace hosts (TCP between them) gives the
//     population of a 1-worker run.
// Skipped unless such a cluster answers and the test runs as root (it kills a
// node and enters namespaces). CIC_TEST_SLURM_NO_REQUEUE=1 submits the lost-node
// study with --no-requeue: then the test must fail (docs/cluster.md).
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <memory>
#include <set>
#include <sstream>
#include <thread>

#include "support/child_env.hpp"
#include "support/run_helpers.hpp"
#include "support/slurm_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

const fs::path kSlurmLocal = fs::path(CIC_SOURCE_DIR) / "scripts" / "slurm-local.sh";

// The namespace nodes of the local cluster (none when it is a single node).
std::vector<std::string> cluster_nodes() {
    std::vector<std::string> out;
    for (const auto& n : lines_of(shell("timeout 10 sinfo -h -N -o %N 2>/dev/null | sort -u")))
        if (n.rfind("cic-n", 0) == 0) out.push_back(n);
    return out;
}

// Every host a run has run on (its run.log gets a head per start or resume).
std::set<std::string> hosts_of(const fs::path& run) {
    std::set<std::string> out;
    if (!fs::exists(run / "run.log")) return out;
    for (const auto& l : lines_of(read_text(run / "run.log")))
        if (l.rfind("host: ", 0) == 0) out.insert(l.substr(6));
    return out;
}

// A compare report without what differs between two studies of the same runs:
// their names and folders, and the wall-time column (the last of each configuration row).
std::string without_names_and_times(const std::string& report) {
    std::string out;
    bool configurations = false;
    for (std::string l : lines_of(report)) {
        if (l.rfind("# Comparison", 0) == 0 || l.rfind("Study `", 0) == 0) continue;
        if (l.rfind("## ", 0) == 0) configurations = l == "## Configurations";
        if (configurations && l.rfind("| ", 0) == 0) l = l.substr(0, l.rfind(" |", l.size() - 3));
        out += l + "\n";
    }
    return out;
}

// 2 configurations x 3 repeats of small HyperGP runs on R0.
std::string sweep_text(const std::string& name, const fs::path& study, int generations) {
    return tiny_sweep_text(name, study, 8, generations, 4, "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 3);
}

class SlurmCluster : public ::testing::Test {
protected:
    void SetUp() override {
        lock = std::make_unique<SlurmTestLock>();
        if (::geteuid() != 0) GTEST_SKIP() << "needs root (kills a node, enters its namespace)";
        nodes = cluster_nodes();
        if (nodes.size() < 2)
            GTEST_SKIP() << "no multi-node cluster here (start one with scripts/slurm-local.sh start --nodes 3)";
        dir = temp_dir(std::string("cluster-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void TearDown() override {
        if (!dir.empty()) fs::remove_all(dir);
    }

    // The same study run locally, uninterrupted: the bytes every cluster run must give.
    void run_reference(int generations) {
        write_text(dir / "ref.xml", sweep_text("reference", dir / "reference", generations));
        ASSERT_EQ(run_command("sweep " + (dir / "ref.xml").string() + " --jobs 2 --workers 1", dir / "ref.log"), 0)
            << read_text(dir / "ref.log");
    }

    void expect_populations_match_reference() {
        int compared = 0;
        for (const auto& e : fs::recursive_directory_iterator(dir / "reference" / "runs")) {
            if (e.path().filename() != "population.xml") continue;
            const fs::path rel = fs::relative(e.path(), dir / "reference");
            ASSERT_TRUE(fs::exists(dir / "study" / rel)) << rel;
            EXPECT_EQ(read_text(dir / "study" / rel), read_text(e.path())) << rel;
            ++compared;
        }
        EXPECT_EQ(compared, 6);
    }

    std::unique_ptr<SlurmTestLock> lock;   // held for the whole test
    std::vector<std::string> nodes;
    fs::path dir;
};

TEST_F(SlurmCluster, AStudyRunsOnEveryNodeAndComparesAsALocalOne) {
    run_reference(3);
    write_text(dir / "s.xml", sweep_text("cluster", dir / "study", 3));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --slurm --jobs 6 --workers 1", dir / "log"), 0)
        << read_text(dir / "log");
    const std::string submitted = shell("sbatch --wait " + (dir / "study" / "slurm.sh").string() + " 2>&1");
    EXPECT_NE(submitted.find("Submitted batch job"), std::string::npos) << submitted;
    std::set<std::string> used;
    for (const auto& e : fs::directory_iterator(dir / "study" / "runs"))
        for (const auto& run : fs::directory_iterator(e.path()))
            for (const auto& h : hosts_of(run.path())) used.insert(h);
    for (const auto& n : nodes) EXPECT_TRUE(used.count(n)) << "node " << n << " ran no task";
    expect_populations_match_reference();
    ASSERT_EQ(run_command("compare " + (dir / "reference").string() + " --metric best_ever", dir / "ref.md"), 0);
    ASSERT_EQ(run_command("compare " + (dir / "study").string() + " --metric best_ever", dir / "study.md"), 0);
    EXPECT_EQ(without_names_and_times(read_text(dir / "study.md")), without_names_and_times(read_text(dir / "ref.md")));
}

TEST_F(SlurmCluster, ALostNodesTasksAreRequeuedAndEndWithTheSameBytes) {
    run_reference(30);
    write_text(dir / "s.xml", sweep_text("lost", dir / "study", 30));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --slurm --jobs 6 --workers 1", dir / "log"), 0);
    const bool no_requeue = std::getenv("CIC_TEST_SLURM_NO_REQUEUE") != nullptr;
    const std::string submitted =
        shell(std::string("sbatch --parsable ") + (no_requeue ? "--no-requeue " : "") +
              (dir / "study" / "slurm.sh").string());
    ASSERT_FALSE(submitted.empty());
    // Lose the node of the first run that has a checkpoint and is not finished.
    std::string lost;
    fs::path victim;
    for (int i = 0; i < 1200 && lost.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (!fs::is_directory(dir / "study" / "runs")) continue;
        for (const auto& e : fs::directory_iterator(dir / "study" / "runs")) {
            for (const auto& run : fs::directory_iterator(e.path())) {
                const auto hosts = hosts_of(run.path());
                if (hosts.size() != 1 || !fs::exists(run.path() / "populations" / "gen-0003.xml") ||
                    fs::exists(run.path() / "summary.txt"))
                    continue;
                lost = *hosts.begin();
                victim = run.path();
                break;
            }
            if (!lost.empty()) break;
        }
    }
    if (lost.empty()) {
        wait_for_jobs("cic-lost", 600);
        GTEST_SKIP() << "every run finished before a node could be lost";
    }
    const std::string killed = shell("'" + kSlurmLocal.string() + "' kill-node " + lost + " 2>&1");
    EXPECT_NE(killed.find("is down"), std::string::npos) << killed;
    const bool finished = wait_for_jobs("cic-lost", 900);
    const std::string revived = shell("'" + kSlurmLocal.string() + "' revive-node " + lost + " 2>&1");
    ASSERT_TRUE(finished) << shell("squeue");
    EXPECT_NE(revived.find("is idle"), std::string::npos) << revived;
    // The victim started on the lost node and finished on another, from its checkpoint.
    const auto hosts = hosts_of(victim);
    EXPECT_GE(hosts.size(), 2u) << victim;
    EXPECT_NE(read_text(victim / "run.log").find("resumed in place"), std::string::npos) << read_text(victim / "run.log");
    expect_populations_match_reference();
}

TEST_F(SlurmCluster, MpiRanksOnOtherHostsGiveTheBytesOfOneWorker) {
    if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun is not on PATH";
    write_text(dir / "tiny.xml", tiny_hypergp_settings(3, 1));
    ASSERT_EQ(run_command("--quiet --settings " + (dir / "tiny.xml").string() + " --output " +
                              (dir / "one").string(),
                          dir / "one.log"),
              0)
        << read_text(dir / "one.log");
    std::string hostfile;
    for (const auto& n : nodes) hostfile += n + " slots=2\n";
    write_text(dir / "hosts", hostfile);
    // Open MPI reaches the other hosts through slurm-local.sh rsh (its plm_rsh_agent,
    // in place of ssh) and talks TCP between the namespaces' addresses.
    const std::string mpirun =
        without_leak_check() + "timeout 300 mpirun --allow-run-as-root --oversubscribe --hostfile '" +
        (dir / "hosts").string() + "' --mca plm_rsh_agent '" + kSlurmLocal.string() +
        " rsh' --mca btl tcp,self --mca btl_tcp_if_include 10.77.0.0/24 --mca oob_tcp_if_include 10.77.0.0/24 "
        "-np " + std::to_string(nodes.size() + 1) + " ";
    const int rc = std::system((mpirun + "'" + cic_binary() + "' --quiet --settings '" + (dir / "tiny.xml").string() +
                                "' --output '" + (dir / "mpi").string() + "' > '" + (dir / "mpi.log").string() +
                                "' 2>&1")
                                   .c_str());
    ASSERT_EQ(rc, 0) << read_text(dir / "mpi.log");
    const auto only = [](const fs::path& p) {
        std::vector<fs::path> found;
        for (const auto& e : fs::directory_iterator(p)) found.push_back(e.path());
        return found.size() == 1 ? found.front() : fs::path();
    };
    const fs::path one = only(dir / "one"), mpi = only(dir / "mpi");
    ASSERT_FALSE(mpi.empty()) << "worker ranks must not create run folders";
    EXPECT_EQ(read_text(mpi / "population.xml"), read_text(one / "population.xml"));
    // Rank 0 ran on a namespace host, not on the submit machine.
    const auto hosts = hosts_of(mpi);
    ASSERT_EQ(hosts.size(), 1u);
    EXPECT_EQ(hosts.begin()->rfind("cic-n", 0), 0u) << *hosts.begin();
}

// A rank on a host that cannot see the robot file (the test's folder is not on a
// shared file system there) stops the run before generation 0, naming the rank,
// its host and what every host must see.
TEST_F(SlurmCluster, MpiRankThatCannotSeeTheRobotFileIsNamedAtStart) {
    if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun is not on PATH";
    fs::copy_file(fs::path(CIC_SOURCE_DIR) / "settings/robots/r0.xml", dir / "robot.xml");
    write_text(dir / "tiny.xml", tiny_hypergp_settings(1, 1));
    // Rank 0 here, on the submit host, where the folder is; rank 1 on a node, where it is not.
    write_text(dir / "hosts", shell("hostname -s").substr(0, shell("hostname -s").find('\n')) + " slots=1\n" +
                                  nodes.front() + " slots=1\n");
    const std::string cmd =
        without_leak_check() + "CIC_NODE_PRIVATE='" + dir.string() + "' timeout 300 mpirun --allow-run-as-root " +
        "--hostfile '" + (dir / "hosts").string() + "' --mca plm_rsh_agent '" + kSlurmLocal.string() + " rsh' " +
        "--mca btl tcp,self --mca btl_tcp_if_include 10.77.0.0/24 --mca oob_tcp_if_include 10.77.0.0/24 -np 2 '" +
        cic_binary() + "' --quiet --settings '" + (dir / "tiny.xml").string() + "' --set Simulator.robotFile='" +
        (dir / "robot.xml").string() + "' --output '" + (dir / "out").string() + "' > '" + (dir / "mpi.log").string() +
        "' 2>&1";
    EXPECT_NE(std::system(cmd.c_str()), 0);
    const std::string log = read_text(dir / "mpi.log");
    EXPECT_NE(log.find("worker ranks cannot use the settings (is every file at the same path on every machine?): "
                       "MPI rank 1: (" + nodes.front() + ")"),
              std::string::npos)
        << log;
    EXPECT_NE(log.find("robot.xml"), std::string::npos) << log;
}

} // namespace
} // namespace cic
