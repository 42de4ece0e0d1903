// `cic sweep`: every (configuration, seed) runs in its own folder, N at a time;
// an interrupted study resumes and ends as if it had never stopped; index.csv
// tells where each run stands; --slurm writes a job array. Reading sweep files: sweep_file_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <chrono>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "cic/report/plot.hpp"
#include "cic/study/sweep.hpp"
#include "support/expect_has.hpp"
#include "support/grid_sweep.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// `cic sweep FILE --jobs 2` in a process group of its own (so a test can signal
// the sweep alone or the whole group), its stderr to LOG; the pid, or -1.
pid_t start_sweep(const fs::path& file, const fs::path& log) {
    const pid_t pid = fork();
    if (pid != 0) return pid;
    setpgid(0, 0);
    freopen(log.c_str(), "w", stderr);
    const std::string bin = cic_binary();
    execl(bin.c_str(), bin.c_str(), "sweep", file.c_str(), "--jobs", "2", static_cast<char*>(nullptr));
    _exit(127);
}

TEST(Sweep, DryRunListsEveryRunAndWritesNothing) {
    const auto dir = temp_dir("sweep-dry");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study"));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "log"), 0) << read_text(dir / "log");
    const std::string out = read_text(dir / "log");
    EXPECT_NE(out.find("4 configurations x 3 repeats = 12 runs"), std::string::npos) << out;
    EXPECT_NE(out.find("12 pending"), std::string::npos) << out;
    EXPECT_NE(out.find("--set Neural.sampleAverageCount=2 --set Experiment.seed=6"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "study"));
    fs::remove_all(dir);
}

// `--dry-run --csv` is for scripts (scripts/scaling.sh reads it): index.csv's
// columns, the task index first and the run's command last, and nothing else on
// stdout; after the runs, its rows are index.csv's.
TEST(Sweep, CsvDryRunIsTheIndexWithTaskAndCommand) {
    const auto dir = temp_dir("sweep-dry-csv");
    const std::string text = tiny_sweep_text("c", dir / "study", 6, 2, 2.5,
                                             "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 2, 4);
    write_text(dir / "s.xml", text);
    const std::string dry = "--quiet sweep " + (dir / "s.xml").string() + " --dry-run --csv";
    ASSERT_EQ(run_command(dry, dir / "before.csv"), 0) << read_text(dir / "before.csv");
    EXPECT_FALSE(fs::exists(dir / "study"));
    const auto before = lines_of(read_text(dir / "before.csv"));
    ASSERT_EQ(before.size(), 5u) << read_text(dir / "before.csv");
    EXPECT_EQ(before[0], "task,run_dir,config,GP.elitism,seed,status,final_best,generations,evaluations,"
                         "wall_seconds,best_ever,commit,run_key,command");
    EXPECT_EQ(before[4].rfind("3,runs/elitism=1/s5,elitism=1,1,5,pending,", 0), 0u) << before[4];
    EXPECT_NE(before[4].find(",cic --settings "), std::string::npos) << before[4];
    EXPECT_NE(before[4].find(" --set GP.elitism=1 --set Experiment.seed=5"), std::string::npos) << before[4];

    ASSERT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string(), dir / "run.log"), 0) << read_text(dir / "run.log");
    ASSERT_EQ(run_command(dry, dir / "after.csv"), 0) << read_text(dir / "after.csv");
    const auto after = lines_of(read_text(dir / "after.csv"));
    const auto index = lines_of(read_text(dir / "study/index.csv"));
    ASSERT_EQ(after.size(), index.size());
    for (std::size_t i = 1; i < after.size(); ++i) {
        // task first, the command last (as before the run): between them, the index row.
        const std::string command = before[i].substr(before[i].rfind(",cic --settings "));
        EXPECT_EQ(after[i], std::to_string(i - 1) + "," + index[i] + command) << i;
        EXPECT_NE(index[i].find(",done,"), std::string::npos) << index[i];
    }

    // --csv alone is refused before anything is read or written.
    fs::remove_all(dir / "study");
    EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --csv", dir / "alone.log"), 2);
    EXPECT_NE(read_text(dir / "alone.log").find("--csv goes with --dry-run"), std::string::npos)
        << read_text(dir / "alone.log");
    EXPECT_FALSE(fs::exists(dir / "study"));
    fs::remove_all(dir);
}

// Issue 39, class 7: a configuration dropped from an edited sweep file leaves
// its runs on disk, which index.csv and export leave out: the sweep says so.
TEST(Sweep, RunsOfADroppedConfigurationAreNamed) {
    const auto dir = temp_dir("sweep-dropped");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study"));
    fs::create_directories(dir / "study/runs/gone/s1");
    write_text(dir / "study/runs/gone/s1/settings.xml", "<settings/>\n");
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "log"), 0) << read_text(dir / "log");
    const std::string out = read_text(dir / "log");
    EXPECT_NE(out.find("1 run folder of the study belongs to no task of"), std::string::npos) << out;
    EXPECT_NE(out.find("runs/gone/s1"), std::string::npos) << out;
    fs::remove_all(dir);
}

TEST(Sweep, RunsEveryTaskInItsFolderAndMatchesAPlainRun) {
    const auto dir = temp_dir("sweep-run");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study"));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "log"), 0) << read_text(dir / "log");
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(index.rfind("run_dir,config,GP.elitism,Neural.sampleAverageCount,seed,status,final_best,generations,"
                          "evaluations,wall_seconds,best_ever,commit,run_key\n",
                          0),
              0u)
        << index;
    // Every run records the commit of the cic that made it (`cic --version`'s second line).
    ASSERT_EQ(run_command("--version", dir / "version"), 0);
    const std::string version = read_text(dir / "version");
    const auto at = version.find("commit: ") + 8;
    const std::string commit = version.substr(at, version.find('\n', at) - at);
    ASSERT_FALSE(commit.empty()) << version;
    std::size_t rows = 0;
    for (std::size_t p = index.find('\n'); (p = index.find("," + commit + ",", p)) != std::string::npos; ++p) ++rows;
    EXPECT_EQ(rows, 12u) << index;
    // best_ever is the largest best of the run's generations, as stats.csv writes it.
    {
        const report::StudyIndex study = report::read_study_index(dir / "study");
        ASSERT_EQ(study.runs.size(), 12u);
        for (const report::StudyRun& run : study.runs) {
            double most = -1e300;
            for (const auto& row : report::read_stats_csv(dir / "study" / run.run_dir / "stats.csv")) most = std::max(most, row.best);
            ASSERT_TRUE(run.best_ever.has_value()) << run.run_dir;
            EXPECT_EQ(*run.best_ever, most) << run.run_dir;
            EXPECT_GE(*run.best_ever, *run.final_best);
        }
    }
    EXPECT_EQ(lines(index), 13) << index;
    EXPECT_EQ(std::count(index.begin(), index.end(), 'd') >= 12, true);
    EXPECT_NE(index.find("runs/elitism=1+sampleAverageCount=2/s6,elitism=1+sampleAverageCount=2,1,2,6,done,"),
              std::string::npos)
        << index;
    // One task equals a plain run of the same settings.
    const std::string plain = "--quiet --settings " + (fs::path(CIC_SOURCE_DIR) / "settings" / "r0_settings.xml").string() +
                              " --output " + (dir / "plain").string() +
                              " --set GP.generatedPopulationSize=6 --set GP.tournament_size=3"
                              " --set Control.maximumIterations=3 --set Simulator.sample_to=2.5"
                              " --set Simulator.delayed_start=0.5 --set GP.elitism=1"
                              " --set Neural.sampleAverageCount=2 --set Experiment.seed=6";
    ASSERT_EQ(run_command(plain, dir / "plain.log"), 0) << read_text(dir / "plain.log");
    EXPECT_EQ(read_text(dir / "study/runs/elitism=1+sampleAverageCount=2/s6/population.xml"),
              read_text(only_run(dir / "plain") / "population.xml"));
    // Issue 39, class 7: `cic assess STUDY` expands the study, as plot, export and compare do.
    ASSERT_EQ(run_command("--quiet assess " + (dir / "study").string() + " --out " + (dir / "assess.csv").string(),
                          dir / "assess.log"),
              0)
        << read_text(dir / "assess.log");
    EXPECT_EQ(lines(read_text(dir / "assess.csv")), 13) << read_text(dir / "assess.csv");
    // Class 7: a run folder that index.csv does not list (a dropped configuration) is named by export.
    fs::create_directories(dir / "study/runs/gone/s1");
    write_text(dir / "study/runs/gone/s1/settings.xml", "<settings/>\n");
    ASSERT_EQ(run_command("export " + (dir / "study").string() + " --out " + (dir / "export.csv").string(),
                          dir / "export.log"),
              0)
        << read_text(dir / "export.log");
    EXPECT_NE(read_text(dir / "export.log").find("1 run folder of " + (dir / "study").string() +
                                                  " is not in its index.csv"),
              std::string::npos)
        << read_text(dir / "export.log");
    fs::remove_all(dir / "study/runs/gone");
    // Run again: nothing left to do.
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "again.log"), 0);
    EXPECT_NE(read_text(dir / "again.log").find("0 of 12 runs to do"), std::string::npos) << read_text(dir / "again.log");
    fs::remove_all(dir);
}

// Two studies that share a run store and one configuration: the second
// reuses the first's run (one folder, linked from both studies) and runs only
// its own; a dry run already counts the shared run as done.
TEST(Sweep, StudiesSharingAStoreRunACommonConfigurationOnce) {
    const auto dir = temp_dir("sweep-store");
    auto with_store = [](std::string text) {
        return text.replace(text.find("</output>") + 9, 0, "\n  <store>../store</store>");
    };
    std::string b = tiny_sweep_text("b", dir / "b", 6, 2, 2.5,
                                    "<grid><vary key=\"Neural.sampleAverageCount\">1 2</vary></grid>", 1, 4);
    b.replace(b.find("<grid>"), 0, "<set>GP.elitism=0</set>\n  ");
    write_text(dir / "a.xml", with_store(tiny_sweep_text("a", dir / "a", 6, 2, 2.5,
                                                         "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 1, 4)));
    write_text(dir / "b.xml", with_store(b));
    ASSERT_EQ(run_command("sweep " + (dir / "a.xml").string(), dir / "a.log"), 0) << read_text(dir / "a.log");
    // A store folder is found by the settings it ran, whatever its name (an older cic's key).
    const fs::path stored = fs::canonical(dir / "a/runs/elitism=0/s4");
    fs::rename(stored, stored.parent_path() / "named-by-an-older-cic");
    fs::remove(dir / "a/runs/elitism=0/s4");
    fs::create_directory_symlink("../../../store/named-by-an-older-cic", dir / "a/runs/elitism=0/s4");
    ASSERT_EQ(run_command("sweep " + (dir / "b.xml").string() + " --dry-run", dir / "dry.log"), 0);
    EXPECT_NE(read_text(dir / "dry.log").find("1 done, 1 pending"), std::string::npos) << read_text(dir / "dry.log");
    EXPECT_NE(read_text(dir / "dry.log").find("run store " + (dir / "store").string()), std::string::npos);
    // --index-only links and lists what is there, and runs nothing.
    ASSERT_EQ(run_command("sweep " + (dir / "b.xml").string() + " --index-only", dir / "index.log"), 0);
    EXPECT_NE(read_text(dir / "b/index.csv").find(",done,"), std::string::npos) << read_text(dir / "b/index.csv");
    EXPECT_NE(read_text(dir / "b/index.csv").find(",pending,"), std::string::npos) << read_text(dir / "b/index.csv");
    // ... and leaves no empty store folder, nor a link, for the run still to do.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "store"), fs::directory_iterator()), 2);
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "b/runs/sampleAverageCount=2/s4")));
    EXPECT_TRUE(fs::is_symlink(dir / "b/runs/sampleAverageCount=1/s4"));
    ASSERT_EQ(run_command("sweep " + (dir / "b.xml").string(), dir / "b.log"), 0) << read_text(dir / "b.log");
    EXPECT_NE(read_text(dir / "b.log").find("1 of 2 runs to do"), std::string::npos) << read_text(dir / "b.log");
    const fs::path shared_a = dir / "a/runs/elitism=0/s4", shared_b = dir / "b/runs/sampleAverageCount=1/s4";
    ASSERT_TRUE(fs::is_symlink(shared_a) && fs::is_symlink(shared_b));
    EXPECT_EQ(fs::canonical(shared_a), fs::canonical(shared_b));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "store"), fs::directory_iterator()), 3);
    EXPECT_EQ(lines(read_text(shared_a / "run.log")) > 0, true);
    EXPECT_NE(read_text(dir / "b/index.csv").find("runs/sampleAverageCount=1/s4,sampleAverageCount=1,1,4,done,"),
              std::string::npos)
        << read_text(dir / "b/index.csv");
    EXPECT_NE(fs::canonical(dir / "a/runs/elitism=1/s4"), fs::canonical(dir / "b/runs/sampleAverageCount=2/s4"));
    fs::remove_all(dir);
}

// A sweep file edited after its runs (here its base settings' tournament size):
// the study's links move to the runs of the new settings, which run; the old
// runs stay in the store, where the old settings find them again.
TEST(Sweep, EditedSweepUsesTheRunsOfItsNewSettings) {
    const auto dir = temp_dir("sweep-edited");
    std::string text = tiny_sweep_text("e", dir / "e", 6, 2, 2.5, "<variant name=\"R0\"/>", 1, 4);
    text.replace(text.find("</output>") + 9, 0, "\n  <store>../store</store>");
    write_text(dir / "s.xml", text);
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "first.log"), 0) << read_text(dir / "first.log");
    const fs::path run = dir / "e/runs/R0/s4", old = fs::canonical(run);
    // The run's key, the name of its store folder, is in index.csv and in the dry run:
    // a record kept elsewhere (scripts/scaling.sh's ledger) can tell the run the sweep asks for.
    const std::string old_key = old.filename().string();
    ASSERT_EQ(old_key.size(), 16u) << old;
    auto last_cell = [&] {   // index.csv's one row ends with the run's key
        const std::string index = read_text(dir / "e/index.csv");
        return index.substr(index.rfind(',') + 1);
    };
    EXPECT_EQ(last_cell(), old_key + "\n");
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "dry0.log"), 0);
    EXPECT_NE(read_text(dir / "dry0.log").find(" done         runs/R0/s4 key=" + old_key + " (skipped)\n"), std::string::npos)
        << read_text(dir / "dry0.log");
    std::string edited = text;
    edited.replace(edited.find("GP.tournament_size=3"), 20, "GP.tournament_size=4");
    write_text(dir / "s.xml", edited);
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "dry.log"), 0);
    EXPECT_NE(read_text(dir / "dry.log").find("\n1 pending;"), std::string::npos) << read_text(dir / "dry.log");
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "second.log"), 0) << read_text(dir / "second.log");
    EXPECT_NE(read_text(dir / "second.log").find("1 of 1 runs to do"), std::string::npos) << read_text(dir / "second.log");
    ASSERT_TRUE(fs::is_symlink(run));
    EXPECT_NE(fs::canonical(run), old);
    EXPECT_NE(read_text(run / "settings.xml").find("<tournament_size>4</tournament_size>"), std::string::npos);
    EXPECT_TRUE(fs::exists(old / "summary.txt"));
    const std::string new_key = fs::canonical(run).filename().string();
    EXPECT_NE(new_key, old_key);
    EXPECT_NE(read_text(dir / "dry.log").find(" pending      runs/R0/s4 key=" + new_key + " cic --settings "), std::string::npos)
        << read_text(dir / "dry.log");
    EXPECT_EQ(last_cell(), new_key + "\n");
    write_text(dir / "s.xml", text);   // back to the first settings: their run is found, nothing runs
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "third.log"), 0) << read_text(dir / "third.log");
    EXPECT_NE(read_text(dir / "third.log").find("0 of 1 runs to do"), std::string::npos) << read_text(dir / "third.log");
    EXPECT_EQ(fs::canonical(run), old);
    fs::remove_all(dir);
}

// A store knows a run by what it ran, and a robot file by its bytes, not its
// path: a study run from another checkout (its robot file elsewhere) reuses its
// runs, and a robot file edited after its runs is another robot, to run anew.
TEST(Sweep, AStoreKnowsARobotFileByItsBytesNotItsPath) {
    const auto dir = temp_dir("sweep-robot-bytes");
    auto study = [&](const std::string& where) {
        fs::create_directories(dir / where);
        fs::copy_file(fs::path(CIC_SOURCE_DIR) / "settings" / "robots" / "r0.xml", dir / where / "robot.xml");
        std::string text = tiny_sweep_text(where, dir / where / "study", 6, 2, 2.5,
                                           "<variant name=\"file\"><set>Simulator.robotFile=robot.xml</set></variant>", 1, 4);
        text.replace(text.find("</output>") + 9, 0, "\n  <store>" + (dir / "store").string() + "</store>");
        write_text(dir / where / "s.xml", text);
        return dir / where / "s.xml";
    };
    const fs::path here = study("here"), there = study("there");
    ASSERT_EQ(run_command("sweep " + here.string(), dir / "here.log"), 0) << read_text(dir / "here.log");
    ASSERT_EQ(run_command("sweep " + there.string(), dir / "there.log"), 0) << read_text(dir / "there.log");
    EXPECT_NE(read_text(dir / "there.log").find("0 of 1 runs to do"), std::string::npos) << read_text(dir / "there.log");
    EXPECT_EQ(fs::canonical(dir / "there/study/runs/file/s4"), fs::canonical(dir / "here/study/runs/file/s4"));
    // The same path, other bytes: not the stored run.
    std::string robot = read_text(dir / "there/robot.xml");
    robot.replace(robot.find("name=\"R0\""), 9, "name=\"R0 edited\"");
    write_text(dir / "there/robot.xml", robot);
    ASSERT_EQ(run_command("sweep " + there.string() + " --dry-run", dir / "dry.log"), 0);
    EXPECT_NE(read_text(dir / "dry.log").find("\n1 pending;"), std::string::npos) << read_text(dir / "dry.log");
    fs::remove_all(dir);
}

// Without a store, a study's run folders are its own: after an edit they hold runs
// of other settings. They are refused (exit 2, nothing written), never counted as
// done nor run over; a robot file named by another path but of the same bytes
// is not a difference.
TEST(Sweep, EditedSweepWithoutAStoreRefusesItsOldRuns) {
    const auto dir = temp_dir("sweep-edited-nostore");
    fs::copy_file(fs::path(CIC_SOURCE_DIR) / "settings/robots/r0.xml", dir / "robot.xml");
    const std::string variant = "<variant name=\"R0\"><set>Simulator.robotFile=" + (dir / "robot.xml").string() +
                                "</set></variant>";
    const std::string text = tiny_sweep_text("n", dir / "n", 6, 2, 2.5, variant, 1, 4);
    write_text(dir / "s.xml", text);
    const std::string sweep = "sweep " + (dir / "s.xml").string();
    ASSERT_EQ(run_command(sweep, dir / "first.log"), 0) << read_text(dir / "first.log");
    const fs::path run = dir / "n/runs/R0/s4";
    ASSERT_TRUE(fs::exists(run / "summary.txt"));
    fs::copy_file(dir / "robot.xml", dir / "moved.xml");   // same bytes, another path: the same run
    std::string moved = text;
    moved.replace(moved.find("robot.xml"), 9, "moved.xml");
    write_text(dir / "s.xml", moved);
    ASSERT_EQ(run_command(sweep + " --dry-run", dir / "dry1.log"), 0);
    EXPECT_NE(read_text(dir / "dry1.log").find("\n1 done;"), std::string::npos) << read_text(dir / "dry1.log");

    std::string edited = moved;
    edited.replace(edited.find("GP.tournament_size=3"), 20, "GP.tournament_size=4");
    write_text(dir / "s.xml", edited);
    const std::string index = read_text(dir / "n/index.csv"), summary = read_text(run / "summary.txt");
    EXPECT_EQ(run_command(sweep, dir / "refused.log"), 2) << read_text(dir / "refused.log");
    const std::string why = read_text(dir / "refused.log");
    EXPECT_NE(why.find(run.string()), std::string::npos) << why;
    EXPECT_NE(why.find("GP.tournament_size: ran '3', the sweep asks '4'"), std::string::npos) << why;
    EXPECT_EQ(run_command(sweep + " --task 0", dir / "task.log"), 2) << read_text(dir / "task.log");
    EXPECT_EQ(read_text(dir / "n/index.csv"), index);
    EXPECT_EQ(read_text(run / "summary.txt"), summary);
    EXPECT_NE(read_text(dir / "n/sweep.xml").find("GP.tournament_size=3"), std::string::npos);
    ASSERT_EQ(run_command(sweep + " --dry-run", dir / "dry2.log"), 0);
    EXPECT_NE(read_text(dir / "dry2.log").find("\n1 mismatched;"), std::string::npos) << read_text(dir / "dry2.log");
    ASSERT_EQ(run_command(sweep + " --index-only", dir / "index.log"), 0);
    EXPECT_NE(read_text(dir / "n/index.csv").find(",mismatched,"), std::string::npos) << read_text(dir / "n/index.csv");

    fs::rename(dir / "n/runs/R0/s4", dir / "old-s4");   // moved away: the task runs with the new settings
    ASSERT_EQ(run_command(sweep, dir / "second.log"), 0) << read_text(dir / "second.log");
    EXPECT_NE(read_text(run / "settings.xml").find("<tournament_size>4</tournament_size>"), std::string::npos);
    fs::remove_all(dir);
}

// The base settings file edited while a task runs: the task runs and indexes
// the settings it read when it started (its index says done, not mismatched);
// a sweep started after the edit sees the run as one of other settings.
TEST(Sweep, EditingTheBaseWhileATaskRunsChangesNeitherTheRunNorItsIndex) {
    const auto dir = temp_dir("sweep-base-edited");
    const std::string base = read_text(fs::path(CIC_SOURCE_DIR) / "settings/r0_settings.xml");
    write_text(dir / "base.xml", base);
    std::string text = tiny_sweep_text("b", dir / "study", 6, 12, 2.5, "<variant name=\"R0\"/>", 1);
    const std::size_t at = text.find("<base>") + 6;
    text.replace(at, text.find("</base>") - at, (dir / "base.xml").string());
    write_text(dir / "s.xml", text);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        freopen((dir / "task.log").c_str(), "w", stderr);
        const std::string bin = cic_binary(), file = (dir / "s.xml").string();
        execl(bin.c_str(), bin.c_str(), "sweep", file.c_str(), "--task", "0", "--workers", "1",
              static_cast<char*>(nullptr));
        _exit(127);
    }
    const fs::path run = dir / "study/runs/R0/s1";
    bool started = false;
    for (int i = 0; i < 2400 && !started; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        started = fs::exists(run / "stats.csv");
    }
    ASSERT_TRUE(started) << read_text(dir / "task.log");
    std::string edited = base;
    const std::string from = "<expectedGeneratedTreeSize>30<", to = "<expectedGeneratedTreeSize>20<";
    ASSERT_NE(edited.find(from), std::string::npos);
    edited.replace(edited.find(from), from.size(), to);
    write_text(dir / "base.xml", edited);
    ASSERT_FALSE(fs::exists(run / "summary.txt")) << "the run ended before the edit: lengthen it";
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "task.log");
    EXPECT_NE(read_text(dir / "study/index.csv").find(",1,done,"), std::string::npos)
        << read_text(dir / "study/index.csv");
    EXPECT_NE(read_text(run / "settings.xml").find("<expectedGeneratedTreeSize>30<"), std::string::npos);
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "dry.log"), 0);
    EXPECT_NE(read_text(dir / "dry.log").find("\n1 mismatched;"), std::string::npos) << read_text(dir / "dry.log");
    fs::remove_all(dir);
}

// cic reinstalled while a study runs: the tasks still to start run the binary
// that started the study (/proc/self/exe), not a missing or different file.
TEST(Sweep, ReplacingTheBinaryMidStudyChangesNothing) {
    const auto dir = temp_dir("sweep-replaced");
    const fs::path bin = dir / "cic-copy";
    fs::copy_file(cic_binary(), bin);
    write_text(dir / "s.xml", tiny_sweep_text("replaced", dir / "study", 6, 3, 2.5,
                                              "<variant name=\"R0\"><set>Simulator.robot_type=0</set></variant>", 3));
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        freopen((dir / "sweep.log").c_str(), "w", stderr);
        const std::string file = (dir / "s.xml").string();
        execl(bin.c_str(), bin.c_str(), "sweep", file.c_str(), "--jobs", "1", static_cast<char*>(nullptr));
        _exit(127);
    }
    // The first task's folder exists: the sweep is running and tasks 2 and 3 are still to start.
    bool started = false;
    for (int i = 0; i < 1200 && !started; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
        started = fs::exists(dir / "study" / "runs" / "R0" / "s1" / "settings.xml");
    }
    ASSERT_TRUE(started) << read_text(dir / "sweep.log");
    fs::remove(bin);
    write_text(bin, "#!/bin/sh\nexit 3\n");   // a broken "new version" in its place
    fs::permissions(bin, fs::perms::owner_all);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "sweep.log");
    EXPECT_EQ(WEXITSTATUS(status), 0) << read_text(dir / "sweep.log");
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 4) << index;
    EXPECT_EQ(index.find(",pending,"), std::string::npos) << index;
    EXPECT_EQ(index.find(",failed,"), std::string::npos) << index;
    fs::remove_all(dir);
}

TEST(Sweep, InterruptedStudyResumesToTheSameBytes) {
    const auto dir = temp_dir("sweep-resume");
    write_text(dir / "ref.xml", grid_sweep_text(dir / "reference", 6));
    ASSERT_EQ(run_command("sweep " + (dir / "ref.xml").string() + " --jobs 2", dir / "ref.log"), 0)
        << read_text(dir / "ref.log");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study", 6));
    const pid_t pid = start_sweep(dir / "s.xml", dir / "first.log");
    ASSERT_GE(pid, 0);
    // Let some runs finish and others start, then stop the whole study as Slurm would.
    for (int i = 0; i < 400; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
        const std::string index = read_text(dir / "study" / "index.csv");
        if (index.find(",done,") != std::string::npos) break;
    }
    kill(-pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "first.log");
    if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "the study ended before the signal";
    EXPECT_EQ(WEXITSTATUS(status), 143) << read_text(dir / "first.log");
    const std::string partial = read_text(dir / "study" / "index.csv");
    EXPECT_NE(partial.find(",pending,"), std::string::npos) << partial;

    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "second.log"), 0)
        << read_text(dir / "second.log");
    for (const auto& e : fs::recursive_directory_iterator(dir / "reference" / "runs")) {
        if (e.path().filename() != "population.xml") continue;
        const fs::path rel = fs::relative(e.path(), dir / "reference");
        EXPECT_EQ(read_text(dir / "study" / rel), read_text(e.path())) << rel;
    }
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(index.find(",pending,"), std::string::npos) << index;
    EXPECT_EQ(index.find(",interrupted,"), std::string::npos) << index;
    fs::remove_all(dir);
}

// `kill PID` of the sweep alone (not its process group): the running tasks are told
// at once and stop after their generation, instead of running on until one of them
// ends by itself (the sweep's wait used to restart on the signal). The runs here
// would take hours to finish, so "stopped" means "was told".
TEST(Sweep, SignalToTheSweepAloneStopsItsRunningTasks) {
    const auto dir = temp_dir("sweep-term");
    write_text(dir / "s.xml", tiny_sweep_text("long", dir / "study", 6, 100000, 2.5, "<variant name=\"long\"/>", 2));
    const pid_t pid = start_sweep(dir / "s.xml", dir / "sweep.log");
    ASSERT_GE(pid, 0);
    const auto started = [&] {
        for (const char* seed : {"s1", "s2"}) {
            const fs::path stats = dir / "study" / "runs" / "long" / seed / "stats.csv";
            if (!fs::exists(stats) || lines(read_text(stats)) < 2) return false;
        }
        return true;
    };
    for (int i = 0; i < 2400 && !started(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    kill(pid, SIGTERM);
    int status = 0;
    bool ended = false;
    for (int i = 0; i < 2400 && !ended; ++i) {   // a minute at most; the runs alone would take hours
        ended = waitpid(pid, &status, WNOHANG) == pid;
        if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    if (!ended) {
        kill(-pid, SIGKILL);
        waitpid(pid, &status, 0);
    }
    ASSERT_TRUE(ended) << "the sweep did not stop its tasks\n" << read_text(dir / "sweep.log");
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "sweep.log");
    EXPECT_EQ(WEXITSTATUS(status), 143) << read_text(dir / "sweep.log");
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 3) << index;
    EXPECT_EQ(index.find(",done,"), std::string::npos) << index;
    EXPECT_NE(index.find(",interrupted,"), std::string::npos) << index;
    fs::remove_all(dir);
}

// A Switch-HybrID run stopped in its gait phase is interrupted, not done: its
// summary opens with the HyperGP phase's text, and index.csv once took that for a
// finished run (issue 38's study recorded one such run as done, 1,101 of 2,500
// evaluations in). A summary of cic before the run loop's status line is read by
// its stop lines.
TEST(Sweep, ASwitchHybridRunStoppedInItsGaitPhaseIsInterruptedNotDone) {
    const auto dir = temp_dir("sweep-switch-term");
    const std::string sets =
        "<set>Neural.substrate=gait</set>\n  <set>Neural.switchPatience=2</set>\n  "
        "<set>Gait.evaluations=1000000</set>\n  <set>Gait.populationSize=7</set>\n  "
        "<set>Gait.restarts=ipop</set>\n  <variant name=\"switch\"/>";
    write_text(dir / "s.xml", tiny_sweep_text("switch", dir / "study", 6, 100000, 2.5, sets, 1));
    const pid_t pid = start_sweep(dir / "s.xml", dir / "sweep.log");
    ASSERT_GE(pid, 0);
    const fs::path run = dir / "study" / "runs" / "switch" / "s1";
    const auto gait_rows = [&] {   // stats.csv rows after the hand-over
        const std::string log = read_text(run / "run.log");
        const auto at = log.find("switch: HyperGP hands over");
        return at == std::string::npos ? 0 : lines(log.substr(at));
    };
    for (int i = 0; i < 2400 && gait_rows() < 3; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    ASSERT_GE(gait_rows(), 3) << "no hand-over in a minute\n" << read_text(run / "run.log");
    // The sweep alone: it tells its task once, and the task writes its summary. (A signal to the
    // whole group would reach the task twice, and a second signal ends a run without one.)
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "sweep.log");
    EXPECT_EQ(WEXITSTATUS(status), 143) << read_text(dir / "sweep.log");
    const std::string summary = read_text(run / "summary.txt");
    ASSERT_EQ(summary.rfind("HyperGP phase:\n", 0), 0u) << summary;
    EXPECT_HAS(summary, "\nstatus: interrupted\n");
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(index.find(",done,"), std::string::npos) << index;
    EXPECT_HAS(index, ",interrupted,");
    // The same folder as an older cic left it: no status line.
    const auto cut = summary.find("status: interrupted\n");
    write_text(run / "summary.txt", summary.substr(0, cut) + summary.substr(cut + 20));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "dry.log"), 0)
        << read_text(dir / "dry.log");
    EXPECT_HAS(read_text(dir / "dry.log"), "interrupted  runs/switch/s1");
    fs::remove_all(dir);
}

TEST(Sweep, SlurmScriptRunsTheSameResumableCommandPerTask) {
    const auto dir = temp_dir("sweep-slurm");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study"));
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --slurm --jobs 3 --workers 1", dir / "log"), 0)
        << read_text(dir / "log");
    const std::string script = read_text(dir / "study" / "slurm.sh");
    EXPECT_NE(script.find("#SBATCH --array=0-11%3\n"), std::string::npos) << script;
    EXPECT_NE(script.find("#SBATCH --requeue\n"), std::string::npos) << script;
    EXPECT_NE(script.find("sweep " + (dir / "s.xml").string() + " --task \"$SLURM_ARRAY_TASK_ID\" --workers 1"),
              std::string::npos)
        << script;
    // What one array task does: run task 7 by itself.
    ASSERT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string() + " --task 7 --workers 1", dir / "task.log"), 0)
        << read_text(dir / "task.log");
    const std::string index = read_text(dir / "study" / "index.csv");
    EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 13);
    EXPECT_NE(index.find(",done,"), std::string::npos) << index;
    EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --task 12", dir / "bad.log"), 2);
    fs::remove_all(dir);
}

// --config runs one configuration's runs and leaves the others pending; the
// dry run and the Slurm array list only those; an unknown name is refused
// with the names the sweep has.
TEST(Sweep, ConfigSelectsOneConfigurationsRuns) {
    const auto dir = temp_dir("sweep-config");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study", 2));
    const std::string sweep = "sweep " + (dir / "s.xml").string();
    const std::string one = " --config elitism=1+sampleAverageCount=1";
    ASSERT_EQ(run_command(sweep + one + " --dry-run", dir / "dry.log"), 0) << read_text(dir / "dry.log");
    EXPECT_NE(read_text(dir / "dry.log").find("3 pending;"), std::string::npos) << read_text(dir / "dry.log");
    ASSERT_EQ(run_command(sweep + one + " --slurm --workers 1", dir / "slurm.log"), 0) << read_text(dir / "slurm.log");
    // Tasks are seed-major: configuration 2 of 4 is tasks 2, 6 and 10.
    EXPECT_NE(read_text(dir / "study" / "slurm.sh").find("#SBATCH --array=2,6,10%1\n"), std::string::npos)
        << read_text(dir / "study" / "slurm.sh");
    ASSERT_EQ(run_command(sweep + one + " --jobs 2", dir / "log"), 0) << read_text(dir / "log");
    EXPECT_NE(read_text(dir / "log").find("3 of 3 runs to do"), std::string::npos) << read_text(dir / "log");
    const report::StudyIndex study = report::read_study_index(dir / "study");
    ASSERT_EQ(study.runs.size(), 12u);
    for (const report::StudyRun& run : study.runs)
        EXPECT_EQ(run.status == "done", run.config == "elitism=1+sampleAverageCount=1") << run.run_dir;
    EXPECT_EQ(run_command(sweep + " --config elitism=2 --dry-run", dir / "bad.log"), 2);
    EXPECT_NE(read_text(dir / "bad.log").find("--config elitism=2: the sweep has no such configuration (it has: "
                                              "elitism=0+sampleAverageCount=1, elitism=0+sampleAverageCount=2, "),
              std::string::npos)
        << read_text(dir / "bad.log");
    EXPECT_EQ(run_command(sweep + one + " --task 2", dir / "task.log"), 2);
    fs::remove_all(dir);
}

// A finished study whose budget is raised goes on: each run continues from its
// checkpoint to the bytes of a study that had the larger budget from the start;
// added seeds run alone; a shrunk budget or another key is still refused. With
// and without a run store (where the shorter runs stay for the studies using them).
void raised_budget_continues(bool store) {
    const auto dir = temp_dir(store ? "sweep-extend-store" : "sweep-extend");
    auto text = [&](const std::string& name, const fs::path& study, int generations, int repeats, int tournament = 3) {
        std::string t = tiny_sweep_text(name, study, 6, generations, 2.0, "", repeats);
        if (tournament != 3) t.replace(t.find("GP.tournament_size=3"), 20, "GP.tournament_size=" + std::to_string(tournament));
        if (store) t.replace(t.find("</output>") + 9, 0, "\n  <store>" + (dir / "store").string() + "</store>");
        return t;
    };
    const fs::path study = dir / "study", straight = dir / "straight";
    write_text(dir / "s.xml", text("s", study, 2, 2));
    ASSERT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "log"), 0) << read_text(dir / "log");
    write_text(dir / "s.xml", text("s", study, 4, 3));   // two more generations, one more seed
    ASSERT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "dry"), 0);
    EXPECT_NE(read_text(dir / "dry").find("extend"), std::string::npos) << read_text(dir / "dry");
    ASSERT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "log"), 0) << read_text(dir / "log");
    write_text(dir / "t.xml", text("t", straight, 4, 3));
    ASSERT_EQ(run_command("--quiet sweep " + (dir / "t.xml").string() + " --jobs 2", dir / "log"), 0) << read_text(dir / "log");
    for (int seed = 1; seed <= 3; ++seed) {
        const std::string run = "runs/base/s" + std::to_string(seed);
        ASSERT_TRUE(fs::exists(study / run / "population.xml")) << run;
        EXPECT_EQ(file_hash(study / run / "population.xml"), file_hash(straight / run / "population.xml")) << run;
        EXPECT_EQ(file_hash(study / run / "populations/gen-0003.xml"), file_hash(straight / run / "populations/gen-0003.xml"));
    }
    // Continued, not run again: seeds 1 and 2 went on from their checkpoints; seed 3 is new.
    for (int seed = 1; seed <= 3; ++seed) {
        const std::string log = read_text(study / ("runs/base/s" + std::to_string(seed)) / "run.log");
        EXPECT_EQ(log.find("resumed in place from population.xml") != std::string::npos, seed < 3) << seed << ":\n" << log;
    }
    const std::string index = read_text(study / "index.csv");
    EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 4) << index;
    if (store) {   // the two-generation runs are still in the store, beside their continuations
        std::size_t runs = 0;
        for (const auto& e : fs::directory_iterator(dir / "store")) runs += fs::exists(e.path() / "settings.xml");
        EXPECT_EQ(runs, 5u);
    } else {
        for (const auto& [generations, tournament, why] :
             {std::tuple{3, 3, "Control.maximumIterations: ran '4', the sweep asks '3'"},
              std::tuple{6, 5, "GP.tournament_size: ran '3', the sweep asks '5'"}}) {
            write_text(dir / "s.xml", text("s", study, generations, 3, tournament));
            EXPECT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string(), dir / "no"), 2);
            EXPECT_NE(read_text(dir / "no").find(why), std::string::npos) << read_text(dir / "no");
        }
    }
    fs::remove_all(dir);
}

TEST(Sweep, ARaisedBudgetContinuesEachRunExactly) { raised_budget_continues(false); }
TEST(Sweep, ARaisedBudgetContinuesStoredRunsExactly) { raised_budget_continues(true); }

} // namespace
} // namespace cic

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

std::string output_of(const std::string& args, const fs::path& log, int* rc = nullptr) {
    const int code = run_command(args, log);
    if (rc) *rc = code;
    return read_text(log);
}

TEST(Sweep, StatusShowsEachStateAndTheTimeLeft) {
    const auto dir = temp_dir("sweep-status");
    write_text(dir / "s.xml", tiny_sweep_text("st", dir / "study", 6, 2, 2.5,
                                              "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 2));
    const std::string sweep = "sweep " + (dir / "s.xml").string();
    std::string out = output_of(sweep + " --status", dir / "log");
    EXPECT_NE(out.find("4 runs\n4 pending\ntime left: unknown until a run has finished"), std::string::npos) << out;
    ASSERT_EQ(run_command("--quiet " + sweep + " --jobs 2 --workers 1", dir / "run.log"), 0) << read_text(dir / "run.log");
    EXPECT_NE(output_of(sweep + " --status", dir / "log").find("4 done\ntime left: none"), std::string::npos);
    fs::remove_all(dir / "study" / "runs" / "elitism=1" / "s2");
    fs::remove(dir / "study" / "runs" / "elitism=0" / "s2" / "summary.txt");
    out = output_of(sweep + " --status --jobs 2", dir / "log");
    EXPECT_NE(out.find("2 done, 1 pending, 1 interrupted\ntime left: about "), std::string::npos) << out;
    EXPECT_NE(out.find("(2 to go, 2 at a time, "), std::string::npos) << out;
    fs::remove_all(dir);
}

TEST(Sweep, SlurmOptionsReachTheScript) {
    const auto dir = temp_dir("sweep-slurm-options");
    write_text(dir / "s.xml", tiny_sweep_text("opt", dir / "study", 6, 2, 2.5,
                                              "<grid><vary key=\"GP.elitism\">0 1</vary></grid>", 2));
    const std::string sweep = "sweep " + (dir / "s.xml").string() + " --slurm --jobs 3 --workers 1";
    ASSERT_EQ(run_command(sweep + " --slurm-partition debug --slurm-time 1-02:00 --slurm-mem 2G "
                                  "--slurm-account lab --sbatch=--comment=cic-test",
                          dir / "log"),
              0)
        << read_text(dir / "log");
    const std::string script = read_text(dir / "study" / "slurm.sh");
    for (const char* line : {"#SBATCH --array=0-3%3\n", "#SBATCH --partition=debug\n", "#SBATCH --time=1-02:00\n",
                             "#SBATCH --mem=2G\n", "#SBATCH --account=lab\n", "#SBATCH --comment=cic-test\n"})
        EXPECT_NE(script.find(line), std::string::npos) << line << " in\n" << script;
    int rc = 0;
    EXPECT_NE(output_of(sweep + " --slurm-time 2h", dir / "log", &rc).find("--slurm-time \"2h\": a time limit"),
              std::string::npos);
    EXPECT_EQ(rc, 2);
    EXPECT_NE(output_of("sweep " + (dir / "s.xml").string() + " --slurm-mem 2G", dir / "log", &rc).find("go with --slurm"),
              std::string::npos);
    EXPECT_EQ(rc, 2);
    EXPECT_NE(output_of(sweep + " --sbatch=qos", dir / "log", &rc).find("one sbatch option on one line"), std::string::npos);
    // Where a Slurm answers, it takes the script as it is (sbatch --test-only submits nothing).
    if (std::system("timeout 10 sinfo -h -p debug -o %P > /dev/null 2>&1") == 0) {
        ASSERT_EQ(run_command(sweep + " --slurm-partition debug --slurm-time 10 --slurm-mem 100M", dir / "log"), 0);
        EXPECT_EQ(std::system(("sbatch --test-only '" + (dir / "study" / "slurm.sh").string() + "' > /dev/null 2>&1").c_str()),
                  0);
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
