#pragma once
// Is a replayed individual walking? Thesis 7.3.2.1 found high-fitness gaits
// that "did not elevate their body from the ground, but just quickly moved the
// joints up and down": shaking. This measures, from a replay with a trace,
//   - the dominant frequency of the joint commands (the same Schmitt-trigger
//     crossing count as the oscillation penalty, hypergp/oscillation.hpp);
//   - the mean and lowest height of the centre module;
//   - whether the centre module ended upside down: the body axis that pointed
//     up in the first frame points down (world z < 0) in the last;
// and marks the gait as shaking when its dominant frequency is above a bound.
#include <string>
#include <vector>

#include "cic/report/replay.hpp"

namespace cic::report {

// Walking gaits of these robots step at about 0.3 to 2 Hz (docs/thesis-ch7).
inline constexpr double kShakingAboveHz = 4.0;

struct GaitAssessment {
    double fitness = 0;              // replayed, as the run scored it
    double raw_fitness = 0;          // eq. 7.1 without the oscillation penalty
    double dominant_hz = 0;          // max over joints of the command's crossing frequency
    double mean_height = 0;          // centre module, m, over every control step
    double min_height = 0;
    double final_up = 1;             // world z of the body's initial up axis in the last frame
    bool flipped = false;            // final_up < 0
    bool shaking = false;            // dominant_hz > shaking_above_hz
    double distance = 0;             // eq. 7.1's walk along the preferred axis, m
    double elevation = 0;            // eq. 7.1's elevation gained, m
    // One word for the gait, the first that holds: flipped; shaking; standing
    // up (no cyclic stepping, the score mostly elevation); sliding (no cyclic
    // stepping, the score mostly distance); walking.
    std::string verdict;
    std::vector<std::string> foot_names;   // the robot's branch ends (feet)
    std::vector<double> duty_factors;      // per foot: the fraction of time it touched the ground
};

// Below this dominant command frequency a gait does not step cyclically.
inline constexpr double kSteppingAboveHz = 0.2;

// Throws std::invalid_argument when the item has no trace or no frames, or
// shaking_above_hz <= 0.
GaitAssessment assess_gait(const ReplayItem& item, double shaking_above_hz = kShakingAboveHz);

} // namespace cic::report
