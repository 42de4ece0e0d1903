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
using gp::BloatVariant;
using gp::ForestDepth;
using gp::InitMethod;
using gp::NodeSelection;
using gp::SelectionType;

// Experiment (ours)
void experiment_rows(std::vector<SettingKey>& t) {
    t.push_back(detail::experiment_type_row());
    t.push_back(detail::search_row());
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

// Evolving for transfer (issue 55; docs/hypergp.md): several bodies in one
// fitness, and a growing robot. Out of the digest at their defaults (one body),
// so that older runs keep theirs.
void transfer_rows(std::vector<SettingKey>& t) {
    const std::size_t first = t.size();
    t.push_back(path_list_row("Simulator", "extraRobotFiles",
                              "Several bodies in one fitness (HyperGP, generational search): each genotype is also "
                              "scored on these robot files, beside the robot, and its fitness is bodiesAggregate of "
                              "the bodies' fitnesses; empty = the robot alone",
                              FIELD(robot.extra_robot_files)));
    t.push_back(enum_row<BodiesAggregate>(
        "Simulator", "bodiesAggregate", {{BodiesAggregate::Mean, {"mean"}}, {BodiesAggregate::Min, {"min"}}},
        "How the bodies' fitnesses (eq. 7.1 after any penalty) make one with extraRobotFiles: their mean or their "
        "minimum",
        FIELD(robot.bodies_aggregate)));
    t.push_back(path_list_row("Simulator", "growRobotFiles",
                              "A growing robot (HyperGP, generational search): the bodies after the robot, in "
                              "order; the population moves to the next at each share of growAt and is evaluated "
                              "again there; empty = one body for the whole run",
                              FIELD(robot.grow_robot_files)));
    t.push_back(double_list_row("Simulator", "growAt", Bounds{0.0, 1.0, true, false}, 0,
                              "The shares of the budget (Control.maximumIterations) at which each body of "
                              "growRobotFiles takes over, increasing, one per file: body k's first generation is "
                              "ceil(share x maximumIterations), the population re-evaluated",
                              FIELD(robot.grow_at)));
    for (std::size_t i = first; i < t.size(); ++i) t[i].digest_at_default = false;
}

// Simulator: SimConfig's fields as sim::for_each_field describes them, with
// the robot's keys where the thesis's files have them.
void simulator_rows(std::vector<SettingKey>& t) {
    const sim::SimConfig defaults{};
    sim::for_each_field(defaults, [&](const sim::FieldSpec& f, const auto& v) {
        t.push_back(sim_row<std::decay_t<decltype(v)>>(f));
        // Added for issue 38: out of the digest at its default, so older runs keep theirs.
        // The default since issue 55 is sweep, which gives simple's bits: either is the default.
        if (f.name == "collision_space") {
            t.back().digest_at_default = false;
            t.back().same_result_as_default = {std::to_string(sim::kCollisionSimple)};
        }
        if (f.name == "delayed_start") {
            t.push_back(int_row("Simulator", "robot_type", 0, 2, "Robot: 0 R0, 1 R1, 2 R2 (thesis 7.1.1)",
                                FIELD(robot.robot_type)));
            t.push_back(string_row("Simulator", "robotFile", ValueType::Path, true,
                                   "Robot description XML; overrides robot_type when set", FIELD(robot.robot_file)));
            transfer_rows(t);
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
    map_elites_rows(t);
    return t;
}

#undef FIELD

} // namespace

namespace detail {
// Mutable only through register_settings_keys and register_experiment_type
// (settings_extension.cpp, experiment_types.cpp), before settings are read.
const std::vector<std::string>& builtin_settings_sections() {
    static const std::vector<std::string> s{"Experiment", "GP",     "Simulator",          "Control",
                                            "BloatControl", "Neural", "SymbolicRegression", "Gait",
                                            "MapElites"};
    return s;
}

std::vector<std::string>& mutable_settings_sections() {
    static std::vector<std::string> s = builtin_settings_sections();
    return s;
}

namespace {
bool table_built = false;   // constant-initialised: safe to read from any static initialiser
} // namespace

std::vector<SettingKey>& mutable_settings_table() {
    static std::vector<SettingKey> table = [] {
        auto t = build_table();
        table_built = true;
        return t;
    }();
    return table;
}

bool settings_table_built() { return table_built; }
} // namespace detail

} // namespace cic::io
