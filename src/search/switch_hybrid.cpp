// Switch-HybrID (Clune et al. 2009; Helms & Clune 2017's Auto-Switch;
// docs/hypergp.md) as a search: one run, one budget of evaluations
// (Gait.evaluations), one checkpoint chain. HyperGP-gait evolves (the
// generational search) until its best has not improved for
// Neural.switchPatience generations or it has spent Neural.switchShare of the
// budget; then the evolution strategy (Gait.optimizer: CMA-ES, xNES or the
// separable CMA-ES, with IPOP restarts if Gait.restarts says so) runs on the
// direct gait, started from the best individual's gait mapped exactly into
// the gait's box (hypergp::gait_box_point), for the rest of the budget. Each
// phase saves its own state: population files carry the stagnation clock, gait
// checkpoints the hand-over; a resume from either continues the same run.
#include <algorithm>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "evolution_strategy.hpp"
#include "generational.hpp"

namespace cic::search {
namespace {

// The gait phase's evolution strategy (Gait.optimizer: cmaes, xnes or sepcmaes).
std::string optimizer_name(const io::Settings& s) { return gait::to_string(gait::optimizer_of(s.gait.optimizer)); }

// The summary's heading of the gait phase, after the HyperGP phase's part.
std::string gait_phase_heading(const io::Settings& s) {
    return "\ngait phase (" + optimizer_name(s) + " from the best's gait):\n";
}

// When the HyperGP phase hands over: the stagnation clock (best so far and the
// first generation that reached it) and the budget.
class HandoverRule {
public:
    HandoverRule(const io::Settings& s, std::optional<io::PopulationFile::SwitchClock> clock)
        : patience_(s.neural.switch_patience), share_(s.neural.switch_share), budget_(s.gait.evaluations),
          population_(s.gp.population_size), clock_(clock) {}

    void note(const gp::GenerationRecord& r) {
        if (!clock_ || r.best > clock_->best) clock_ = io::PopulationFile::SwitchClock{r.best, r.generation};
    }

    // Why the phase ends after generation r; empty: it goes on.
    std::string why(const gp::GenerationRecord& r) const {
        if (patience_ > 0 && clock_ && r.generation - clock_->best_generation >= patience_)
            return fmt::format("its best ({:.6g}, generation {}) has not improved for {} generations",
                               clock_->best, clock_->best_generation, r.generation - clock_->best_generation);
        if (share_ > 0 && static_cast<double>(r.evaluations) >= share_ * static_cast<double>(budget_))
            return fmt::format("it has spent {} of {} evaluations (switchShare {:g})", r.evaluations, budget_, share_);
        // A generation may evaluate a few more than the population (duplicates bred again).
        if (r.evaluations + population_ > budget_)
            return fmt::format("another generation would pass the budget of {} evaluations", budget_);
        return {};
    }

    const std::optional<io::PopulationFile::SwitchClock>& clock() const { return clock_; }

private:
    int patience_;
    double share_;
    long budget_;
    long population_;
    std::optional<io::PopulationFile::SwitchClock> clock_;
};

// The HyperGP phase's population file: its budget is the run's evaluations.
class SwitchPopulationCheckpoint : public PopulationCheckpoint {
public:
    void check_goes_on(const io::Settings& s) const override {
        PopulationCheckpoint::check_goes_on(s);
        if (population.state.evaluations >= s.gait.evaluations)
            throw InputError(fmt::format("the run has spent {} of its {} evaluations; ask for more with "
                                         "--set Gait.evaluations=E (E > {})",
                                         population.state.evaluations, s.gait.evaluations,
                                         population.state.evaluations),
                             file);
    }
};

class SwitchHybrid : public Search {
public:
    SwitchHybrid(const Services& services, std::unique_ptr<Checkpoint> resume) : services_(services) {
        const io::Settings& s = services.settings;
        if (auto* g = dynamic_cast<GaitCheckpoint*>(resume.get())) {   // the run had handed over already
            resume.release();
            std::unique_ptr<GaitCheckpoint> gait(g);
            const io::GaitHandover h = *gait->gait.handover;   // checked by io::check_compatible
            resumed_gait_line_ = fmt::format("Switch-HybrID: continuing the gait phase (HyperGP handed over after "
                                             "generation {}, {} evaluations)", h.generation, h.evaluations);
            // The HyperGP phase's own summary went with the session that ran it (its run.log);
            // this one says where it handed over, so every Switch-HybrID summary names both phases.
            es_ = std::make_unique<EvolutionStrategy>(
                services, std::move(gait), h,
                fmt::format("HyperGP phase:\nhanded over after generation {} ({} evaluations; its summary is in the "
                            "run.log of the session that ran it)\n",
                            h.generation, h.evaluations) +
                    gait_phase_heading(s));
            return;
        }
        std::unique_ptr<PopulationCheckpoint> population(static_cast<PopulationCheckpoint*>(resume.release()));
        rule_.emplace(s, population ? population->population.switch_clock : std::nullopt);
        GenerationalHooks hooks;
        hooks.on_generation = [this](const gp::GenerationRecord& r) { rule_->note(r); };
        hooks.annotate = [this](io::PopulationFile& f) { f.switch_clock = rule_->clock(); };
        // At most: the generations HyperGP's share of the budget allows.
        const double share = s.neural.switch_share > 0 ? s.neural.switch_share : 1.0;
        hooks.progress_generations = std::max(
            1, static_cast<int>(share * static_cast<double>(s.gait.evaluations) / std::max(1, s.gp.population_size)));
        hooks.hand_over = [this](const gp::GenerationRecord& r) {
            rule_->note(r);   // a resumed population's own record: no-op when the file's clock has it
            why_ = rule_->why(r);
            return !why_.empty();
        };
        gp_ = std::make_unique<Generational>(services, std::move(population), std::move(hooks));
    }

    StatsLayout stats_layout() const override { return es_ ? es_->stats_layout() : gp_->stats_layout(); }

    std::optional<Row> start() override {
        if (es_) {
            services_.say(resumed_gait_line_);
            return es_->start();
        }
        return gp_->start();
    }

    Stop stop(bool signal) override {
        if (es_) return es_->stop(signal);
        gp_stop_ = gp_->stop(signal);
        if (gp_->reason() != gp::StopReason::HandedOver) return gp_stop_;   // interrupted, or minimumFitness reached
        gp_->log_session_note();
        const std::string gp_summary = gp_->summary_text();
        const io::Settings& s = services_.settings;
        if (gp_->state().evaluations + gait::Setup::from_settings(s).population > s.gait.evaluations) {
            // HyperGP spent the budget: no room for one batch of the gait phase.
            final_summary_ = gp_summary + "the budget leaves no room for the gait phase\n";
            return {"handed over", false};
        }
        head_ = "HyperGP phase:\n" + gp_summary + gait_phase_heading(s);
        if (signal) {   // stopped as HyperGP handed over: its checkpoint resumes
            final_summary_ = head_ + "stopped: interrupted before the gait phase began\n";
            return {"interrupted", true};
        }
        switch_pending_ = true;
        return {};
    }

    bool checkpoint_due(const Stop& stop) override {
        // The GP phase's own stop decides its checkpoints (its last, when it hands over).
        return es_ ? es_->checkpoint_due(stop) : gp_->checkpoint_due(gp_stop_);
    }

    CheckpointText checkpoint() const override { return es_ ? es_->checkpoint() : gp_->checkpoint(); }

    Row step() override {
        if (!switch_pending_) return es_ ? es_->step() : gp_->step();
        switch_pending_ = false;
        const io::Settings& s = services_.settings;
        const gp::Individual& best = gp_->population().best();
        const hypergp::Model model = hypergp::Model::from_settings(s);
        io::GaitHandover h;
        h.generation = gp_->population().generation;
        h.evaluations = gp_->state().evaluations;
        h.x = hypergp::gait_box_point(model.robot, best.genotype, model.neural, best.direct);
        services_.say(fmt::format("switch: HyperGP hands over after generation {} ({} evaluations): {}; {} starts "
                                  "from individual {}'s gait (fitness {:.17g}) for the remaining {} evaluations",
                                  h.generation, h.evaluations, why_, optimizer_name(s), best.id, best.fitness,
                                  s.gait.evaluations - h.evaluations));
        es_ = std::make_unique<EvolutionStrategy>(services_, nullptr, h, head_);
        // The HyperGP phase is over: its worker processes go with it, so that
        // each phase has Experiment.workers of them, not both phases' together.
        gp_.reset();
        return *es_->start();   // a fresh gait phase evaluates its first generation
    }

    std::string summary(const Stop& stop) override {
        if (!final_summary_.empty()) return final_summary_;
        if (es_) return es_->summary(stop);
        gp_->log_session_note();
        return gp_->summary_text();
    }

private:
    Services services_;
    std::optional<HandoverRule> rule_;
    std::unique_ptr<Generational> gp_;
    std::unique_ptr<EvolutionStrategy> es_;
    Stop gp_stop_;
    std::string why_, head_, final_summary_, resumed_gait_line_;
    bool switch_pending_ = false;
};

const Registrar registrar{SearchKind{
    .name = "switch-hybrid",
    .doc = {},   // a built-in: its name and doc are the settings' (io/search_names.cpp)
    .forms = {io::GenotypeForm::Trees},
    .keys = {},
    .budget_key = "Gait.evaluations",
    .budget_unit = "evaluations",
    .claims = [](const io::Settings& s) { return s.neural.switches() && !s.map_elites.enabled; },
    .claimed_by = "Neural.switchPatience > 0 or Neural.switchShare > 0",
    .fallback = false,
    .load = [](const io::Settings& s, const std::string& file) -> std::unique_ptr<Checkpoint> {
        if (io::is_gait_file(file)) return load_gait_checkpoint(s, file);   // the gait phase's
        auto c = std::make_unique<SwitchPopulationCheckpoint>();
        auto loaded = load_population_checkpoint(s, file);
        static_cast<PopulationCheckpoint&>(*c) = std::move(*loaded);
        return c;
    },
    .checkpoint_schema = {},   // its io reader checks the shipped settings/cic-population.xsd and cic-gait.xsd
    .checkpoint_root = {},
    .best = {},
    .make = [](const Services& services, std::unique_ptr<Checkpoint> resume) -> std::unique_ptr<Search> {
        return std::make_unique<SwitchHybrid>(services, std::move(resume));
    },
}};

} // namespace
} // namespace cic::search
