#pragma once
// `cic resume RUN`: a run continued in its own folder, as if it had never
// stopped. stats.csv and run.log grow, checkpoints are numbered on from the
// last, and the populations are the bytes of a run that went straight on
// (the state in population.xml holds the RNG, the generation and the bloat
// limit). The budget may grow (more generations, Gait.evaluations, or a higher
// Control.minimumFitness for a run that reached it); any other key that
// changes the result is refused, naming each.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cic::run {

struct ResumeRequest {
    std::filesystem::path run_dir;
    std::optional<int> generations;    // this many more generations (GP families)
    std::optional<int> until;          // until this many have been evaluated in all (Control.maximumIterations)
    std::vector<std::string> sets;     // Section.key=value: workers, the budget; nothing that changes the result
    std::string command_line;          // for run.log
    bool quiet = false, verbose = false;
};

// Returns the run's exit code (0, 1, 130, 143). Throws cic::InputError (exit 2)
// before anything is written (settings.xml and run.log included) when the
// folder holds no resumable run, when a key other than the budget or one that
// changes no result would change, when the checkpoint fails any check of
// prepare_run (its origin above all), or when the budget adds no generation or
// batch (as the same budget is refused at the start). A budget change is said
// ("continuing with a budget of N evaluations (was M)"). A folder killed before
// its first checkpoint (settings.xml, no population.xml, no summary.txt)
// starts again in place: the bytes of an unbroken run.
int resume_run(const ResumeRequest& request);

} // namespace cic::run
