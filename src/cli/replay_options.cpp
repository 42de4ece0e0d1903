#include "cic/cli/replay_options.hpp"

namespace cic::cli {

void add_replay_options(Command& command, report::ReplaySource& source) {
    command.option("input", source.input, "run folder or population XML file to replay");
    command.option("--individual", source.individual, "best, or an individual's id").show_default();
    command.option("--cell", source.cell,
                   "a MAP-Elites run's elite: its cell as I,J,... (one bin per descriptor dimension, from 0) or "
                   "its number, as `cic export` lists them");
    command.option("--robot", source.robot, "replay a robot instead: R0, R1, R2 or a robot file");
    command.flag("--middle-legs", source.middle_legs, "with --robot: the 6-legged variant");
    command.option("--controller", source.controller,
                       "with --robot: sine (= sine:0.8,0.5), sine:AMPLITUDE,FREQUENCY[,PHASE_STEP], constant (= constant:0) "
                       "or constant:ANGLE")
        .show_default();
    command.option("--seconds", source.seconds, "with --robot: simulated seconds (default: the simulator's)");
    command.option("--set", source.overrides,
                       "with --robot: a simulator setting, Simulator.key=value (repeatable), e.g. "
                       "Simulator.selfCollision=0");
}

} // namespace cic::cli
