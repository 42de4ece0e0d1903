#pragma once
// Replays for a preset robot under a hand-written controller ("--robot R1
// --controller sine:0.6,0.5"), and what `cic view`, `cic render` and `cic
// trace` are asked to replay (their options: cic/cli/replay_options.hpp).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cic/report/replay.hpp"
#include "cic/sim/config.hpp"
#include "cic/sim/controller.hpp"

namespace cic::report {

// "sine:A,F[,P]": joint j follows A sin(2 pi F t + j P) (P defaults to pi/2,
// a travelling wave along the joint order); "constant:ANGLE" holds every joint.
// Bare "sine" is sine:0.8,0.5 and bare "constant" is constant:0.
// Throws cic::InputError naming the spec for anything else.
std::unique_ptr<sim::Controller> parse_controller_spec(std::string_view spec);

// "R0", "R1", "R2" (or "0", "1", "2"); throws cic::InputError otherwise.
int parse_robot_name(std::string_view name);

struct PresetReplay {
    int robot_type = 1;
    bool middle_legs = false;
    std::string robot_file;                      // a robot file instead of the preset
    std::vector<std::string> overrides;          // --set Section.key=value for the simulator
    std::string controller = "sine:0.6,0.5";
    sim::SimConfig sim;                          // sample_to sets the length
};

// One item (label "R1 sine:0.6,0.5"; generation -1, id 0; stored and replayed
// fitness both the evaluated one). With trace, raw_outputs holds what the
// controller returned each control step (before the simulator clamps it).
ReplayItem replay_preset(const PresetReplay& preset, double fps, bool trace);

// What to replay, as given on the command line: either a run folder /
// population file, or --robot with --controller.
struct ReplaySource {
    std::string input;                 // RUN_DIR or POPULATION.xml
    std::string individual = "best";
    std::string cell;                  // a MAP-Elites run's elite: "I,J,..." or the cell's number
    std::string robot;                 // R0 | R1 | R2 | a robot file
    std::vector<std::string> overrides;  // --set Section.key=value (simulator keys)
    bool middle_legs = false;
    std::string controller = "sine:0.6,0.5";
    double seconds = 0.0;              // 0 = the simulator default
};

// Resolves the options (throws cic::InputError when neither or both sources are given).
std::vector<ReplayItem> load_replay(const ReplaySource& source, int count, double fps, bool trace);

// item.joint_names, or "j0", "j1", ... sized to the trace when those are empty.
std::vector<std::string> joint_names_of(const ReplayItem& item);

} // namespace cic::report
