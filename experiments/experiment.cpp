#include "cic/experiments/experiment.hpp"

#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/symreg/problem.hpp"

namespace cic::experiments {

std::unique_ptr<Experiment> make_symreg_experiment(const Context& ctx);
std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx);

std::unique_ptr<Experiment> make_experiment(const Context& ctx) {
    switch (ctx.settings.experiment.type) {
    case io::ExperimentType::Symreg: return make_symreg_experiment(ctx);
    case io::ExperimentType::HyperGP: return make_hypergp_experiment(ctx);
    case io::ExperimentType::Gait: break;   // not a GP experiment: the app runs it (src/app/run_gait.cpp)
    }
    throw std::logic_error("make_experiment: the gait experiment has no GP evaluator");
}

void check_inputs(const io::Settings& s) {
    switch (s.experiment.type) {
    case io::ExperimentType::Symreg: symreg::make_dataset(s.symreg, {}); return;
    case io::ExperimentType::HyperGP: hypergp::check_inputs(s); return;
    case io::ExperimentType::Gait: gait::check_inputs(s); return;
    }
}

} // namespace cic::experiments
