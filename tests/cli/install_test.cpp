// Installation (issue 11, docs/install.md): `cmake --install` lays out binary, settings,
// docs, examples, man page and completion; the installed cic finds its settings by
// name from any folder; `cpack -G DEB` makes a .deb into /usr; the man page renders
// without warnings and the completion script is valid bash. Also find_settings_file.
#include <gtest/gtest.h>

#include <sstream>
#include <iterator>
#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cic/run/settings_lookup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_table.hpp"
#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using cic::testing::read_text;
using cic::testing::temp_dir;

namespace {

#ifndef CIC_CMAKE_COMMAND
#define CIC_CMAKE_COMMAND "cmake"
#endif
#ifndef CIC_CPACK_COMMAND
#define CIC_CPACK_COMMAND "cpack"
#endif
#ifndef CIC_EXAMPLE_CXX_FLAGS
#define CIC_EXAMPLE_CXX_FLAGS ""
#endif


std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// The build folder holding the cic binary (and CPackConfig.cmake, generated/).
fs::path build_dir() { return fs::path(cic::testing::cic_binary()).parent_path(); }

struct Shell {
    int rc = -1;
    std::string out;   // stdout and stderr
};

Shell sh(const std::string& command) {
    Shell r;
    FILE* p = ::popen(("(" + command + ") 2>&1").c_str(), "r");
    if (!p) return r;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
    const int status = ::pclose(p);
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

bool have(const std::string& tool) { return sh("command -v " + tool + " >/dev/null").rc == 0; }

// A fresh temporary folder, removed when the test ends (also when an ASSERT returns).
struct ScratchDir {
    fs::path path;
    explicit ScratchDir(const std::string& name) : path(temp_dir(name)) {}
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// Installs the build once per test program into a fresh prefix, removed at exit.
const fs::path& installed_prefix() {
    struct Prefix {
        fs::path path = temp_dir("install-prefix");
        Prefix() {
            const Shell r = sh(q(CIC_CMAKE_COMMAND) + " --install " + q(build_dir()) + " --prefix " + q(path));
            EXPECT_EQ(r.rc, 0) << r.out;
        }
        ~Prefix() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    };
    static const Prefix prefix;
    return prefix.path;
}

} // namespace

TEST(Install, LaysOutEveryFile) {
    const fs::path& p = installed_prefix();
    for (const char* f : {"bin/cic", "share/cic/settings/r1_settings.xml", "share/cic/settings/symreg_settings.xml",
                          "share/cic/settings/robots/r1.xml", "share/cic/settings/robots/snake.xml",
                          "share/cic/settings/cic-settings.xsd", "share/cic/settings/cic-sweep.xsd",
                          "share/cic/examples/tournament-sweep.xml", "share/doc/cic/README.md",
                          "share/doc/cic/settings.md", "share/doc/cic/install.md", "share/doc/cic/img/r1-best.png",
                          "share/man/man1/cic.1", "share/bash-completion/completions/cic"})
        EXPECT_TRUE(fs::is_regular_file(p / f)) << f;
    EXPECT_EQ(fs::status(p / "bin/cic").permissions() & fs::perms::owner_exec, fs::perms::owner_exec);
    // Every shipped settings file and robot is there.
    for (const char* sub : {"settings", "settings/robots"}) {
        for (const auto& e : fs::directory_iterator(fs::path(CIC_SOURCE_DIR) / sub)) {
            if (e.path().extension() == ".xml") {
                EXPECT_TRUE(fs::is_regular_file(p / "share/cic" / sub / e.path().filename())) << e.path();
            }
        }
    }
    // The installed example names its base settings where they are installed.
    const std::string example = read_text(p / "share/cic/examples/tournament-sweep.xml");
    EXPECT_HAS(example, "<base>../settings/r1_settings.xml</base>");
    EXPECT_TRUE(fs::is_regular_file(p / "share/cic/examples/../settings/r1_settings.xml"));
}

// The thesis released cic under the Lesser GPL (chapter 8): the licence says
// which version, and a citation file cites the thesis and the software.
TEST(Install, LicenceAndCitationAreInstalled) {
    const fs::path doc = installed_prefix() / "share/doc/cic";
    const std::string licence = read_text(doc / "LICENSE");
    EXPECT_HAS(licence, "GNU Lesser General Public License as published by the Free Software\nFoundation, either version 3");
    EXPECT_HAS(licence, "GNU LESSER GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007");
    EXPECT_HAS(read_text(doc / "COPYING"), "GNU GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007");
    const std::string cff = read_text(doc / "CITATION.cff");
    for (const char* line : {"cff-version: 1.2.0\n", "license: LGPL-3.0-or-later\n", "  type: thesis\n",
                             "  title: \"Neuroevolutionary Design of Control Strategy of a Multi-Legged Robot\"\n",
                             "  year: 2013\n"})
        EXPECT_HAS(cff, line);
    EXPECT_HAS(cff, std::string("version: ") + CIC_VERSION + "\n");
}

TEST(Install, InstalledBinaryFindsItsSettingsFromAnyFolder) {
    const fs::path& p = installed_prefix();
    ASSERT_TRUE(fs::is_regular_file(p / "bin/cic"));
    const ScratchDir scratch("install-run");   // unrelated to prefix and source tree
    const fs::path& work = scratch.path;
    const Shell r = sh("cd " + q(work) + " && " + q(p / "bin/cic") +
                       " --settings r1_settings.xml --set GP.generatedPopulationSize=6"
                       " --set Control.maximumIterations=2 --set Simulator.sample_to=3 --quiet --output out");
    EXPECT_EQ(r.rc, 0) << r.out;
    const fs::path used = fs::canonical(p / "share/cic/settings/r1_settings.xml");
    EXPECT_HAS(r.out, "cic: settings r1_settings.xml: using " + used.string());
    ASSERT_TRUE(fs::is_directory(work / "out")) << r.out;
    const fs::path run = cic::testing::only_run(work / "out");
    EXPECT_TRUE(fs::is_regular_file(run / "population.xml")) << run;
    EXPECT_TRUE(fs::is_regular_file(run / "stats.csv")) << run;
}

// Videos and strips from an installed cic: the scripts are installed beside it
// and use the cic next to them, not one of the build tree or PATH.
TEST(Install, VideoAndStripScriptsWorkFromTheInstalledCic) {
    const fs::path& p = installed_prefix();
    for (const char* f : {"bin/cic-render-video", "bin/cic-screenshot-strip"}) {
        ASSERT_TRUE(fs::is_regular_file(p / f)) << f;
        EXPECT_EQ(fs::status(p / f).permissions() & fs::perms::owner_exec, fs::perms::owner_exec) << f;
    }
    EXPECT_HAS(sh(q(p / "bin/cic-render-video") + " --help").out, "Render the POV-Ray scenes");
    if (!have("ffmpeg") || (!std::getenv("DISPLAY") && !have("xvfb-run"))) GTEST_SKIP() << "no ffmpeg or no X";
    const ScratchDir scratch("install-strip");
    const auto run = cic::testing::run_settings(scratch.path, "tiny", cic::testing::tiny_hypergp_settings(1, 1));
    ASSERT_EQ(run.rc, 0) << run.log;
    // PATH without the build folder, no CIC: the installed script must find the installed cic.
    const Shell strip = sh("env -u CIC PATH=/usr/bin:/bin ASAN_OPTIONS=detect_leaks=0 " + q(p / "bin/cic-screenshot-strip") +
                           " " + q(run.run) + " " + q(scratch.path / "strip.png") + " --at '0.5 1' --width 120 --height 90");
    ASSERT_EQ(strip.rc, 0) << strip.out;
    EXPECT_TRUE(fs::is_regular_file(scratch.path / "strip.png")) << strip.out;
}

TEST(Install, InstalledBinaryNamesThePlacesItLookedIn) {
    const fs::path& p = installed_prefix();
    const ScratchDir scratch("install-missing");
    const fs::path& work = scratch.path;
    const Shell r = sh("cd " + q(work) + " && " + q(p / "bin/cic") + " --settings no_such_settings.xml --quiet");
    EXPECT_EQ(r.rc, 2) << r.out;
    EXPECT_HAS(r.out, "no_such_settings.xml");
    EXPECT_HAS(r.out, (fs::canonical(p) / "share/cic/settings").string());
    EXPECT_EQ(r.out.find(std::string(CIC_SOURCE_DIR) + "/settings"), std::string::npos)
        << "an installed cic searched the source tree it was built from:\n" << r.out;
    EXPECT_FALSE(fs::exists(work / "runs"));
}

// cic as a CMake package: examples/library, an out-of-tree project, builds
// against the installed cic with find_package(cic) and scores a genotype as a
// cic run does, bit for bit.
TEST(Install, LibraryPackageBuildsAnOutOfTreeProject) {
    const fs::path& p = installed_prefix();
    for (const char* f : {"lib/cmake/cic/cicConfig.cmake", "lib/cmake/cic/cicConfigVersion.cmake",
                          "lib/libcic_experiments.a", "include/cic/sim/cpg.hpp",
                          "include/cic/experiments/hypergp/model.hpp"})
        EXPECT_TRUE(fs::is_regular_file(p / f)) << f;
    EXPECT_TRUE(fs::is_regular_file(p / "include/cic/cli/cli.hpp")) << "an own type runs through cic's command line";
    const ScratchDir scratch("install-library");
    const fs::path build = scratch.path / "build";
    const Shell made = sh(q(CIC_CMAKE_COMMAND) + " -S " + q(fs::path(CIC_SOURCE_DIR) / "examples/library") + " -B " +
                          q(build) + " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + q(p) + " '-DCMAKE_CXX_FLAGS=" +
                          CIC_EXAMPLE_CXX_FLAGS + "' && " +
                          q(CIC_CMAKE_COMMAND) + " --build " + q(build));
    ASSERT_EQ(made.rc, 0) << made.out;
    const char* tree = "(sin (add x0 (mul x2 x3)))";
    const Shell ran = sh(q(build / "cpg-walk") + " '" + tree + "'");
    ASSERT_EQ(ran.rc, 0) << ran.out;
    cic::io::Settings settings;
    settings.neural.substrate = "cpg";
    const auto outcome = cic::hypergp::run(cic::hypergp::Model::from_settings(settings),
                                           cic::tree::Forest{cic::tree::Tree::parse(tree)});
    EXPECT_EQ(std::stod(ran.out), outcome.fitness) << ran.out;
}

// examples/plugin: an experiment type of its own (`straight`, with a settings
// section of its own), built against the installed package, run through cic's
// command line; its stored fitness is its own score of the replayed genotype.
// The parent's fitness of a one-plus-lambda checkpoint (<parent fitness="F">).
std::string killed_parent_fitness(const std::string& xml) {
    const std::size_t at = xml.find("<parent fitness=\"") + 17;
    return xml.substr(at, xml.find('"', at) - at);
}

TEST(Install, PluginTypeBuildsAndRunsThroughCicsCommandLine) {
    const fs::path& p = installed_prefix();
    const ScratchDir scratch("install-plugin");
    const fs::path build = scratch.path / "build";
    const fs::path example = fs::path(CIC_SOURCE_DIR) / "examples/plugin";
    const Shell made = sh(q(CIC_CMAKE_COMMAND) + " -S " + q(example) + " -B " + q(build) +
                          " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + q(p) + " '-DCMAKE_CXX_FLAGS=" +
                          CIC_EXAMPLE_CXX_FLAGS + "' && " + q(CIC_CMAKE_COMMAND) + " --build " + q(build));
    ASSERT_EQ(made.rc, 0) << made.out;
    const std::string cic = q(build / "straight-cic");

    // Its own key is as strict as any other: out of range, exit 2.
    const Shell bad = sh(cic + " settings " + q(example / "straight_r1.xml") + " --set StraightWalk.driftWeight=-1");
    EXPECT_EQ(bad.rc, 2) << bad.out;
    EXPECT_HAS(bad.out, "<StraightWalk> driftWeight");

    const fs::path runs = scratch.path / "runs";
    const Shell ran = sh("cd " + q(scratch.path) + " && " + cic + " --quiet --settings " + q(example / "straight_r1.xml") +
                         " --set Control.maximumIterations=2 --set GP.generatedPopulationSize=6 --set Experiment.workers=2" +
                         " --output " + q(runs));
    ASSERT_EQ(ran.rc, 0) << ran.out;
    const fs::path run = runs / "straight_r1-001";
    EXPECT_HAS(read_text(run / "settings.xml"), "<driftWeight>2</driftWeight>");
    const cic::io::PopulationFile pop = cic::io::load_population(run / "population.xml");
    EXPECT_EQ(pop.experiment, "straight");
    const cic::gp::Individual& best = pop.population.best();
    // The plugin's model is HyperGP's default (R1); its score: along - 2 * across.
    const auto model = cic::hypergp::Model::from_settings(cic::io::Settings{});
    const auto o = cic::hypergp::run(model, best.genotype);
    const std::size_t a = model.robot.preferred == cic::sim::Axis::X ? 0 : 1;
    const double along = std::fabs(o.result.end[a] - o.result.start[a]);
    const double across = std::fabs(o.result.end[1 - a] - o.result.start[1 - a]);
    EXPECT_EQ(best.fitness, along - 2.0 * across);
    EXPECT_NE(best.fitness, o.fitness) << "scored as eq. 7.1, not by the plugin";

    // Its controller, `square`, with the built-in type: the run's best replays
    // (`assess`, through make_controller) to its stored fitness, which the
    // built-in gait substrate would not give.
    const fs::path square_runs = scratch.path / "square";
    const Shell sq = sh(cic + " --quiet --settings " + q(example / "straight_r1.xml") +
                        " --set Experiment.type=hypergp --set Neural.substrate=square --set Control.maximumIterations=2" +
                        " --set GP.generatedPopulationSize=6 --set Experiment.workers=2 --output " + q(square_runs));
    ASSERT_EQ(sq.rc, 0) << sq.out;
    const fs::path square_run = square_runs / "straight_r1-001";
    const cic::io::PopulationFile square_pop = cic::io::load_population(square_run / "population.xml");
    const Shell assessed = sh(cic + " --quiet assess " + q(square_run) + " --out " + q(scratch.path / "gaits.csv"));
    ASSERT_EQ(assessed.rc, 0) << assessed.out;
    const std::string gaits = read_text(scratch.path / "gaits.csv");
    const std::string row = gaits.substr(gaits.find('\n') + 1);
    const std::string replayed = row.substr(row.find(',') + 1, row.find(',', row.find(',') + 1) - row.find(',') - 1);
    EXPECT_EQ(std::stod(replayed), square_pop.population.best().fitness) << gaits;
    cic::io::Settings as_gait;
    as_gait.neural.substrate = "gait";
    const auto g = cic::hypergp::run(cic::hypergp::Model::from_settings(as_gait), square_pop.population.best().genotype);
    EXPECT_NE(g.fitness, square_pop.population.best().fitness) << "the square wave was not used";

    // Its `circle` type scores the whole walk (the centre's path, asked for
    // through WalkNeeds): 1 and 2 workers give the same bytes, and the run's best
    // replays (`assess`) to its stored fitness, which eq. 7.1 is not.
    std::string circle_bytes[2];
    fs::path circle_run;
    for (int w : {1, 2}) {
        const fs::path out = scratch.path / ("circle-" + std::to_string(w));
        const Shell c = sh(cic + " --quiet --settings " + q(example / "circle_r1.xml") +
                           " --set Control.maximumIterations=2 --set GP.generatedPopulationSize=6" +
                           " --set Simulator.sample_to=4 --set Experiment.workers=" + std::to_string(w) +
                           " --output " + q(out));
        ASSERT_EQ(c.rc, 0) << c.out;
        circle_run = out / "circle_r1-001";
        circle_bytes[w - 1] = read_text(circle_run / "population.xml");
    }
    EXPECT_EQ(circle_bytes[0], circle_bytes[1]);
    const cic::io::PopulationFile circle_pop = cic::io::load_population(circle_run / "population.xml");
    EXPECT_EQ(circle_pop.experiment, "circle");
    const Shell judged = sh(cic + " --quiet assess " + q(circle_run) + " --out " + q(scratch.path / "circle.csv"));
    ASSERT_EQ(judged.rc, 0) << judged.out;
    std::istringstream csv(read_text(scratch.path / "circle.csv"));
    std::string header, line;
    std::getline(csv, header);
    std::getline(csv, line);
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 10u) << header << "\n" << line;
    const double circle_best = circle_pop.population.best().fitness;
    EXPECT_EQ(std::stod(cells[1]), circle_best) << "replayed with eq. 7.1, not the type's own score: " << line;
    EXPECT_NE(std::stod(cells[8]), circle_best) << "raw_fitness (eq. 7.1) should differ from the circle score: " << line;
    EXPECT_GT(circle_best, 0.0);

    // Its search, `one-plus-lambda` (a (1+lambda)-ES of its own file), runs in
    // cic's one loop: its key is strict, it refuses trees, 1 and 2 workers give
    // the same bytes, and a run killed with SIGKILL and resumed (`cic resume`)
    // ends in the bytes of one that was never stopped.
    const fs::path ol = example / "one_plus_lambda_r1.xml";
    const std::string quick = " --set Simulator.sample_to=2 --set Simulator.delayed_start=0.5";
    const Shell bad_lambda = sh(cic + " settings " + q(ol) + " --set OnePlusLambda.lambda=0");
    EXPECT_EQ(bad_lambda.rc, 2) << bad_lambda.out;
    EXPECT_HAS(bad_lambda.out, "<OnePlusLambda> lambda");
    const Shell on_trees = sh(cic + " settings " + q(example / "straight_r1.xml") + " --set Experiment.search=one-plus-lambda");
    EXPECT_EQ(on_trees.rc, 2) << on_trees.out;
    EXPECT_HAS(on_trees.out, "Experiment.search = one-plus-lambda varies gait vectors");
    std::string search_bytes[2];
    for (int w : {1, 2}) {
        const fs::path out = scratch.path / ("ol-" + std::to_string(w));
        const Shell r = sh(cic + " --quiet --settings " + q(ol) + quick + " --set OnePlusLambda.evaluations=49" +
                           " --set Experiment.workers=" + std::to_string(w) + " --output " + q(out));
        ASSERT_EQ(r.rc, 0) << r.out;
        search_bytes[w - 1] = read_text(out / "one_plus_lambda_r1-001" / "population.xml");
        const std::string stats = read_text(out / "one_plus_lambda_r1-001" / "stats.csv");
        EXPECT_HAS(stats, ",sigma\n");
        EXPECT_EQ(std::count(stats.begin(), stats.end(), '\n'), 8) << stats;   // header, generations 0..6
    }
    EXPECT_HAS(search_bytes[0], "format=\"cic-one-plus-lambda\"");
    EXPECT_HAS(search_bytes[0], "<origin");
    EXPECT_EQ(search_bytes[0], search_bytes[1]);
    const std::string long_run = quick + " --set OnePlusLambda.evaluations=801 --set Experiment.workers=1";
    const Shell whole = sh(cic + " --quiet --settings " + q(ol) + long_run + " --output " + q(scratch.path / "ol-whole"));
    ASSERT_EQ(whole.rc, 0) << whole.out;
    const fs::path killed = scratch.path / "ol-killed" / "one_plus_lambda_r1-001";
    const Shell kill9 = sh(cic + " --quiet --settings " + q(ol) + long_run + " --output " + q(scratch.path / "ol-killed") +
                           " & p=$!; while kill -0 $p 2>/dev/null && [ ! -e " + q(killed / "populations" / "gen-0005.xml") +
                           " ]; do sleep 0.02; done; kill -9 $p; wait $p; true");
    ASSERT_TRUE(fs::exists(killed / "population.xml")) << kill9.out;
    ASSERT_FALSE(fs::exists(killed / "summary.txt")) << "the run ended before it was killed";
    // Its checkpoint schema is checked before its reader runs: an unknown attribute, exit 2, nothing written.
    const std::string saved = read_text(killed / "population.xml");
    std::string broken = saved;
    broken.replace(broken.find(" sigma=\""), 1, " sigmaX=\"0\" ");
    cic::testing::write_text(scratch.path / "broken.xml", broken);
    const Shell refused = sh(cic + " --quiet --settings " + q(ol) + long_run + " --output " + q(scratch.path / "ol-broken") +
                             " --set Control.populationXmlLoadFrom=" + q(scratch.path / "broken.xml"));
    EXPECT_EQ(refused.rc, 2) << refused.out;
    EXPECT_HAS(refused.out, "does not match the one-plus-lambda search's checkpoint schema");
    EXPECT_FALSE(fs::exists(scratch.path / "ol-broken")) << "a refusal wrote a run folder";
    const Shell resumed = sh(cic + " --quiet resume " + q(killed));
    ASSERT_EQ(resumed.rc, 0) << resumed.out;
    EXPECT_EQ(read_text(killed / "population.xml"), read_text(scratch.path / "ol-whole" / "one_plus_lambda_r1-001" / "population.xml"));
    // `assess` replays its best (the search's SearchKind::best) to the fitness the run stored.
    const Shell ol_assessed = sh(cic + " --quiet assess " + q(killed) + " --out " + q(scratch.path / "ol.csv"));
    ASSERT_EQ(ol_assessed.rc, 0) << ol_assessed.out;
    const std::string ol_csv = read_text(scratch.path / "ol.csv");
    const std::string ol_row = ol_csv.substr(ol_csv.find('\n') + 1);
    const std::string stored = killed_parent_fitness(read_text(killed / "population.xml"));
    EXPECT_EQ(std::stod(ol_row.substr(ol_row.find(',') + 1)), std::stod(stored)) << ol_csv;
    // `export` gives a row per saved checkpoint of its own format: the best it keeps, id 0.
    const fs::path ol_whole = scratch.path / "ol-whole" / "one_plus_lambda_r1-001";
    const Shell exported = sh(cic + " --quiet export " + q(ol_whole) + " --out " + q(scratch.path / "ol-export.csv"));
    ASSERT_EQ(exported.rc, 0) << exported.out;
    const std::string ol_export = read_text(scratch.path / "ol-export.csv");
    const auto saved_files = std::distance(fs::directory_iterator(ol_whole / "populations"), fs::directory_iterator());
    EXPECT_EQ(std::count(ol_export.begin(), ol_export.end(), '\n'), saved_files + 1) << ol_export;
    std::vector<std::string> last;
    std::istringstream last_row(ol_export.substr(ol_export.rfind('\n', ol_export.size() - 2) + 1));
    for (std::string c; std::getline(last_row, c, ',');) last.push_back(c);
    ASSERT_GE(last.size(), 6u) << ol_export;
    EXPECT_EQ(last[4], "0");
    EXPECT_EQ(std::stod(last[5]), std::stod(killed_parent_fitness(read_text(ol_whole / "population.xml")))) << ol_export;
}

// The Python package (docs/python.md) from an installed prefix: found with
// PYTHONPATH at PREFIX/lib/python3.X/dist-packages, it runs the installed cic as
// its workers and finds the installed settings, from a folder unrelated to both.
TEST(Install, PythonPackageImportsFromThePrefixAndScores) {
#ifndef CIC_HAVE_PYTHON
    GTEST_SKIP() << "built without the Python package (CIC_WITH_PYTHON)";
#else
    const fs::path& p = installed_prefix();
    fs::path site;
    for (const auto& e : fs::directory_iterator(p / "lib"))
        if (e.path().filename().string().rfind("python3.", 0) == 0) site = e.path() / "dist-packages";
    ASSERT_TRUE(fs::exists(site / "cic" / "__init__.py")) << "no package under " << (p / "lib");
    const ScratchDir scratch("install-python");
    const Shell r = sh("cd " + q(scratch.path) + " && env -u CIC_EXECUTABLE PYTHONPATH=" + q(site) +
                       " /usr/bin/python3 -c \"import cic, importlib.metadata; ev = cic.Evaluator('r1_gait.xml', "
                       "set={'Simulator.sample_to': 1, 'Simulator.delayed_start': 0}); print(cic.executable()); print(ev.settings_file); "
                       "print(len(ev.evaluate([[0.5] * ev.dimension]).fitness)); "
                       "print('version', cic.__version__, importlib.metadata.version('cic'))\" 2>&1");
    ASSERT_EQ(r.rc, 0) << r.out;
    // A Python package to Python: its version (a dist-info), its type stubs and py.typed.
    EXPECT_HAS(r.out, std::string("version ") + CIC_VERSION + " " + CIC_VERSION + "\n");
    EXPECT_TRUE(fs::exists(site / "cic" / "__init__.pyi"));
    EXPECT_TRUE(fs::exists(site / "cic" / "py.typed"));
    EXPECT_HAS(r.out, (p / "bin" / "cic").string() + "\n");
    EXPECT_HAS(r.out, (p / "share" / "cic" / "settings" / "r1_gait.xml").string() + "\n");
    EXPECT_HAS(r.out, "\n1\n");
#endif
}

TEST(Install, DebianPackage) {
    if (!have(q(CIC_CPACK_COMMAND)) || !have("dpkg-deb")) GTEST_SKIP() << "cpack or dpkg-deb missing";
    const ScratchDir scratch("install-deb");
    const fs::path& out = scratch.path;
    const Shell made =
        sh(q(CIC_CPACK_COMMAND) + " -G DEB --config " + q(build_dir() / "CPackConfig.cmake") + " -B " + q(out));
    ASSERT_EQ(made.rc, 0) << made.out;
    fs::path deb;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().extension() == ".deb") deb = e.path();
    ASSERT_FALSE(deb.empty()) << made.out;
    EXPECT_EQ(deb.filename().string().rfind(std::string("cic_") + CIC_VERSION + "_", 0), 0u) << deb;

    const Shell info = sh("dpkg-deb --info " + q(deb));
    ASSERT_EQ(info.rc, 0) << info.out;
    EXPECT_HAS(info.out, "Package: cic\n");
    EXPECT_HAS(info.out, std::string("Version: ") + CIC_VERSION + "\n");
    EXPECT_HAS(info.out, "Section: science\n");
    EXPECT_HAS(info.out, "Maintainer: ");
    const auto depends_at = info.out.find("Depends: ");
    ASSERT_NE(depends_at, std::string::npos) << info.out;
    const std::string depends = info.out.substr(depends_at, info.out.find('\n', depends_at) - depends_at);
    EXPECT_HAS(depends, "libode");
    EXPECT_HAS(depends, "libxml2");
    EXPECT_HAS(depends, "libc6");
    EXPECT_HAS(depends, "gnuplot");
    EXPECT_HAS(info.out, "Recommends: povray, ffmpeg\n");

    const Shell contents = sh("dpkg-deb --contents " + q(deb));
    ASSERT_EQ(contents.rc, 0) << contents.out;
    for (const char* f : {"./usr/bin/cic", "./usr/share/cic/settings/r1_settings.xml",
                          "./usr/share/cic/settings/robots/r1.xml", "./usr/share/cic/settings/cic-settings.xsd",
                          "./usr/share/cic/examples/tournament-sweep.xml", "./usr/share/doc/cic/README.md",
                          "./usr/share/bash-completion/completions/cic"})
        EXPECT_HAS(contents.out, std::string(f) + "\n");
#ifdef CIC_HAVE_PYTHON
    // The Python package where Debian's python3 finds it, with its core module.
    EXPECT_HAS(contents.out, "./usr/lib/python3/dist-packages/cic/__init__.py\n");
    EXPECT_HAS(contents.out, "./usr/lib/python3/dist-packages/cic/_core.cpython-");
    EXPECT_HAS(contents.out, "./usr/lib/python3/dist-packages/cic-" CIC_VERSION ".dist-info/METADATA\n");
    EXPECT_HAS(contents.out, "./usr/lib/python3/dist-packages/cic/py.typed\n");
#endif
    EXPECT_TRUE(contents.out.find("./usr/share/man/man1/cic.1\n") != std::string::npos ||
                contents.out.find("./usr/share/man/man1/cic.1.gz\n") != std::string::npos)
        << contents.out;
    EXPECT_EQ(contents.out.find("./usr/local/"), std::string::npos) << contents.out;
}

TEST(Install, ManPageIsMadeFromTheCliAndRendersCleanly) {
    const Shell man = sh(q(cic::testing::cic_binary()) + " man 2>/dev/null");
    ASSERT_EQ(man.rc, 0) << man.out;
    // The build installs what `cic man` prints (one source of truth).
    EXPECT_EQ(read_text(build_dir() / "generated/cic.1"), man.out);
    for (const char* part : {".TH CIC 1", ".SH NAME", ".SH SYNOPSIS", ".SH DESCRIPTION", ".SH OPTIONS",
                             ".SH COMMANDS", ".SH SETTINGS", ".SH EXIT STATUS", ".SH FILES", ".SH SEE ALSO",
                             ".SS settings", ".SS sweep", ".SS compare", ".B 130", ".B 143", "\\-\\-settings"})
        EXPECT_HAS(man.out, part);
    for (const auto& k : cic::io::settings_table()) EXPECT_HAS(man.out, "\\fB" + k.section + "." + k.key + "\\fR");
    for (const char* listed : {".SS help", ".SS man", ".SS completion"}) EXPECT_HAS(man.out, listed);
    EXPECT_EQ(man.out.find(".SS worker"), std::string::npos);   // the hidden command stays hidden

    if (!have("groff")) GTEST_SKIP() << "groff missing: rendering not checked";
    const ScratchDir scratch("install-man");
    const fs::path& dir = scratch.path;
    cic::testing::write_text(dir / "cic.1", man.out);
    const Shell rendered = sh("groff -man -Tutf8 -ww -z " + q(dir / "cic.1"));
    EXPECT_EQ(rendered.rc, 0);
    EXPECT_EQ(rendered.out, "") << "groff warnings";
}

TEST(Install, CompletionScriptIsValidBashAndCompletes) {
    const Shell script = sh(q(cic::testing::cic_binary()) + " completion 2>/dev/null");
    ASSERT_EQ(script.rc, 0) << script.out;
    EXPECT_EQ(read_text(build_dir() / "generated/cic.bash-completion"), script.out);
    const ScratchDir scratch("install-completion");
    const fs::path& dir = scratch.path;
    cic::testing::write_text(dir / "cic", script.out);
    const Shell syntax = sh("bash -n " + q(dir / "cic"));
    EXPECT_EQ(syntax.rc, 0) << syntax.out;

    // Runs the completion function as bash would for COMP_LINE; prints COMPREPLY.
    cic::testing::write_text(dir / "complete.sh", R"(source "$1"
COMP_LINE=$2; COMP_POINT=${#2}
_cic
printf '%s\n' "${COMPREPLY[@]}"
)");
    auto complete = [&](const std::string& line) {
        return sh("cd " + q(dir) + " && bash complete.sh cic " + q(line)).out;
    };
    const std::string commands = complete("cic ");
    for (const char* c : {"settings\n", "simulate\n", "plot\n", "compare\n", "sweep\n", "help\n", "man\n"})
        EXPECT_HAS(commands, c);
    EXPECT_EQ(commands.find("worker\n"), std::string::npos);   // internal
    EXPECT_HAS(complete("cic --se"), "--settings\n");
    EXPECT_HAS(complete("cic sweep --"), "--dry-run\n");
    EXPECT_HAS(complete("cic --set GP.tour"), "GP.tournament_size=\n");
    EXPECT_HAS(complete("cic --set Experiment.type="), "hypergp\n");
    EXPECT_HAS(complete("cic --settings co"), "complete.sh\n");   // file names
    const std::string keys = complete("cic --set ");
    for (const auto& k : cic::io::settings_table()) EXPECT_HAS(keys, k.section + "." + k.key + "=\n");
}

TEST(SettingsLookup, GivenPathWinsThenInstalledThenSourceTree) {
    const ScratchDir scratch("settings-lookup");
    const fs::path& dir = scratch.path;
    struct InFolder {   // back to the old current folder before the scratch folder goes
        fs::path old = fs::current_path();
        explicit InFolder(const fs::path& d) { fs::current_path(d); }
        ~InFolder() { fs::current_path(old); }
    } in_dir(dir);
    cic::testing::write_text(dir / "mine.xml", "<settings/>");
    EXPECT_EQ(cic::run::find_settings_file("mine.xml"), fs::path("mine.xml"));
    EXPECT_EQ(cic::run::find_settings_file((dir / "mine.xml").string()), dir / "mine.xml");
    // Not here: the source tree's settings/ (a test binary has no share/cic next to it).
    EXPECT_EQ(cic::run::find_settings_file("r1_settings.xml"),
              fs::canonical(fs::path(CIC_SOURCE_DIR) / "settings/r1_settings.xml"));
    EXPECT_EQ(cic::run::find_settings_file("robots/r1.xml"),
              fs::canonical(fs::path(CIC_SOURCE_DIR) / "settings/robots/r1.xml"));
    try {
        cic::run::find_settings_file("nowhere.xml");
        ADD_FAILURE() << "no InputError";
    } catch (const cic::InputError& e) {
        const std::string what = e.what();
        EXPECT_HAS(what, "nowhere.xml");
        EXPECT_HAS(what, (dir / "nowhere.xml").string());
        for (const auto& folder : cic::run::settings_search_folders()) EXPECT_HAS(what, folder.string());
    }
    // An absolute path is never looked up elsewhere.
    EXPECT_THROW(cic::run::find_settings_file((dir / "r1_settings.xml").string()), cic::InputError);
    // The path cic execs for its workers (cic eval's) stands for the file it names, not /proc/share/cic.
    EXPECT_EQ(cic::run::settings_search_folders("/proc/self/exe"), cic::run::settings_search_folders());
    EXPECT_EQ(cic::run::find_settings_file("r1_settings.xml", "/proc/self/exe"),
              fs::canonical(fs::path(CIC_SOURCE_DIR) / "settings/r1_settings.xml"));
}
