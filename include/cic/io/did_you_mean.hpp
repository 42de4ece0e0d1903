#pragma once
// "Did you mean ...?" for every name a user types: settings keys and sections,
// elements and attributes of every XML file cic reads, command-line options and
// subcommands. One rule, so that every reader suggests alike.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace cic::io {

// Edit distance, case-insensitive: insertions, deletions, substitutions and
// swaps of two neighbouring letters count one each.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest of `names` to `given`, when it is close enough to be a slip of the
// keys (at most a third of its letters, at least one); of two as close, the one
// `given` is a subsequence of (a letter left out is the commonest slip: --sed is
// --seed rather than --set). Empty when none is close, or `given` is in `names`.
std::string nearest_name(std::string_view given, const std::vector<std::string>& names);

// "; did you mean X?" for the nearest of `names`, else "" (a suffix for messages).
std::string did_you_mean(std::string_view given, const std::vector<std::string>& names);

} // namespace cic::io
