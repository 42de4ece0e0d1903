// The rows of the settings table for the Neural, SymbolicRegression and Gait
// sections (see settings_table.hpp; the other sections are in settings_table.cpp).
#include <string>
#include <vector>

#include "cic/core/limits.hpp"
#include "settings_rows.hpp"
#include "settings_values.hpp"

namespace cic::io::rows {
namespace {

using detail::format_double;
using detail::join;
using detail::split_items;

// By nn::SynapseType. A function, not a namespace-scope vector: the table may be
// built while other files' statics are initialised (a registration in a
// static initialiser), before such a vector would exist.
const std::vector<std::string>& synapse_names() {
    static const std::vector<std::string> names{"ih", "ho", "hh", "oo", "oh"};
    return names;
}

SettingKey synapse_types_row() {
    auto k = row("Neural", "synapseTypes", ValueType::NameList,
                 "Synapse types the substrate builds: ih (input-hidden), ho, hh, oo, oh (thesis fig. 6.8)");
    for (auto& n : synapse_names()) k.choices.push_back({n});
    k.get = [](const Settings& s) {
        std::vector<std::string> names;
        for (std::size_t i = 0; i < synapse_names().size() && i < s.neural.synapse_enabled.size(); ++i)
            if (s.neural.synapse_enabled[i]) names.push_back(synapse_names()[i]);
        return join(names);
    };
    k.set = [](Settings& s, std::string_view t) {
        std::vector<bool> on(synapse_names().size(), false);
        for (auto item : split_items(t)) {
            auto it = std::find(synapse_names().begin(), synapse_names().end(), item);
            if (it == synapse_names().end()) throw ValueError("unknown synapse type '" + std::string(item) + "'");
            auto i = static_cast<std::size_t>(it - synapse_names().begin());
            if (on[i]) throw ValueError("synapse type '" + std::string(item) + "' listed twice");
            on[i] = true;
        }
        s.neural.synapse_enabled = on;
    };
    return k;
}

SettingKey forest_map_row() {
    auto k = row("Neural", "forestMap", ValueType::IntList,
                 "Tree index per synapse type (ih ho hh oo oh) when the genotype has several trees; "
                 "empty = type i uses tree i mod numberOfTreesInForestGenotype");
    k.min = 0;
    k.max = 15;
    k.min_items = 0;
    k.max_items = synapse_names().size();
    SettingKey bounds = k;
    k.get = [](const Settings& s) {
        std::vector<std::string> items;
        for (int v : s.neural.forest_map) items.push_back(std::to_string(v));
        return join(items);
    };
    k.set = [bounds](Settings& s, std::string_view t) {
        std::vector<int> v;
        for (auto item : split_items(t)) v.push_back(static_cast<int>(detail::parse_integer(bounds, item)));
        s.neural.forest_map = std::move(v);
    };
    return k;
}

// Neural keys beyond the thesis (docs/hypergp.md). Their defaults keep the
// thesis's network, and they stay out of the digest at their defaults.
void beyond_thesis_neural_rows(std::vector<SettingKey>& t) {
    const std::size_t first = t.size();
    t.push_back(detail::substrate_row());
    t.push_back(bool_row("Neural", "evolveClock",
                         "network: the clock inputs' frequency is read from the genotype, in "
                         "[frequencyMin, frequencyMax], instead of clockPeriod",
                         FIELD(neural.evolve_clock)));
    t.push_back(double_row("Neural", "frequencyMin", kPositive,
                           "Lowest evolved frequency (evolveClock, substrate gait), Hz", FIELD(neural.frequency_min)));
    t.push_back(double_row("Neural", "frequencyMax", kPositive,
                           "Highest evolved frequency (evolveClock, substrate gait), Hz", FIELD(neural.frequency_max)));
    t.push_back(double_row("Neural", "cpgWeightScale", kPositive,
                           "cpg: largest |weight|, rad/s (w = scale tanh(tree)); a lone oscillator of weight w "
                           "runs at |w| / 2 pi Hz",
                           FIELD(neural.cpg_weight_scale)));
    t.push_back(int_row("Neural", "cpgHops", 1, 100,
                        "cpg: joints whose modules are at most this many links apart in the body tree are coupled",
                        FIELD(neural.cpg_hops)));
    t.push_back(double_row("Neural", "cpgFeedback", kNonNegative,
                           "cpg: largest feedback gain of the joint angles into the oscillators, 1/s; 0 = open loop",
                           FIELD(neural.cpg_feedback)));
    t.push_back(bool_row("Neural", "directOffsets",
                         "gait: Offset-HybrID (Helms & Clune 2017): the genotype also holds one directly encoded "
                         "offset d_i per joint, added to the tree's: o_i = pi/2 clamp(tanh(T(p_i, O)) + d_i, -1, 1), "
                         "d_i in [-2, 2]; drawn from N(0, offsetSigma), inherited with the first parent's trees, "
                         "saved in population files (docs/hypergp.md)",
                         FIELD(neural.direct_offsets)));
    t.push_back(double_row("Neural", "offsetSigma", kNonNegative,
                           "directOffsets: the Gaussian step of a direct offset, in units of pi/2 rad (0.1 = 9 "
                           "degrees); also the spread of the initial offsets",
                           FIELD(neural.offset_sigma)));
    t.push_back(double_row("Neural", "offsetRate", kUnit,
                           "directOffsets: the probability that a child of crossover or mutation moves each of its "
                           "offsets by a step (reproduction copies and elites keep theirs)",
                           FIELD(neural.offset_rate)));
    t.push_back(int_row("Neural", "switchPatience", 0, 1000000,
                        "gait: Switch-HybrID (Clune et al. 2009; Helms & Clune 2017's Auto-Switch): hand the run "
                        "over to CMA-ES on the direct gait (Gait.* keys, started from the best individual's gait) "
                        "after this many generations without improvement of the best; 0 = not on stagnation. The "
                        "run's budget is then Gait.evaluations, shared by both phases (docs/hypergp.md)",
                        FIELD(neural.switch_patience)));
    t.push_back(double_row("Neural", "switchShare", kUnit,
                           "gait: Switch-HybrID: hand over once HyperGP has spent this share of Gait.evaluations "
                           "(whichever of switchPatience and switchShare comes first); 0 = no fixed share",
                           FIELD(neural.switch_share)));
    t.push_back(enum_row<nn::SubstrateLayout>(
        "Neural", "substrateLayout",
        {{nn::SubstrateLayout::Normalised, {"normalised"}}, {nn::SubstrateLayout::Absolute, {"absolute"}}},
        "Where the substrate's neurons sit (the CPPF's x and y): normalised = each axis of the robot's bounding box "
        "mapped onto [-1, 1] (the thesis's; a bigger body squeezes its legs closer); absolute = cells from the "
        "centre module divided by substrateUnit (a bigger body keeps the spacing of its legs and is queried beyond "
        "the smaller one's range)",
        FIELD(neural.substrate_layout)));
    t.push_back(double_row("Neural", "substrateUnit", kPositive,
                           "substrateLayout absolute: the number of module cells that make one unit of the CPPF's "
                           "coordinates, on both axes",
                           FIELD(neural.substrate_unit)));
    for (std::size_t i = first; i < t.size(); ++i) t[i].digest_at_default = false;
}

} // namespace


// Neural
void neural_rows(std::vector<SettingKey>& t) {
    t.push_back(double_row("Neural", "synopsisThreshold", kNonNegative,
                           "Synapses with |weight| below this are left out of the substrate", FIELD(neural.threshold)));
    t.push_back(bool_row("Neural", "useMiddleLegs", "Use the 6-leg variant of the robot (0 = 4 legs)",
                         FIELD(neural.middle_legs)));
    t.push_back(int_row("Neural", "sampleAverageCount", 1, 1000, "Consecutive sample averaging (thesis 7.3.2.1)",
                        FIELD(neural.sample_average_count)));
    t.push_back(synapse_types_row());
    t.push_back(forest_map_row());
    t.push_back(enum_row<nn::WeightRule>("Neural", "weightRule",
                                         {{nn::WeightRule::Raw, {"raw"}}, {nn::WeightRule::Scaled, {"scaled"}}},
                                         "Synapse weight: raw CPPF output, or rescaled to +-maxWeight",
                                         FIELD(neural.weight_rule)));
    t.push_back(double_row("Neural", "maxWeight", kPositive, "Largest |weight| for weightRule scaled",
                           FIELD(neural.max_weight)));
    t.push_back(enum_row<nn::NeuronModel>("Neural", "neuronModel",
                                          {{nn::NeuronModel::Tanh, {"tanh"}}, {nn::NeuronModel::Integrating, {"integrating"}}},
                                          "Neuron model (thesis eq. 7.2-7.3)", FIELD(neural.neuron)));
    t.push_back(bool_row("Neural", "biasInput", "Add a constant bias input neuron", FIELD(neural.bias_input)));
    t.push_back(bool_row("Neural", "clockInputs", "Add sin/cos clock input neurons", FIELD(neural.clock_inputs)));
    t.push_back(double_row("Neural", "clockPeriod", kPositive, "Period of the clock inputs, s", FIELD(neural.clock_period)));
    t.push_back(bool_row("Neural", "extraCppfInputs", "Give the CPPF layer index and distance as extra inputs",
                         FIELD(neural.extra_cppf_inputs)));
    t.push_back(enum_row<nn::OscillationPenalty>("Neural", "oscillationPenalty",
                                                 {{nn::OscillationPenalty::None, {"none"}},
                                                  {nn::OscillationPenalty::Frequency, {"frequency"}},
                                                  {nn::OscillationPenalty::CommandChange, {"commandChange"}}},
                                                 "Fitness penalty for jittery control", FIELD(neural.penalty)));
    t.push_back(double_row("Neural", "penaltyMaxFrequency", kPositive,
                           "Command frequency above which the frequency penalty applies, Hz",
                           FIELD(neural.penalty_max_frequency)));
    t.push_back(double_row("Neural", "penaltyWeight", kNonNegative, "Weight of the command-change penalty",
                           FIELD(neural.penalty_weight)));
    beyond_thesis_neural_rows(t);
}

// SymbolicRegression
void symreg_rows(std::vector<SettingKey>& t) {
    t.push_back(string_row("SymbolicRegression", "target", ValueType::String, false,
                           "Benchmark name (koza-1 ...) or an expression over x0, x1, ...", FIELD(symreg.target)));
    t.push_back(string_row("SymbolicRegression", "dataFile", ValueType::Path, true,
                           "CSV with a header; the last column is the target (overrides target)",
                           FIELD(symreg.data_file)));
    t.push_back(int_row("SymbolicRegression", "samples", 1, 10000000, "Equidistant sample points in [rangeMin, rangeMax]",
                        FIELD(symreg.samples)));
    t.push_back(double_row("SymbolicRegression", "rangeMin", kAnyFinite, "Lower end of the sampled range",
                           FIELD(symreg.range_min)));
    t.push_back(double_row("SymbolicRegression", "rangeMax", kAnyFinite, "Upper end of the sampled range",
                           FIELD(symreg.range_max)));
    t.push_back(bool_row("SymbolicRegression", "benchmarkSampling",
                         "Use the named benchmark's own training points instead of samples/range",
                         FIELD(symreg.benchmark_sampling)));
    t.push_back(double_row("SymbolicRegression", "hitTolerance", kNonNegative,
                           "A point is a hit when |error| <= this", FIELD(symreg.hit_tolerance)));
}

// Gait (ours: the parameter-optimised baseline)
void gait_rows(std::vector<SettingKey>& t) {
    t.push_back(enum_row<GaitOptimizer>("Gait", "optimizer",
                                        {{GaitOptimizer::Cmaes, {"cmaes"}}, {GaitOptimizer::Xnes, {"xnes"}},
                                         {GaitOptimizer::Sade, {"sade"}}, {GaitOptimizer::Sepcmaes, {"sepcmaes"}}},
                                        "Optimiser of the gait parameters: pagmo2's CMA-ES, xNES or self-adaptive DE, or "
                                        "separable (diagonal) CMA-ES for long gait vectors (Ros & Hansen 2008)",
                                        FIELD(gait.optimizer)));
    t.push_back(long_row("Gait", "evaluations", 1, 100000000,
                         "Budget of evaluations: the run stops before a generation that would exceed it",
                         FIELD(gait.evaluations)));
    t.push_back(int_row("Gait", "populationSize", 0, 100000,
                        "Candidates per generation (lambda); 0 = 4 + floor(3 ln n) for n parameters, at least 7 "
                        "for sade", FIELD(gait.population_size)));
    t.push_back(bool_row("Gait", "secondHarmonic", "Add a second harmonic b sin(4 pi f t + psi) to every joint",
                         FIELD(gait.second_harmonic)));
    t.push_back(double_row("Gait", "sigma0", Bounds{0.0, 1.0, true, false},
                           "Initial step of cmaes, xnes and sepcmaes, as a fraction of each parameter's range",
                           FIELD(gait.sigma0)));
    t.push_back(double_row("Gait", "frequencyMin", kPositive, "Lowest gait frequency, Hz", FIELD(gait.frequency_min)));
    t.push_back(double_row("Gait", "frequencyMax", kPositive, "Highest gait frequency, Hz", FIELD(gait.frequency_max)));
    t.push_back(enum_row<GaitBounds>("Gait", "bounds", {{GaitBounds::Clamp, {"clamp"}}, {GaitBounds::Reflect, {"reflect"}}},
                                     "How cmaes, xnes and sepcmaes samples outside a parameter's range are read: clamp (the "
                                     "nearest bound; flat outside, so the search can drift away; the default only "
                                     "so that runs made before this key replay alike) or reflect (mirrored at the "
                                     "bounds; recommended, used by settings/r1_gait.xml)",
                                     FIELD(gait.bounds)));
    t.push_back(enum_row<GaitController>("Gait", "controller",
                                         {{GaitController::Sine, {"sine"}}, {GaitController::Cpg, {"cpg"}}},
                                         "What the parameters drive: sine (per joint amplitude, phase, offset and "
                                         "one frequency) or cpg (the weights w_i, w_ij and feedback gains of "
                                         "HyperGP's cpg substrate, Neural.cpg* keys; docs/hypergp.md)",
                                         FIELD(gait.controller)));
    t.back().digest_at_default = false;
    t.push_back(enum_row<GaitRestarts>("Gait", "restarts", {{GaitRestarts::None, {"none"}}, {GaitRestarts::Ipop, {"ipop"}}},
                                       "Restarts of cmaes, xnes and sepcmaes: none (one start) or ipop (Auger & Hansen 2005: when "
                                       "a start stagnates, start again from fresh uniform points with twice the "
                                       "population, lambda_r = lambda_0 2^r, keeping the best gait; within the "
                                       "budget). sade allows none only. See docs/baselines.md, \"IPOP restarts\"",
                                       FIELD(gait.restarts)));
    t.push_back(int_row("Gait", "restartPatience", 0, 1000000,
                        "ipop: a start stagnates when its best fitness has risen by no more than restartTolerance "
                        "over this many generations; 0 = 10 + ceil(30 n / lambda_r) (Hansen's TolHistFun window; "
                        "n parameters, lambda_r the start's population)",
                        FIELD(gait.restart_patience)));
    t.push_back(double_row("Gait", "restartTolerance", kNonNegative,
                           "ipop: the rise of a start's best fitness (metres) over restartPatience generations at or "
                           "below which the start stagnates (0 = only no rise at all)",
                           FIELD(gait.restart_tolerance)));
    t.push_back(double_row("Gait", "restartTolX", kUnit,
                           "ipop: a start has collapsed, and restarts, when every parameter's standard deviation "
                           "across its current candidates is below this (in the unit box, where each range is 1); "
                           "0 = no collapse test",
                           FIELD(gait.restart_tol_x)));
}

} // namespace cic::io::rows
