#pragma once
// The experiment types the settings know: each has a name (<Experiment><type>),
// a family, and optionally a section whose presence in a settings file selects
// it. The three built-in types are known here; a type added from outside (a
// plugin: docs/extending.md) is registered through
// experiments::register_experiment, which calls register_experiment_type.
//
// The family says what a type's genotypes are and how its results are stored
// and replayed, so a new type reuses its family's run loop, files and replays
// and brings only its own evaluation and settings:
//   symreg  - expression trees scored on a dataset;
//   hypergp - expression trees that build a robot controller (every substrate);
//   gait    - a parameter vector tuned by a pagmo2 optimiser.
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/settings.hpp"

namespace cic::io {

enum class ExperimentFamily { Symreg, HyperGP, Gait };

struct ExperimentType {
    std::string name;            // the <Experiment><type> value: lower case, digits, '-' or '_'
    ExperimentFamily family = ExperimentFamily::HyperGP;
    std::string section;         // a file with this section runs this type unless it names one ("" = none)
    std::string doc;             // one line, for `cic settings --defaults` and the man page
};

// Built-ins first (hypergp, symreg, gait), then registrations in their order.
const std::vector<ExperimentType>& experiment_types();
// nullptr when no type has this name.
const ExperimentType* find_experiment_type(std::string_view name);
// Adds a type; the Experiment.type key accepts it from then on. Register before
// reading settings (at static initialisation, as experiments::Registrar does).
// Throws std::invalid_argument for a bad or taken name, or an unknown section.
void register_experiment_type(ExperimentType type);

// What a type's genotypes are, as a search sees them (search/search.hpp):
// expression trees (symreg, hypergp) or a parameter vector (gait).
enum class GenotypeForm { Trees, Vector };
GenotypeForm genotype_form(const Settings& s);
std::string_view to_string(GenotypeForm f);
// Whether the type's runs walk a robot (replays, POV-Ray, the viewer, a path):
// every family but symbolic regression.
bool walks_a_robot(const Settings& s);
// Whether the type evaluates in rank 0's process (threads, no worker processes):
// symbolic regression.
bool evaluates_in_process(const Settings& s);

// The family of the settings' experiment type (which is always a known one:
// the reader checks it).
ExperimentFamily family_of(const Settings& s);
std::string_view to_string(ExperimentFamily f);

} // namespace cic::io
