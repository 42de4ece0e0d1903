#pragma once
// What searches share: statistics of a set of fitness values, eq. 7.1's
// summary line, and what a run says about the checkpoint it goes on from.
#include <string>
#include <vector>

#include "cic/gp/evolution.hpp"
#include "cic/io/settings.hpp"
#include "cic/search/search.hpp"

namespace cic::search {

// best, mean and median of a generation's (or an archive's) fitness values;
// leaves them 0 when there is none.
void fill_fitness_stats(gp::GenerationRecord& r, std::vector<double> fitness);

// The summary line that splits the best's score into eq. 7.1's terms.
std::string eq71_line(double distance, double elevation);

// The note on a checkpoint whose origin matched but whose search settings
// differ: its fitness values hold; the search goes on with these settings.
// Empty when the digests match.
std::string search_note(const std::string& file_digest, const io::Settings& s, const std::string& from);

// Throws cic::InputError naming `file` when `best` has reached
// Control.minimumFitness: a resume would stop at once (Checkpoint::check_goes_on).
void refuse_if_reached(double best, const io::Settings& s, const std::string& file);

// Says a checkpoint's notes (origin_note, search_note) through `services`.
void say_checkpoint_notes(const Checkpoint& c, const Services& services);

} // namespace cic::search
