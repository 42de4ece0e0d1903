#pragma once
// A search of gait vectors written as ask and tell (pyribs's schedulers): each
// step asks the search for one batch, evaluates it in the run's worker
// processes or MPI ranks (the same bytes for 1 or N of them), and tells the
// search what came back. The search still owns its start, stop rule,
// checkpoint and summary (search.hpp); step() is this class's.
// examples/plugin/one_plus_lambda.cpp is one.
#include <memory>
#include <vector>

#include "cic/experiments/gait/setup.hpp"
#include "cic/gp/map_elites.hpp"
#include "cic/search/search.hpp"
#include "cic/sim/config.hpp"

namespace cic::search {

class VectorAskTell : public Search {
public:
    // `services`: the loop's; the gait comes from the settings (gait::Setup),
    // each point's descriptor from MapElites.descriptor.
    explicit VectorAskTell(const Services& services);
    ~VectorAskTell() override;

    // The next batch: points of the unit box, setup().dimension() numbers each.
    virtual std::vector<std::vector<double>> ask() = 0;
    // The batch's evaluations, in its order (fitness, descriptor, failed); the step's row.
    virtual Row tell(const std::vector<std::vector<double>>& batch, const std::vector<gp::Evaluation>& evaluations) = 0;
    // ask, evaluate, tell. Throws std::invalid_argument for an empty batch or a
    // point of the wrong length or outside the unit box.
    Row step() final;

protected:
    const Services& services() const { return services_; }
    const gait::Setup& setup() const { return setup_; }
    // Evaluates a batch as step() does (for start()'s first batch).
    std::vector<gp::Evaluation> evaluate(const std::vector<std::vector<double>>& batch);
    long failed() const;   // evaluations that failed so far (physics or worker)

private:
    Services services_;
    gait::Setup setup_;
    sim::Descriptor descriptor_;
    std::unique_ptr<gait::Evaluator> evaluator_;   // made at the first batch: the workers start then
};

} // namespace cic::search
