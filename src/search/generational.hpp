#pragma once
// Private to src/search: the thesis's generational GP as a search (its file
// generational.cpp registers it), and what Switch-HybrID (switch_hybrid.cpp)
// builds its first phase from.
#include <functional>
#include <memory>
#include <optional>

#include "cic/experiments/experiment.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/search/search.hpp"
#include "cic/tree/primitives.hpp"

namespace cic::search {

// A population file, loaded and checked against the settings.
class PopulationCheckpoint : public Checkpoint {
public:
    io::PopulationFile population;
    void check_goes_on(const io::Settings& s) const override;   // minimumFitness not yet reached
};
std::unique_ptr<PopulationCheckpoint> load_population_checkpoint(const io::Settings& s, const std::string& file);

// What a later phase of the run adds to the GP phase (Switch-HybrID).
struct GenerationalHooks {
    // Called with each generation's record before the loop sees it.
    std::function<void(const gp::GenerationRecord&)> on_generation;
    // Adds the phase's own state to each checkpoint.
    std::function<void(io::PopulationFile&)> annotate;
    // Ends the phase after a generation (reason "handed over"); with it
    // Control.maximumIterations does not apply.
    std::function<bool(const gp::GenerationRecord&)> hand_over;
    // What the progress line counts to instead of maximumIterations; 0 = that.
    int progress_generations = 0;
};

class Generational : public Search {
public:
    Generational(const Services& services, std::unique_ptr<PopulationCheckpoint> resume, GenerationalHooks hooks = {});
    StatsLayout stats_layout() const override;
    std::optional<Row> start() override;
    Stop stop(bool signal) override;
    bool checkpoint_due(const Stop& stop) override;
    CheckpointText checkpoint() const override;
    Row step() override;
    std::string summary(const Stop& stop) override;

    // For a phase after this one: the reason it stopped, and its last generation.
    gp::StopReason reason() const { return reason_; }
    const gp::Population& population() const { return generations_->population(); }
    const gp::EvolutionState& state() const { return generations_->state(); }
    // "stopped: ... best: ... best trees: ..." (without the replay of the best).
    std::string summary_text() const;
    // The experiment's note on its evaluations (run.log), if it has one.
    void log_session_note() const;

private:
    Row row_of(const gp::GenerationRecord& r);

    Services services_;
    std::unique_ptr<PopulationCheckpoint> resume_;
    GenerationalHooks hooks_;
    std::unique_ptr<experiments::Experiment> experiment_;
    gp::GpConfig gp_;
    tree::PrimitiveSet primitives_;
    io::PopulationFile header_;
    std::unique_ptr<gp::Generations> generations_;
    gp::GenerationRecord record_;
    gp::StopReason reason_ = gp::StopReason::MaximumIterations;
    int maximum_iterations_ = 0;
    bool first_check_ = true;
    long evaluations_before_ = 0;
    int first_generation_ = 0;
    std::size_t body_ = 0;   // a growing robot's current body (io/bodies.hpp); 0 = the robot
};

} // namespace cic::search
