// The benchmark table (formulas and samplings copied from ECJ's Benchmarks.java,
// which follows McDermott et al. 2012, tables 2 and 3, with ECJ's revisions).
#include "cic/experiments/symreg/benchmarks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "cic/core/hash.hpp"

namespace cic::symreg {
namespace {

using Kind = Sampling::Kind;

Sampling U(std::vector<double> lo, std::vector<double> hi, int n) {
    return {Kind::Random, std::move(lo), std::move(hi), {}, n, false};
}
Sampling E(std::vector<double> lo, std::vector<double> hi, std::vector<double> step) {
    return {Kind::Grid, std::move(lo), std::move(hi), std::move(step), 0, false};
}
Sampling same() { return {Kind::Random, {}, {}, {}, 0, true}; }

double p4(double v) { return v * v * v * v; }
double keijzer_1_3(const double* x) { return 0.3 * x[0] * std::sin(2 * std::numbers::pi * x[0]); }
double keijzer_4(const double* x) {   // = vladislavleva-2
    const double v = x[0];
    return v * v * v * std::exp(-v) * std::cos(v) * std::sin(v) *
           (std::sin(v) * std::sin(v) * std::cos(v) - 1);
}
double keijzer_6(const double* x) {   // harmonic number H(floor(x))
    double sum = 0;
    const double fx = std::floor(x[0]);
    for (int i = 1; i < fx + 1; ++i) sum += 1.0 / i;
    return sum;
}

std::vector<Benchmark> make_table() {
    std::vector<Benchmark> t;
    auto add = [&t](std::string name, int vars, std::string formula, double (*f)(const double*),
                    Sampling train, Sampling test) {
        t.push_back({std::move(name), vars, std::move(formula), f, std::move(train), std::move(test)});
    };
    // Koza (GP-1, GP-2)
    add("koza-1", 1, "x^4 + x^3 + x^2 + x",
        [](const double* x) { const double v = x[0]; return v * v * v * v + v * v * v + v * v + v; },
        U({-1}, {1}, 20), same());
    add("koza-2", 1, "x^5 - 2x^3 + x",
        [](const double* x) { const double v = x[0]; return v * v * v * v * v - 2.0 * v * v * v + v; },
        U({-1}, {1}, 20), same());
    add("koza-3", 1, "x^6 - 2x^4 + x^2",
        [](const double* x) { const double v = x[0]; return v * v * v * v * v * v - 2.0 * v * v * v * v + v * v; },
        U({-1}, {1}, 20), same());
    // Nguyen et al. 2011
    add("nguyen-1", 1, "x^3 + x^2 + x",
        [](const double* x) { const double v = x[0]; return v * v * v + v * v + v; }, U({-1}, {1}, 20), same());
    add("nguyen-2", 1, "x^4 + x^3 + x^2 + x",
        [](const double* x) { const double v = x[0]; return v * v * v * v + v * v * v + v * v + v; },
        U({-1}, {1}, 20), same());
    add("nguyen-3", 1, "x^5 + x^4 + x^3 + x^2 + x",
        [](const double* x) { const double v = x[0]; return v * v * v * v * v + v * v * v * v + v * v * v + v * v + v; },
        U({-1}, {1}, 20), same());
    add("nguyen-4", 1, "x^6 + x^5 + x^4 + x^3 + x^2 + x",
        [](const double* x) {
            const double v = x[0];
            return v * v * v * v * v * v + v * v * v * v * v + v * v * v * v + v * v * v + v * v + v;
        },
        U({-1}, {1}, 20), same());
    add("nguyen-5", 1, "sin(x^2) cos(x) - 1",
        [](const double* x) { return std::sin(x[0] * x[0]) * std::cos(x[0]) - 1.0; }, U({-1}, {1}, 20), same());
    add("nguyen-6", 1, "sin(x) + sin(x + x^2)",
        [](const double* x) { return std::sin(x[0]) + std::sin(x[0] * x[0] + x[0]); }, U({-1}, {1}, 20), same());
    add("nguyen-7", 1, "log(x + 1) + log(x^2 + 1)",
        [](const double* x) { return std::log(x[0] + 1) + std::log(x[0] * x[0] + 1.0); }, U({0}, {2}, 20), same());
    add("nguyen-8", 1, "sqrt(x)", [](const double* x) { return std::sqrt(x[0]); }, U({0}, {4}, 20), same());
    add("nguyen-9", 2, "sin(x) + sin(y^2)",
        [](const double* x) { return std::sin(x[0]) + std::sin(x[1] * x[1]); }, U({0, 0}, {1, 1}, 100), same());
    add("nguyen-10", 2, "2 sin(x) cos(y)",
        [](const double* x) { return 2 * std::sin(x[0]) * std::cos(x[1]); }, U({0, 0}, {1, 1}, 100), same());
    // Keijzer 2003
    add("keijzer-1", 1, "0.3 x sin(2 pi x)", keijzer_1_3, E({-1}, {1}, {0.1}), E({-1}, {1}, {0.001}));
    add("keijzer-2", 1, "0.3 x sin(2 pi x)", keijzer_1_3, E({-2}, {2}, {0.1}), E({-2}, {2}, {0.001}));
    add("keijzer-3", 1, "0.3 x sin(2 pi x)", keijzer_1_3, E({-3}, {3}, {0.1}), E({-3}, {3}, {0.001}));
    add("keijzer-4", 1, "x^3 exp(-x) cos(x) sin(x) (sin(x)^2 cos(x) - 1)", keijzer_4,
        E({0}, {10}, {0.05}), E({0.05}, {10.05}, {0.05}));
    add("keijzer-5", 3, "30 x z / ((x - 10) y^2)",
        [](const double* x) { return (30.0 * x[0] * x[2]) / ((x[0] - 10.0) * x[1] * x[1]); },
        U({-1, 1, -1}, {1, 2, 1}, 1000), U({-1, 1, -1}, {1, 2, 1}, 10000));
    add("keijzer-6", 1, "sum_{i=1}^{floor(x)} 1/i", keijzer_6, E({1}, {50}, {1}), E({1}, {120}, {1}));
    add("keijzer-7", 1, "log(x)", [](const double* x) { return std::log(x[0]); },
        E({1}, {100}, {1}), E({1}, {100}, {0.1}));
    add("keijzer-8", 1, "sqrt(x)", [](const double* x) { return std::sqrt(x[0]); },
        E({0}, {100}, {1}), E({0}, {100}, {0.1}));
    add("keijzer-9", 1, "arcsinh(x) = log(x + sqrt(x^2 + 1))",
        [](const double* x) { return std::log(x[0] + std::sqrt(x[0] * x[0] + 1.0)); },
        E({0}, {100}, {1}), E({0}, {100}, {0.1}));
    add("keijzer-10", 2, "x^y", [](const double* x) { return std::pow(x[0], x[1]); },
        U({0, 0}, {1, 1}, 100), E({0, 0}, {1, 1}, {0.01, 0.01}));
    const Sampling k_train = U({-3, -3}, {3, 3}, 20);
    const Sampling k_test = E({-3, -3}, {3, 3}, {0.01, 0.01});
    add("keijzer-11", 2, "x y + sin((x - 1)(y - 1))",
        [](const double* x) { return x[0] * x[1] + std::sin((x[0] - 1.0) * (x[1] - 1.0)); }, k_train, k_test);
    add("keijzer-12", 2, "x^4 - x^3 + y^2/2 - y",
        [](const double* x) { const double a = x[0], b = x[1]; return a * a * a * a - a * a * a + b * b / 2.0 - b; },
        k_train, k_test);
    add("keijzer-13", 2, "6 sin(x) cos(y)",
        [](const double* x) { return 6.0 * std::sin(x[0]) * std::cos(x[1]); }, k_train, k_test);
    add("keijzer-14", 2, "8 / (2 + x^2 + y^2)",
        [](const double* x) { return 8.0 / (2.0 + x[0] * x[0] + x[1] * x[1]); }, k_train, k_test);
    add("keijzer-15", 2, "x^3/5 + y^3/2 - y - x",
        [](const double* x) {
            const double a = x[0], b = x[1];
            return a * a * a / 5.0 + b * b * b / 2.0 - b - a;
        },
        k_train, k_test);
    // Pagie and Hogeweg 1997
    add("pagie-1", 2, "1/(1 + x^-4) + 1/(1 + y^-4)",
        [](const double* x) { return 1.0 / (1.0 + 1.0 / p4(x[0])) + 1.0 / (1.0 + 1.0 / p4(x[1])); },
        E({-5, -5}, {5, 5}, {0.4, 0.4}), same());
    // Vladislavleva et al. 2009
    add("vladislavleva-1", 2, "exp(-(x - 1)^2) / (1.2 + (y - 2.5)^2)",
        [](const double* x) { return std::exp(-(x[0] - 1) * (x[0] - 1)) / (1.2 + (x[1] - 2.5) * (x[1] - 2.5)); },
        U({0.3, 0.3}, {4, 4}, 100), E({-0.2, -0.2}, {4.2, 4.2}, {0.1, 0.1}));
    add("vladislavleva-2", 1, "exp(-x) x^3 cos(x) sin(x) (cos(x) sin(x)^2 - 1)", keijzer_4,
        E({0.05}, {10}, {0.1}), E({-0.5}, {10.5}, {0.05}));
    add("vladislavleva-3", 2, "exp(-x) x^3 cos(x) sin(x) (cos(x) sin(x)^2 - 1) (y - 5)",
        [](const double* x) { return keijzer_4(x) * (x[1] - 5); },
        E({0.05, 0.05}, {10, 10.05}, {0.1, 2}), E({-0.5, -0.5}, {10.5, 10.5}, {0.05, 0.5}));
    add("vladislavleva-4", 5, "10 / (5 + sum_{i=1}^{5} (x_i - 3)^2)",
        [](const double* x) {
            double sum = 0;
            for (int i = 0; i < 5; ++i) sum += (x[i] - 3) * (x[i] - 3);
            return 10.0 / (5.0 + sum);
        },
        U({0.05, 0.05, 0.05, 0.05, 0.05}, {6.05, 6.05, 6.05, 6.05, 6.05}, 1024),
        U({-0.25, -0.25, -0.25, -0.25, -0.25}, {6.35, 6.35, 6.35, 6.35, 6.35}, 5000));
    add("vladislavleva-5", 3, "30 (x - 1)(z - 1) / (y^2 (x - 10))",
        [](const double* x) { return (30.0 * (x[0] - 1.0) * (x[2] - 1.0)) / (x[1] * x[1] * (x[0] - 10.0)); },
        U({0.05, 1, 0.05}, {2, 2, 2}, 300), E({-0.05, 0.95, -0.05}, {2.1, 2.05, 2.1}, {0.15, 0.15, 0.1}));
    add("vladislavleva-6", 2, "6 sin(x) cos(y)",
        [](const double* x) { return 6.0 * std::sin(x[0]) * std::cos(x[1]); },
        U({0.1, 0.1}, {5.9, 5.9}, 30), E({-0.05, -0.05}, {6.05, 6.05}, {0.02, 0.02}));
    add("vladislavleva-7", 2, "(x - 3)(y - 3) + 2 sin((x - 4)(y - 4))",
        [](const double* x) { return (x[0] - 3.0) * (x[1] - 3.0) + 2 * std::sin((x[0] - 4.0) * (x[1] - 4.0)); },
        U({0.05, 0.05}, {6.05, 6.05}, 300), U({-0.25, -0.25}, {6.35, 6.35}, 1000));
    add("vladislavleva-8", 2, "((x - 3)^4 + (y - 3)^3 - (y - 3)) / ((y - 2)^4 + 10)",
        [](const double* x) {
            const double a = x[0] - 3.0, b = x[1] - 3.0, c = x[1] - 2.0;
            return (a * a * a * a + b * b * b - b) / (c * c * c * c + 10.0);
        },
        U({0.05, 0.05}, {6.05, 6.05}, 50), E({-0.25, -0.25}, {6.35, 6.35}, {0.2, 0.2}));
    return t;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// Adds every grid point with variables >= v fixed by `current`, first variable outermost.
void grid(const Sampling& s, std::size_t v, std::vector<double>& current,
          std::vector<std::vector<double>>& columns) {
    if (v == s.min.size()) {
        for (std::size_t i = 0; i < current.size(); ++i) columns[i].push_back(current[i]);
        return;
    }
    const auto jumps = static_cast<long>(std::floor((s.max[v] - s.min[v]) / s.step[v] + 1e-9)) + 1;
    for (long j = 0; j < jumps; ++j) {
        current[v] = s.min[v] + s.step[v] * static_cast<double>(j);
        grid(s, v + 1, current, columns);
    }
}

} // namespace

const std::vector<Benchmark>& benchmarks() {
    static const std::vector<Benchmark> table = make_table();
    return table;
}

std::vector<std::string> benchmark_names() {
    std::vector<std::string> names;
    for (const auto& b : benchmarks()) names.push_back(b.name);
    return names;
}

std::optional<Benchmark> find_benchmark(std::string_view name) {
    const std::string key = lower(name);
    for (const auto& b : benchmarks())
        if (b.name == key) return b;
    return std::nullopt;
}

std::uint64_t benchmark_seed(std::string_view canonical_name) {
    return fnv1a_64(canonical_name);
}

std::vector<std::vector<double>> sample(const Sampling& s, Rng& rng) {
    const std::size_t vars = s.min.size();
    if (vars == 0 || s.max.size() != vars || s.same_as_training)
        throw std::invalid_argument("symreg::sample: sampling has no ranges of its own");
    std::vector<std::vector<double>> columns(vars);
    if (s.kind == Sampling::Kind::Random) {
        if (s.points <= 0) throw std::invalid_argument("symreg::sample: points must be > 0");
        for (auto& c : columns) c.reserve(static_cast<std::size_t>(s.points));
        for (int i = 0; i < s.points; ++i)
            for (std::size_t v = 0; v < vars; ++v) columns[v].push_back(rng.uniform(s.min[v], s.max[v]));
        return columns;
    }
    if (s.step.size() != vars || std::any_of(s.step.begin(), s.step.end(), [](double d) { return !(d > 0); }))
        throw std::invalid_argument("symreg::sample: grid needs a positive step per variable");
    std::vector<double> current(vars);
    grid(s, 0, current, columns);
    return columns;
}

} // namespace cic::symreg
