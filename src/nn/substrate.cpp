#include "cic/nn/substrate.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/tree/eval.hpp"

namespace cic::nn {

namespace {

[[noreturn]] void bad(const std::string& field, const std::string& why) {
    throw InputError("neural settings: " + field + " " + why);
}

// One layer as seen by the CPPF: its points and its layer index.
struct LayerRef {
    const std::vector<Point>* points;
    double index;
};

// Source and target layer of each synapse type (fig. 6.8).
struct Ends {
    LayerRef src, dst;
};

std::array<Ends, kSynapseTypes> synapse_ends(const NeuronLayout& l) {
    const LayerRef in{&l.input, kInputLayer}, hid{&l.hidden, kHiddenLayer}, out{&l.output, kOutputLayer};
    return {{{in, hid}, {hid, out}, {hid, hid}, {out, out}, {out, hid}}};
}

} // namespace

void validate(const NeuralConfig& cfg, std::size_t trees) {
    if (trees == 0) bad("numberOfTreesInForestGenotype", "must be >= 1, got 0");
    if (!std::isfinite(cfg.threshold) || cfg.threshold < 0.0)
        bad("synopsisThreshold", "must be a finite value >= 0, got " + std::to_string(cfg.threshold));
    if (cfg.weight_rule == WeightRule::Scaled) {
        if (cfg.threshold >= 1.0)
            bad("synopsisThreshold", "must be < 1 with the scaled weight rule, got " + std::to_string(cfg.threshold));
        if (!std::isfinite(cfg.max_weight) || cfg.max_weight <= 0.0)
            bad("max_weight", "must be a finite value > 0, got " + std::to_string(cfg.max_weight));
    }
    if (cfg.sample_average_count < 1)
        bad("sampleAverageCount", "must be >= 1, got " + std::to_string(cfg.sample_average_count));
    if (cfg.synapse_enabled.size() != static_cast<std::size_t>(kSynapseTypes))
        bad("synapse_enabled", "must have 5 entries (IH HO HH OO OH), got " +
                                   std::to_string(cfg.synapse_enabled.size()));
    if (!cfg.forest_map.empty()) {
        if (cfg.forest_map.size() != static_cast<std::size_t>(kSynapseTypes))
            bad("forest_map", "must have 5 entries (IH HO HH OO OH) or none, got " +
                                  std::to_string(cfg.forest_map.size()));
        for (int i = 0; i < kSynapseTypes; ++i) {
            const int k = cfg.forest_map[i];
            if (k < 0 || static_cast<std::size_t>(k) >= trees)
                bad("forest_map", "entry " + std::to_string(i) + " (" + std::string(name(static_cast<SynapseType>(i))) +
                                      ") is tree " + std::to_string(k) + ", but the genotype has " +
                                      std::to_string(trees) + " tree(s)");
        }
    }
    if (!std::isfinite(cfg.clock_period) || cfg.clock_period <= 0.0)
        bad("clock_period", "must be a finite value > 0, got " + std::to_string(cfg.clock_period));
    if (!std::isfinite(cfg.penalty_max_frequency) || cfg.penalty_max_frequency <= 0.0)
        bad("penalty_max_frequency", "must be a finite value > 0, got " + std::to_string(cfg.penalty_max_frequency));
    if (!std::isfinite(cfg.penalty_weight) || cfg.penalty_weight < 0.0)
        bad("penalty_weight", "must be a finite value >= 0, got " + std::to_string(cfg.penalty_weight));
}

std::array<int, kSynapseTypes> resolve_forest_map(const NeuralConfig& cfg, std::size_t trees) {
    validate(cfg, trees);
    std::array<int, kSynapseTypes> map{};
    for (int i = 0; i < kSynapseTypes; ++i)
        map[i] = cfg.forest_map.empty() ? static_cast<int>(static_cast<std::size_t>(i) % trees) : cfg.forest_map[i];
    return map;
}

double apply_weight_rule(double w, const NeuralConfig& cfg) {
    if (!std::isfinite(w) || std::abs(w) < cfg.threshold) return 0.0;
    if (cfg.weight_rule == WeightRule::Raw) return w;
    const double mag = std::min(std::abs(w), 1.0);
    const double scaled = (mag - cfg.threshold) / (1.0 - cfg.threshold) * cfg.max_weight;
    return w < 0.0 ? -scaled : scaled;
}

Network build_network(const Geometry& g, const tree::Forest& genotype, const NeuralConfig& cfg) {
    return build_network(make_neuron_layout(g, cfg), genotype, cfg);
}

Network build_network(const NeuronLayout& layout, const tree::Forest& genotype, const NeuralConfig& cfg) {
    if (genotype.empty()) throw std::invalid_argument("nn::build_network: empty genotype (no trees)");
    for (std::size_t k = 0; k < genotype.size(); ++k)
        if (genotype[k].empty())
            throw std::invalid_argument("nn::build_network: tree " + std::to_string(k) + " is empty");
    const auto map = resolve_forest_map(cfg, genotype.size());
    const auto ends = synapse_ends(layout);
    const bool extra = cfg.extra_cppf_inputs;
    const auto vars = static_cast<std::size_t>(cppf_variable_count(cfg));

    std::array<std::vector<Eigen::Triplet<double>>, kSynapseTypes> triplets;
    std::vector<std::vector<double>> cols(vars);
    std::vector<double> out;
    for (std::size_t k = 0; k < genotype.size(); ++k) {
        // All pairs of all types this tree answers, in (type, target, source) order.
        for (auto& c : cols) c.clear();
        for (int t = 0; t < kSynapseTypes; ++t) {
            if (map[t] != static_cast<int>(k) || !cfg.synapse_enabled[t]) continue;
            for (const Point& d : *ends[t].dst.points)
                for (const Point& s : *ends[t].src.points) {
                    cols[0].push_back(s.x);
                    cols[1].push_back(s.y);
                    cols[2].push_back(d.x);
                    cols[3].push_back(d.y);
                    if (extra) {
                        cols[4].push_back(ends[t].src.index);
                        cols[5].push_back(ends[t].dst.index);
                        cols[6].push_back(std::hypot(d.x - s.x, d.y - s.y));
                    }
                }
        }
        const std::size_t rows = cols[0].size();
        if (rows == 0) continue;
        std::vector<const double*> ptrs(vars);
        for (std::size_t v = 0; v < vars; ++v) ptrs[v] = cols[v].data();
        out.assign(rows, 0.0);
        tree::evaluate(genotype[k], ptrs, rows, out);   // ONE batch evaluation per tree

        std::size_t row = 0;
        for (int t = 0; t < kSynapseTypes; ++t) {
            if (map[t] != static_cast<int>(k) || !cfg.synapse_enabled[t]) continue;
            const auto nd = ends[t].dst.points->size(), ns = ends[t].src.points->size();
            for (std::size_t d = 0; d < nd; ++d)
                for (std::size_t s = 0; s < ns; ++s, ++row) {
                    const double w = apply_weight_rule(out[row], cfg);
                    if (w != 0.0)
                        triplets[t].emplace_back(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(s), w);
                }
        }
    }

    SynapseBlocks blocks;
    for (int t = 0; t < kSynapseTypes; ++t) {
        blocks[t].resize(static_cast<Eigen::Index>(ends[t].dst.points->size()),
                         static_cast<Eigen::Index>(ends[t].src.points->size()));
        blocks[t].setFromTriplets(triplets[t].begin(), triplets[t].end());
    }
    return Network(layout.input.size(), layout.hidden.size(), layout.output.size(), std::move(blocks), cfg.neuron);
}

void encode_inputs(const NeuronLayout& layout, const NeuralConfig& cfg, double t, std::span<const double> angles,
                   std::span<double> in) {
    if (angles.size() != layout.joint_count || in.size() != layout.input.size())
        throw std::invalid_argument("nn::encode_inputs: got " + std::to_string(angles.size()) + " angles and " +
                                    std::to_string(in.size()) + " inputs, expected " +
                                    std::to_string(layout.joint_count) + " and " +
                                    std::to_string(layout.input.size()));
    std::size_t i = 0;
    for (; i < angles.size(); ++i) in[i] = angles[i] / (std::numbers::pi / 2.0);
    if (layout.bias) in[i++] = 1.0;
    if (layout.clock) {
        const double phase = 2.0 * std::numbers::pi * t / cfg.clock_period;
        in[i++] = std::sin(phase);
        in[i++] = std::cos(phase);
    }
}

} // namespace cic::nn
