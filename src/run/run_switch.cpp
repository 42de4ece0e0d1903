// Switch-HybrID (Clune et al. 2009; Helms & Clune 2017's Auto-Switch;
// docs/hypergp.md): one run, one budget of evaluations (Gait.evaluations),
// one checkpoint chain. HyperGP-gait evolves (run.cpp's GP loop) until its
// best has not improved for Neural.switchPatience generations or it has spent
// Neural.switchShare of the budget; then the gait loop (run_gait.cpp) runs
// CMA-ES (with IPOP restarts if Gait.restarts says so) on the direct gait,
// started from the best individual's gait, mapped exactly into the gait's box
// (hypergp::gait_box_point), for the rest of the budget. Each phase saves its
// own state: population files carry the stagnation clock, gait checkpoints
// the hand-over; a resume from either continues the same run.
#include <algorithm>

#include <fmt/format.h>

#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "run_support.hpp"

namespace cic::app::detail {
namespace {

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

} // namespace

int run_switch(PreparedRun prepared, const RunOptions& opt) {
    const io::Settings& s = prepared.settings;
    RunConsole console(opt);
    StopSignalGuard stop_signals;   // one for both phases: a signal between them is not lost
    if (prepared.gait_resume) {     // the run had handed over already
        const io::GaitHandover h = *prepared.gait_resume->handover;   // checked by io::check_compatible
        console.say(fmt::format("Switch-HybrID: continuing the gait phase (HyperGP handed over after generation {}, "
                                "{} evaluations)", h.generation, h.evaluations));
        return run_gait_phase(prepared, opt, console, h, "");
    }

    HandoverRule rule(s, prepared.resume ? prepared.resume->switch_clock : std::nullopt);
    std::string why;
    GpPhase phase;
    phase.on_generation = [&](const gp::GenerationRecord& r) { rule.note(r); };
    phase.annotate = [&](io::PopulationFile& f) { f.switch_clock = rule.clock(); };
    // At most: the generations HyperGP's share of the budget allows.
    const double share = s.neural.switch_share > 0 ? s.neural.switch_share : 1.0;
    phase.progress_generations = std::max(1, static_cast<int>(share * static_cast<double>(s.gait.evaluations) /
                                                              std::max(1, s.gp.population_size)));
    phase.hand_over = [&](const gp::GenerationRecord& r) {
        rule.note(r);   // a resumed population's own record: no-op when the file's clock has it
        why = rule.why(r);
        return !why.empty();
    };
    const GpPhaseResult gp_phase = run_gp_phase(prepared, opt, console, phase);
    const gp::EvolutionResult& result = gp_phase.result;
    const std::string gp_summary = summary_of(result, *gp_phase.experiment, s);
    if (result.reason != gp::StopReason::HandedOver) {   // interrupted, or minimumFitness reached
        console.summary(gp_summary);
        if (result.reason == gp::StopReason::Interrupted) return console.interrupted();
        finish_run(s, opt, console);
        return 0;
    }

    const gp::Individual& best = result.population.best();
    const hypergp::Model model = hypergp::Model::from_settings(s);
    if (result.state.evaluations + gait::Setup::from_settings(s).population > s.gait.evaluations) {
        // HyperGP spent the budget: no room for one batch of the gait phase.
        console.summary(gp_summary + "the budget leaves no room for the gait phase\n");
        finish_run(s, opt, console);
        return 0;
    }
    io::GaitHandover h;
    h.generation = result.population.generation;
    h.evaluations = result.state.evaluations;
    h.x = hypergp::gait_box_point(model.robot, best.genotype, model.neural, best.direct);
    console.say(fmt::format("switch: HyperGP hands over after generation {} ({} evaluations): {}; CMA-ES starts from "
                            "individual {}'s gait (fitness {:.17g}) for the remaining {} evaluations",
                            h.generation, h.evaluations, why, best.id, best.fitness,
                            s.gait.evaluations - h.evaluations));
    prepared.gait_resume.reset();
    return run_gait_phase(prepared, opt, console, h,
                          "HyperGP phase:\n" + gp_summary + "\ngait phase (CMA-ES from the best's gait):\n");
}

} // namespace cic::app::detail
