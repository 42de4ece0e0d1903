// MAP-Elites runs end to end (docs/quality-diversity.md): killed with SIGKILL
// and resumed, or continued with a larger budget, they give the bytes of a run
// that never stopped; bad settings exit 2 before anything is written; an elite
// of any cell replays to its stored fitness; export and plot read the archive.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <random>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"


namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

// R1's 4-D duty-factor grid with 3 bins, 2.5 s simulations, batches of 12.
std::string settings(const std::string& type, int evaluations, int workers, const std::string& emitter = "") {
    return R"(<settings>
  <Experiment><type>)" + type + R"(</type><seed>3</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <MapElites><enabled>1</enabled><bins>3</bins><batch>12</batch><initial>24</initial><evaluations>)" +
           std::to_string(evaluations) + "</evaluations>" + (emitter.empty() ? "" : "<emitter>" + emitter + "</emitter>") +
           R"(</MapElites>
  <GP><numberOfTreesInForestGenotype>3</numberOfTreesInForestGenotype></GP>
  <Neural><substrate>gait</substrate><clockInputs>0</clockInputs><frequencyMax>3</frequencyMax></Neural>
  <Simulator><robot_type>1</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
</settings>
)";
}

TEST(MapElitesRun, KilledAtRandomMomentsAndResumedGivesTheSameArchive) {
    const auto dir = temp_dir("me-crash");
    write_text(dir / "run.xml", settings("hypergp", 96, 2));
    const auto t0 = std::chrono::steady_clock::now();
    const auto reference = run_settings(dir, "reference", read_text(dir / "run.xml"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(reference.rc, 0) << reference.log;
    const std::string want = read_text(reference.run / "population.xml");

    std::mt19937 rng(20261203);   // fixed: the same moments every time the test runs
    std::uniform_real_distribution<double> moment(0.1, 0.9);
    for (int k = 0; k < 4; ++k) {
        const double at = moment(rng) * seconds;
        SCOPED_TRACE("killed after " + std::to_string(at) + " s of a " + std::to_string(seconds) + " s run");
        fs::path resumed, from;
        ASSERT_TRUE(kill_then_resume(dir, dir / "run.xml", k, at, true, resumed, from)) << read_text(dir / "resumed.log");
        EXPECT_EQ(read_text(resumed / "population.xml"), want)
            << (from.empty() ? "started again" : "resumed from " + from.string());
    }
    fs::remove_all(dir);
}

// A resume from a finished run's last archive ends at once, and its folder holds the
// run's final archive too, as every other search's does (the crash test above meets
// this case when its kill comes after the last batch).
TEST(MapElitesRun, AResumeFromTheLastArchiveEndsAtOnceWithItsBytes) {
    const auto dir = temp_dir("me-end");
    for (const std::string type : {"gait", "hypergp"}) {
        SCOPED_TRACE(type);
        const auto whole = run_settings(dir, type + "-whole", settings(type, 36, 1));
        ASSERT_EQ(whole.rc, 0) << whole.log;
        std::string again = settings(type, 36, 2);
        again.replace(again.find("</settings>"), 0,
                      "  <Control><populationXmlLoadFrom>" + (whole.run / "population.xml").string() +
                          "</populationXmlLoadFrom></Control>\n");
        const auto resumed = run_settings(dir, type + "-resumed", again);
        ASSERT_EQ(resumed.rc, 0) << resumed.log;
        EXPECT_EQ(read_text(resumed.run / "population.xml"), read_text(whole.run / "population.xml"));
    }
    fs::remove_all(dir);
}

TEST(MapElitesRun, ResumeWithALargerBudgetGivesTheLongerRunsBytes) {
    const auto dir = temp_dir("me-resume");
    for (const std::string type : {"gait", "hypergp"}) {
        SCOPED_TRACE(type);
        const auto straight = run_settings(dir, type + "-straight", settings(type, 72, 1));
        const auto part = run_settings(dir, type + "-part", settings(type, 36, 2));
        ASSERT_EQ(straight.rc, 0) << straight.log;
        ASSERT_EQ(part.rc, 0) << part.log;
        EXPECT_EQ(run_command("resume " + part.run.string() + " --generations 3", dir / "no.log"), 2);
        EXPECT_HAS(read_text(dir / "no.log"), "--set MapElites.evaluations=E");
        EXPECT_EQ(run_command("resume " + part.run.string() + " --set MapElites.bins=4 --set MapElites.evaluations=72", dir / "no.log"), 2);
        EXPECT_HAS(read_text(dir / "no.log"), "MapElites.bins");
        ASSERT_EQ(run_command("--quiet resume " + part.run.string() + " --set MapElites.evaluations=72", dir / "r.log"), 0)
            << read_text(dir / "r.log");
        EXPECT_EQ(file_hash(part.run / "population.xml"), file_hash(straight.run / "population.xml"));
        // stats.csv: one row per batch, the same numbers but the wall times.
        const std::string a = read_text(part.run / "stats.csv"), b = read_text(straight.run / "stats.csv");
        EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 7);
        EXPECT_EQ(std::count(b.begin(), b.end(), '\n'), 7);
        EXPECT_HAS(a, ",qd_score,coverage,filled,kept\n");
    }
    fs::remove_all(dir);
}

// Each gait-family emitter beyond the default is one key away, and its run
// continued from a checkpoint (with 2 workers) gives the bytes of the run
// that never stopped (1 worker). CMA-ME's checkpoint carries its CMA-ES state.
TEST(MapElitesRun, EveryGaitEmitterIsOneKeyAwayAndResumesBitForBit) {
    const auto dir = temp_dir("me-emitters");
    const auto gaussian = run_settings(dir, "gaussian", settings("gait", 72, 1));
    ASSERT_EQ(gaussian.rc, 0) << gaussian.log;
    EXPECT_HAS(read_text(gaussian.run / "run.log"), "gaussian emitter");   // auto, for the gait family
    for (const std::string emitter : {"iso-line", "cma-me"}) {
        SCOPED_TRACE(emitter);
        const auto straight = run_settings(dir, emitter + "-straight", settings("gait", 72, 1, emitter));
        const auto part = run_settings(dir, emitter + "-part", settings("gait", 36, 2, emitter));
        ASSERT_EQ(straight.rc, 0) << straight.log;
        ASSERT_EQ(part.rc, 0) << part.log;
        EXPECT_HAS(read_text(straight.run / "run.log"), emitter + " emitter");
        EXPECT_NE(file_hash(straight.run / "population.xml"), file_hash(gaussian.run / "population.xml"));
        EXPECT_EQ(read_text(part.run / "population.xml").find("<emitter") != std::string::npos, emitter == "cma-me");
        ASSERT_EQ(run_command("--quiet resume " + part.run.string() + " --set MapElites.evaluations=72",
                              dir / (emitter + ".log")),
                  0)
            << read_text(dir / (emitter + ".log"));
        EXPECT_EQ(file_hash(part.run / "population.xml"), file_hash(straight.run / "population.xml"));
    }
    // An edited emitter state, or another emitter, is refused before the resume writes anything.
    const auto part = only_run(dir / "cma-me-part");
    std::string archive = read_text(part / "population.xml");
    const auto at = archive.find("\ngeneration ");
    ASSERT_NE(at, std::string::npos);
    archive.insert(at + 12, "oops ");
    // In a file of format version 1 (no contentHash, which would refuse the edit first).
    archive.erase(archive.find(" contentHash=\""), 31);
    archive.replace(archive.find(" version=\"2\""), 12, " version=\"1\"");
    write_text(dir / "edited.xml", archive);
    const std::string from = " --set Control.populationXmlLoadFrom=" + (dir / "edited.xml").string();
    write_text(dir / "resume.xml", settings("gait", 96, 1, "cma-me"));
    EXPECT_EQ(run_command("--quiet --settings " + (dir / "resume.xml").string() + " --output " +
                              (dir / "edited-out").string() + from,
                          dir / "edited.log"),
              2);
    EXPECT_HAS(read_text(dir / "edited.log"), "cma-me emitter state");
    EXPECT_FALSE(fs::exists(dir / "edited-out"));
    write_text(dir / "other.xml", settings("gait", 96, 1, "iso-line"));
    EXPECT_EQ(run_command("--quiet --settings " + (dir / "other.xml").string() + " --output " +
                              (dir / "other-out").string() + " --set Control.populationXmlLoadFrom=" +
                              (part / "population.xml").string(),
                          dir / "other.log"),
              2);
    EXPECT_HAS(read_text(dir / "other.log"), "state of a cma-me emitter");
    EXPECT_FALSE(fs::exists(dir / "other-out"));
    fs::remove_all(dir);
}

TEST(MapElitesRun, BadSettingsExitTwoBeforeAnythingIsWritten) {
    const auto dir = temp_dir("me-bad");
    struct Case {
        std::string name, text, says;
    };
    const std::string good = settings("gait", 36, 1);
    auto with = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    const std::vector<Case> cases = {
        {"descriptor", with("<bins>3</bins>", "<descriptor>speed</descriptor>"), "one of: duty-factor, omni"},
        {"symreg", with("<type>gait</type>", "<type>symreg</type>"), "hypergp and gait families"},
        {"batch", with("<batch>12</batch>", "<batch>50</batch>"), "does not cover one batch"},
        {"bins", with("<bins>3</bins>", "<bins>100</bins>"), "past the limit of 10000000"},
        {"ipop", with("<Neural>", "<Gait><restarts>ipop</restarts></Gait><Neural>"), "Gait.restarts"},
        {"key", with("<bins>3</bins>", "<bims>3</bims>"), "did you mean bins"},
        {"emitter", with("<bins>3</bins>", "<bins>3</bins><emitter>cma-mae</emitter>"),
         "auto, gp, gaussian, iso-line, cma-me"},
        {"emitter-family", with("<bins>3</bins>", "<bins>3</bins><emitter>gp</emitter>"),
         "allowed here: auto | gaussian | iso-line"},
        {"line-sigma", with("<bins>3</bins>", "<bins>3</bins><lineSigma>-1</lineSigma>"), "lineSigma"},
        {"cma-me", with("<initial>24</initial>", "<initial>30</initial><emitter>cma-me</emitter>"),
         "multiple of batch"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto r = run_settings(dir, c.name, c.text);
        EXPECT_EQ(r.rc, 2) << r.log;
        EXPECT_HAS(r.log, c.says);
        EXPECT_FALSE(fs::exists(dir / c.name)) << "wrote a run folder";
    }
    fs::remove_all(dir);
}

TEST(MapElitesRun, AnyEliteReplaysToItsStoredFitnessAndExportAndPlotReadTheArchive) {
    const auto dir = temp_dir("me-replay");
    for (const std::string type : {"gait", "hypergp"}) {
        SCOPED_TRACE(type);
        const auto r = run_settings(dir, type, settings(type, 36, 2));
        ASSERT_EQ(r.rc, 0) << r.log;
        ASSERT_EQ(run_command("export " + r.run.string(), dir / "export.csv"), 0) << read_text(dir / "export.csv");
        const std::string csv = read_text(dir / "export.csv");
        // Every elite: replayed in its cell to its stored fitness, by its bins.
        std::istringstream rows(csv);
        std::string row;
        std::getline(rows, row);
        EXPECT_EQ(row, "run,config,seed,generation,id,fitness,distance,elevation,depth,size,failed,tree,cell,descriptor");
        int elites = 0;
        while (std::getline(rows, row)) {
            ++elites;
            const auto open = row.rfind(",\"");   // the cell's bins, quoted: ...,"I,J,K,L",descriptor
            const std::string bins = row.substr(open + 2, row.find('"', open + 2) - open - 2);
            if (elites > 3) continue;   // three replays are enough
            ASSERT_EQ(run_command("assess " + r.run.string() + " --cell " + bins, dir / "assess.csv"), 0)
                << read_text(dir / "assess.csv");
            const std::string assess = read_text(dir / "assess.csv");
            const std::string line = assess.substr(assess.find('\n') + 1);
            const std::string stored = line.substr(line.find(',') + 1, line.find(',', line.find(',') + 1) - line.find(',') - 1);
            std::istringstream fields(row);
            std::string fitness;
            for (int f = 0; f < 6; ++f) std::getline(fields, fitness, ',');
            EXPECT_EQ(std::stod(stored), std::stod(fitness)) << row;   // assess's replay is the stored fitness
        }
        EXPECT_GT(elites, 3);
        EXPECT_HAS(read_text(r.run / "summary.txt"), "cells filled");
        // A cell out of the grid, and --cell on a run without an archive, are refused.
        EXPECT_EQ(run_command("assess " + r.run.string() + " --cell 3,0,0,0", dir / "no.log"), 2);
        EXPECT_HAS(read_text(dir / "no.log"), "bins 0 to 2");
        EXPECT_EQ(run_command("plot " + r.run.string() + " --archive --dims 2,3 --out " + (dir / "a.svg").string(),
                              dir / "plot.log"),
                  0)
            << read_text(dir / "plot.log");
        EXPECT_HAS(read_text(dir / "a.svg"), "duty factor, foot");
    }
    fs::remove_all(dir);
}

// The omni descriptor: where the centre went, on a 2-D grid of x and y
// displacements; the heatmap's axes say so.
TEST(MapElitesRun, TheOmniDescriptorMapsWhereTheRobotWent) {
    const auto dir = temp_dir("me-omni");
    std::string text = settings("gait", 36, 2);
    text.replace(text.find("<bins>3</bins>"), 14, "<descriptor>omni</descriptor><bins>8</bins><omniRange>2</omniRange>");
    const auto r = run_settings(dir, "omni", text);
    ASSERT_EQ(r.rc, 0) << r.log;
    const std::string archive = read_text(r.run / "population.xml");
    EXPECT_HAS(archive, "<grid descriptor=\"omni\">");
    EXPECT_HAS(archive, "<dimension bins=\"8\" lo=\"-2\" hi=\"2\"/>");
    EXPECT_HAS(read_text(r.run / "summary.txt"), "of 64 cells filled");
    ASSERT_EQ(run_command("plot " + r.run.string() + " --archive --out " + (dir / "o.svg").string(), dir / "p.log"), 0)
        << read_text(dir / "p.log");
    EXPECT_HAS(read_text(dir / "o.svg"), "x displacement [m]");
    // Its checkpoint cannot resume a run with the duty-factor descriptor.
    text = settings("gait", 72, 1);
    text.replace(text.find("<Simulator>"), 11,
                 "<Control><populationXmlLoadFrom>" + (r.run / "population.xml").string() +
                     "</populationXmlLoadFrom></Control><Simulator>");
    const auto refused = run_settings(dir, "refused", text);
    EXPECT_EQ(refused.rc, 2) << refused.log;
    // The origin names what differs (issue 39): the descriptor and the grid it makes.
    EXPECT_HAS(refused.log, "descriptor checkpoint omni, settings duty-factor");
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
