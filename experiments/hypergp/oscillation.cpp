#include "cic/experiments/hypergp/oscillation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::hypergp {

namespace {

std::size_t step_count(std::span<const double> commands, std::size_t joints) {
    if (joints == 0) throw std::invalid_argument("oscillation: joints must be >= 1");
    if (commands.size() % joints != 0)
        throw std::invalid_argument("oscillation: " + std::to_string(commands.size()) +
                                    " command values are not a whole number of steps of " +
                                    std::to_string(joints) + " joints");
    return commands.size() / joints;
}

} // namespace

double dominant_frequency(std::span<const double> commands, std::size_t joints, double dt, double hysteresis) {
    const std::size_t steps = step_count(commands, joints);
    if (!(dt > 0.0)) throw std::invalid_argument("oscillation: dt must be > 0, got " + std::to_string(dt));
    if (!(hysteresis >= 0.0))
        throw std::invalid_argument("oscillation: hysteresis must be >= 0, got " + std::to_string(hysteresis));
    if (steps < 2) return 0.0;
    const double span_seconds = static_cast<double>(steps - 1) * dt;
    double f = 0.0;
    for (std::size_t j = 0; j < joints; ++j) {
        double mean = 0.0;
        for (std::size_t s = 0; s < steps; ++s) mean += commands[s * joints + j];
        mean /= static_cast<double>(steps);
        int side = 0;   // +1 above the band, -1 below, 0 not yet left it
        long crossings = 0;
        for (std::size_t s = 0; s < steps; ++s) {
            const double v = commands[s * joints + j] - mean;
            const int now = v > hysteresis ? 1 : v < -hysteresis ? -1 : 0;
            if (now == 0) continue;
            if (side != 0 && now != side) ++crossings;
            side = now;
        }
        f = std::max(f, static_cast<double>(crossings) / (2.0 * span_seconds));
    }
    return f;
}

double frequency_factor(double f, double f_max) {
    if (!(f_max > 0.0)) throw std::invalid_argument("oscillation: f_max must be > 0, got " + std::to_string(f_max));
    return f > f_max ? std::exp(f_max - f) : 1.0;
}

double mean_command_change(std::span<const double> commands, std::size_t joints) {
    const std::size_t steps = step_count(commands, joints);
    if (steps < 2) return 0.0;
    double sum = 0.0;
    for (std::size_t i = joints; i < commands.size(); ++i) sum += std::abs(commands[i] - commands[i - joints]);
    return sum / static_cast<double>((steps - 1) * joints);
}

double penalised_fitness(double fitness, const nn::NeuralConfig& cfg, std::span<const double> commands,
                         std::size_t joints, double dt) {
    switch (cfg.penalty) {
    case nn::OscillationPenalty::None: return fitness;
    case nn::OscillationPenalty::Frequency: {
        const double k = frequency_factor(dominant_frequency(commands, joints, dt), cfg.penalty_max_frequency);
        return fitness >= 0.0 ? fitness * k : fitness / k;
    }
    case nn::OscillationPenalty::CommandChange:
        if (!(cfg.penalty_weight >= 0.0))
            throw std::invalid_argument("oscillation: penalty_weight must be >= 0");
        return fitness - cfg.penalty_weight * mean_command_change(commands, joints);
    }
    throw std::invalid_argument("oscillation: unknown penalty");
}

} // namespace cic::hypergp
