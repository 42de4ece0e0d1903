// The single table of settings keys (see settings_table.hpp). Thesis names
// (Appendix B) are kept verbatim, including their mixed naming styles.
#include "cic/io/settings_table.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>

#include "cic/core/limits.hpp"
#include "settings_rows.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

using namespace rows;
using detail::format_double;
using detail::join;
using detail::split_items;

std::vector<std::string> function_names() {
    std::vector<std::string> names;
    for (auto op : tree::canonical_functions()) names.emplace_back(tree::name(op));
    return names;
}

const std::vector<std::string> kSynapseNames{"ih", "ho", "hh", "oo", "oh"};   // by nn::SynapseType

// Rows with their own conversions: names <-> Ops, counts, synapse flags.
SettingKey functions_row() {
    auto k = row("GP", "functions", ValueType::NameList,
                 "Function set by name (overrides functionCount); see docs/primitives.md");
    for (auto& n : function_names()) k.choices.push_back({n});
    k.get = [](const Settings& s) {
        std::vector<std::string> names;
        for (auto op : s.gp.primitives.functions) names.emplace_back(tree::name(op));
        return join(names);
    };
    k.set = [](Settings& s, std::string_view t) {
        std::vector<tree::Op> ops;
        for (auto item : split_items(t)) {
            auto op = tree::function_from_name(item);
            if (!op) throw ValueError("unknown function '" + std::string(item) + "'");
            if (std::find(ops.begin(), ops.end(), *op) != ops.end())
                throw ValueError("function '" + std::string(item) + "' listed twice");
            ops.push_back(*op);
        }
        s.gp.primitives.functions = std::move(ops);
    };
    return k;
}

// The thesis's count form of a list setting: the first N entries of a canonical list.
// `list` selects the settings member that the named form of the key also writes.
template <typename List>
SettingKey count_row(const char* key, std::string doc, std::size_t canonical_size, double min,
                     List list, std::function<void(Settings&, std::size_t)> take_first) {
    auto k = row("GP", key, ValueType::Int, std::move(doc));
    k.min = min;
    k.max = static_cast<double>(canonical_size);
    SettingKey bounds = k;
    k.get = [list](const Settings& s) { return std::to_string(list(s).size()); };
    k.set = [bounds, take_first](Settings& s, std::string_view t) {
        take_first(s, static_cast<std::size_t>(detail::parse_integer(bounds, t)));
    };
    return k;
}

SettingKey function_count_row() {
    return count_row(
        "functionCount",
        "Thesis form of the function set: the first N of the canonical list "
        "(add mul atan sin gauss sub div ...); must match the length of functions when both are given",
        tree::canonical_functions().size(), 1,
        [](const Settings& s) -> const auto& { return s.gp.primitives.functions; },
        [](Settings& s, std::size_t n) {
            auto all = tree::canonical_functions();
            s.gp.primitives.functions.assign(all.begin(), all.begin() + static_cast<long>(n));
        });
}

SettingKey consts_count_row() {
    return count_row(
        "terminalConstsCount",
        "Thesis form of the constants: the first N of the canonical list (1 -1 0 2 -2 0.5 ...); "
        "must match the length of terminalConsts when both are given",
        tree::canonical_constants().size(), 0,
        [](const Settings& s) -> const auto& { return s.gp.primitives.constants; },
        [](Settings& s, std::size_t n) {
            auto all = tree::canonical_constants();
            s.gp.primitives.constants.assign(all.begin(), all.begin() + static_cast<long>(n));
        });
}

SettingKey function_probabilities_row() {
    auto k = double_list_row("GP", "functionProbabilities", kPositive, 1,
                             "Relative weight of each function for PTC1, in the order of functions; "
                             "one number = the same weight for all",
                             FIELD(gp.primitives.function_weights));
    k.get = [](const Settings& s) {
        const auto& p = s.gp.primitives;
        std::vector<std::string> items;
        for (double w : p.function_weights) items.push_back(format_double(w));
        if (items.empty()) items.assign(p.functions.size(), "1");
        return join(items);
    };
    auto parse = k.set;
    k.set = [parse](Settings& s, std::string_view t) {
        parse(s, t);
        auto& w = s.gp.primitives.function_weights;
        if (w.size() == 1) w.assign(std::max<std::size_t>(1, s.gp.primitives.functions.size()), w.front());
    };
    return k;
}

SettingKey synapse_types_row() {
    auto k = row("Neural", "synapseTypes", ValueType::NameList,
                 "Synapse types the substrate builds: ih (input-hidden), ho, hh, oo, oh (thesis fig. 6.8)");
    for (auto& n : kSynapseNames) k.choices.push_back({n});
    k.get = [](const Settings& s) {
        std::vector<std::string> names;
        for (std::size_t i = 0; i < kSynapseNames.size() && i < s.neural.synapse_enabled.size(); ++i)
            if (s.neural.synapse_enabled[i]) names.push_back(kSynapseNames[i]);
        return join(names);
    };
    k.set = [](Settings& s, std::string_view t) {
        std::vector<bool> on(kSynapseNames.size(), false);
        for (auto item : split_items(t)) {
            auto it = std::find(kSynapseNames.begin(), kSynapseNames.end(), item);
            if (it == kSynapseNames.end()) throw ValueError("unknown synapse type '" + std::string(item) + "'");
            auto i = static_cast<std::size_t>(it - kSynapseNames.begin());
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
    k.max_items = kSynapseNames.size();
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

using gp::BloatVariant;
using gp::ForestDepth;
using gp::InitMethod;
using gp::NodeSelection;
using gp::SelectionType;

// Experiment (ours)
void experiment_rows(std::vector<SettingKey>& t) {
    t.push_back(detail::experiment_type_row());
    {
        auto k = row("Experiment", "seed", ValueType::UInt64, "Master random seed; the same seed gives the same run");
        k.min = 0;
        k.get = [](const Settings& s) { return std::to_string(s.experiment.seed); };
        k.set = [](Settings& s, std::string_view v) { s.experiment.seed = detail::parse_uint64(v); };
        t.push_back(std::move(k));
    }
    t.push_back(string_row("Experiment", "outputDirectory", ValueType::String, false,
                           "Folder that receives the run folders NAME-NNN (relative to the current folder)", FIELD(experiment.output_directory)));
    t.push_back(string_row("Experiment", "name", ValueType::String, true,
                           "Run name (run folder prefix); empty = the settings file's name", FIELD(experiment.name)));
    t.push_back(int_row("Experiment", "workers", 0, 4096, "Evaluation worker processes; 0 = one per core",
                        FIELD(experiment.workers)));
    t.push_back(int_row("Experiment", "checkpointInterval", 1, 1000000,
                        "A population file after every N evaluated generations (N = 1: each one), and always after the last", FIELD(experiment.checkpoint_interval)));
    t.push_back(double_row("Experiment", "workerTimeout", kPositive,
                           "Seconds before a hung worker is replaced", FIELD(experiment.worker_timeout)));
}

// GP (thesis Appendix B)
void gp_rows(std::vector<SettingKey>& t) {
    t.push_back(double_row("GP", "defaultFitness", kAnyFinite, "Fitness of individuals before they are evaluated",
                           FIELD(gp.default_fitness)));
    t.push_back(int_row("GP", "generatedPopulationSize", 2, static_cast<long long>(limits::kMaxPopulation),
                        "Individuals in each generation",
                        FIELD(gp.population_size)));
    t.push_back(double_row("GP", "expectedGeneratedTreeSize", {1.0, 1e6},
                           "Expected tree size for PTC1 initialisation (thesis 6.3.4.4)", FIELD(gp.expected_tree_size)));
    t.push_back(int_row("GP", "maximumGeneratedTreeDepth", 1, 20, "Maximum depth of generated trees",
                        FIELD(gp.max_init_depth)));
    t.push_back(int_row("GP", "minimumGeneratedTreeDepth", 1, 20, "Minimum depth of generated trees",
                        FIELD(gp.min_init_depth)));
    t.push_back(enum_row<InitMethod>("GP", "initMethod",
                                     {{InitMethod::Ptc1, {"ptc1"}}, {InitMethod::Grow, {"grow"}},
                                      {InitMethod::Full, {"full"}}, {InitMethod::RampedHalfAndHalf, {"rhh"}}},
                                     "Tree initialisation: PTC1, grow, full or ramped half-and-half",
                                     FIELD(gp.init_method)));
    t.push_back(int_row("GP", "ptc1RootDepth", 0, 1,
                        "Depth PTC1 counts for the root: 0 as the thesis's pseudocode (6.3.4.4; maximum depth 6 "
                        "allows 7 levels, and the minimum depth counts alike), 1 as Grow and Full count (a leaf = 1)",
                        FIELD(gp.ptc1_root_depth)));
    t.push_back(int_row("GP", "terminalVariableCount", 0, 64,
                        "Variables x0..x{N-1} among the terminals (HyperGP: 4, x1 y1 x2 y2)",
                        FIELD(gp.primitives.variable_count)));
    t.push_back(function_count_row());
    t.push_back(functions_row());
    t.push_back(function_probabilities_row());
    t.push_back(consts_count_row());
    t.push_back(double_list_row("GP", "terminalConsts", kAnyFinite, 0,
                                "Constant terminals by value (overrides terminalConstsCount)",
                                FIELD(gp.primitives.constants)));
    t.push_back(bool_row("GP", "ephemeralConstants", "Add ephemeral random constants drawn from [ephemeralMin, ephemeralMax]",
                         FIELD(gp.primitives.ephemeral)));
    t.push_back(double_row("GP", "ephemeralMin", kAnyFinite, "Lower bound of ephemeral constants",
                           FIELD(gp.primitives.ephemeral_min)));
    t.push_back(double_row("GP", "ephemeralMax", kAnyFinite, "Upper bound of ephemeral constants",
                           FIELD(gp.primitives.ephemeral_max)));
    t.push_back(double_row("GP", "variableWeight", kPositive, "Relative weight of each variable terminal",
                           FIELD(gp.primitives.variable_weight)));
    t.push_back(double_row("GP", "constantWeight", kPositive, "Relative weight of each constant terminal",
                           FIELD(gp.primitives.constant_weight)));
    t.push_back(enum_row<SelectionType>("GP", "selection_type",
                                        {{SelectionType::Tournament, {"0", "tournament"}},
                                         {SelectionType::Roulette, {"1", "roulette"}}},
                                        "Selection: 0 tournament, 1 roulette", FIELD(gp.selection)));
    t.push_back(int_row("GP", "tournament_size", 1, 10000000, "Individuals per tournament",
                        FIELD(gp.tournament_size)));
    t.push_back(bool_row("GP", "tournamentSelection",
                         "On equal fitness prefer the smaller tree (lexicographic parsimony pressure)",
                         FIELD(gp.lexicographic_parsimony)));
    t.push_back(int_row("GP", "numberOfTreesInForestGenotype", 1, 16, "Trees per genotype (thesis 7.3.1)",
                        FIELD(gp.trees_per_genotype)));
    t.push_back(bool_row("GP", "preventDuplicates", "Generated trees are unique", FIELD(gp.prevent_duplicates)));
    t.push_back(int_row("GP", "duplicateRetries", 0, 1000000,
                        "Attempts to generate a unique tree before a duplicate is accepted",
                        FIELD(gp.duplicate_retries)));
    t.push_back(double_row("GP", "crossoverRate", kUnit, "Probability that a child comes from crossover",
                           FIELD(gp.crossover_rate)));
    t.push_back(double_row("GP", "mutationRate", kUnit,
                           "Probability that a child comes from mutation (the rest is reproduction)",
                           FIELD(gp.mutation_rate)));
    t.push_back(int_row("GP", "elitism", 0, 10000000,
                        "Best individuals copied unchanged into the next generation (the thesis: none)",
                        FIELD(gp.elitism)));
    t.push_back(enum_row<NodeSelection>("GP", "nodeSelection",
                                        {{NodeSelection::Koza, {"koza"}}, {NodeSelection::Uniform, {"uniform"}}},
                                        "Node that crossover and mutation pick: koza = a function node with "
                                        "probability 0.9 (else a leaf), uniform = any node alike",
                                        FIELD(gp.node_selection)));
    t.push_back(enum_row<InitMethod>("GP", "mutationGenerator",
                                     {{InitMethod::Grow, {"grow"}}, {InitMethod::Full, {"full"}},
                                      {InitMethod::Ptc1, {"ptc1"}}},
                                     "Method that grows mutation's new subtrees (to maximumMutationDepth)",
                                     FIELD(gp.mutation_generator)));
    t.push_back(int_row("GP", "maximumMutationDepth", 1, 20, "Maximum depth of subtrees grown by mutation",
                        FIELD(gp.max_mutation_depth)));
    t.push_back(int_row("GP", "maximumTreeDepth", 0, 100,
                        "Depth cap of each offspring tree when bloat control is off (Koza's 17); 0 = none",
                        FIELD(gp.max_tree_depth)));
    t.push_back(enum_row<ForestDepth>("GP", "forestDepth",
                                      {{ForestDepth::Sum, {"sum"}}, {ForestDepth::Max, {"max"}}},
                                      "Depth of a forest genotype for Dynamic Limits and statistics: the sum of its "
                                      "trees' depths (thesis 7.2.1, fig. 7.4b) or its deepest tree",
                                      FIELD(gp.forest_depth)));
}

// Simulator: SimConfig's fields as sim::for_each_field describes them, with
// the robot's keys where the thesis's files have them.
void simulator_rows(std::vector<SettingKey>& t) {
    const sim::SimConfig defaults{};
    sim::for_each_field(defaults, [&](const sim::FieldSpec& f, const auto& v) {
        t.push_back(sim_row<std::decay_t<decltype(v)>>(f));
        if (f.name == "delayed_start") {
            t.push_back(int_row("Simulator", "robot_type", 0, 2, "Robot: 0 R0, 1 R1, 2 R2 (thesis 7.1.1)",
                                FIELD(robot.robot_type)));
            t.push_back(string_row("Simulator", "robotFile", ValueType::Path, true,
                                   "Robot description XML; overrides robot_type when set", FIELD(robot.robot_file)));
        }
        if (f.name == "step_divider")
            t.push_back(bool_row("Simulator", "generatePovrayFiles",
                                 "Write POV-Ray scenes of the best individual's run", FIELD(robot.generate_povray)));
    });
}

// Control
void control_rows(std::vector<SettingKey>& t) {
    t.push_back(int_row("Control", "maximumIterations", 1, 10000000,
                        "Maximum number of generations, counting generation 0",
                        FIELD(control.maximum_iterations)));
    t.push_back(double_row("Control", "minimumFitness", {-kHuge, kHuge, false, true},
                           "Stop early once the best fitness reaches this (inf = never)", FIELD(control.minimum_fitness)));
    t.push_back(string_row("Control", "populationXmlLoadFrom", ValueType::Path, true,
                           "Start from this population file instead of a new one (empty = generate)",
                           FIELD(control.population_load_from)));
    t.push_back(bool_row("Control", "useMatlabPlot", "Write statistics plots (gnuplot; replaces the thesis's Matlab plots)",
                         FIELD(control.plot)));
    t.push_back(bool_row("Control", "isAutonomousExperiment", "1 = never open the viewer; 0 = show the best at the end",
                         FIELD(control.autonomous)));
}

// BloatControl
void bloat_rows(std::vector<SettingKey>& t) {
    t.push_back(bool_row("BloatControl", "useBloatControl", "Use Dynamic Limits bloat control (thesis 5.2)",
                         FIELD(bloat.enabled)));
    t.push_back(enum_row<BloatVariant>("BloatControl", "bloatControlVariant",
                                       {{BloatVariant::Simple, {"0", "simple"}},
                                        {BloatVariant::Heavy, {"1", "heavy"}},
                                        {BloatVariant::VeryHeavy, {"2", "veryHeavy"}}},
                                       "Dynamic Limits variant: 0 simple, 1 heavy, 2 very heavy", FIELD(bloat.variant)));
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
    for (std::size_t i = first; i < t.size(); ++i) t[i].digest_at_default = false;
}

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
                                         {GaitOptimizer::Sade, {"sade"}}},
                                        "pagmo2 optimiser of the gait parameters: CMA-ES, xNES or self-adaptive DE",
                                        FIELD(gait.optimizer)));
    {
        auto k = row("Gait", "evaluations", ValueType::Int,
                     "Budget of evaluations: the run stops before a generation that would exceed it");
        k.min = 1;
        k.max = 100000000;
        const SettingKey bounds = k;
        k.get = [](const Settings& s) { return std::to_string(s.gait.evaluations); };
        k.set = [bounds](Settings& s, std::string_view v) { s.gait.evaluations = detail::parse_integer(bounds, v); };
        t.push_back(std::move(k));
    }
    t.push_back(int_row("Gait", "populationSize", 0, 100000,
                        "Candidates per generation (lambda); 0 = 4 + floor(3 ln n) for n parameters, at least 7 "
                        "for sade", FIELD(gait.population_size)));
    t.push_back(bool_row("Gait", "secondHarmonic", "Add a second harmonic b sin(4 pi f t + psi) to every joint",
                         FIELD(gait.second_harmonic)));
    t.push_back(double_row("Gait", "sigma0", Bounds{0.0, 1.0, true, false},
                           "Initial step of cmaes and xnes, as a fraction of each parameter's range",
                           FIELD(gait.sigma0)));
    t.push_back(double_row("Gait", "frequencyMin", kPositive, "Lowest gait frequency, Hz", FIELD(gait.frequency_min)));
    t.push_back(double_row("Gait", "frequencyMax", kPositive, "Highest gait frequency, Hz", FIELD(gait.frequency_max)));
    t.push_back(enum_row<GaitBounds>("Gait", "bounds", {{GaitBounds::Clamp, {"clamp"}}, {GaitBounds::Reflect, {"reflect"}}},
                                     "How cmaes and xnes samples outside a parameter's range are read: clamp (the "
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
                                       "Restarts of cmaes and xnes: none (one start) or ipop (Auger & Hansen 2005: when "
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

std::vector<SettingKey> build_table() {
    std::vector<SettingKey> t;
    experiment_rows(t);
    gp_rows(t);
    simulator_rows(t);
    control_rows(t);
    bloat_rows(t);
    neural_rows(t);
    symreg_rows(t);
    gait_rows(t);
    return t;
}

#undef FIELD

} // namespace

std::string_view type_name(ValueType t) {
    switch (t) {
    case ValueType::Bool: return "bool";
    case ValueType::Int: return "int";
    case ValueType::UInt64: return "uint64";
    case ValueType::Double: return "number";
    case ValueType::String: return "text";
    case ValueType::Path: return "path";
    case ValueType::Enum: return "name";
    case ValueType::NameList: return "names";
    case ValueType::DoubleList: return "numbers";
    case ValueType::IntList: return "integers";
    }
    return "?";
}

namespace detail {
// Mutable only through register_settings_keys and register_experiment_type
// (settings_extension.cpp, experiment_types.cpp), before settings are read.
const std::vector<std::string>& builtin_settings_sections() {
    static const std::vector<std::string> s{"Experiment", "GP",     "Simulator",          "Control",
                                            "BloatControl", "Neural", "SymbolicRegression", "Gait"};
    return s;
}

std::vector<std::string>& mutable_settings_sections() {
    static std::vector<std::string> s = builtin_settings_sections();
    return s;
}

std::vector<SettingKey>& mutable_settings_table() {
    static std::vector<SettingKey> table = build_table();
    return table;
}
} // namespace detail

const std::vector<std::string>& settings_sections() { return detail::mutable_settings_sections(); }

const std::vector<SettingKey>& settings_table() { return detail::mutable_settings_table(); }

const SettingKey* find_setting(std::string_view section, std::string_view key) {
    for (const auto& k : settings_table())
        if (k.section == section && k.key == key) return &k;
    return nullptr;
}

namespace {
std::string bounds_text(const SettingKey& k, std::string_view what) {
    bool integer = k.type == ValueType::Int || k.type == ValueType::IntList;
    auto format_double = [integer](double v) {
        return integer ? std::to_string(static_cast<long long>(v)) : detail::format_double(v);
    };
    bool has_min = k.min > -kHuge, has_max = k.max < kHuge;
    std::string s(what);
    if (has_min && has_max)
        s += std::string(" in ") + (k.min_exclusive ? "(" : "[") + format_double(k.min) + ", " + format_double(k.max) + "]";
    else if (has_min)
        s += (k.min_exclusive ? " > " : " >= ") + format_double(k.min);
    else if (has_max)
        s += " <= " + format_double(k.max);
    else if (k.type == ValueType::Double || k.type == ValueType::DoubleList)
        s = "any finite " + std::string(what);
    if (k.allow_inf) s += " or inf";
    return s;
}

std::string choices_text(const SettingKey& k) {
    std::vector<std::string> items;
    for (const auto& c : k.choices) items.push_back(join(c, "|"));
    return join(items, ", ");
}
} // namespace

std::string describe_allowed(const SettingKey& k) {
    switch (k.type) {
    case ValueType::Bool: return "0 or 1";
    case ValueType::Int: return bounds_text(k, "integer");
    case ValueType::UInt64: return "integer in [0, 18446744073709551615]";
    case ValueType::Double: return bounds_text(k, "number");
    case ValueType::String: return k.min_items == 0 ? "text (may be empty)" : "non-empty text";
    case ValueType::Path: return k.min_items == 0 ? "file path (empty = none)" : "non-empty path";
    case ValueType::Enum: return "one of: " + choices_text(k);
    case ValueType::NameList:
        return "space-separated distinct names from: " + choices_text(k);
    case ValueType::DoubleList:
        return "space-separated list of " + bounds_text(k, "numbers") + (k.min_items == 0 ? " (may be empty)" : "");
    case ValueType::IntList: {
        std::string s = "space-separated list of " + bounds_text(k, "integers");
        if (k.max_items < std::numeric_limits<std::size_t>::max())
            s += ", at most " + std::to_string(k.max_items);
        return s + (k.min_items == 0 ? " (may be empty)" : "");
    }
    }
    return {};
}

std::string default_text(const SettingKey& k) {
    static const Settings defaults{};
    return k.get(defaults);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

} // namespace cic::io
