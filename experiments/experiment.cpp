#include "experiments/experiment.hpp"

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

} // namespace cic::experiments
