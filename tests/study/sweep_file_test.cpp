// Sweep files (`cic sweep FILE`): a grid and its variants plan every
// (configuration, seed); paths are read against the file's folder; every
// shipped study is valid; and mistakes are refused with file and line before
// anything is written. Running them: sweep_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "cic/study/sweep.hpp"
#include "support/grid_sweep.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

TEST(SweepFile, PlansEveryConfigurationAndSeed) {
    const auto dir = temp_dir("sweep-plan");
    write_text(dir / "s.xml", grid_sweep_text(dir / "study"));
    const study::SweepPlan plan = study::read_sweep_file(dir / "s.xml");
    ASSERT_EQ(plan.configs.size(), 4u);
    EXPECT_EQ(plan.configs[1].name, "elitism=0+sampleAverageCount=2");
    EXPECT_EQ(plan.varied_keys, (std::vector<std::string>{"GP.elitism", "Neural.sampleAverageCount"}));
    const auto tasks = plan.tasks();
    ASSERT_EQ(tasks.size(), 12u);
    EXPECT_EQ(tasks[5].config, 1u);   // seed-major: every configuration gets seed 4 first
    EXPECT_EQ(tasks[5].seed, 5u);
    EXPECT_EQ(tasks[5].run_dir, fs::path("runs/elitism=0+sampleAverageCount=2/s5"));
    EXPECT_EQ(plan.overrides(tasks[5]).back(), "Experiment.seed=5");
    // The schema accepts it too.
    const auto problems = io::xml::Document::load_file(dir / "s.xml")
                              .validate(fs::path(CIC_SOURCE_DIR) / "settings" / "cic-sweep.xsd");
    EXPECT_TRUE(problems.empty()) << problems.front();
    // Distinct seeds: configuration c gets firstSeed + c * repeats + r.
    std::string distinct = grid_sweep_text(dir / "study");
    distinct.replace(distinct.find("firstSeed=\"4\""), 13, "firstSeed=\"4\" seeds=\"distinct\"");
    write_text(dir / "d.xml", distinct);
    EXPECT_EQ(study::read_sweep_file(dir / "d.xml").tasks()[5].seed, 4u + 1 * 3 + 1);
    fs::remove_all(dir);
}

// A path in a sweep file is read against the sweep file's folder, as one in a
// settings file is, whatever folder cic runs in: in <set>, in a variant and in a <vary>.
TEST(SweepFile, RelativePathsAreReadAgainstTheSweepFilesFolder) {
    const auto dir = temp_dir("sweep-paths");
    fs::create_directories(dir / "studies");
    write_text(dir / "base.xml", "<settings><Control><maximumIterations>2</maximumIterations></Control></settings>\n");
    write_text(dir / "studies" / "s.xml", R"(<sweep name="p">
  <base>../base.xml</base>
  <set>SymbolicRegression.dataFile=data/a.csv</set>
  <grid><vary key="Control.populationXmlLoadFrom">pop/a.xml /abs/b.xml</vary></grid>
  <variant name="v"><set>Simulator.robotFile=../robots/r.xml</set></variant>
  <repeats count="1" firstSeed="1"/>
</sweep>
)");
    const study::SweepPlan plan = study::read_sweep_file(dir / "studies" / "s.xml");
    const auto folder = fs::absolute(dir / "studies").lexically_normal();
    EXPECT_EQ(plan.common.at(0), "SymbolicRegression.dataFile=" + (folder / "data/a.csv").string());
    ASSERT_EQ(plan.configs.size(), 2u);
    EXPECT_EQ(plan.configs[0].overrides.at(0), "Control.populationXmlLoadFrom=" + (folder / "pop/a.xml").string());
    EXPECT_EQ(plan.configs[1].overrides.at(0), "Control.populationXmlLoadFrom=/abs/b.xml");
    EXPECT_EQ(plan.configs[0].overrides.at(1),
              "Simulator.robotFile=" + (folder / "../robots/r.xml").lexically_normal().string());
    fs::remove_all(dir);
}

// Every study the repository ships (experiments/**/*.xml with a <sweep> root)
// passes the schema and plans with every configuration's settings accepted, so a
// reader can rerun any of them as the docs say.
TEST(SweepFile, ShippedStudiesAreValid) {
    const fs::path root = CIC_SOURCE_DIR;
    const auto dir = temp_dir("sweep-shipped");
    int checked = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root / "experiments")) {
        if (entry.path().extension() != ".xml") continue;
        const auto doc = io::xml::Document::load_file(entry.path());
        if (doc.root().name() != "sweep") continue;
        SCOPED_TRACE(entry.path().string());
        const auto problems = doc.validate(root / "settings" / "cic-sweep.xsd");
        EXPECT_TRUE(problems.empty()) << problems.front();
        const fs::path study = dir / std::to_string(checked);
        EXPECT_EQ(run_command("--quiet sweep '" + entry.path().string() + "' --dry-run --output '" + study.string() +
                                  "'",
                              dir / "log"),
                  0)
            << read_text(dir / "log");
        ++checked;
    }
    EXPECT_GE(checked, 10);
    fs::remove_all(dir);
}

// The settings of the seed-1 run of `config` in a sweep file, as the sweep runs
// it, with the base's seed: what a shipped settings file must equal.
std::string swept_settings(const fs::path& sweep, const std::string& config) {
    const study::SweepPlan plan = study::read_sweep_file(sweep);
    const auto tasks = plan.tasks();
    const auto task = std::find_if(tasks.begin(), tasks.end(),
                                   [&](const study::SweepTask& t) { return plan.configs[t.config].name == config; });
    if (task == tasks.end()) throw std::runtime_error(sweep.string() + " has no configuration " + config);
    std::vector<std::string> overrides = plan.overrides(*task);
    if (overrides.empty() || overrides.back().rfind("Experiment.seed=", 0) != 0)
        throw std::runtime_error(sweep.string() + ": the last override is not the seed");
    overrides.pop_back();
    return io::write_settings(io::load_settings(plan.base, overrides));
}

// experiments/baselines/bases/hypergp-best.xml, which every HyperGP study of
// issue 21 starts from, is the configuration that won the search of
// docs/baselines.md (stage B's "threshold0.05" variant of search-b.xml).
TEST(SweepFile, FrozenHyperGpBaseIsTheSearchWinner) {
    const fs::path root = CIC_SOURCE_DIR;
    EXPECT_EQ(io::write_settings(io::load_settings(root / "experiments" / "baselines" / "bases" / "hypergp-best.xml", {})),
              swept_settings(root / "experiments" / "baselines" / "search-b.xml", "threshold0.05"));
}

// settings/r{0,1,2}_best.xml and r{0,1,2}_best_hypergp.xml ship the winners of
// issue 21's comparison: each is exactly the configuration that
// experiments/baselines/results/walk-winners.csv (scripts/walk-report.py
// winners) names, as its sweep ran it. scripts/ship-winners.py writes them.
TEST(SweepFile, ShippedBestSettingsAreTheComparisonWinners) {
    const fs::path root = CIC_SOURCE_DIR;
    std::istringstream csv(read_text(root / "experiments" / "baselines" / "results" / "walk-winners.csv"));
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    ASSERT_EQ(line.rfind("robot,file,budget,study,config,", 0), 0u) << line;
    int checked = 0;
    while (std::getline(csv, line)) {
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        ASSERT_GE(cells.size(), 5u) << line;
        const std::string& file = cells[1];
        EXPECT_EQ(io::write_settings(io::load_settings(root / file, {})),
                  swept_settings(root / "experiments" / "baselines" / (cells[3] + ".xml"), cells[4]))
            << file << " is not " << cells[3] << " " << cells[4] << ": rerun scripts/ship-winners.py";
        ++checked;
    }
    EXPECT_EQ(checked, 6);   // _best and _best_hypergp for R0, R1 and R2
}

// Each edit of `good` (find, replace) makes `cic sweep` exit 2 with the message
// `why` before the study folder exists.
using Edits = std::vector<std::pair<std::pair<std::string, std::string>, std::string>>;
void expect_each_edit_refused(const fs::path& dir, const std::string& good, const Edits& cases) {
    for (const auto& [edit, why] : cases) {
        std::string text = good;
        text.replace(text.find(edit.first), edit.first.size(), edit.second);
        write_text(dir / "s.xml", text);
        EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "log"), 2) << edit.second;
        EXPECT_NE(read_text(dir / "log").find(why), std::string::npos) << read_text(dir / "log");
        EXPECT_FALSE(fs::exists(dir / "study"));
    }
}

TEST(SweepFile, MistakesAreRefusedWithFileAndLine) {
    const auto dir = temp_dir("sweep-errors");
    const std::string good = grid_sweep_text(dir / "study");
    const Edits cases = {
        {{"<repeats count=\"3\" firstSeed=\"4\"/>", "<repeats count=\"zero\"/>"}, "s.xml:13: <repeats> count=\"zero\""},
        {{"<grid>", "<grid><vary key=\"GP.nonsense\">1</vary>"}, "s.xml:9: <vary> names no settings key: <GP> nonsense"},
        {{"<vary key=\"GP.elitism\">0 1</vary>", "<vary key=\"GP.elitism\">0 x</vary>"},
         "s.xml:10: <vary> <GP> elitism = \"x\": not an integer (allowed: integer in [0, 10000000])"},
        {{"<set>GP.tournament_size=3</set>", "<set>GP.tournament_size=-3</set>"},
         "s.xml:5: <set> <GP> tournament_size = \"-3\""},
        {{"<vary key=\"GP.elitism\">0 1</vary>", "<vary key=\"GP.elitism\">0 0</vary>"}, "lists a value twice"},
        {{"<set>GP.tournament_size=3</set>", "<sett>GP.tournament_size=3</sett>"}, "s.xml:5: unknown element <sett>"},
        {{"r0_settings.xml", "no_such_settings.xml"}, "s.xml:2: <base>"},
        // The reader is as strict as every other (tests/io/strict_xml_test.cpp).
        {{"<grid>", "oops <grid>"}, "stray text \"oops\" in <sweep>, which holds only elements"},
        {{"<repeats count=\"3\"", "<repeats cuont=\"3\""}, "s.xml:13: <repeats> has no attribute cuont; did you mean count?"},
    };
    expect_each_edit_refused(dir, good, cases);
    // A value the settings refuse, in one configuration, stops the sweep before the study folder exists.
    std::string text = good;
    text.replace(text.find("0 1</vary>"), 3, "0 9");
    write_text(dir / "s.xml", text);
    EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "log"), 2);
    EXPECT_NE(read_text(dir / "log").find("s.xml:9: configuration elitism=9+sampleAverageCount=1: "), std::string::npos)
        << read_text(dir / "log");
    EXPECT_FALSE(fs::exists(dir / "study"));
    fs::remove_all(dir);
}

// A sweep owns its seeds: <repeats> gives them, and a seed set anywhere else
// was silently replaced (a <vary> on it made configurations that ran the same seeds).
TEST(SweepFile, SeedsComeOnlyFromRepeats) {
    const auto dir = temp_dir("sweep-seeds");
    const std::string good = grid_sweep_text(dir / "study");
    const Edits cases = {
        {{"<set>GP.tournament_size=3</set>", "<set>Experiment.seed=7</set>"},
         "s.xml:5: <set> sets Experiment.seed, which a sweep owns: each run's seed comes from <repeats"},
        {{"<vary key=\"GP.elitism\">0 1</vary>", "<vary key=\"Experiment.seed\">1 2</vary>"},
         "s.xml:10: <vary> sets Experiment.seed, which a sweep owns"},
        {{"<grid>", "<variant name=\"v\"><set>Experiment.seed=3</set></variant><grid>"},
         "s.xml:9: <set> sets Experiment.seed, which a sweep owns"},
    };
    expect_each_edit_refused(dir, good, cases);
    fs::remove_all(dir);
}

// Two configurations with the same effective settings would only repeat each
// other's runs: refused, naming both, even when they are written differently.
TEST(SweepFile, DuplicateConfigurationsAreRefusedNamingBoth) {
    const auto dir = temp_dir("sweep-duplicates");
    std::string text = grid_sweep_text(dir / "study");
    const auto grid = text.find("<grid>");
    text.replace(grid, text.find("</grid>") + 7 - grid,
                 "<variant name=\"plain\"/>\n  <variant name=\"three\"><set>GP.tournament_size=3</set></variant>");
    write_text(dir / "s.xml", text);
    EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string(), dir / "log"), 2);
    EXPECT_NE(read_text(dir / "log").find("s.xml:10: configurations plain (line 9) and three would run the same "
                                          "settings"),
              std::string::npos)
        << read_text(dir / "log");
    EXPECT_FALSE(fs::exists(dir / "study"));
    // Differing in a stop condition is a different configuration.
    const std::string same = "<set>GP.tournament_size=3</set></variant>";
    text.replace(text.find(same), same.size(), "<set>Control.maximumIterations=2</set></variant>");
    write_text(dir / "s.xml", text);
    EXPECT_EQ(run_command("sweep " + (dir / "s.xml").string() + " --dry-run", dir / "log"), 0) << read_text(dir / "log");
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
