#pragma once
// A fitness penalty for high-frequency oscillation of the commands, the
// remedy thesis 7.3.2.1 planned but did not implement. Pure functions over a
// recorded command signal, step-major: joint j at step s is commands[s * joints + j].
//
//   None:          fitness unchanged.
//   Frequency:     Lee et al.'s factor k = e^(f_max - f), applied when the dominant
//                  command frequency f exceeds f_max (penalty_max_frequency):
//                  fitness * k when fitness >= 0, fitness / k when negative,
//                  so the penalty always lowers the fitness.
//   CommandChange: fitness - penalty_weight * mean |c[s] - c[s-1]| (rad per control
//                  step, averaged over joints and the steps - 1 differences).
//
// Dominant frequency: for each joint, the mean-removed command is passed
// through a Schmitt trigger with band +-hysteresis (rad), so noise and held
// values do not count; each flip between the upper and the lower side is one
// zero crossing. f_j = crossings / (2 (steps - 1) dt); f = max over joints
// (one shaking joint is enough to shake the robot).
#include <cstddef>
#include <span>

#include "cic/nn/config.hpp"

namespace cic::hypergp {

inline constexpr double kCrossingHysteresis = 0.01;   // rad

// Throws std::invalid_argument: joints == 0, commands.size() not a multiple of
// joints, dt <= 0, hysteresis < 0. Fewer than 2 steps -> 0.
double dominant_frequency(std::span<const double> commands, std::size_t joints, double dt,
                          double hysteresis = kCrossingHysteresis);

// e^(f_max - f) for f > f_max, else 1. Throws std::invalid_argument for f_max <= 0.
double frequency_factor(double f, double f_max);

// Mean |c[s] - c[s-1]| over joints and steps; 0 for fewer than 2 steps.
double mean_command_change(std::span<const double> commands, std::size_t joints);

// The fitness after the penalty cfg.penalty asks for.
double penalised_fitness(double fitness, const nn::NeuralConfig& cfg, std::span<const double> commands,
                         std::size_t joints, double dt);

} // namespace cic::hypergp
