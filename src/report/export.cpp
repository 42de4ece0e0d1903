// Every individual of every saved generation as CSV (export.hpp).
#include "cic/report/export.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <span>
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
#include "cic/report/verify.hpp"
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

// Eq. 7.1's terms of a run's genotypes, each distinct one replayed once (a gait
// vector, or trees with their direct offsets), as the run's settings score it.
// Off (`enabled` false), every cell is empty. Built on first use: a run's
// checkpoints may hold gaits, trees or both (Switch-HybrID).
class TermsReplay {
public:
    TermsReplay(const io::Settings& s, bool enabled) : settings_(s), enabled_(enabled) {}

    // "distance", "elevation" of a gait vector, or two empty cells.
    std::pair<std::string, std::string> gait(const std::vector<double>& x) {
        if (!enabled_) return {};
        std::string key = "gait";
        for (double v : x) key += " " + number(v);
        return cached(key, [&] {
            if (!setup_) setup_.emplace(gait::Setup::from_settings(settings_));
            const auto controller = setup_->controller(x);
            return eq71_terms(setup_->robot, sim::evaluate(setup_->robot, *controller, setup_->sim));
        });
    }

    // The same of trees and their direct offsets (Offset-HybrID; else empty).
    std::pair<std::string, std::string> trees(const tree::Forest& genotype, std::span<const double> offsets) {
        if (!enabled_) return {};
        std::string key = "trees";
        for (const auto& t : genotype) key += " | " + t.to_string();
        for (double v : offsets) key += " " + number(v);
        return cached(key, [&] {
            if (!model_) model_.emplace(hypergp::Model::from_settings(settings_));
            return eq71_terms(model_->robot, hypergp::run(*model_, genotype, offsets).result);
        });
    }

private:
    template <class Replay>
    std::pair<std::string, std::string> cached(const std::string& key, Replay replay) {
        auto [it, fresh] = seen_.try_emplace(key);
        if (fresh) it->second = replay();
        return {number(it->second.first), number(it->second.second)};
    }

    const io::Settings& settings_;
    bool enabled_;
    std::optional<gait::Setup> setup_;
    std::optional<hypergp::Model> model_;
    std::map<std::string, std::pair<double, double>> seen_;   // genotype -> terms, once per run
};

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
void export_elites(const fs::path& run, const io::Settings& s, const std::string& prefix, TermsReplay& terms,
                   std::string& csv) {
    if (!fs::exists(run / "population.xml")) return;   // no batch finished yet
    const io::ArchiveFile a = io::load_archive(run / "population.xml");
    const bool gait = io::family_of(s) == io::ExperimentFamily::Gait;
    for (const io::ArchiveElite& e : a.elites) {
        std::string solution, descriptor;
        for (double x : e.x) solution += (solution.empty() ? "" : " ") + number(x);
        for (const auto& t : e.genotype) solution += (solution.empty() ? "" : " | ") + t.to_string();
        for (double v : e.descriptor) descriptor += (descriptor.empty() ? "" : " ") + number(v);
        const auto [dist, elev] = gait ? terms.gait(e.x) : terms.trees(e.genotype, {});
        std::string depth, size;
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
void export_foreign(const std::vector<fs::path>& files, const io::Settings& s, const CheckpointBestReader& reader,
                    const std::string& prefix, TermsReplay& terms, std::string& csv) {
    for (const fs::path& file : files) {
        const CheckpointBest best = read_checkpoint_best(reader, s, file.string());
        const std::string digits = file.stem().string().substr(4);   // gen-NNNN
        if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
            throw InputError("a saved generation is named gen-NUMBER.xml", file.string());
        std::string solution, depth, size;
        for (const auto& t : best.trees) solution += (solution.empty() ? "" : " | ") + t.to_string();
        if (best.trees.empty())   // a gait; beside trees, x holds their direct offsets, not shown (as in a population's rows)
            for (double x : best.x) solution += (solution.empty() ? "" : " ") + number(x);
        if (!best.trees.empty()) {
            depth = std::to_string(gp::forest_depth(best.trees, s.gp.forest_depth));
            size = std::to_string(tree::total_size(best.trees));
        }
        const auto [dist, elev] = best.trees.empty() ? terms.gait(best.x) : terms.trees(best.trees, best.x);
        csv += prefix + fmt::format("{},0,{},{},{},{},{},0,{},,\n", std::stoi(digits), number(best.fitness), dist,
                                    elev, depth, size, cell(solution));
    }
}

void export_run(const fs::path& run, const std::string& label, const std::string& config, const std::string& seed,
                bool replay_terms, std::string& csv) {
    if (!fs::is_regular_file(run / "settings.xml"))
        throw InputError("not a run folder (no settings.xml) nor a study (no index.csv): " + run.string());
    const io::Settings s = io::read_settings(run / "settings.xml");
    const std::string prefix = cell(label) + "," + cell(config) + "," + seed + ",";
    const io::ExperimentFamily family = io::family_of(s);
    TermsReplay terms(s, replay_terms && family != io::ExperimentFamily::Symreg);
    const std::vector<fs::path> saved = saved_generations(run);
    if (!saved.empty())
        if (const CheckpointBestReader* reader = checkpoint_reader_for(saved.front().string()))
            return export_foreign(saved, s, *reader, prefix, terms, csv);
    if (s.map_elites.enabled) return export_elites(run, s, prefix, terms, csv);

    // A gait run's checkpoints, and a Switch-HybrID run's after its hand-over
    // (numbered on from the hand-over, as stats.csv numbers them).
    auto export_gait = [&](const fs::path& file) {
        const io::GaitFile g = io::load_gait(file);
        for (std::size_t i = 0; i < g.population.size(); ++i) {
            const io::GaitPoint& point = g.population[i];
            std::string params;
            for (double x : point.x) params += (params.empty() ? "" : " ") + number(x);
            const auto [dist, elev] = terms.gait(point.x);
            const int generation = g.generation + (g.handover ? g.handover->generation + 1 : 0);
            csv += prefix + fmt::format("{},{},{},{},{},,,0,{},,\n", generation, i, number(point.fitness), dist, elev,
                                        cell(params));
        }
    };
    if (family == io::ExperimentFamily::Gait) {
        for (const fs::path& file : saved) export_gait(file);
        return;
    }
    for (const fs::path& file : saved) {
        if (s.neural.switches() && io::is_gait_file(file)) {
            export_gait(file);
            continue;
        }
        const io::PopulationFile pop = io::load_population(file);
        for (const auto& ind : pop.population) {
            std::string trees;
            for (const auto& t : ind->genotype) trees += (trees.empty() ? "" : " | ") + t.to_string();
            const auto [dist, elev] = terms.trees(ind->genotype, ind->direct);
            csv += prefix + fmt::format("{},{},{},{},{},{},{},{},{},,\n", pop.population.generation, ind->id,
                                        number(ind->fitness), dist, elev, ind->depth(s.gp.forest_depth), ind->size(),
                                        ind->failed ? 1 : 0, cell(trees));
        }
    }
}

// With --terms (replays asked for): the run's champion, replayed, or a line
// saying that it does not give its stored fitness.
void say_if_champion_disagrees(const fs::path& run, const ExportRequest& request) {
    if (!request.terms || !request.warn || !fs::is_regular_file(run / "population.xml")) return;
    const io::Settings s = io::read_settings(run / "settings.xml");
    if (io::family_of(s) == io::ExperimentFamily::Symreg) return;
    const std::string file = (run / "population.xml").string();
    if (const auto c = replay_champion(s, file); c && !c->agrees()) request.warn(mismatch_text(*c, file));
}

} // namespace

std::string export_individuals(const ExportRequest& request) {
    std::string csv = kExportHeader;
    for (const fs::path& input : request.inputs) {
        if (is_study_folder(input)) {
            const StudyIndex index = read_study_index(input);
            for (const StudyRun& r : index.runs)
                if (fs::exists(index.run_path(r) / "settings.xml")) {
                    export_run(index.run_path(r), (input / r.run_dir).string(), r.config, r.seed, request.terms, csv);
                    say_if_champion_disagrees(index.run_path(r), request);
                }
        } else {
            const io::Settings s = fs::is_regular_file(input / "settings.xml") ? io::read_settings(input / "settings.xml")
                                                                               : io::Settings{};
            export_run(input, input.string(), s.experiment.name, std::to_string(s.experiment.seed), request.terms, csv);
            say_if_champion_disagrees(input, request);
        }
    }
    return csv;
}

} // namespace cic::report
