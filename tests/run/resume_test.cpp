// `cic resume RUN` (cic/run/resume.hpp): a run continued in its own folder gives
// the bytes of a run that never stopped; what cannot continue is refused, naming
// why, before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using cic::testing::file_hash;
using cic::testing::read_text;
using cic::testing::run_command;
using cic::testing::temp_dir;
using cic::testing::write_text;

namespace {

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << "no '" << (part) << "' in:\n" << (text)

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
            "with other settings than it ran:\n  GP.tournament_size: ran '5', the resume asks '9'\n"
            "  GP.crossoverRate: ran '0.9', the resume asks '0.5'\n");
    refused("--generations 1 --set GP.tournamentSize=9", "did you mean");
    const int rc = run_command("resume " + (dir / "nothing").string(), dir / "out.log");
    EXPECT_EQ(rc, 2);
    EXPECT_HAS(read_text(dir / "out.log"), "not a run folder with a checkpoint");
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
    ASSERT_EQ(run_command("--quiet resume " + part.string() + " --set Gait.evaluations=84", dir / "r.log"), 0)
        << read_text(dir / "r.log");
    EXPECT_EQ(file_hash(part / "population.xml"), file_hash(straight / "population.xml"));
    fs::remove_all(dir);
}

} // namespace
