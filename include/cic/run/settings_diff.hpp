#pragma once
// Which settings a run folder ran, against those now asked of it: the check
// behind `cic resume` (resume.hpp) and a sweep's refusal of an edited study.
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/settings.hpp"

namespace cic::run {

// The settings less the keys that change no result: the run's name, output
// folder, worker count and resume file. What a run store fingerprints and what
// a run folder is checked against.
io::Settings result_settings(io::Settings s);

// The keys whose values differ, as "Section.key: ran A, <asker> asks B", in
// table order. Keys that change no result are left out; a path counts as the
// same when both name files of identical contents (a copy elsewhere); a path
// whose file is gone is compared as written (refused, loudly).
std::vector<std::string> settings_differences(const io::Settings& ran, const io::Settings& asked,
                                              std::string_view asker);

// Whether a difference (as settings_differences writes it) is of a key that
// bounds a run's length: Control.maximumIterations, Control.minimumFitness or
// Gait.evaluations.
bool is_budget_difference(const std::string& difference);

// Whether `asked` continues the run `ran` made: they differ (past the keys that
// change no result) in the budget only, and no budget shrinks. A run so asked
// goes on from its checkpoint (`cic resume`, an extended sweep).
bool extends(const io::Settings& ran, const io::Settings& asked);

} // namespace cic::run
