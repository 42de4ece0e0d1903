#include "experiments/experiment.hpp"

#include "experiments/hypergp/model.hpp"
#include "experiments/symreg/problem.hpp"

namespace cic::experiments {

std::unique_ptr<Experiment> make_symreg_experiment(const Context& ctx);
std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx);

std::unique_ptr<Experiment> make_experiment(const Context& ctx) {
    switch (ctx.settings.experiment.type) {
    case io::ExperimentType::Symreg: return make_symreg_experiment(ctx);
    case io::ExperimentType::HyperGP: return make_hypergp_experiment(ctx);
    }
    return nullptr;
}

void check_inputs(const io::Settings& s) {
    switch (s.experiment.type) {
    case io::ExperimentType::Symreg: symreg::make_dataset(s.symreg, {}); return;
    case io::ExperimentType::HyperGP: hypergp::check_inputs(s); return;
    }
}

} // namespace cic::experiments
