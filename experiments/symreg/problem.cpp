// Reference data from the settings, and the fitness of a genotype (thesis 6.2.1).
#include "cic/experiments/symreg/problem.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/core/rng.hpp"
#include "cic/tree/eval.hpp"

namespace cic::symreg {
namespace {

constexpr double max_points = 1e7;

std::string known_benchmarks() {
    std::string s;
    for (const auto& n : benchmark_names()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// "koza-7", "Nguyen-11", "korns-3": a benchmark family, '-', digits. Such a target is
// meant as a benchmark; "x-1" is not (x is no family) and stays an expression.
bool looks_like_benchmark(const std::string& t) {
    const auto dash = t.find('-');
    if (dash == std::string::npos || dash == 0 || dash + 1 == t.size()) return false;
    for (std::size_t i = dash + 1; i < t.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
    std::string family = t.substr(0, dash);
    for (char& c : family) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (family == "korns") return true;   // in ECJ's list, not in ours
    for (const auto& n : benchmark_names())
        if (n.substr(0, n.find('-')) == family) return true;
    return false;
}

bool is_identifier(const std::string& t) {
    if (t.empty()) return false;
    for (unsigned char c : t)
        if (!std::isalnum(c) && c != '_') return false;
    return true;
}

std::string number(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

// The full grid of `n` equidistant values per variable, x0 outermost.
std::vector<std::vector<double>> equidistant_grid(int vars, const SymregConfig& cfg) {
    if (cfg.samples < 1) throw InputError("symreg samples must be >= 1, got " + std::to_string(cfg.samples));
    if (!(cfg.range_min <= cfg.range_max) || !std::isfinite(cfg.range_min) || !std::isfinite(cfg.range_max))
        throw InputError("symreg range must be finite with range_min <= range_max, got [" + number(cfg.range_min) +
                         ", " + number(cfg.range_max) + "]");
    if (std::pow(static_cast<double>(cfg.samples), vars) > max_points)
        throw InputError("symreg: " + std::to_string(cfg.samples) + " samples per variable over " +
                         std::to_string(vars) + " variables is more than 10^7 points");
    const auto axis = equidistant(cfg.samples, cfg.range_min, cfg.range_max);
    std::size_t total = 1;
    for (int v = 0; v < vars; ++v) total *= axis.size();
    std::vector<std::vector<double>> columns(static_cast<std::size_t>(vars), std::vector<double>(total));
    // Row r has digit (r / n^(vars-1-v)) % n in variable v: x0 changes slowest.
    std::size_t stride = total;
    for (int v = 0; v < vars; ++v) {
        stride /= axis.size();
        for (std::size_t r = 0; r < total; ++r) columns[v][r] = axis[(r / stride) % axis.size()];
    }
    return columns;
}

template <class F>
std::vector<double> target_values(const std::vector<std::vector<double>>& columns, const std::string& what, F f) {
    const std::size_t rows = columns.empty() ? 0 : columns[0].size();
    std::vector<double> target(rows), x(columns.size());
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t v = 0; v < columns.size(); ++v) x[v] = columns[v][r];
        target[r] = f(x);
        if (!std::isfinite(target[r])) {
            std::string at;
            for (std::size_t v = 0; v < x.size(); ++v) at += (v ? ", x" : "x") + std::to_string(v) + " = " + number(x[v]);
            throw InputError("symreg target " + what + " is not finite at " + at +
                             "; choose a range where it is defined");
        }
    }
    return target;
}

std::vector<std::string> variable_names(int vars) {
    std::vector<std::string> names;
    for (int v = 0; v < vars; ++v) names.push_back("x" + std::to_string(v));
    return names;
}

std::string range_text(const SymregConfig& cfg, int vars) {
    return std::to_string(cfg.samples) + " equidistant points in [" + number(cfg.range_min) + ", " +
           number(cfg.range_max) + "]" + (vars > 1 ? " per variable (grid)" : "");
}

Dataset from_benchmark(const Benchmark& b, const SymregConfig& cfg) {
    Dataset d;
    d.variable_names = variable_names(b.variables);
    if (cfg.benchmark_sampling) {
        Rng rng(benchmark_seed(b.name));
        d.columns = sample(b.training, rng);
        d.description = b.name + ": " + b.formula + ", its own training set of " +
                        std::to_string(d.columns[0].size()) + " points";
    } else {
        d.columns = equidistant_grid(b.variables, cfg);
        d.description = b.name + ": " + b.formula + ", " + range_text(cfg, b.variables);
    }
    d.target = target_values(d.columns, "'" + b.name + "'", [&b](const std::vector<double>& x) { return b.function(x.data()); });
    return d;
}

Dataset from_expression(const SymregConfig& cfg) {
    Expression e = [&cfg] {
        try {
            return Expression::parse(cfg.target);
        } catch (const InputError& err) {
            if (!is_identifier(cfg.target)) throw;
            throw InputError(err.message() + "; known benchmarks: " + known_benchmarks());
        }
    }();
    Dataset d;
    d.variable_names = variable_names(e.variables());
    d.columns = equidistant_grid(e.variables(), cfg);
    d.target = target_values(d.columns, "\"" + cfg.target + "\"", [&e](const std::vector<double>& x) { return e.evaluate(x); });
    d.description = cfg.target + ", " + range_text(cfg, e.variables());
    return d;
}

} // namespace

std::vector<double> equidistant(int n, double lo, double hi) {
    if (n < 1) throw std::invalid_argument("symreg::equidistant: n must be >= 1");
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
    if (n > 1) v.back() = hi;   // exact end despite rounding
    return v;
}

Dataset make_dataset(const SymregConfig& cfg, const std::string& base_dir) {
    if (!(cfg.hit_tolerance >= 0) || !std::isfinite(cfg.hit_tolerance))
        throw InputError("symreg hit tolerance must be a finite number >= 0, got " + number(cfg.hit_tolerance));
    if (!cfg.data_file.empty()) {
        std::filesystem::path p(cfg.data_file);
        if (p.is_relative() && !base_dir.empty()) p = std::filesystem::path(base_dir) / p;
        return load_csv(p);
    }
    if (auto b = find_benchmark(cfg.target)) return from_benchmark(*b, cfg);
    if (looks_like_benchmark(cfg.target))
        throw InputError("unknown symreg benchmark '" + cfg.target + "'; known benchmarks: " + known_benchmarks());
    return from_expression(cfg);
}

Score score(const tree::Forest& genotype, const Dataset& data, double hit_tolerance,
            std::vector<double>& scratch) {
    if (genotype.empty() || genotype[0].empty())
        throw std::invalid_argument("symreg::score: the genotype has no tree");
    const std::size_t rows = data.rows();
    scratch.resize(rows);

    // Column pointers on the stack for the usual few variables.
    constexpr std::size_t few = 16;
    std::array<const double*, few> small{};
    std::vector<const double*> many;
    const auto vars = data.columns.size();
    const double** cols = small.data();
    if (vars > few) { many.resize(vars); cols = many.data(); }
    for (std::size_t v = 0; v < vars; ++v) cols[v] = data.columns[v].data();

    tree::evaluate(genotype[0], std::span<const double* const>(cols, vars), rows, std::span<double>(scratch.data(), rows));

    Score s;
    double sum = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
        const double err = std::fabs(scratch[r] - data.target[r]);
        sum += err;
        if (err <= hit_tolerance) ++s.hits;   // NaN is never a hit
    }
    // NaN, inf and huge sums tie at the bottom (like ECJ's BIG_NUMBER cut-off), so a
    // clamped DBL_MAX output never ranks below a non-finite one.
    if (!(sum < -failed_fitness)) {
        s.fitness = failed_fitness;
        return s;
    }
    s.fitness = sum == 0.0 ? 0.0 : -sum;   // no "-0" in reports
    s.success = s.hits == static_cast<int>(rows);
    return s;
}

} // namespace cic::symreg
