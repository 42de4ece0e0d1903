#pragma once
// Scoring genotypes from outside a run: the Python package (python/) and
// `cic eval` (JSON lines). A session reads a settings file as `cic --settings`
// does (the same lookup, the same `--set` checks, the same input checks), then
// evaluates batches with the job texts and `cic worker` processes a run of
// those settings uses, so every fitness is a run's to the last bit, for any
// number of workers. Nothing is written but a private copy of the effective
// settings for the workers, in $TMPDIR/cic-eval-XXXXXX, removed when the
// session ends; a folder whose session was killed (SIGKILL: no destructor ran)
// is removed by the next session's start.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cic/io/settings.hpp"
#include "cic/sim/controller.hpp"

namespace cic::run {

// One genotype: a point of the gait family's unit box (gait or CPG vector), or
// a HyperGP forest as S-expressions (one per tree). Switch-HybrID settings take
// both: trees, and after the hand-over the gait vector.
struct Genotype {
    std::vector<double> vector;
    std::vector<std::string> trees;
    // Offset-HybrID (Neural.directOffsets = 1): beside the trees, one direct
    // offset per hinge, in units of pi/2 within +-kOffsetLimit (gait_substrate.hpp).
    std::vector<double> offsets;
};

enum class GenotypeForm { Vector, Forest };

// One entry per genotype, in batch order.
struct Scores {
    std::vector<double> fitness;        // the run's score (its penalty or a type's own score included)
    std::vector<double> distance;       // eq. 7.1's walk along the preferred axis, m (0 when failed)
    std::vector<double> elevation;      // eq. 7.1's elevation gained, m (0 when failed)
    std::vector<std::vector<double>> descriptor;   // when the settings ask for one (MapElites.descriptor)
    std::vector<char> failed;
    std::vector<std::string> failure;
};

// The whole of one evaluation (simulate): per control step its time, the
// centre's position, each joint's measured angle and commanded target, and each
// foot's ground contact.
struct Walk {
    double fitness = 0.0, distance = 0.0, elevation = 0.0;
    bool failed = false;
    std::string failure;
    std::vector<std::string> joint_names;   // actuated joints, in controller order
    std::vector<std::string> foot_names;    // branch ends (sim::branch_ends), in module order
    std::vector<double> time;               // s, one per control step
    std::vector<double> centre;             // steps x 3, row-major (x, y, z), m
    std::vector<double> angles;             // steps x joints, rad
    std::vector<double> targets;            // steps x joints, rad (after the simulator's clamp)
    std::vector<unsigned char> feet;        // steps x feet: 1 = touched the ground in that step
    // Each foot's duty factor as `cic assess` gives it (sim::duty_factors: the
    // physics steps from the delayed start on); empty without the trace.
    std::vector<double> duty_factors;
};

// How in_box reads a point outside the unit box: as the settings' Gait.bounds
// does (the run's own reading), or by reflecting or clipping it. Phases wrap
// in every case (they are periodic).
enum class BoxReading { Settings, Reflect, Clip };

struct SessionOptions {
    std::string settings_file;               // as given: found like --settings (installed settings too)
    std::vector<std::string> overrides;      // "Section.key=value", checked exactly like --set
    int workers = 1;                         // >= 1
    std::string worker_executable;           // the cic binary that serves `cic worker`
    std::function<bool()> interrupted = {};  // asked during a batch (Ctrl-C); true throws cic::Interrupted
    std::function<void(const std::string&)> warn = [](const std::string&) {};   // a replaced worker, a failed job
    // Notes that are not trouble: which installed settings file a bare name found
    // (empty: printed on stderr, as cic --settings does).
    std::function<void(const std::string&)> note = {};
};

class EvaluationSession {
public:
    // Throws run::SettingsNotFound for a settings file found nowhere, cic::InputError
    // for bad settings, a symbolic-regression experiment (not a robot), or
    // workers < 1; std::runtime_error when workers cannot start.
    explicit EvaluationSession(SessionOptions options);
    ~EvaluationSession();
    EvaluationSession(const EvaluationSession&) = delete;
    EvaluationSession& operator=(const EvaluationSession&) = delete;

    const io::Settings& settings() const;
    std::filesystem::path settings_file() const;   // the file found
    GenotypeForm form() const;
    // A vector's length, or the trees of a forest.
    std::size_t dimension() const;
    // The direct offsets a forest carries beside its trees (Offset-HybrID: one
    // per hinge), or 0 when the settings have none.
    std::size_t offsets() const;
    // The gait vector's length when the session takes gait vectors: the gait
    // family's (then dimension()), or a Switch-HybrID run's after its hand-over
    // beside its trees; else 0.
    std::size_t vector_dimension() const;
    int workers() const;

    // Throws cic::InputError for a genotype these settings cannot take: the wrong
    // form or length, a value outside the unit box or not finite, a tree that
    // does not parse or uses a function or variable the settings lack, offsets
    // the settings do not have, or not one per hinge, or out of their range.
    void check(const Genotype& genotype, std::size_t index = 0) const;

    // Every genotype is checked first (cic::InputError naming its index and what
    // is wrong), then the batch runs on the workers. An empty batch gives empty scores.
    Scores evaluate(const std::vector<Genotype>& batch);

    // One evaluation in this process, with the trace when asked: the same
    // simulation a worker runs (each evaluation resets ODE's global state).
    Walk simulate(const Genotype& genotype, bool trace) const;

    // The point of the unit box a gait or CPG vector `x` is read as (gait::Setup::in_box):
    // with BoxReading::Settings, the point whose fitness is the fitness a run gives
    // x, bit for bit. Throws cic::InputError for settings without gait vectors, or
    // the wrong length or a non-finite value.
    std::vector<double> in_box(const std::vector<double>& x, BoxReading reading) const;

    // The sine gait a gait vector decodes to (frequency, each joint's amplitude,
    // phase, offset; summary.txt's numbers). Throws cic::InputError for CPG or
    // HyperGP-only settings and for a vector these settings cannot take.
    sim::GaitSpec decode(const std::vector<double>& x) const;
    // The actuated joints' names, in controller order (a gait vector's joint order).
    std::vector<std::string> joint_names() const;

    // Ends the workers now (the destructor does too); evaluate() after it throws.
    void close();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The best genotype of a run folder as the session takes it, with its stored
// fitness: a gait run's champion, a HyperGP run's best individual of its latest
// checkpoint, a MAP-Elites run's best elite. A gait vector is given in the unit
// box (the optimiser may store a point outside it, which decodes to the same gait).
struct RunBest {
    GenotypeForm form = GenotypeForm::Vector;
    Genotype genotype;
    double fitness = 0.0;
    int generation = 0;
    std::filesystem::path settings;   // the run's settings.xml
};
RunBest read_run_best(const std::filesystem::path& run_dir);

} // namespace cic::run
