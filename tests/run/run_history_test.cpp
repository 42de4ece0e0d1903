// Issue 56: a resume never rewrites a run's history (cic/run/run_history.hpp),
// and a stored fitness is one that replays (cic/report/verify.hpp). Each
// hand-edited checkpoint is refused with exit 2 before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <regex>
#include <string>

#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using cic::testing::file_hash;
using cic::testing::read_text;
using cic::testing::run_command;
using cic::testing::temp_dir;
using cic::testing::write_text;

namespace {

std::string symreg(int generations) {
    std::string s = cic::testing::golden_symreg_settings(1);
    const std::string from = "<maximumIterations>6</maximumIterations>";
    return s.replace(s.find(from), from.size(), "<maximumIterations>" + std::to_string(generations) + "</maximumIterations>");
}

fs::path run_of(const fs::path& dir, const std::string& name, const std::string& settings) {
    const auto r = cic::testing::run_settings(dir, name, settings);
    EXPECT_EQ(r.rc, 0) << r.log;
    return r.run;
}

// Every file of a run folder and its text, to show that a refusal wrote nothing.
std::map<std::string, std::string> snapshot(const fs::path& run) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(run))
        if (e.is_regular_file()) out[e.path().lexically_relative(run).string()] = read_text(e.path());
    return out;
}

// A file written anew: population.xml is a hard link to the last gen-NNNN.xml,
// which writing through it would change too.
void replace_file(const fs::path& file, const std::string& text) {
    fs::remove(file);
    write_text(file, text);
}

// The same edit in population.xml and its twin, the last populations/gen-NNNN.xml,
// so that only the edit itself can be what refuses it.
void edit_checkpoint(const fs::path& run, const std::string& last, const std::function<std::string(std::string)>& edit) {
    const std::string text = edit(read_text(run / "population.xml"));
    replace_file(run / "population.xml", text);
    replace_file(run / "populations" / last, text);
}

// A checkpoint in the format of the files today's runs in flight hold (issue 56):
// version 1, no contentHash over the file; loaded, with the replay as proof.
std::string old_format(std::string text) {
    text = std::regex_replace(text, std::regex(" contentHash=\"[0-9a-f]+\""), "");
    return std::regex_replace(text, std::regex(" version=\"2\""), " version=\"1\"", std::regex_constants::format_first_only);
}

// Every individual's fitness set to `value` (an edit that no hash covered in version 1 files).
std::string fake_fitness(const std::string& text, const std::string& value) {
    return std::regex_replace(text, std::regex("(<individual id=\"[0-9]+\" fitness=\")[^\"]+\""), "$01" + value + "\"");
}

void expect_refused(const fs::path& dir, const fs::path& run, const std::string& args, const std::string& why) {
    const auto before = snapshot(run);
    EXPECT_EQ(run_command("resume " + run.string() + " " + args, dir / "out.log"), 2) << read_text(dir / "out.log");
    EXPECT_HAS(read_text(dir / "out.log"), why);
    EXPECT_TRUE(snapshot(run) == before) << "a refused resume wrote in " << run;
}

} // namespace

// A population's fitness is covered by no hash: the champion's replay refuses it,
// for a resume and for a Control.populationXmlLoadFrom start alike.
TEST(RunHistory, AFakedFitnessDoesNotReplayAndIsRefused) {
    const fs::path dir = temp_dir("history-faked");
    const fs::path run = run_of(dir, "hgp", cic::testing::tiny_hypergp_settings(2, 1));
    edit_checkpoint(run, "gen-0001.xml", [](std::string t) { return fake_fitness(old_format(t), "45"); });
    expect_refused(dir, run, "--generations 1", "stored fitness 45 does not replay: the replay gives");
    write_text(dir / "load.xml", cic::testing::tiny_hypergp_settings(3, 1));
    EXPECT_EQ(run_command("--quiet --settings " + (dir / "load.xml").string() + " --output " + (dir / "load").string() +
                              " --set Control.populationXmlLoadFrom=" + (run / "population.xml").string(),
                          dir / "load.log"),
              2);
    EXPECT_HAS(read_text(dir / "load.log"), "does not replay");
    EXPECT_FALSE(fs::exists(dir / "load"));
    // cic verify names the values that do not replay, and exits 1.
    EXPECT_EQ(run_command("--quiet verify " + run.string(), dir / "verify.log"), 1);
    EXPECT_HAS(read_text(dir / "verify.log"), "stored fitness 45 does not replay");
    fs::remove_all(dir);
}

TEST(RunHistory, VerifyAgreesWithAnUnbrokenRun) {
    const fs::path dir = temp_dir("history-verify");
    const fs::path hgp = run_of(dir, "hgp", cic::testing::tiny_hypergp_settings(2, 1));
    EXPECT_EQ(run_command("--quiet verify " + hgp.string(), dir / "verify.log"), 0) << read_text(dir / "verify.log");
    EXPECT_HAS(read_text(dir / "verify.log"), "6 stored values replayed, 0 disagreements");
    const fs::path sr = run_of(dir, "sr", symreg(2));
    EXPECT_EQ(run_command("--quiet verify " + sr.string(), dir / "verify.log"), 0) << read_text(dir / "verify.log");
    EXPECT_HAS(read_text(dir / "verify.log"), ", 0 disagreements");
    fs::remove_all(dir);
}

// A gait checkpoint without its contentHash, its champion faked: the replay refuses it.
TEST(RunHistory, AFakedGaitChampionIsRefused) {
    const fs::path dir = temp_dir("history-gait");
    const std::string gait = (fs::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml").string();
    ASSERT_EQ(run_command("--quiet --settings " + gait + " --set Gait.populationSize=7 --set Gait.evaluations=14"
                          " --set Simulator.sample_to=1 --set Simulator.delayed_start=0.5 --output " + (dir / "g").string(),
                          dir / "g.log"),
              0)
        << read_text(dir / "g.log");
    const fs::path run = cic::testing::only_run(dir / "g");
    edit_checkpoint(run, "gen-0001.xml", [](std::string t) {
        return std::regex_replace(old_format(t), std::regex("(<champion fitness=\")[^\"]+\""), "$0145\"");
    });
    // Refused (here already by the replay of the search's history, which the
    // champion is part of); cic verify names the champion.
    expect_refused(dir, run, "--set Gait.evaluations=21", "population.xml");
    EXPECT_EQ(run_command("--quiet verify " + run.string(), dir / "verify.log"), 1);
    EXPECT_HAS(read_text(dir / "verify.log"), "the champion's stored fitness 45 does not replay");
    fs::remove_all(dir);
}

// An archive's elites faked (their hashes removed, an old-format file): the best
// elite's replay refuses it, whatever Control.minimumFitness says.
TEST(RunHistory, AFakedEliteIsRefused) {
    const fs::path dir = temp_dir("history-elite");
    const fs::path run = run_of(dir, "me", cic::testing::golden_me_gait_settings(1));
    fs::path last;
    for (const auto& e : fs::directory_iterator(run / "populations")) last = std::max(last, e.path());
    edit_checkpoint(run, last.filename().string(), [](std::string t) {
        t = std::regex_replace(old_format(t), std::regex(" hash=\"[0-9a-f]+\""), "");
        return std::regex_replace(t, std::regex("(<elite cell=\"[0-9]+\" fitness=\")[^\"]+\""), "$0199\"");
    });
    expect_refused(dir, run, "--set MapElites.evaluations=72 --set Control.minimumFitness=100",
                   "stored fitness 99 does not replay");
    fs::remove_all(dir);
}

// History is never rewritten: a population.xml that is not the last checkpoint,
// or counters that disagree with stats.csv, are refused.
TEST(RunHistory, ACheckpointThatDisagreesWithItsFolderIsRefused) {
    const fs::path dir = temp_dir("history-folder");
    const fs::path run = run_of(dir, "sr", symreg(3));
    const std::string population = read_text(run / "population.xml");
    // The generation edited from 2 to 0 in population.xml alone.
    const std::string at0 = std::regex_replace(population, std::regex(" generation=\"2\""), " generation=\"0\"");
    replace_file(run / "population.xml", at0);
    expect_refused(dir, run, "--generations 2", "differs from the run's last checkpoint");
    // ... and in its twin too (written through the hard link): refused by the
    // content hash, and in a file of the old format with none, by the folder.
    edit_checkpoint(run, "gen-0002.xml", [&](std::string) { return at0; });
    expect_refused(dir, run, "--generations 2", "does not match what the population file holds (edited by hand?)");
    edit_checkpoint(run, "gen-0002.xml", [&](std::string) { return old_format(at0); });
    expect_refused(dir, run, "--generations 2", "says it is number 0");
    // The evaluation counter edited in both: stats.csv's row disagrees.
    edit_checkpoint(run, "gen-0002.xml", [&](std::string) {
        return old_format(std::regex_replace(population, std::regex("(<counters nextId=\"[0-9]+\" evaluations=\")[0-9]+\""), "$010\""));
    });
    expect_refused(dir, run, "--generations 2", "stats.csv's row 2 counts");
    // population.xml that is a folder: refused, nothing written.
    fs::remove(run / "population.xml");
    replace_file(run / "populations" / "gen-0002.xml", population);
    fs::create_directory(run / "population.xml");
    expect_refused(dir, run, "--generations 2", "not a regular file");
    fs::remove_all(dir);
}

// A lost population.xml, or one left a checkpoint behind by a kill between the
// two writes, goes on from the last gen-NNNN.xml: the bytes of an unbroken run.
TEST(RunHistory, ALostPopulationGoesOnFromTheLastCheckpoint) {
    const fs::path dir = temp_dir("history-lost");
    const fs::path straight = run_of(dir, "straight", symreg(6));
    const fs::path lost = run_of(dir, "lost", symreg(3)), behind = run_of(dir, "behind", symreg(3));
    fs::remove(lost / "population.xml");
    replace_file(behind / "population.xml", read_text(behind / "populations" / "gen-0001.xml"));
    write_text(behind / "populations" / "gen-0003.xml.tmp-999999999", "half a checkpoint");
    for (const fs::path& run : {lost, behind}) {
        ASSERT_EQ(run_command("resume " + run.string() + " --until 6", dir / "r.log"), 0) << read_text(dir / "r.log");
        EXPECT_HAS(read_text(dir / "r.log"), "going on from the last checkpoint");
        EXPECT_EQ(file_hash(run / "population.xml"), file_hash(straight / "population.xml")) << run;
        for (int g = 0; g < 6; ++g) {
            const std::string name = "populations/gen-000" + std::to_string(g) + ".xml";
            EXPECT_EQ(file_hash(run / name), file_hash(straight / name)) << run << " " << name;
        }
        std::size_t rows = 0;
        for (char c : read_text(run / "stats.csv")) rows += c == '\n';
        EXPECT_EQ(rows, 7u) << run;
    }
    EXPECT_FALSE(fs::exists(behind / "populations" / "gen-0003.xml.tmp-999999999"));   // a dead process's, removed
    fs::remove_all(dir);
}

TEST(RunHistory, AFolderThatCannotBeReadIsRefusedWithItsPath) {
    const fs::path dir = temp_dir("history-loop");
    fs::create_directory_symlink(dir / "loop", dir / "loop");
    EXPECT_EQ(run_command("resume " + (dir / "loop").string() + " --generations 1", dir / "out.log"), 2);
    EXPECT_HAS(read_text(dir / "out.log"), (dir / "loop").string());
    fs::remove_all(dir);
}

// Switch-HybrID's gait phase: a hand-over whose evaluations were edited (in an
// old-format file, with no hash over it) would spend more than the budget and
// make stats.csv's evaluations go backwards; the folder refuses it.
TEST(RunHistory, AnEditedHandoverIsRefused) {
    const fs::path dir = temp_dir("history-handover");
    std::string s = cic::testing::tiny_hypergp_settings(1, 1);
    s.replace(s.find("</settings>"), 0,
              "  <Neural><substrate>gait</substrate><switchPatience>2</switchPatience></Neural>\n"
              "  <Gait><evaluations>60</evaluations><populationSize>7</populationSize></Gait>\n");
    const fs::path run = run_of(dir, "switch", s);
    ASSERT_NE(read_text(run / "population.xml").find("<handover "), std::string::npos) << "no hand-over";
    EXPECT_EQ(run_command("--quiet verify " + run.string(), dir / "verify.log"), 0) << read_text(dir / "verify.log");
    fs::path last;
    for (const auto& e : fs::directory_iterator(run / "populations")) last = std::max(last, e.path());
    edit_checkpoint(run, last.filename().string(), [](std::string t) {
        return std::regex_replace(old_format(t), std::regex("(<handover generation=\"[0-9]+\" evaluations=\")[0-9]+\""),
                                  "$010\"");
    });
    expect_refused(dir, run, "--set Gait.evaluations=80", "the HyperGP phase's last checkpoint");
    fs::remove_all(dir);
}

// The runs in flight hold checkpoints of format version 1 (written at f1f72c3):
// they resume, their champion's replay the proof, to the bytes of an unbroken run.
TEST(RunHistory, AnOldFormatCheckpointResumes) {
    const fs::path dir = temp_dir("history-old");
    const fs::path straight = run_of(dir, "straight", symreg(5)), part = run_of(dir, "part", symreg(3));
    edit_checkpoint(part, "gen-0002.xml", [](std::string t) { return old_format(t); });
    ASSERT_NE(read_text(part / "population.xml").find(" version=\"1\""), std::string::npos);
    ASSERT_EQ(run_command("--quiet resume " + part.string() + " --until 5", dir / "r.log"), 0) << read_text(dir / "r.log");
    EXPECT_EQ(file_hash(part / "population.xml"), file_hash(straight / "population.xml"));
    const std::string gait = (fs::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml").string();
    auto gait_run = [&](const std::string& name, int evaluations) {
        EXPECT_EQ(run_command("--quiet --settings " + gait + " --set Gait.populationSize=7 --set Gait.evaluations=" +
                                  std::to_string(evaluations) +
                                  " --set Simulator.sample_to=1 --set Simulator.delayed_start=0.5 --output " +
                                  (dir / name).string(),
                              dir / (name + ".log")),
                  0);
        return cic::testing::only_run(dir / name);
    };
    const fs::path g_straight = gait_run("g-straight", 28), g_part = gait_run("g-part", 14);
    edit_checkpoint(g_part, "gen-0001.xml", [](std::string t) {   // version 1 with its own (older) hash gone
        return old_format(t);
    });
    ASSERT_EQ(run_command("--quiet resume " + g_part.string() + " --set Gait.evaluations=28", dir / "g.log"), 0)
        << read_text(dir / "g.log");
    EXPECT_EQ(file_hash(g_part / "population.xml"), file_hash(g_straight / "population.xml"));
    fs::remove_all(dir);
}

// An old gait checkpoint without <origin>, made on R2, in an R1 run's folder:
// its champion does not replay on R1 (the origin could only note its absence).
TEST(RunHistory, AnOldCheckpointOfAnotherRobotDoesNotReplay) {
    const fs::path dir = temp_dir("history-robot");
    const std::string gait = (fs::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml").string();
    auto gait_run = [&](const std::string& name, int robot) {
        EXPECT_EQ(run_command("--quiet --settings " + gait + " --set Gait.populationSize=7 --set Gait.evaluations=14"
                              " --set Simulator.robot_type=" + std::to_string(robot) +
                                  " --set Simulator.sample_to=1 --set Simulator.delayed_start=0.5 --output " +
                                  (dir / name).string(),
                              dir / (name + ".log")),
                  0);
        return cic::testing::only_run(dir / name);
    };
    const fs::path r1 = gait_run("r1", 1), r2 = gait_run("r2", 2);
    const std::string foreign =
        std::regex_replace(old_format(read_text(r2 / "population.xml")), std::regex("\\s*<origin[\\s\\S]*?</origin>"), "");
    ASSERT_EQ(foreign.find("<origin"), std::string::npos);
    edit_checkpoint(r1, "gen-0001.xml", [&](std::string) { return foreign; });
    expect_refused(dir, r1, "--set Gait.evaluations=21", "does not replay");
    fs::remove_all(dir);
}
