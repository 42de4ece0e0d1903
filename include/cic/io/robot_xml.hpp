#pragma once
// Robot files (XML): modules on grid cells, see docs/simulator.md.
//   <robot name="R1" centre="torso.0" preferred="y">
//     <module name="torso.0" x="0" y="0" z="0" axis="fixed" attach="none"/>
//     ...
//   </robot>
// `centre` names a module (or gives its 0-based index). Errors are
// cic::InputError naming the file and line.
#include <filesystem>
#include <string>
#include <string_view>

#include "cic/sim/robot.hpp"

namespace cic::io {

sim::RobotSpec read_robot_file(const std::filesystem::path& path);
sim::RobotSpec parse_robot_xml(std::string_view text, const std::string& name = "<string>");

std::string robot_to_xml(const sim::RobotSpec& robot);
void write_robot_file(const sim::RobotSpec& robot, const std::filesystem::path& path);   // atomic

// "R0" / "R1" / "R2" (any case) -> sim::preset(type, middle_legs); anything
// else is a robot file path (middle_legs is then ignored: the file says it all).
sim::RobotSpec load_robot(const std::string& preset_or_file, bool middle_legs);

} // namespace cic::io
