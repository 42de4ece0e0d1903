// Replay before you believe (verify.hpp): a checkpoint's stored fitness values
// against what their genotypes give when evaluated again.
#include "cic/report/verify.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cic/core/error.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "replay_support.hpp"

namespace cic::report {
namespace fs = std::filesystem;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

enum class FileKind { Population, Gait, Archive, Foreign };

FileKind kind_of(const io::Settings& s, const std::string& file) {
    if (checkpoint_reader_for(file)) return FileKind::Foreign;
    if (s.map_elites.enabled) return FileKind::Archive;
    if (io::family_of(s) == io::ExperimentFamily::Gait || (s.neural.switches() && io::is_gait_file(file)))
        return FileKind::Gait;
    return FileKind::Population;
}

// An individual whose stored fitness a run believes: evaluated and not edited
// by hand (an edited one is evaluated again on resume).
bool believed(const gp::Individual& ind) { return ind.evaluated && !ind.edited; }

// Replays population individuals: HyperGP trees in this process with the
// worker's functions; symbolic regression with its own in-process evaluator.
class TreeReplayer {
public:
    TreeReplayer(const io::Settings& s, const std::string& file) : s_(s), file_(file) {}

    ReplayCheck check(const io::PopulationFile& pop, const gp::Individual& ind) {
        ReplayCheck c;
        c.who = fmt::format("individual {}", ind.id);
        if (const auto at = pop.lines.find(ind.id); at != pop.lines.end()) c.line = at->second;
        c.stored = ind.fitness;
        if (ind.failed) {   // a crash or a hang is not replayed: its fitness is failureFitness, no other
            c.replayed_at_all = false;
            c.replayed = s_.sim.failure_fitness;
            return c;
        }
        if (io::walks_a_robot(s_)) {
            // A growing robot's population was scored on the body its checkpoint names.
            const std::size_t body = pop.body.value_or(0);
            if (!model_ || body_ != body) {
                model_.emplace(hypergp::Model::from_settings(s_).on_body(body));
                body_ = body;
            }
            c.replayed = detail::replay_trees(*model_, s_, ind.genotype, ind.direct, 0.0, false).replayed_fitness;
            return c;
        }
        if (!experiment_) {   // symbolic regression: evaluated in process, as the run does
            const fs::path base = s_.source_file.empty() ? fs::path(file_).parent_path()
                                                         : fs::path(s_.source_file).parent_path();
            context_ = std::make_unique<experiments::Context>(experiments::Context{s_, base, {}, {}, 1});
            experiment_ = experiments::make_experiment(*context_);
        }
        auto again = std::make_shared<gp::Individual>(ind);
        again->evaluated = false;
        const std::vector<gp::IndividualPtr> todo{again};
        experiment_->evaluator().evaluate(todo);
        c.replayed = again->fitness;
        return c;
    }

private:
    const io::Settings& s_;
    std::string file_;
    std::optional<hypergp::Model> model_;
    std::size_t body_ = 0;   // the body model_ walks
    std::unique_ptr<experiments::Context> context_;
    std::unique_ptr<experiments::Experiment> experiment_;
};

io::PopulationFile read_population(const io::Settings& s, const std::string& file) {
    io::PopulationFile pop = io::load_population(file);
    io::check_compatible(pop, s, file);
    return pop;
}

const gp::Individual* champion_of(const io::PopulationFile& pop) {
    const gp::Individual* best = nullptr;
    for (const auto& ind : pop.population)
        if (believed(*ind) && (!best || gp::better(*ind, *best))) best = ind.get();
    return best;
}

struct ArchiveReplayer {
    io::ArchiveFile archive;
    std::optional<gait::Setup> setup;
    std::optional<hypergp::Model> model;
    sim::Descriptor descriptor = sim::Descriptor::None;

    ArchiveReplayer(const io::Settings& s, const std::string& file) : archive(io::load_archive(file)) {
        const bool gait = io::genotype_form(s) == io::GenotypeForm::Vector;
        if (gait) setup.emplace(gait::Setup::from_settings(s));
        else model.emplace(hypergp::Model::from_settings(s));
        const sim::RobotSpec& robot = gait ? setup->robot : model->robot;
        io::check_compatible(archive, s, experiments::map_elites_grid(s, robot), gait ? setup->dimension() : 0, file);
        descriptor = s.map_elites.descriptor;
    }

    ReplayCheck check(const io::Settings& s, const io::ArchiveElite& e) const {
        ReplayCheck c;
        c.who = fmt::format("the elite of cell {} ({})", archive.grid.cell_name(e.cell), e.cell);
        c.line = e.line;
        c.stored = e.fitness;
        c.stored_descriptor = e.descriptor;
        const ReplayItem item = setup ? detail::replay_point(*setup, e.x, 0.0, false, descriptor)
                                      : detail::replay_trees(*model, s, e.genotype, {}, 0.0, false, descriptor);
        c.replayed = item.replayed_fitness;
        c.replayed_descriptor = item.descriptor;
        return c;
    }
};

ReplayCheck check_point(const gait::Setup& setup, const std::string& who, const io::GaitPoint& p) {
    ReplayCheck c;
    c.who = who;
    c.stored = p.fitness;
    c.replayed = detail::replay_point(setup, p.x, 0.0, false).replayed_fitness;
    return c;
}

io::GaitFile read_gait(const io::Settings& s, const gait::Setup& setup, const std::string& file) {
    io::GaitFile g = io::load_gait(file);
    io::check_compatible(g, s, setup.dimension(), file);
    return g;
}

ReplayCheck check_foreign(const io::Settings& s, const std::string& file) {
    const CheckpointBest best = read_checkpoint_best(*checkpoint_reader_for(file), s, file);
    ReplayCheck c;
    c.who = best.who.empty() ? "the best" : best.who;
    c.stored = best.fitness;
    c.replayed = best.trees.empty()
                     ? detail::replay_point(gait::Setup::from_settings(s), best.x, 0.0, false).replayed_fitness
                     : detail::replay_trees(hypergp::Model::from_settings(s), s, best.trees, best.x, 0.0, false)
                           .replayed_fitness;
    return c;
}

// The run folder of a checkpoint: population.xml's folder, or the one above populations/.
fs::path run_folder_of(const std::string& file) {
    const fs::path dir = fs::absolute(file).parent_path();
    return dir.filename() == "populations" ? dir.parent_path() : dir;
}

} // namespace

std::string handover_problem(const io::Settings& s, const std::string& file) {
    if (!s.neural.switches() || !io::is_gait_file(file)) return {};
    const io::GaitFile g = io::load_gait(file);
    if (!g.handover) return {};
    const io::GaitHandover& h = *g.handover;
    const fs::path phase = run_folder_of(file) / "populations" / fmt::format("gen-{:04d}.xml", h.generation);
    std::error_code ec;
    if (!fs::is_regular_file(phase, ec)) return {};
    const io::PopulationFile pop = read_population(s, phase.string());
    if (pop.population.generation != h.generation || pop.state.evaluations != h.evaluations)
        return fmt::format("{}: <handover generation=\"{}\" evaluations=\"{}\"> but the HyperGP phase's last "
                           "checkpoint, {}, is generation {} with {} evaluations",
                           file, h.generation, h.evaluations, phase.string(), pop.population.generation,
                           pop.state.evaluations);
    const gp::Individual& best = pop.population.best();
    const hypergp::Model model = hypergp::Model::from_settings(s);
    if (hypergp::gait_box_point(model.robot, best.genotype, model.neural, best.direct) != h.x)
        return fmt::format("{}: the hand-over's gait is not the gait of the best individual ({}) of the HyperGP "
                           "phase's last checkpoint, {}",
                           file, best.id, phase.string());
    if (ReplayCheck c = TreeReplayer(s, phase.string()).check(pop, best); !c.agrees())
        return mismatch_text(c, phase.string());
    return {};
}

bool ReplayCheck::agrees() const {
    if (!same_bits(stored, replayed)) return false;
    if (stored_descriptor.size() != replayed_descriptor.size()) return false;
    for (std::size_t i = 0; i < stored_descriptor.size(); ++i)
        if (!same_bits(stored_descriptor[i], replayed_descriptor[i])) return false;
    return true;
}

namespace {

// What disagrees, without where.
std::string disagreement(const ReplayCheck& c) {
    if (!c.replayed_at_all)
        return fmt::format("{} is marked failed but its stored fitness {:.17g} is not failureFitness {:.17g}", c.who,
                           c.stored, c.replayed);
    if (!same_bits(c.stored, c.replayed))
        return fmt::format("{}'s stored fitness {:.17g} does not replay: the replay gives {:.17g}", c.who, c.stored,
                           c.replayed);
    return fmt::format("{}'s stored descriptor ({:.17g}) does not replay: the replay gives ({:.17g})", c.who,
                       fmt::join(c.stored_descriptor, ", "), fmt::join(c.replayed_descriptor, ", "));
}

} // namespace

std::string mismatch_text(const ReplayCheck& c, const std::string& file) {
    return (c.line > 0 ? fmt::format("{}:{}", file, c.line) : file) + ": " + disagreement(c);
}

std::optional<ReplayCheck> replay_champion(const io::Settings& s, const std::string& file) {
    switch (kind_of(s, file)) {
    case FileKind::Foreign:
        return check_foreign(s, file);
    case FileKind::Archive: {
        const ArchiveReplayer a(s, file);
        const io::ArchiveElite* best = a.archive.best();
        if (!best) return std::nullopt;
        return a.check(s, *best);
    }
    case FileKind::Gait: {
        const gait::Setup setup = gait::Setup::from_settings(s);
        const io::GaitFile g = read_gait(s, setup, file);
        return check_point(setup, "the champion", g.champion);
    }
    case FileKind::Population: {
        const io::PopulationFile pop = read_population(s, file);
        const gp::Individual* best = champion_of(pop);
        if (!best) return std::nullopt;
        ReplayCheck c = TreeReplayer(s, file).check(pop, *best);
        c.who = "the best, " + c.who;
        return c;
    }
    }
    return std::nullopt;
}

void refuse_unless_champion_replays(const io::Settings& s, const std::string& file) {
    const std::optional<ReplayCheck> c = replay_champion(s, file);
    if (!c || c->agrees()) return;
    throw InputError(disagreement(*c) +
                         "; a checkpoint's fitness must be what its genotype gives (edited by hand, or made by "
                         "another build?): cic verify RUN lists every value that does not replay",
                     file, c->line);
}

std::vector<ReplayCheck> replay_all(const io::Settings& s, const std::string& file,
                                    const std::function<void(const ReplayCheck&)>& each) {
    std::vector<ReplayCheck> out;
    auto add = [&](ReplayCheck c) {
        if (each) each(c);
        out.push_back(std::move(c));
    };
    switch (kind_of(s, file)) {
    case FileKind::Foreign:
        add(check_foreign(s, file));
        break;
    case FileKind::Archive: {
        const ArchiveReplayer a(s, file);
        for (const auto& e : a.archive.elites) add(a.check(s, e));
        break;
    }
    case FileKind::Gait: {
        const gait::Setup setup = gait::Setup::from_settings(s);
        const io::GaitFile g = read_gait(s, setup, file);
        add(check_point(setup, "the champion", g.champion));
        for (std::size_t i = 0; i < g.population.size(); ++i)
            add(check_point(setup, fmt::format("candidate {} of generation {}", i, g.generation), g.population[i]));
        break;
    }
    case FileKind::Population: {
        const io::PopulationFile pop = read_population(s, file);
        TreeReplayer replayer(s, file);
        for (const auto& ind : pop.population)
            if (believed(*ind)) add(replayer.check(pop, *ind));
        break;
    }
    }
    return out;
}

} // namespace cic::report
