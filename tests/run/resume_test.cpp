// `cic resume RUN` (cic/run/resume.hpp): a run continued in its own folder gives
// the bytes of a run that never stopped; what cannot continue is refused, naming
// why, before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using cic::testing::file_hash;
using cic::testing::read_text;
using cic::testing::run_command;
using cic::testing::temp_dir;
using cic::testing::write_text;

namespace {


// Symbolic regression, 6 generations unless told otherwise; never stops early.
std::string settings(int generations) {
    std::string s = cic::testing::golden_symreg_settings(1);
    const std::string from = "<maximumIterations>6</maximumIterations>";
    return s.replace(s.find(from), from.size(), "<maximumIterations>" + std::to_string(generations) + "</maximumIterations>");
}

fs::path run_of(const fs::path& dir, const std::string& name, int generations) {
    write_text(dir / (name + ".xml"), settings(generations));
    EXPECT_EQ(run_command("--quiet --settings " + (dir / (name + ".xml")).string() + " --output " + (dir / name).string(),
                          dir / (name + ".log")),
              0)
        << read_text(dir / (name + ".log"));
    return cic::testing::only_run(dir / name);
}

TEST(Resume, ContinuesInPlaceToTheBytesOfARunThatNeverStopped) {
    const fs::path dir = temp_dir("resume-bytes");
    const fs::path straight = run_of(dir, "straight", 6), part = run_of(dir, "part", 3);
    ASSERT_EQ(run_command("--quiet resume " + part.string() + " --until 5", dir / "r1.log"), 0) << read_text(dir / "r1.log");
    ASSERT_EQ(run_command("--quiet resume " + part.string() + " --generations 1", dir / "r2.log"), 0)
        << read_text(dir / "r2.log");
    EXPECT_EQ(file_hash(part / "population.xml"), file_hash(straight / "population.xml"));
    for (int g = 0; g < 6; ++g) {
        const std::string name = "populations/gen-000" + std::to_string(g) + ".xml";
        EXPECT_EQ(file_hash(part / name), file_hash(straight / name)) << name;
    }
    // stats.csv: one row per generation, 0..5, once each (the timing columns aside).
    const std::string stats = read_text(part / "stats.csv");
    std::size_t rows = 0;
    for (char c : stats) rows += c == '\n';
    EXPECT_EQ(rows, 7u) << stats;
    EXPECT_EQ(stats.substr(0, stats.find('\n')), read_text(straight / "stats.csv").substr(0, stats.find('\n')));
    // One run.log, a head per session; the settings now ask for 6 generations.
    const std::string log = read_text(part / "run.log");
    std::size_t heads = 0;
    for (std::size_t p = 0; (p = log.find("\ncommit: ", p)) != std::string::npos; ++p) ++heads;
    EXPECT_EQ(heads, 3u) << log;
    EXPECT_HAS(log, "resumed in place from population.xml");
    EXPECT_HAS(read_text(part / "settings.xml"), "<maximumIterations>6</maximumIterations>");
    fs::remove_all(dir);
}

TEST(Resume, WhatCannotContinueIsRefusedBeforeAnythingIsWritten) {
    const fs::path dir = temp_dir("resume-refused");
    const fs::path run = run_of(dir, "run", 2);
    const std::string settings_before = read_text(run / "settings.xml"), log_before = read_text(run / "run.log");
    auto refused = [&](const std::string& args, const std::string& why) {
        const int rc = run_command("resume " + run.string() + " " + args, dir / "out.log");
        EXPECT_EQ(rc, 2) << args;
        EXPECT_HAS(read_text(dir / "out.log"), why);
        EXPECT_EQ(read_text(run / "settings.xml"), settings_before) << args;
        EXPECT_EQ(read_text(run / "run.log"), log_before) << args;
    };
    refused("", "the run has evaluated 2 generations (Control.maximumIterations 2); ask for more");
    refused("--until 2", "ask for more with --generations N or --until G (G > 2)");
    refused("--generations 1 --until 5", "--generations and --until: give one of them");
    refused("--generations 1 --set GP.tournament_size=9 --set GP.crossoverRate=0.5",
            "with other settings than it ran (GP.tournament_size: ran '5', the resume asks '9'; "
            "GP.crossoverRate: ran '0.9', the resume asks '0.5'); resume changes only the budget");
    refused("--generations 1 --set GP.tournamentSize=9", "did you mean");
    const int rc = run_command("resume " + (dir / "nothing").string(), dir / "out.log");
    EXPECT_EQ(rc, 2);
    EXPECT_HAS(read_text(dir / "out.log"), "not a run folder");
    // Keys that change no result may change: the worker count.
    EXPECT_EQ(run_command("--quiet resume " + run.string() + " --generations 1 --set Experiment.workers=2", dir / "ok.log"), 0)
        << read_text(dir / "ok.log");
    fs::remove_all(dir);
}

// A gait run's budget is its evaluations; resumed to more, it equals a run given them at once.
TEST(Resume, AGaitRunGoesOnToMoreEvaluations) {
    const fs::path dir = temp_dir("resume-gait");
    const std::string gait = (fs::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml").string();
    auto run = [&](const std::string& name, int evaluations) {
        EXPECT_EQ(run_command("--quiet --settings " + gait + " --set Gait.populationSize=7 --set Gait.evaluations=" +
                                  std::to_string(evaluations) + " --output " + (dir / name).string(),
                              dir / (name + ".log")),
                  0)
            << read_text(dir / (name + ".log"));
        return cic::testing::only_run(dir / name);
    };
    const fs::path straight = run("straight", 84), part = run("part", 42);
    EXPECT_EQ(run_command("resume " + part.string() + " --until 9", dir / "no.log"), 2);
    EXPECT_HAS(read_text(dir / "no.log"), "resume it with --set Gait.evaluations=E");
    // A budget that adds no generation of 7 is refused, as it would be at the start, before anything is written.
    const std::string settings_before = read_text(part / "settings.xml"), log_before = read_text(part / "run.log");
    EXPECT_EQ(run_command("resume " + part.string() + " --set Gait.evaluations=48", dir / "no.log"), 2);
    EXPECT_HAS(read_text(dir / "no.log"), "a budget of 48 adds no generation of 7");
    EXPECT_EQ(read_text(part / "settings.xml"), settings_before);
    EXPECT_EQ(read_text(part / "run.log"), log_before);
    ASSERT_EQ(run_command("resume " + part.string() + " --set Gait.evaluations=84", dir / "r.log"), 0)
        << read_text(dir / "r.log");
    EXPECT_EQ(file_hash(part / "population.xml"), file_hash(straight / "population.xml"));
    // A budget-only change says so plainly, and is not called "other settings".
    EXPECT_HAS(read_text(dir / "r.log"), "continuing with a budget of 84 evaluations (was 42)");
    EXPECT_HAS(read_text(part / "run.log"), "continuing with a budget of 84 evaluations (was 42)");
    EXPECT_EQ(read_text(dir / "r.log").find("made with other settings"), std::string::npos) << read_text(dir / "r.log");
    fs::remove_all(dir);
}

// Issue 39, class 1: a gait checkpoint of R2 put in an R1 run's folder (both
// gaits have the same parameter count) is refused, naming both robots, and
// nothing is written.
TEST(Resume, ACheckpointOfAnotherRobotIsRefused) {
    const fs::path dir = temp_dir("resume-robot");
    const std::string gait = (fs::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml").string();
    auto run = [&](const std::string& name, int robot) {
        EXPECT_EQ(run_command("--quiet --settings " + gait + " --set Gait.populationSize=7 --set Gait.evaluations=16"
                              " --set Simulator.robot_type=" + std::to_string(robot) +
                                  " --set Simulator.sample_to=1 --set Simulator.delayed_start=0.5 --output " +
                                  (dir / name).string(),
                              dir / (name + ".log")),
                  0)
            << read_text(dir / (name + ".log"));
        return cic::testing::only_run(dir / name);
    };
    const fs::path r1 = run("r1", 1), r2 = run("r2", 2);
    // Class 7: a budget of 16 is not whole generations of 7; said, not rounded down silently.
    EXPECT_HAS(read_text(r1 / "run.log"), "Gait.evaluations 16 is not a whole number of generations of 7 candidates; "
                                          "the run stops after 2 generations, at 14 evaluations");
    // With its twin, the last gen-NNNN.xml, so that the folder agrees with itself and the origin is what refuses it.
    fs::copy_file(r2 / "population.xml", r1 / "population.xml", fs::copy_options::overwrite_existing);
    fs::copy_file(r2 / "population.xml", r1 / "populations" / "gen-0001.xml", fs::copy_options::overwrite_existing);
    const std::string settings_before = read_text(r1 / "settings.xml"), log_before = read_text(r1 / "run.log");
    EXPECT_EQ(run_command("resume " + r1.string() + " --set Gait.evaluations=28", dir / "out.log"), 2);
    const std::string out = read_text(dir / "out.log");
    EXPECT_HAS(out, "robot: checkpoint R2 (");
    EXPECT_HAS(out, "settings R1 (");
    EXPECT_EQ(read_text(r1 / "settings.xml"), settings_before);
    EXPECT_EQ(read_text(r1 / "run.log"), log_before);
    fs::remove_all(dir);
}

// Issue 39, class 5: a run killed before its first checkpoint (settings.xml,
// run.log, a header-only stats.csv, an empty populations/) goes on with
// `cic resume`, to the bytes of an unbroken run, in all three modes.
TEST(Resume, ARunKilledBeforeItsFirstCheckpointGoesOn) {
    const fs::path dir = temp_dir("resume-no-checkpoint");
    const std::string src = (fs::path(CIC_SOURCE_DIR) / "settings").string();
    write_text(dir / "symreg.xml", settings(3));
    write_text(dir / "me.xml", cic::testing::golden_me_gait_settings(1));
    const std::vector<std::pair<std::string, std::string>> modes = {
        {"gp", "--settings " + (dir / "symreg.xml").string()},
        {"gait", "--settings " + src + "/r1_gait.xml --set Gait.populationSize=7 --set Gait.evaluations=21 "
                 "--set Simulator.sample_to=1 --set Simulator.delayed_start=0.5"},
        {"map-elites", "--settings " + (dir / "me.xml").string()}};
    for (const auto& [name, args] : modes) {
        ASSERT_EQ(run_command("--quiet " + args + " --output " + (dir / name).string(), dir / (name + ".log")), 0)
            << read_text(dir / (name + ".log"));
        const fs::path straight = cic::testing::only_run(dir / name);
        // What a kill -9 before the first checkpoint leaves.
        const fs::path killed = dir / (name + "-killed");
        fs::create_directories(killed / "populations");
        fs::copy_file(straight / "settings.xml", killed / "settings.xml");
        write_text(killed / "run.log", "cic 0 (killed)\n");
        const std::string stats = read_text(straight / "stats.csv");
        write_text(killed / "stats.csv", stats.substr(0, stats.find('\n') + 1));
        ASSERT_EQ(run_command("--quiet resume " + killed.string(), dir / (name + "-resume.log")), 0)
            << name << ": " << read_text(dir / (name + "-resume.log"));
        EXPECT_EQ(file_hash(killed / "population.xml"), file_hash(straight / "population.xml")) << name;
        EXPECT_HAS(read_text(killed / "run.log"), "killed before its first checkpoint");
        if (name == "gp") {   // class 7: why a generation's evaluations differ from its population, said in run.log
            EXPECT_HAS(read_text(killed / "run.log"), "under Dynamic Limits also each child bred past the depth limit");
        }
    }
    fs::remove_all(dir);
}

// Issue 39, class 3: an archive the settings cannot take (an elite lacking a
// parameter) and a budget that adds no batch are refused before settings.xml
// or run.log change.
TEST(Resume, AMapElitesRefusalWritesNothing) {
    const fs::path dir = temp_dir("resume-archive");
    write_text(dir / "me.xml", cic::testing::golden_me_gait_settings(1));
    ASSERT_EQ(run_command("--quiet --settings " + (dir / "me.xml").string() + " --output " + (dir / "me").string(),
                          dir / "me.log"),
              0)
        << read_text(dir / "me.log");
    const fs::path run = cic::testing::only_run(dir / "me");
    const std::string settings_before = read_text(run / "settings.xml"), log_before = read_text(run / "run.log");
    auto refused = [&](const std::string& args, const std::string& why) {
        EXPECT_EQ(run_command("resume " + run.string() + " " + args, dir / "out.log"), 2) << args;
        EXPECT_HAS(read_text(dir / "out.log"), why);
        EXPECT_EQ(read_text(run / "settings.xml"), settings_before) << args;
        EXPECT_EQ(read_text(run / "run.log"), log_before) << args;
    };
    refused("--set MapElites.evaluations=65", "a budget of 65 adds no batch of 12 (ask for --set MapElites.evaluations=72");
    // An elite with one parameter fewer (its hash removed too, so the length check is what refuses it).
    std::string archive = read_text(run / "population.xml");
    const auto x = archive.find("<x>");
    archive.erase(archive.find(' ', x), archive.find(' ', archive.find(' ', x) + 1) - archive.find(' ', x));
    const auto h = archive.rfind(" hash=\"", x);
    archive.erase(h, archive.find('"', h + 7) + 1 - h);
    // ... in a file of the old format (version 1: no contentHash over the file).
    const auto c = archive.find(" contentHash=\"");
    archive.erase(c, 31);
    archive.replace(archive.find(" version=\"2\""), 12, " version=\"1\"");
    write_text(run / "population.xml", archive);
    fs::path last;   // population.xml's twin, the last gen-NNNN.xml: the folder agrees with itself
    for (const auto& e : fs::directory_iterator(run / "populations")) last = std::max(last, e.path());
    write_text(last, archive);
    refused("--set MapElites.evaluations=72", "parameters, these settings make");
    fs::remove_all(dir);
}

} // namespace
