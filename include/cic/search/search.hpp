#pragma once
// A search is a block (thesis ch. 8: "any alternative algorithm can be tested
// in the same environment by merely plugging in new blocks"). It is one file
// that registers a SearchKind: its name, the genotype forms it varies, its
// budget key, its checkpoint's strict reader, and a factory for the Search
// that the run's one loop (run/run.hpp) drives:
//
//   start()                  the first evaluation (a fresh run's generation 0)
//   loop: stop(signal)       the search's stop rule: budget, minimum fitness, a signal
//         checkpoint_due()   -> checkpoint(): the text the loop writes atomically
//         step()             one generation or batch: each batch of genotypes
//                            goes through the run's evaluation context
//                            (Services::context: worker processes or MPI
//                            ranks), which tells their fitness (and descriptors)
//   summary()                summary.txt's text
//
// Each start() and step() returns a Row: stats.csv's columns (the search's
// own after io::kStatsColumns), run.log's line and the progress line. The
// loop writes them, watches the stop signals, writes the checkpoints and ends
// the run; it knows no family and no search. The built-ins register this way
// (generational GP, the evolution strategies, MAP-Elites, Switch-HybrID), and
// so does a search built outside cic against the installed package
// (examples/plugin/one_plus_lambda.cpp, docs/extending.md).
//
// Why a step evaluates rather than returning one batch: generational GP
// evaluates inside a generation (Dynamic Limits' filter, duplicates bred
// again) and pagmo2's algorithms call their problem from inside evolve(). A
// step may evaluate any number of batches, the same bytes for 1 or N workers:
// pagmo2's evolve() with the problem as a service. A search that asks for one
// batch per step, as pyribs's schedulers do, derives from VectorAskTell
// (ask_tell.hpp) and writes only ask() and tell().
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cic/experiments/experiment.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/settings.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/report/replay.hpp"
#include "cic/search/progress_line.hpp"

namespace cic::search {

// What the loop gives a search: the run's settings and evaluation context
// (worker processes or MPI ranks: experiments::Context), its folder, and its voice.
struct Services {
    const io::Settings& settings;
    const experiments::Context& context;
    std::filesystem::path run_dir;
    // Resuming in the run's own folder (cic resume, a sweep task): stats.csv
    // keeps its rows up to the checkpoint and grows from there.
    bool continue_in_place = false;
    std::function<void(const std::string&)> say;   // run.log and the console
    std::function<void(const std::string&)> log;   // run.log only
};

// One generation or batch, as stats.csv, run.log and the console see it.
struct Row {
    gp::GenerationRecord record;   // io::kStatsColumns (tree columns 0 for other genotypes)
    std::string extra;             // the search's own columns' values, comma-separated ("" = none)
    std::string log;               // run.log's line
    ProgressLine progress;
};

// Why a run stops: empty reason = it goes on.
struct Stop {
    std::string reason;            // "maximum iterations reached", "evaluation budget", ...
    bool interrupted = false;      // by a stop signal: the loop says where the state is
    bool done() const { return !reason.empty(); }
};

// The file a checkpoint writes: populations/gen-NNNN.xml and population.xml.
struct CheckpointText {
    int number = 0;
    std::string text;
};

// How stats.csv opens: its extra columns, and for a run continued in place
// the last row that stays.
struct StatsLayout {
    std::string extra_columns;
    std::optional<int> continue_after;
};

class Search {
public:
    virtual ~Search() = default;
    virtual StatsLayout stats_layout() const = 0;
    // Says the run's first lines; a fresh run evaluates its first generation and
    // returns its row, a resumed one restores its checkpoint (nullopt: no row).
    virtual std::optional<Row> start() = 0;
    virtual Stop stop(bool signal) = 0;
    // Asked once after each stop(): whether the loop writes checkpoint() now.
    virtual bool checkpoint_due(const Stop& stop) = 0;
    virtual CheckpointText checkpoint() const = 0;
    virtual Row step() = 0;
    // summary.txt's text (the loop adds where and when); may replay the best.
    virtual std::string summary(const Stop& stop) = 0;
};

// A checkpoint as the search's strict reader loaded it (from
// Control.populationXmlLoadFrom), checked against the settings before the run
// writes anything.
class Checkpoint {
public:
    virtual ~Checkpoint() = default;
    std::string file;              // where it was read
    std::string settings_digest;   // of the settings it was made with
    std::string origin_note;       // io::check_origin's note (a file without <origin>)
    int generations = 0;           // generations (or batches) it holds evaluated
    // Where it stands in its run's history, checked against the run folder on
    // resume (run/run_history.hpp): the number N of the populations/gen-NNNN.xml
    // it was saved as (stats.csv's row N) and stats.csv's evaluations there.
    // -1: the search does not say (one built outside cic); then not checked.
    int number = -1;
    long evaluations = -1;
    // Set by the run (run/run.hpp's prepare_run): made with other search
    // settings, its fitness values hold (search_note); cleared by a resume in place.
    std::string search_note;
    // Throws cic::InputError naming `file` when the settings' budget adds no
    // step to it (cic resume, a sweep's extend): nothing may be written then.
    virtual void check_goes_on(const io::Settings& s) const = 0;
};

struct SearchKind {
    std::string name;              // Experiment.search's value
    std::string doc;               // one line
    std::vector<io::GenotypeForm> forms;   // the genotypes it varies
    // Its own settings section's keys, if any (registered with the settings table).
    std::vector<io::SettingKey> keys;
    // The key that bounds a run's length ("Gait.evaluations"), and what it
    // counts ("evaluations" or "generations"); a resume may raise it.
    std::string budget_key;
    std::string budget_unit = "evaluations";
    // What `auto` picks: a search that the other keys ask for (MapElites.enabled)
    // claims the run, with the text that says why; else the form's fallback.
    std::function<bool(const io::Settings&)> claims;
    std::string claimed_by;
    bool fallback = false;         // auto's choice for its forms when nothing claims
    // The strict reader of its checkpoints: parses `file` completely and checks
    // it against the settings (origin, shape, values); throws cic::InputError
    // with file and line. Writes nothing.
    std::function<std::unique_ptr<Checkpoint>(const io::Settings&, const std::string& file)> load;
    // The XSD of its checkpoint file, if it has one of its own: load_checkpoint
    // validates the file against it before `load` reads it. (The built-ins'
    // files are checked against the shipped settings/cic-*.xsd by their io readers.)
    std::string checkpoint_schema;
    // For view, assess, trace and render (report::replay): the root element of
    // its checkpoint file and the best individual one holds (a gait vector, or a
    // search of trees' trees with any direct genes). A search with a file of its
    // own gives both; cic's three files are read by report itself.
    std::string checkpoint_root;
    report::CheckpointBestReader best;
    // The search of a run: fresh, or from `resume` (this kind's own checkpoint).
    std::function<std::unique_ptr<Search>(const Services&, std::unique_ptr<Checkpoint> resume)> make;
};

// Registers a kind and its name for Experiment.search (and its keys with the
// settings table). Throws std::invalid_argument for a name registered twice,
// no forms, no load or make, or keys the settings table refuses.
void register_search(SearchKind kind);
const std::vector<SearchKind>& search_kinds();
// The search the settings pick (Experiment.search, or auto's choice). Throws
// cic::InputError naming Experiment.search and the allowed values when the
// named search does not vary the type's genotypes or another key asks for
// another search.
const SearchKind& search_of(const io::Settings& s);
// The kind's checkpoint at `file`: validated against its checkpoint_schema (if
// any), then read by its `load`. Throws cic::InputError with file and line.
std::unique_ptr<Checkpoint> load_checkpoint(const SearchKind& kind, const io::Settings& s, const std::string& file);
// Every budget key of the registered searches, and Control.minimumFitness.
std::vector<std::string> budget_keys();

// Registers at static initialisation: `const Registrar registrar{kind};` in the search's own file.
struct Registrar {
    explicit Registrar(SearchKind kind) { register_search(std::move(kind)); }
};

} // namespace cic::search
