#pragma once
// Where a checkpoint came from: the one integrity rule of every checkpoint
// (population, gait and archive files). A checkpoint's fitness values are
// believed on resume, so they must have been measured on the same problem:
// the same experiment type, robot geometry (its modules, axes, attachments,
// centre and preferred axis: the robot's content, not its file path),
// simulator, controller or substrate, genotype shape and function set, dataset
// and behaviour descriptor. Each of these is one part of the origin, written
// as text a person can read; the origin's digest covers them all, so an edit
// is noticed.
//
// Left out, on purpose: the budget (Control.*, Gait.evaluations,
// MapElites.evaluations), keys that change no result (workers, names, output
// folder, checkpoint interval, POV-Ray), the search's own settings (GP
// operator rates, tournament size, optimiser step sizes: they decide what is
// tried next, not what a stored fitness means; a change of them is said as a
// note), and the seed: a checkpoint holds its own RNG state and a resume goes
// on from it, so the settings' seed shapes nothing a checkpoint holds.
//
// Keys of the swept sections (Simulator, Neural, SymbolicRegression) are
// recorded only when not at their default, so a key added later (its default
// keeping the old behaviour) leaves every stored origin as it was.
#include <optional>
#include <string>
#include <vector>

#include "cic/io/settings.hpp"
#include "cic/io/xml.hpp"
#include "cic/sim/robot.hpp"

namespace cic::io {

struct OriginPart {
    std::string name;   // experiment, robot, simulator, controller, genotype, dataset, descriptor
    std::string text;   // "R1 (15 modules, 8 joints; geometry 0123456789abcdef)", "sampleStep=0.5", ...
    bool operator==(const OriginPart&) const = default;
};

struct CheckpointOrigin {
    std::vector<OriginPart> parts;
    int line = 0;                        // of the <origin> element read (0: made in memory)
    std::string digest() const;          // 16 hex digits over every part
};

// The origin of the runs these settings make. The robot families load the
// robot from the settings (file or preset); pass it when it is at hand.
CheckpointOrigin origin_of(const Settings& s);
CheckpointOrigin origin_of(const Settings& s, const sim::RobotSpec& robot);

// "R1 (15 modules, 8 joints; geometry 0123456789abcdef)": the robot's name,
// size and a digest of its geometry.
std::string robot_origin_text(const sim::RobotSpec& robot);

// <origin digest="..."><part name="robot">...</part>...</origin> under `root`.
void write_origin(xml::Node root, const CheckpointOrigin& origin);
// Reads an <origin> element; throws InputError (file, line) when its digest
// does not match its parts (edited by hand) or a part is malformed.
CheckpointOrigin read_origin(const xml::Node& element);

// Refuses (InputError naming `file` and the <origin> line, exit 2) a
// checkpoint whose origin differs from the settings', naming every part that
// differs with both values, on one line. A checkpoint without an origin
// (written before origins were recorded) is believed: the return value is then
// a note saying so, for the run to print; otherwise it is empty.
std::string check_origin(const std::optional<CheckpointOrigin>& loaded, const Settings& s, const std::string& file);

} // namespace cic::io
