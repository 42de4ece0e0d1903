#pragma once
// The open registry of experiment types. A type is one file that registers
// itself with a static Registrar: its name and family (io/experiment_types.hpp),
// the keys of its own settings section, the check of its inputs, the
// evaluator the GP loop drives, and the job kinds its worker processes serve.
// The built-ins (symreg, hypergp, gait) register this way too, and so does a
// type built outside cic against the installed package (examples/plugin,
// docs/extending.md).
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cic/experiments/experiment.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/settings_table.hpp"

namespace cic::experiments {

// What a worker process knows when it builds its job handlers: where the run's
// effective settings are (`cic worker --settings FILE`, or rank 0's text under MPI).
struct WorkerContext {
    std::string settings_file;   // may be empty
    // The effective settings as XML text, for workers that cannot read rank 0's
    // run folder (MPI ranks on other machines). When set, it wins over settings_file.
    std::string settings_text;
    // Reads them (call it lazily: a worker that serves only self-contained jobs
    // is started without settings). Throws std::invalid_argument when there are none.
    io::Settings load_settings() const;
};

// A job is text whose first line is its kind; the handler gets the rest (the
// body) and returns the reply. Built once per worker process; it may keep state.
using JobHandler = std::function<std::string(const std::string& body)>;
using JobHandlerFactory = std::function<JobHandler(const WorkerContext&)>;

struct ExperimentKind {
    io::ExperimentType type;
    // Its own settings section (io::extra_*_key); empty for the built-ins,
    // whose keys are rows of the settings table.
    std::vector<io::SettingKey> keys;
    // Loads and checks every input it will read, throwing cic::InputError with
    // file and line; writes nothing (prepare_run and `cic settings FILE` call it).
    std::function<void(const io::Settings&)> check_inputs;
    // The experiment the GP loop drives (families symreg and hypergp). The gait
    // family is varied by a search of gait vectors (src/search/evolution_strategy.cpp), so gait types leave it empty.
    std::function<std::unique_ptr<Experiment>(const Context&)> make;
    // Job kinds its worker processes serve, by the first line of a job.
    std::map<std::string, JobHandlerFactory> job_kinds;
    // A HyperGP-family type's own fitness instead of eq. 7.1, and what it reads
    // of the walk (the centre's path, joint angles, feet's contacts: recorded
    // only when asked). A type that gives `score` and no `make` or job kinds
    // gets both: HyperGP's experiment, with a job kind named after the type that
    // scores with it. Replays (view, assess, trace, Python's simulate) score with it too.
    hypergp::Score score = {};
    hypergp::WalkNeeds needs = {};
};

// Registers a kind. Throws std::invalid_argument for a name registered twice, a
// job kind that another type already serves, a GP-family type without `make`,
// or keys the settings table refuses (io::register_settings_keys).
void register_experiment(ExperimentKind kind);

// Every registered kind, in registration order.
const std::vector<ExperimentKind>& experiment_kinds();
// The kind of the settings' type; throws std::logic_error when the type is known
// to the settings but nothing registered its behaviour (a library linked without it).
const ExperimentKind& experiment_kind(std::string_view name);

// Registers at static initialisation: `const Registrar registrar{kind};` in the
// type's own file.
struct Registrar {
    explicit Registrar(ExperimentKind kind) { register_experiment(std::move(kind)); }
};

// One evaluation of a HyperGP-family genotype scored as the settings' type
// scores it in its worker jobs (its `score`, else eq. 7.1 with the penalty),
// recording what `options` ask plus what the type's score reads. For replays.
// `offsets`: an Offset-HybrID individual's direct genes (Neural.directOffsets).
hypergp::Outcome evaluate_as_type(const hypergp::Model& model, const io::Settings& settings,
                                  const tree::Forest& genotype, sim::EvalOptions options = {},
                                  bool record_control = false, std::span<const double> offsets = {});

// The job kinds of every registered type, plus sim's self-contained `sine`
// jobs (`cic simulate`), built for one worker process.
std::map<std::string, JobHandler> make_job_handlers(const WorkerContext& context);

} // namespace cic::experiments
