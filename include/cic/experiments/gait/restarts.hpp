#pragma once
// IPOP restarts of the gait experiment's search (Gait.restarts and the
// Gait.restart* keys): the settings' RestartRule, and the search a run starts
// with or resumes, which carry it (experiments/gait/search.hpp).
#include <cstdint>
#include <string>

#include "cic/io/gait_xml.hpp"
#include "cic/io/settings.hpp"
#include "cic/experiments/gait/search.hpp"
#include "cic/experiments/gait/setup.hpp"

namespace cic::gait {

RestartRule restart_rule_of(const io::Settings& s);

// A fresh search of the setup's optimiser, population and sigma0 under `rule`.
Search make_search(const Setup& setup, const RestartRule& rule, std::uint64_t seed);

// What a checkpoint's <restarts> element says of `search` (for the writer).
io::GaitRestartRecord restart_record_of(const Search& search);

// The search a checkpoint describes, rebuilt by replaying its history from the
// seed under `rule` (no evaluation), and checked against the candidates,
// champion and (when the file records them) restarts the checkpoint lists.
// Throws cic::InputError naming `file` when they differ.
Search resume_search(const Setup& setup, const RestartRule& rule, const io::GaitFile& checkpoint,
                     const std::string& file);

} // namespace cic::gait
