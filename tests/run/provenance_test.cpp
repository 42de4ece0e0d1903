// Provenance (issue 23): every run folder says which build of cic made it, on
// which host, when and with which command; `cic --version` prints the build;
// none of it reaches the population files, whose bytes the golden hashes guard.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "cic/run/provenance.hpp"
#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using namespace cic::run;
using cic::testing::read_text;
using cic::testing::temp_dir;

namespace {


TEST(Provenance, TheBuildKnowsItsCommitCompilerAndLibraries) {
    const BuildInfo& b = build_info();
    EXPECT_TRUE(std::regex_match(b.commit, std::regex("[0-9a-f]{40}|unknown"))) << b.commit;
    EXPECT_STREQ(b.version, CIC_VERSION);
    for (const char* v : {b.compiler, b.build_type, b.ode, b.libxml2, b.pagmo, b.eigen}) EXPECT_STRNE(v, "");
    const std::string text = build_text();
    EXPECT_EQ(text.rfind(std::string("cic ") + CIC_VERSION + "\ncommit: " + b.commit, 0), 0u) << text;
    EXPECT_TRUE(std::regex_search(text, std::regex("libraries: ODE [0-9.]+, libxml2 [0-9.]+, pagmo2 [0-9.]+, "
                                                   "Eigen [0-9.]+\n")))
        << text;
    EXPECT_HAS(build_label(), std::string(CIC_VERSION) + ", commit ");
}

TEST(Provenance, TimesAreIsoUtcAndTheLastRecordedCommitCounts) {
    EXPECT_EQ(iso_utc(std::chrono::system_clock::from_time_t(0)), "1970-01-01T00:00:00Z");
    EXPECT_EQ(iso_utc(std::chrono::system_clock::from_time_t(1796290200)), "2026-12-03T09:30:00Z");
    const fs::path dir = temp_dir("provenance-log");
    EXPECT_EQ(recorded_commit(dir), "") << "no run.log";
    std::ofstream(dir / "run.log") << "cic 0.1.0\ncommit: aaa\nhost: x\nresumed in place\ncic 0.1.0\ncommit: bbb (dirty)\n";
    EXPECT_EQ(recorded_commit(dir), "bbb (dirty)");
    fs::remove_all(dir);
}

TEST(Provenance, ARunFolderSaysWhereItCameFromAndItsPopulationDoesNot) {
    const fs::path dir = temp_dir("provenance-run");
    const auto r = cic::testing::run_settings(dir, "p", cic::testing::golden_symreg_settings(1));
    ASSERT_EQ(r.rc, 0) << r.log;
    const std::string log = read_text(r.run / "run.log");
    EXPECT_EQ(log.rfind(build_text(), 0), 0u) << log;
    EXPECT_HAS(log, "\nhost: " + host_name() + "\n");
    EXPECT_TRUE(std::regex_search(log, std::regex("\nstarted: 20[0-9]{2}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z\n"))) << log;
    EXPECT_HAS(log, "\ncommand: " + cic::testing::cic_binary() + " --quiet --settings ");
    const std::string summary = read_text(r.run / "summary.txt");
    EXPECT_TRUE(std::regex_search(summary, std::regex("\ncic: " + std::string(CIC_VERSION) +
                                                      ", commit [^\n]+\nhost: [^\n]+\nstarted: [^\n]+Z\nended: [^\n]+Z\n$")))
        << summary;
    for (const fs::path& f : {r.run / "population.xml", r.run / "populations" / "gen-0005.xml"}) {
        const std::string pop = read_text(f);
        EXPECT_EQ(pop.find(build_info().commit), std::string::npos) << f;
        EXPECT_EQ(pop.find("host"), std::string::npos) << f;
    }
    fs::remove_all(dir);
}

TEST(Provenance, VersionPrintsTheBuild) {
    const fs::path dir = temp_dir("provenance-version");
    ASSERT_EQ(cic::testing::run_command("--version", dir / "out"), 0);
    EXPECT_EQ(read_text(dir / "out").rfind(build_text(), 0), 0u) << read_text(dir / "out");
    fs::remove_all(dir);
}

} // namespace
