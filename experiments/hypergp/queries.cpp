// Single-number queries of a HyperGP genotype (see queries.hpp).
#include "cic/experiments/hypergp/queries.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cic/tree/eval.hpp"

namespace cic::hypergp {

std::vector<double> ask(const tree::Forest& genotype, const nn::NeuralConfig& cfg, std::span<const Query> queries) {
    const bool extra = cfg.extra_cppf_inputs;
    const auto vars = static_cast<std::size_t>(nn::cppf_variable_count(cfg));
    std::vector<double> answers(queries.size(), 0.0);
    for (const Query& q : queries)
        if (q.tree >= genotype.size())
            throw std::invalid_argument("hypergp query of tree " + std::to_string(q.tree) + " of a forest of " +
                                        std::to_string(genotype.size()));
    std::vector<std::vector<double>> cols(vars);
    std::vector<std::size_t> rows_of;
    std::vector<double> out;
    for (std::size_t k = 0; k < genotype.size(); ++k) {
        for (auto& c : cols) c.clear();
        rows_of.clear();
        for (std::size_t i = 0; i < queries.size(); ++i) {
            const Query& q = queries[i];
            if (q.tree != k) continue;
            rows_of.push_back(i);
            cols[0].push_back(q.src.x);
            cols[1].push_back(q.src.y);
            cols[2].push_back(q.dst.x);
            cols[3].push_back(q.dst.y);
            if (extra) {
                cols[4].push_back(q.src_layer);
                cols[5].push_back(q.dst_layer);
                cols[6].push_back(std::hypot(q.dst.x - q.src.x, q.dst.y - q.src.y));
            }
        }
        if (rows_of.empty()) continue;
        if (genotype[k].empty()) throw std::invalid_argument("hypergp query: tree " + std::to_string(k) + " is empty");
        std::vector<const double*> ptrs(vars);
        for (std::size_t v = 0; v < vars; ++v) ptrs[v] = cols[v].data();
        out.assign(rows_of.size(), 0.0);
        tree::evaluate(genotype[k], ptrs, rows_of.size(), out);
        for (std::size_t r = 0; r < rows_of.size(); ++r) answers[rows_of[r]] = out[r];
    }
    return answers;
}

double squash(double v) { return std::isnan(v) ? 0.0 : std::tanh(v); }

double unit(double v) { return 0.5 * (1.0 + squash(v)); }

double evolved_frequency_unit(const tree::Forest& genotype, const nn::NeuralConfig& cfg) {
    const Query q{0, kFrequencyPoint, kFrequencyPoint, nn::kHiddenLayer, nn::kHiddenLayer};
    return unit(ask(genotype, cfg, {&q, 1}).front());
}

double evolved_frequency(const tree::Forest& genotype, const nn::NeuralConfig& cfg) {
    return cfg.frequency_min + (cfg.frequency_max - cfg.frequency_min) * evolved_frequency_unit(genotype, cfg);
}

} // namespace cic::hypergp
