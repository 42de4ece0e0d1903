// A run folder's best genotype (run_genotype.hpp).
#include "cic/report/run_genotype.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"

namespace cic::report {
namespace fs = std::filesystem;

namespace {

// The last gen-N.xml of a Switch-HybrID run that is a HyperGP population: its
// HyperGP phase's last generation.
fs::path last_gp_generation(const fs::path& dir) {
    std::vector<fs::path> gens;
    if (fs::is_directory(dir / "populations"))
        for (const auto& e : fs::directory_iterator(dir / "populations"))
            if (e.path().extension() == ".xml" && e.path().filename().string().rfind("gen-", 0) == 0)
                gens.push_back(e.path());
    std::sort(gens.rbegin(), gens.rend());
    for (const auto& g : gens)
        if (!io::is_gait_file(g)) return g;
    throw InputError("this Switch-HybrID run keeps no checkpoint of its HyperGP phase (populations/gen-*.xml)",
                     dir.string());
}

std::string substrate_name(const io::Settings& s) { return io::find_setting("Neural", "substrate")->get(s); }

void read_archive(RunGenotype& g, const fs::path& checkpoint) {
    const io::Settings& s = g.settings;
    const bool gait = io::family_of(s) == io::ExperimentFamily::Gait;
    const io::ArchiveFile a = io::load_archive(checkpoint);
    std::size_t dimension = 0;
    if (gait) {
        const gait::Setup setup = gait::Setup::from_settings(s);
        g.robot = setup.robot;
        dimension = setup.dimension();
    } else {
        g.robot = hypergp::Model::from_settings(s).robot;
    }
    io::check_compatible(a, s, experiments::map_elites_grid(s, g.robot), dimension, checkpoint.string());
    const io::ArchiveElite* e = a.best();
    if (!e) throw InputError("the archive holds no elite (every evaluation failed)", checkpoint.string());
    g.stored_fitness = e->fitness;
    g.generation = a.batches - 1;
    g.gait = e->x;
    g.trees = e->genotype;
    g.what = gait ? "direct gait (the archive's best elite)"
                  : "HyperGP trees (" + substrate_name(s) + " substrate; the archive's best elite)";
}

void read_gait(RunGenotype& g, const fs::path& checkpoint) {
    const gait::Setup setup = gait::Setup::from_settings(g.settings);
    const io::GaitFile f = io::load_gait(checkpoint);
    io::check_compatible(f, g.settings, setup.dimension(), checkpoint.string());
    g.robot = setup.robot;
    g.gait = f.champion.x;
    g.stored_fitness = f.champion.fitness;
    g.generation = f.generation + (f.handover ? f.handover->generation + 1 : 0);   // as stats.csv counts
    g.what = "direct gait (" + f.optimizer + (f.handover ? ", after Switch-HybrID's hand-over)" : ")");
}

} // namespace

RunGenotype read_run_genotype(const std::string& run_dir, SwitchPhase phase) {
    const fs::path dir(run_dir);
    if (!fs::is_directory(dir)) throw InputError("no such run folder", run_dir);
    if (!fs::is_regular_file(dir / "settings.xml")) throw InputError("not a run folder: it has no settings.xml", run_dir);
    fs::path checkpoint = dir / "population.xml";
    if (!fs::exists(checkpoint))
        throw InputError("the run has no population.xml yet (has it finished a generation?)", run_dir);
    RunGenotype g;
    g.run = run_dir;
    g.settings = io::read_settings(dir / "settings.xml");
    g.robot_file = g.settings.robot.robot_file;
    const io::Settings& s = g.settings;
    if (!io::walks_a_robot(s))
        throw InputError("a symbolic-regression run: only robot runs have a genotype to walk", run_dir);
    if (s.map_elites.enabled) {
        read_archive(g, checkpoint);
        return g;
    }
    const bool gait_checkpoint = s.neural.switches() && io::is_gait_file(checkpoint);
    if (io::genotype_form(s) == io::GenotypeForm::Vector || (gait_checkpoint && phase == SwitchPhase::Latest)) {
        read_gait(g, checkpoint);
        return g;
    }
    if (gait_checkpoint) checkpoint = last_gp_generation(dir);
    const io::PopulationFile pop = io::load_population(checkpoint);
    io::check_compatible(pop, s, checkpoint.string());
    if (pop.population.individuals.empty()) throw InputError("the population is empty", checkpoint.string());
    const auto best = *std::min_element(pop.population.individuals.begin(), pop.population.individuals.end(),
                                        [](const auto& a, const auto& b) { return gp::better(*a, *b); });
    // A growing robot's population was last scored on the body its checkpoint names.
    const std::size_t body = pop.body.value_or(0);
    g.robot = hypergp::Model::from_settings(s).on_body(body).robot;
    if (body > 0) g.robot_file = s.robot.grow_robot_files.at(body - 1);
    g.trees = best->genotype;
    g.offsets = best->direct;
    g.stored_fitness = best->fitness;
    g.generation = pop.population.generation;
    g.what = fmt::format("HyperGP trees ({} substrate{}{})", substrate_name(s),
                         g.offsets.empty() ? "" : ", per-hinge offsets",
                         gait_checkpoint ? fmt::format("; Switch-HybrID's HyperGP phase, generation {}",
                                                       pop.population.generation)
                                         : "");
    return g;
}

} // namespace cic::report
