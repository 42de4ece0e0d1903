#pragma once
// A run's best genotype replayed unchanged on other robots (issue 55, `cic
// transfer`, docs/transfer.md): how far one genotype walks on bodies it was
// never evolved on.
//   - HyperGP trees (network, CPG and gait substrates; Switch-HybrID's HyperGP
//     phase; a MAP-Elites archive of trees): the same trees, queried at the
//     target robot's substrate coordinates. Nothing is fitted.
//   - Offset-HybrID's per-hinge offsets have no counterpart on another body:
//     OffsetRule says what they become.
//   - A direct gait (a gait run, Switch-HybrID after its hand-over, a gait
//     archive) has a number per hinge, so it is tiled (tile_joints).
// The joints of both robots are put into rows along the robot's preferred axis
// (a centipede's leg pairs) and keyed by their place across it (side and
// segment of the leg): the rules below work on any robot whose legs stand in
// such rows, the centipedes, R0, R1 and R2 among them.
#include <cstddef>
#include <string>
#include <vector>

#include "cic/io/settings.hpp"
#include "cic/report/replay.hpp"
#include "cic/report/run_genotype.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::report {

// What Offset-HybrID's per-hinge offsets become on another robot.
//   Interpolate: each target hinge takes the offsets of the source hinges at
//     the same place across the body (side, segment), interpolated linearly
//     along the body (both bodies' rows normalised to [-1, 1] as the substrate
//     does); a single source row gives its offset to every row.
//   None: dropped; the trees alone say the offsets.
enum class OffsetRule { Interpolate, None };

// The tiling rule of the direct gait (issue 55's fair baseline): row k of the
// target takes the parameters of row (k mod rows of the source), joint by joint
// at the same place across the body, so the source's pattern repeats along the
// bigger body from its back (lowest coordinate) on. A hinge the source's row
// lacks (an irregular twin's shortened leg) is taken from the nearest source
// row that has it (the lower on a tie). Returns, per target joint (controller
// order), the source joint (controller order) it copies. Throws
// cic::InputError naming the target joint that has no counterpart anywhere.
std::vector<std::size_t> tile_joints(const sim::RobotSpec& source, const sim::RobotSpec& target);

// Per target joint, the source joints and weights of OffsetRule::Interpolate
// (one or two joints, weights summing to 1).
struct JointBlend {
    std::size_t a = 0, b = 0;
    double weight_b = 0;   // value = (1 - weight_b) * source[a] + weight_b * source[b]
};
std::vector<JointBlend> interpolate_joints(const sim::RobotSpec& source, const sim::RobotSpec& target);

// The genotype transferred: a run's best (run_genotype.hpp), Switch-HybrID's
// from its HyperGP phase, the one whose size does not grow with the robot.
using TransferSource = RunGenotype;
inline TransferSource read_transfer_source(const std::string& run_dir) {
    return read_run_genotype(run_dir, SwitchPhase::HyperGP);
}

// One replay of the source's genotype on `target` (a robot spec; `target_file`
// is recorded as the settings' robot file: a file path, or empty for a preset
// given by `target_preset` 0..2). The recorded item carries eq. 7.1's terms and,
// with trace, what `assess_gait` needs. `how` is set to the rule applied:
// "unchanged" (trees), "offsets-interpolated", "offsets-dropped" or "tiled".
struct TransferTarget {
    sim::RobotSpec robot;
    std::string file;        // robot file, or empty for a preset
    int preset = -1;         // 0..2 for R0..R2 when file is empty
    bool middle_legs = false;
};
ReplayItem replay_transferred(const TransferSource& source, const TransferTarget& target, OffsetRule rule,
                              double fps, bool trace, std::string* how = nullptr);

} // namespace cic::report
