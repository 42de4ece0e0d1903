#pragma once
// Replay before you believe: cic is deterministic, so a stored fitness can
// always be checked by evaluating its genotype again, with the evaluation's
// own code path (report/replay.hpp: the functions a worker's job handler
// calls, ODE's random state reset for each). A resume, an extend and a
// Control.populationXmlLoadFrom start replay the checkpoint's champion before
// they go on (run/run.hpp's prepare_run); `cic verify RUN` replays everything
// the last checkpoint holds.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cic/io/settings.hpp"

namespace cic::report {

// One stored fitness (and an elite's behaviour descriptor) beside its replay.
struct ReplayCheck {
    std::string who;                   // "individual 345", "the champion", "the elite of cell 3,4 (19)"
    int line = 0;                      // of its element in the file; 0 when the file does not say
    double stored = 0, replayed = 0;
    std::vector<double> stored_descriptor, replayed_descriptor;   // an archive elite's
    bool replayed_at_all = true;       // false: a failed evaluation, checked against failureFitness only
    bool agrees() const;               // bit for bit
};

// One line: "FILE:LINE: WHO's stored fitness S does not replay: the replay gives R".
std::string mismatch_text(const ReplayCheck& c, const std::string& file);

// The checkpoint's champion, replayed with the settings `s` (a run's own, or
// those of a run that loads it): a population's fittest evaluated individual
// (an individual edited by hand is evaluated again on resume: not believed,
// not replayed), a gait run's champion, an archive's fittest elite, a
// registered search's best. nullopt: there is nothing to believe (a
// population of edited individuals only, an empty archive). Throws
// cic::InputError for a file that cannot be read.
std::optional<ReplayCheck> replay_champion(const io::Settings& s, const std::string& file);

// Throws cic::InputError (exit 2) naming the file, the line and both values
// when the champion's stored fitness is not what its replay gives.
void refuse_unless_champion_replays(const io::Settings& s, const std::string& file);

// A Switch-HybrID gait checkpoint's hand-over against the HyperGP phase's
// last checkpoint (populations/gen-NNNN.xml of the run that holds `file`, NNNN
// the hand-over's generation): its evaluations, and its best's gait, which
// must be the gait the phase started from, and whose fitness must replay.
// Empty: they agree, or `file` is no hand-over, or that checkpoint is not
// beside it (a file copied elsewhere: its champion's replay is the proof).
std::string handover_problem(const io::Settings& s, const std::string& file);

// Every stored fitness the checkpoint holds: each individual, each elite
// (fitness and descriptor), a gait run's champion and current candidates;
// `each` is told of each check as it is made.
std::vector<ReplayCheck> replay_all(const io::Settings& s, const std::string& file,
                                    const std::function<void(const ReplayCheck&)>& each = {});

} // namespace cic::report
