// Symbolic regression wiring (thesis 6.2.1): the dataset from the settings,
// scored with -sum|error| on worker threads (trees are pure, so threads are safe
// and the result does not depend on their number). Registers the `symreg` type.
#include <fmt/format.h>

#include "cic/core/parallel_for.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/experiments/symreg/problem.hpp"

namespace cic::experiments {
namespace {

class SymregEvaluator final : public gp::Evaluator {
public:
    SymregEvaluator(symreg::Dataset data, double tolerance, int threads)
        : data_(std::move(data)), tolerance_(tolerance), threads_(threads) {}

    void evaluate(std::span<const gp::IndividualPtr> todo) override {
        parallel_for(todo.size(), threads_, [&](std::size_t i) {
            thread_local std::vector<double> scratch;
            const auto s = symreg::score(todo[i]->genotype, data_, tolerance_, scratch);
            todo[i]->fitness = s.fitness;
            todo[i]->evaluated = true;
        });
    }

    symreg::Score score(const gp::Individual& ind) const {
        std::vector<double> scratch;
        return symreg::score(ind.genotype, data_, tolerance_, scratch);
    }
    const symreg::Dataset& data() const { return data_; }

private:
    symreg::Dataset data_;
    double tolerance_;
    int threads_;
};

class SymregExperiment final : public Experiment {
public:
    explicit SymregExperiment(const Context& ctx)
        : eval_(symreg::make_dataset(ctx.settings.symreg, ctx.base_dir.string()), ctx.settings.symreg.hit_tolerance,
                ctx.workers) {}

    gp::Evaluator& evaluator() override { return eval_; }

    std::string describe(const gp::Individual& ind) const override {
        const auto s = eval_.score(ind);
        return fmt::format("hits {}/{}{}", s.hits, eval_.data().rows(), s.success ? " (success)" : "");
    }
    bool success(const gp::Individual& ind) const override { return eval_.score(ind).success; }

private:
    SymregEvaluator eval_;
};

const Registrar registrar{{
    .type = *io::find_experiment_type("symreg"),
    .keys = {},
    .check_inputs = [](const io::Settings& s) { (void)symreg::make_dataset(s.symreg, {}); },
    .make = [](const Context& ctx) -> std::unique_ptr<Experiment> { return std::make_unique<SymregExperiment>(ctx); },
    .job_kinds = {},
}};

} // namespace

} // namespace cic::experiments
