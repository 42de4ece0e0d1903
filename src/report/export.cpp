// Every individual of every saved generation as CSV (export.hpp).
#include "cic/report/export.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/gp/individual.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/report/plot.hpp"
#include "cic/report/replay.hpp"
#include "cic/sim/evaluate.hpp"

namespace cic::report {
namespace {

namespace fs = std::filesystem;

std::string cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string number(double v) { return fmt::format("{}", v); }

// A run's saved generations, oldest first.
std::vector<fs::path> saved_generations(const fs::path& run) {
    std::vector<fs::path> files;
    if (fs::is_directory(run / "populations"))
        for (const auto& e : fs::directory_iterator(run / "populations"))
            if (e.path().extension() == ".xml" && e.path().filename().string().rfind("gen-", 0) == 0)
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A MAP-Elites run: the elites of its last archive, in cell order.
void export_elites(const fs::path& run, const io::Settings& s, const std::string& prefix, bool terms, std::string& csv) {
    if (!fs::exists(run / "population.xml")) return;   // no batch finished yet
    const io::ArchiveFile a = io::load_archive(run / "population.xml");
    const bool gait = io::family_of(s) == io::ExperimentFamily::Gait;
    std::optional<gait::Setup> setup;
    std::optional<hypergp::Model> model;
    if (terms && gait) setup = gait::Setup::from_settings(s);
    if (terms && !gait) model = hypergp::Model::from_settings(s);
    for (const io::ArchiveElite& e : a.elites) {
        std::string solution, descriptor;
        for (double x : e.x) solution += (solution.empty() ? "" : " ") + number(x);
        for (const auto& t : e.genotype) solution += (solution.empty() ? "" : " | ") + t.to_string();
        for (double v : e.descriptor) descriptor += (descriptor.empty() ? "" : " ") + number(v);
        std::string dist, elev, depth, size;
        if (setup) {
            const auto controller = setup->controller(e.x);
            const auto [d, z] = eq71_terms(setup->robot, sim::evaluate(setup->robot, *controller, setup->sim));
            dist = number(d), elev = number(z);
        } else if (model) {
            const auto [d, z] = eq71_terms(model->robot, hypergp::run(*model, e.genotype).result);
            dist = number(d), elev = number(z);
        }
        if (!gait) {
            depth = std::to_string(gp::forest_depth(e.genotype, s.gp.forest_depth));
            size = std::to_string(tree::total_size(e.genotype));
        }
        csv += prefix + fmt::format("{},{},{},{},{},{},{},0,{},{},{}\n", a.batches - 1, e.cell, number(e.fitness), dist,
                                    elev, depth, size, cell(solution), cell(a.grid.cell_name(e.cell)), cell(descriptor));
    }
}

// A search registered from outside keeps its own checkpoint files: each saved
// one gives the individual its reader names (its best), numbered as the file is.
// `seen`: eq. 7.1's terms of each genotype already replayed in this run.
void export_foreign(const std::vector<fs::path>& files, const io::Settings& s, const CheckpointBestReader& reader,
                    const std::string& prefix, bool terms, std::map<std::string, std::pair<double, double>>& seen,
                    std::string& csv) {
    std::optional<gait::Setup> setup;
    std::optional<hypergp::Model> model;
    for (const fs::path& file : files) {
        const CheckpointBest best = read_checkpoint_best(reader, s, file.string());
        const std::string digits = file.stem().string().substr(4);   // gen-NNNN
        if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
            throw InputError("a saved generation is named gen-NUMBER.xml", file.string());
        std::string solution, depth, size;
        for (const auto& t : best.trees) solution += (solution.empty() ? "" : " | ") + t.to_string();
        if (!best.trees.empty()) {
            depth = std::to_string(gp::forest_depth(best.trees, s.gp.forest_depth));
            size = std::to_string(tree::total_size(best.trees));
        }
        std::string key = solution;   // the genotype: a gait, or trees and their direct offsets
        for (double x : best.x) key += " " + number(x);
        if (best.trees.empty()) solution = key.substr(key.empty() ? 0 : 1);
        std::string dist, elev;
        if (terms) {
            auto [it, fresh] = seen.try_emplace(key);
            if (fresh && best.trees.empty()) {
                if (!setup) setup.emplace(gait::Setup::from_settings(s));
                const auto controller = setup->controller(best.x);
                it->second = eq71_terms(setup->robot, sim::evaluate(setup->robot, *controller, setup->sim));
            } else if (fresh) {
                if (!model) model.emplace(hypergp::Model::from_settings(s));
                it->second = eq71_terms(model->robot, hypergp::run(*model, best.trees, best.x).result);
            }
            dist = number(it->second.first), elev = number(it->second.second);
        }
        csv += prefix + fmt::format("{},0,{},{},{},{},{},0,{},,\n", std::stoi(digits), number(best.fitness), dist,
                                    elev, depth, size, cell(solution));
    }
}

void export_run(const fs::path& run, const std::string& label, const std::string& config, const std::string& seed,
                bool terms, std::string& csv) {
    if (!fs::is_regular_file(run / "settings.xml"))
        throw InputError("not a run folder (no settings.xml) nor a study (no index.csv): " + run.string());
    const io::Settings s = io::read_settings(run / "settings.xml");
    const std::string prefix = cell(label) + "," + cell(config) + "," + seed + ",";
    const io::ExperimentFamily family = io::family_of(s);
    std::map<std::string, std::pair<double, double>> seen;   // genotype -> terms, once per run
    const std::vector<fs::path> saved = saved_generations(run);
    if (!saved.empty())
        if (const CheckpointBestReader* reader = checkpoint_reader_for(saved.front().string()))
            return export_foreign(saved, s, *reader, prefix, terms, seen, csv);
    if (s.map_elites.enabled) return export_elites(run, s, prefix, terms, csv);

    // A gait run's checkpoints, and a Switch-HybrID run's after its hand-over
    // (numbered on from the hand-over, as stats.csv numbers them).
    std::optional<gait::Setup> setup;
    if (terms && (family == io::ExperimentFamily::Gait || s.neural.switches())) setup = gait::Setup::from_settings(s);
    auto export_gait = [&](const fs::path& file) {
        const io::GaitFile g = io::load_gait(file);
        for (std::size_t i = 0; i < g.population.size(); ++i) {
            const io::GaitPoint& point = g.population[i];
            std::string params;
            for (double x : point.x) params += (params.empty() ? "" : " ") + number(x);
            std::string dist, elev;
            if (setup) {
                auto [it, fresh] = seen.try_emplace(params);
                if (fresh) {
                    const auto controller = setup->controller(point.x);
                    it->second = eq71_terms(setup->robot, sim::evaluate(setup->robot, *controller, setup->sim));
                }
                dist = number(it->second.first), elev = number(it->second.second);
            }
            const int generation = g.generation + (g.handover ? g.handover->generation + 1 : 0);
            csv += prefix + fmt::format("{},{},{},{},{},,,0,{},,\n", generation, i, number(point.fitness), dist, elev,
                                        cell(params));
        }
    };
    if (family == io::ExperimentFamily::Gait) {
        for (const fs::path& file : saved) export_gait(file);
        return;
    }
    std::optional<hypergp::Model> model;
    if (terms && family == io::ExperimentFamily::HyperGP) model = hypergp::Model::from_settings(s);
    for (const fs::path& file : saved) {
        if (s.neural.switches() && io::is_gait_file(file)) {
            export_gait(file);
            continue;
        }
        const io::PopulationFile pop = io::load_population(file);
        for (const auto& ind : pop.population) {
            std::string trees;
            for (const auto& t : ind->genotype) trees += (trees.empty() ? "" : " | ") + t.to_string();
            std::string dist, elev;
            if (model) {
                std::string key = trees;   // the genotype: trees and direct offsets (Offset-HybrID)
                for (double d : ind->direct) key += fmt::format(" {}", d);
                auto [it, fresh] = seen.try_emplace(key);
                if (fresh)
                    it->second = eq71_terms(model->robot, hypergp::run(*model, ind->genotype, ind->direct).result);
                dist = number(it->second.first), elev = number(it->second.second);
            }
            csv += prefix + fmt::format("{},{},{},{},{},{},{},{},{},,\n", pop.population.generation, ind->id,
                                        number(ind->fitness), dist, elev, ind->depth(s.gp.forest_depth), ind->size(),
                                        ind->failed ? 1 : 0, cell(trees));
        }
    }
}

} // namespace

std::string export_individuals(const ExportRequest& request) {
    std::string csv = kExportHeader;
    for (const fs::path& input : request.inputs) {
        if (is_study_folder(input)) {
            const StudyIndex index = read_study_index(input);
            for (const StudyRun& r : index.runs)
                if (fs::exists(index.run_path(r) / "settings.xml"))
                    export_run(index.run_path(r), (input / r.run_dir).string(), r.config, r.seed, request.terms, csv);
        } else {
            const io::Settings s = fs::is_regular_file(input / "settings.xml") ? io::read_settings(input / "settings.xml")
                                                                               : io::Settings{};
            export_run(input, input.string(), s.experiment.name, std::to_string(s.experiment.seed), request.terms, csv);
        }
    }
    return csv;
}

} // namespace cic::report
