// Cross-field checks of Settings, run once after all layers are applied.
// Single-key checks (type, range) happen in the table's setters.
#include "cic/core/error.hpp"
#include "cic/io/bodies.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/xml.hpp"
#include "cic/nn/geometry.hpp"
#include "settings_values.hpp"

namespace cic::io::detail {
namespace {

// Builds "<Sec> a = 1 must be <= b = 2" errors located at the first of the
// named keys the user actually wrote (else at the settings file).
class Checker {
public:
    Checker(const Settings& s, const Locations& locs) : s_(s), locs_(locs) {}

    void require(bool ok, const std::vector<const char*>& keys, const std::string& why) const {
        if (ok) return;
        Location where{s_.source_file, 0};
        for (const char* k : keys)
            if (auto it = locs_.find(k); it != locs_.end()) {
                where = it->second;
                break;
            }
        std::string msg;
        for (std::size_t i = 0; i < keys.size(); ++i) {
            std::string_view full = keys[i];
            auto dot = full.find('.');
            const SettingKey* k = find_setting(full.substr(0, dot), full.substr(dot + 1));
            msg += (i ? ", " : "") + std::string("<") + std::string(full.substr(0, dot)) + "> " +
                   std::string(full.substr(dot + 1)) + " = \"" + (k ? k->get(s_) : "?") + "\"";
        }
        throw InputError(msg + ": " + why, where.file, where.line);
    }

private:
    const Settings& s_;
    const Locations& locs_;
};

// Evolving for transfer (io/bodies.hpp): several bodies, or a growing robot,
// are built for the generational HyperGP search on whole bodies; anything else
// is refused, not ignored.
void check_bodies(const Settings& s, const Checker& c) {
    const auto& r = s.robot;
    c.require(!several_bodies(s) || !grows(s), {"Simulator.extraRobotFiles", "Simulator.growRobotFiles"},
              "several bodies in one fitness and a growing robot do not combine (allowed: one of the two empty)");
    const std::pair<const char*, bool> keys[] = {{"Simulator.extraRobotFiles", several_bodies(s)},
                                                 {"Simulator.growRobotFiles", grows(s)}};
    for (const auto& [key, given] : keys) {
        if (!given) continue;
        c.require(family_of(s) == ExperimentFamily::HyperGP, {key, "Experiment.type"},
                  "other bodies score HyperGP genotypes, which fit any robot (allowed: a hypergp-family type)");
        c.require(s.experiment.search == "auto" || s.experiment.search == "generational", {key, "Experiment.search"},
                  "other bodies are built for the generational search (allowed: Experiment.search = auto | "
                  "generational)");
        c.require(!s.map_elites.enabled, {key, "MapElites.enabled"},
                  "other bodies are built for the generational search, not MAP-Elites (allowed: MapElites.enabled = 0)");
        c.require(!s.neural.switches(), {key, "Neural.switchPatience", "Neural.switchShare"},
                  "Switch-HybrID's gait phase has one parameter per hinge of one robot (allowed: "
                  "Neural.switchPatience = 0 and Neural.switchShare = 0)");
        c.require(!s.neural.direct_offsets, {key, "Neural.directOffsets"},
                  "Offset-HybrID's offsets are one per hinge of one robot (allowed: Neural.directOffsets = 0)");
    }
    c.require(r.grow_at.size() == r.grow_robot_files.size(), {"Simulator.growAt", "Simulator.growRobotFiles"},
              "give one share of the budget per body of growRobotFiles (" + std::to_string(r.grow_robot_files.size()) +
                  ")");
    if (!grows(s) || r.grow_at.size() != r.grow_robot_files.size()) return;
    int previous = 0;
    for (std::size_t body = 1; body <= r.grow_at.size(); ++body) {
        const int first = grow_generation(s, body);
        c.require(first > previous && first < s.control.maximum_iterations,
                  {"Simulator.growAt", "Control.maximumIterations"},
                  "each body needs a generation of its own: body " + std::to_string(body) + " would start at generation " +
                      std::to_string(first) + " (ceil(share x maximumIterations)), which must be after body " +
                      std::to_string(body - 1) + "'s first (" + std::to_string(previous) +
                      ") and before the last generation (" + std::to_string(s.control.maximum_iterations - 1) + ")");
        previous = first;
    }
}

} // namespace

void validate(const Settings& s, const Locations& locs) {
    Checker c(s, locs);
    // Text goes into settings.xml and population files: refuse what XML cannot hold.
    for (const auto& k : settings_table())
        if (k.type == ValueType::String || k.type == ValueType::Path || k.type == ValueType::PathList)
            if (auto why = xml::unholdable(k.get(s))) {
                const std::string full = k.section + "." + k.key;
                c.require(false, {full.c_str()}, "contains " + *why + ", which an XML file cannot hold");
            }
    const auto& gp = s.gp;
    const auto& p = gp.primitives;
    c.require(gp.min_init_depth <= gp.max_init_depth,
              {"GP.minimumGeneratedTreeDepth", "GP.maximumGeneratedTreeDepth"},
              "the minimum depth must not exceed the maximum depth");
    c.require(s.bloat.enabled || gp.max_tree_depth == 0 || gp.generated_tree_levels() <= gp.max_tree_depth,
              {"GP.maximumGeneratedTreeDepth", "GP.maximumTreeDepth", "GP.ptc1RootDepth"},
              "generated trees must fit the depth cap (" + std::to_string(gp.generated_tree_levels()) +
                  " levels; the cap applies when bloat control is off)");
    c.require(gp.crossover_rate + gp.mutation_rate <= 1.0 + 1e-12, {"GP.crossoverRate", "GP.mutationRate"},
              "crossover and mutation rates must sum to at most 1");
    c.require(gp.tournament_size <= gp.population_size, {"GP.tournament_size", "GP.generatedPopulationSize"},
              "the tournament cannot be larger than the population");
    c.require(gp.elitism < gp.population_size, {"GP.elitism", "GP.generatedPopulationSize"},
              "elitism must leave room for offspring (elitism < population size)");
    c.require(p.function_weights.empty() || p.function_weights.size() == p.functions.size(),
              {"GP.functionProbabilities", "GP.functions"}, "give one weight per function (or a single weight for all)");
    c.require(!p.ephemeral || p.ephemeral_min < p.ephemeral_max, {"GP.ephemeralMin", "GP.ephemeralMax"},
              "the ephemeral constant range is empty");
    c.require(p.variable_count > 0 || !p.constants.empty() || p.ephemeral,
              {"GP.terminalVariableCount", "GP.terminalConsts", "GP.ephemeralConstants"},
              "trees need at least one terminal (a variable, a constant or ephemeral constants)");

    // The simulator's own rules (sim/config.hpp), reported at the settings keys involved.
    for (const sim::ConfigProblem& problem : sim::config_problems(s.sim)) {
        std::vector<std::string> keys;
        for (std::string_view name : problem.fields)
            sim::for_each_field(s.sim, [&](const sim::FieldSpec& f, const auto&) {
                if (f.name == name) keys.push_back("Simulator." + std::string(f.key));
            });
        std::vector<const char*> key_ptrs;
        for (const auto& k : keys) key_ptrs.push_back(k.c_str());
        c.require(false, key_ptrs, problem.why);
    }

    const auto& nn = s.neural;
    c.require(family_of(s) != ExperimentFamily::HyperGP || p.variable_count <= nn::cppf_variable_count(nn),
              {"GP.terminalVariableCount", "Neural.extraCppfInputs"},
              "HyperGP's CPPF has " + std::to_string(nn::cppf_variable_count(nn)) +
                  " inputs (x1 y1 x2 y2, and 3 more with extraCppfInputs); a tree cannot use more variables");
    c.require(nn.forest_map.empty() || nn.forest_map.size() == static_cast<std::size_t>(nn::kSynapseTypes),
              {"Neural.forestMap"}, "give one tree index per synapse type (5) or none");
    for (int t : nn.forest_map)
        c.require(t < gp.trees_per_genotype, {"Neural.forestMap", "GP.numberOfTreesInForestGenotype"},
                  "a tree index is past the last tree of the genotype");

    c.require(nn.frequency_min <= nn.frequency_max, {"Neural.frequencyMin", "Neural.frequencyMax"},
              "the frequency range is empty");
    if (family_of(s) == ExperimentFamily::HyperGP) {
        c.require(!nn.evolve_clock || (nn.substrate == "network" && nn.clock_inputs),
                  {"Neural.evolveClock", "Neural.clockInputs", "Neural.substrate"},
                  "an evolved clock needs the network substrate with clock inputs (clockInputs = 1)");
        // The network's inputs and averaging do not exist in the other substrates: refuse
        // them rather than ignore them.
        const bool network = nn.substrate == "network";
        c.require(network || (!nn.clock_inputs && !nn.bias_input),
                  {"Neural.clockInputs", "Neural.biasInput", "Neural.substrate"},
                  "clock and bias inputs belong to the network substrate; cpg and gait keep their own rhythm");
        c.require(network || nn.sample_average_count == 1, {"Neural.sampleAverageCount", "Neural.substrate"},
                  "sample averaging belongs to the network substrate");
        c.require(nn.substrate == "cpg" || nn.cpg_feedback == 0.0, {"Neural.cpgFeedback", "Neural.substrate"},
                  "feedback gains belong to the cpg substrate");
    }

    // Offset-HybrID adds to the gait substrate's offsets; the archive's operators know no offsets.
    c.require(!nn.direct_offsets || (family_of(s) == ExperimentFamily::HyperGP && nn.substrate == "gait"),
              {"Neural.directOffsets", "Neural.substrate", "Experiment.type"},
              "direct offsets add to the offsets of HyperGP's gait substrate (allowed: Neural.directOffsets = 1 "
              "with a hypergp-family type and Neural.substrate = gait)");
    c.require(!nn.direct_offsets || !s.map_elites.enabled, {"Neural.directOffsets", "MapElites.enabled"},
              "MAP-Elites varies trees only; direct offsets need the GP loop (allowed: MapElites.enabled = 0)");

    // Switch-HybrID hands the gait substrate's best over to the gait family's
    // centred box, which is its exact image only under these conditions.
    if (nn.switches()) {
        c.require(family_of(s) == ExperimentFamily::HyperGP && nn.substrate == "gait" && !s.map_elites.enabled,
                  {"Neural.switchPatience", "Neural.switchShare", "Neural.substrate", "MapElites.enabled"},
                  "Switch-HybrID hands HyperGP's gait substrate over to CMA-ES (allowed: a hypergp-family type, "
                  "Neural.substrate = gait, MapElites.enabled = 0)");
        c.require(nn.penalty == nn::OscillationPenalty::None, {"Neural.switchPatience", "Neural.oscillationPenalty"},
                  "Switch-HybrID compares both phases on eq. 7.1, which the gait phase scores without a penalty "
                  "(allowed: Neural.oscillationPenalty = none)");
        c.require(s.gait.frequency_min == nn.frequency_min && s.gait.frequency_max == nn.frequency_max,
                  {"Gait.frequencyMin", "Gait.frequencyMax", "Neural.frequencyMin", "Neural.frequencyMax"},
                  "Switch-HybrID hands the gait over exactly only when both phases read one frequency range "
                  "(set Gait.frequencyMin/Max equal to Neural.frequencyMin/Max)");
        c.require(s.gait.controller == GaitController::Sine && !s.gait.second_harmonic &&
                      s.gait.optimizer != GaitOptimizer::Sade,
                  {"Gait.controller", "Gait.secondHarmonic", "Gait.optimizer"},
                  "Switch-HybrID's gait phase is cmaes, xnes or sepcmaes on the sine gait without a second harmonic");
        c.require(s.gait.population_size <= s.gait.evaluations, {"Gait.populationSize", "Gait.evaluations"},
                  "the budget does not cover one generation");
    }

    check_bodies(s, c);

    c.require(s.symreg.range_min < s.symreg.range_max,
              {"SymbolicRegression.rangeMin", "SymbolicRegression.rangeMax"}, "the sampled range is empty");

    c.require(s.gait.controller != GaitController::Cpg || !s.gait.second_harmonic,
              {"Gait.secondHarmonic", "Gait.controller"}, "a second harmonic belongs to the sine controller");
    c.require(s.gait.frequency_min <= s.gait.frequency_max, {"Gait.frequencyMin", "Gait.frequencyMax"},
              "the frequency range is empty");
    c.require(family_of(s) != ExperimentFamily::Gait || s.gait.population_size == 0 ||
                  s.gait.population_size >= (s.gait.optimizer == GaitOptimizer::Sade ? 7 : 5),
              {"Gait.populationSize", "Gait.optimizer"},
              "cmaes, xnes and sepcmaes need at least 5 candidates per generation, sade 7 (allowed: "
              "Gait.populationSize = 0 for the optimiser's default, at least 5, or at least 7 with sade)");
    c.require(s.gait.restarts == GaitRestarts::None || s.gait.optimizer != GaitOptimizer::Sade,
              {"Gait.restarts", "Gait.optimizer"},
              "ipop restarts are built for cmaes, xnes and sepcmaes only (allowed: Gait.restarts = none | ipop "
              "with Gait.optimizer = cmaes | xnes | sepcmaes; none with sade)");
    c.require(family_of(s) != ExperimentFamily::Gait || s.gait.population_size <= s.gait.evaluations,
              {"Gait.populationSize", "Gait.evaluations"}, "the budget does not cover one generation");

    c.require(!s.map_elites.enabled || family_of(s) == ExperimentFamily::HyperGP ||
                  family_of(s) == ExperimentFamily::Gait,
              {"MapElites.enabled", "Experiment.type"},
              "MAP-Elites searches the robot experiments (allowed: the hypergp and gait families); symbolic "
              "regression has no behaviour descriptor");
    c.require(!s.map_elites.enabled || s.gait.restarts == GaitRestarts::None, {"Gait.restarts", "MapElites.enabled"},
              "ipop restarts belong to the pagmo optimisers, which MAP-Elites replaces (allowed: Gait.restarts = none)");
    c.require(!s.map_elites.enabled || s.map_elites.batch <= s.map_elites.evaluations,
              {"MapElites.batch", "MapElites.evaluations"}, "the budget does not cover one batch");
    if (s.map_elites.enabled && s.map_elites.emitter != "auto") {
        const EmitterName* e = find_emitter_name(s.map_elites.emitter);
        const ExperimentFamily family = family_of(s);
        std::string allowed = "auto";
        for (const auto& n : emitter_names())
            if (n.family == family) allowed += " | " + n.name;
        c.require(e && e->family == family, {"MapElites.emitter", "Experiment.type"},
                  "this emitter varies " + std::string(e ? to_string(e->family) : "other") +
                      "-family solutions, and a " + std::string(to_string(family)) +
                      "-family run has other ones (allowed here: " + allowed + ")");
    }
    const bool gp_emitter = family_of(s) == ExperimentFamily::HyperGP && resolved_emitter(s) == "gp";
    c.require(!s.map_elites.enabled || !gp_emitter || s.gp.crossover_rate + s.gp.mutation_rate > 0,
              {"GP.crossoverRate", "GP.mutationRate", "MapElites.enabled"},
              "MAP-Elites varies elites by crossover and mutation: their rates cannot both be 0");

    const auto& name = s.experiment.name;
    c.require(name.find('/') == std::string::npos && name != "." && name != "..", {"Experiment.name"},
              "the run name becomes a folder name and cannot contain '/'");
}

} // namespace cic::io::detail
