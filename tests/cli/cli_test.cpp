// The `cic` binary end to end: exit codes, one-line messages, nothing written on bad input,
// fresh numbered run folders.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "support/expect_has.hpp"

namespace fs = std::filesystem;

namespace {

struct Result {
    int code = -1;
    std::string out;   // stdout, or stderr when asked
};

std::string binary() {
    const char* env = std::getenv("CIC_BINARY");
    return env && *env ? env : CIC_BINARY;
}

// Runs cic with args (a shell fragment); captures stderr (or stdout).
Result run(const std::string& args, bool capture_stdout = false) {
    std::string cmd = "'" + binary() + "' " + args + (capture_stdout ? " 2>/dev/null" : " 2>&1 >/dev/null");
    Result r;
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
    int status = ::pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("cic-cli-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    }
    std::string out_arg() const { return " --quiet --output '" + (dir / "out").string() + "'"; }

    fs::path dir;
};

const char* kTinySymreg = R"(<settings>
  <Experiment><type>symreg</type><workers>1</workers></Experiment>
  <GP><generatedPopulationSize>20</generatedPopulationSize><tournament_size>3</tournament_size>
      <terminalVariableCount>1</terminalVariableCount></GP>
  <Control><maximumIterations>2</maximumIterations></Control>
</settings>
)";


} // namespace

TEST_F(Cli, VersionAndHelp) {
    auto v = run("--version", true);
    EXPECT_EQ(v.code, 0);
    EXPECT_HAS(v.out, "cic 0.");
    auto h = run("--help", true);
    EXPECT_EQ(h.code, 0);
    EXPECT_HAS(h.out, "--settings");
    EXPECT_HAS(h.out, "cic settings --defaults");
    EXPECT_HAS(h.out, "useMatlabPlot (Control) writes gnuplot plots");
    EXPECT_HAS(h.out, "generatedPopulationSize");
}

// A subcommand's help lists its own options, the main help the settings keys;
// `cic help [COMMAND]` prints the same; man and completion are listed.
TEST_F(Cli, EachCommandsHelpIsItsOwn) {
    const auto main_help = run("--help", true);
    EXPECT_EQ(run("help", true).out, main_help.out);
    for (const char* listed : {"\n  help ", "\n  man ", "\n  completion "}) EXPECT_HAS(main_help.out, listed);
    const auto sweep_help = run("sweep --help", true);
    EXPECT_EQ(sweep_help.code, 0);
    EXPECT_HAS(sweep_help.out, "Usage: cic sweep [OPTIONS] file");
    EXPECT_HAS(sweep_help.out, "--jobs");
    EXPECT_EQ(sweep_help.out.find("generatedPopulationSize"), std::string::npos) << "the settings keys belong to cic --help";
    EXPECT_EQ(run("help sweep", true).out, sweep_help.out);
    const auto unknown = run("help swep");
    EXPECT_EQ(unknown.code, 2);
    EXPECT_HAS(unknown.out, "no command 'swep'; did you mean sweep?");
}

// A slip of the keys gets the near option or command, under the parser's own line.
TEST_F(Cli, MisspeltOptionsAndCommandsGetTheNearOne) {
    auto r = run("--sed 3");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "unknown option --sed; did you mean --seed?");
    r = run("sweep some.xml --job 2");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "unknown option --job; did you mean --jobs?");
    r = run("swep some.xml");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "unknown command swep; did you mean sweep?");
    r = run("--zzzzzz");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out.find("did you mean"), std::string::npos) << "nothing is near";
}

TEST_F(Cli, AnUnknownRobotNamesWhatItCouldBe) {
    const auto r = run("simulate --robot R4");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "robot 'R4' is not R0, R1, R2 or a readable file");
}

#ifdef CIC_HAVE_VIEWER
// Before any replay (which takes seconds): the source need not even exist.
TEST_F(Cli, ViewWithoutADisplaySaysSoFirst) {
    const std::string cmd = "env -u DISPLAY '" + binary() + "' view /no/such/run 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    const int status = ::pclose(p);
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_HAS(out, "no X display (DISPLAY is unset or empty)");
    EXPECT_EQ(out.find("no such run folder"), std::string::npos) << out;
}
#endif

TEST_F(Cli, UsageErrorsExitWithTwo) {
    auto r = run("");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "give --settings FILE");
    r = run("--no-such-option");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "cic: error:");
}

TEST_F(Cli, MissingSettingsFileWritesNothing) {
    auto r = run("--settings '" + (dir / "nope.xml").string() + "'" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "settings file " + (dir / "nope.xml").string() + " not found; looked in: ");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

// Issue 39, class 7: `cic settings NAME.xml` finds the shipped settings as
// --settings does; a missing one is looked for once per folder (never
// settings/settings/), with a "did you mean" for a near name; a settings file
// given without --settings gets cic's hint alone.
TEST_F(Cli, SettingsFilesAreFoundAsByTheMainJob) {
    Result r;
    const std::string in_dir = "cd '" + dir.string() + "' && '" + binary() + "' ";
    FILE* p = ::popen((in_dir + "settings r1_settings.xml 2>&1").c_str(), "r");
    ASSERT_NE(p, nullptr);
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
    EXPECT_EQ(WEXITSTATUS(::pclose(p)), 0) << r.out;
    EXPECT_HAS(r.out, "settings r1_settings.xml: using ");
    r = run("settings settings/r1_setings.xml");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out.find("settings/settings/"), std::string::npos) << r.out;
    EXPECT_HAS(r.out, "did you mean r1_settings.xml?");
    r = run("settings/r1_settings.xml");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out, "cic: error: 'settings/r1_settings.xml' is not a command; to run a settings file: cic --settings "
                     "settings/r1_settings.xml (to check it: cic settings settings/r1_settings.xml)\n");
}

TEST_F(Cli, BadSettingsGiveOneLineWithFileAndLineAndWriteNothing) {
    auto f = write("bad.xml", "<settings>\n<GP>\n<tournament_size>many</tournament_size>\n</GP>\n</settings>\n");
    auto r = run("--settings '" + f.string() + "'" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out, "cic: error: " + f.string() +
                         ":3: <GP> tournament_size = \"many\": not an integer (allowed: integer in [1, 10000000])\n");
    EXPECT_FALSE(fs::exists(dir / "out"));

    f = write("typo.xml", "<settings>\n<GP>\n<tournamentsize>5</tournamentsize>\n</GP>\n</settings>\n");
    r = run("--settings '" + f.string() + "'" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "typo.xml:3: unknown key <GP> tournamentsize; did you mean tournament_size?");

    f = write("broken.xml", "<settings>\n<GP>\n</settings>\n");
    r = run("--settings '" + f.string() + "'" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "broken.xml:3: malformed XML");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(Cli, BadOverridesNameTheirSource) {
    auto f = write("ok.xml", kTinySymreg);
    auto r = run("--settings '" + f.string() + "' --set GP.elitism=-1" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "--set: <GP> elitism = \"-1\": out of range");
    r = run("--settings '" + f.string() + "' --set elitism=1" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "--set: expected Section.key=value");
    r = run("--settings '" + f.string() + "' --seed abc" + out_arg());
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "<Experiment> seed = \"abc\": not an integer");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(Cli, UnwritableOutputFolderIsRefused) {
    auto f = write("ok.xml", kTinySymreg);
    write("file", "not a folder");
    auto r = run("--settings '" + f.string() + "' --quiet --output '" + (dir / "file" / "sub").string() + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_HAS(r.out, "cannot create the output folder");
}

TEST_F(Cli, RunsGetFreshNumberedFoldersWithEffectiveSettings) {
    auto f = write("tiny.xml", kTinySymreg);
    auto r = run("--settings '" + f.string() + "' --set GP.tournament_size=4 --seed 7" + out_arg());
    ASSERT_EQ(r.code, 0) << r.out;
    fs::path first = dir / "out" / "tiny-001";
    ASSERT_TRUE(fs::is_directory(first));
    EXPECT_TRUE(fs::exists(first / "run.log"));
    auto effective = cic::io::read_settings(first / "settings.xml");
    EXPECT_EQ(effective.gp.tournament_size, 4);
    EXPECT_EQ(effective.experiment.seed, 7u);
    EXPECT_EQ(effective.gp.population_size, 20);
    EXPECT_EQ(effective.experiment.name, "tiny");

    r = run("--settings '" + f.string() + "'" + out_arg());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::is_directory(dir / "out" / "tiny-002"));
    EXPECT_EQ(cic::io::read_settings(first / "settings.xml").experiment.seed, 7u);   // first run untouched
}

TEST_F(Cli, SettingsSubcommand) {
    auto d = run("settings --defaults", true);
    EXPECT_EQ(d.code, 0);
    EXPECT_NO_THROW(cic::io::read_settings_string(d.out, "defaults"));
    auto s = run("settings --schema", true);
    EXPECT_EQ(s.code, 0);
    EXPECT_EQ(s.out, cic::io::xml::read_file(fs::path(CIC_SOURCE_DIR) / "settings" / "cic-settings.xsd"));
    // docs/settings.md carries the key table that `settings --keys` prints.
    auto k = run("settings --keys", true);
    EXPECT_EQ(k.code, 0);
    const std::string docs = cic::io::xml::read_file(fs::path(CIC_SOURCE_DIR) / "docs" / "settings.md");
    std::istringstream rows(k.out);
    for (std::string line; std::getline(rows, line);)
        if (line.rfind("| `", 0) == 0) {
            EXPECT_NE(docs.find(line + "\n"), std::string::npos)
                << "docs/settings.md is stale (regenerate its table from `cic settings --keys`); missing:\n" << line;
        }
    auto f = write("s.xml", kTinySymreg);
    auto e = run("settings '" + f.string() + "' --set GP.elitism=2", true);
    EXPECT_EQ(e.code, 0);
    EXPECT_EQ(cic::io::read_settings_string(e.out).gp.elitism, 2);
    auto bad = run("settings '" + (dir / "missing.xml").string() + "'");
    EXPECT_EQ(bad.code, 2);
    // Looked for as --settings looks (issue 39), with the same message.
    EXPECT_HAS(bad.out, "settings file " + (dir / "missing.xml").string() + " not found; looked in: ");
}

#include "cic/run/run_folder.hpp"

TEST_F(Cli, RunFolderNumbersPastTheHighestAndNeverReuses) {
    fs::create_directories(dir / "o" / "exp-007");
    fs::create_directories(dir / "o" / "exp-x");
    fs::create_directories(dir / "o" / "other-050");
    std::ofstream(dir / "o" / "exp-009") << "a file, not a run";
    EXPECT_EQ(cic::run::create_run_folder(dir / "o", "exp"), dir / "o" / "exp-010");
    EXPECT_EQ(cic::run::create_run_folder(dir / "o", "exp"), dir / "o" / "exp-011");
    EXPECT_EQ(cic::run::create_run_folder(dir / "o", "new"), dir / "o" / "new-001");
    cic::io::Settings s;
    EXPECT_EQ(cic::run::run_name(s), "run");
    s.source_file = "settings/r1_settings.xml";
    EXPECT_EQ(cic::run::run_name(s), "r1_settings");
    s.experiment.name = "sweep";
    EXPECT_EQ(cic::run::run_name(s), "sweep");
}
