#pragma once
// Private to src/search: the evolution strategies on a gait vector (pagmo2's
// CMA-ES, xNES and SaDE, cic's separable CMA-ES; IPOP restarts) as a search
// (evolution_strategy.cpp registers it), and Switch-HybrID's second phase.
#include <memory>
#include <optional>

#include "cic/experiments/gait/restarts.hpp"
#include "cic/experiments/gait/search.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/search/search.hpp"

namespace cic::search {

// A gait checkpoint, loaded, checked against the settings and replayed (a
// checkpoint whose history does not replay is refused when it is loaded).
class GaitCheckpoint : public Checkpoint {
public:
    io::GaitFile gait;
    std::optional<gait::Search> search;   // the replayed search, taken by the run
    // Minimum fitness not reached, and the budget holds one more generation.
    void check_goes_on(const io::Settings& s) const override;
};
std::unique_ptr<GaitCheckpoint> load_gait_checkpoint(const io::Settings& s, const std::string& file);

class EvolutionStrategy : public Search {
public:
    // `handover`: Switch-HybrID's, where the HyperGP phase ended (its
    // generations and evaluations continue the run's); `summary_head` opens summary.txt.
    EvolutionStrategy(const Services& services, std::unique_ptr<GaitCheckpoint> resume,
                      std::optional<io::GaitHandover> handover = std::nullopt, std::string summary_head = {});
    StatsLayout stats_layout() const override;
    std::optional<Row> start() override;
    Stop stop(bool signal) override;
    bool checkpoint_due(const Stop& stop) override;
    CheckpointText checkpoint() const override;
    Row step() override;
    std::string summary(const Stop& stop) override;

private:
    Row after_generation(double generation_seconds);

    Services services_;
    std::unique_ptr<GaitCheckpoint> resume_;
    std::optional<io::GaitHandover> handover_;
    std::string summary_head_;
    int at_generation_ = 0;     // where this search's generations and evaluations start in the run
    long at_evaluations_ = 0;
    gait::Setup setup_;
    gait::RestartRule rule_;
    io::CheckpointOrigin origin_;
    std::optional<gait::Search> search_;
    std::unique_ptr<gait::Evaluator> evaluator_;
    gait::BatchEvaluator batch_;
    bool with_best_so_far_ = true;
    long failed_before_ = 0;
    int restarts_said_ = 0;
    int last_stalled_ = 0;      // why the restart a step begins was decided
    bool last_collapsed_ = false;
    bool stepped_ = false;      // a row since the last stop(): its checkpoint may be due
    int first_generation_ = 0;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

} // namespace cic::search
