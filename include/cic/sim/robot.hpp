#pragma once
// The immutable description of a modular robot made of SSSA modules on a grid
// (thesis ch. 4, 7.1.1). Shared read-only by every evaluation.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cic::sim {

enum class Axis { X, Y, Z, Fixed };      // a module's hinge axis; Fixed = rigid
enum class Dir { PosX, NegX, PosY, NegY, PosZ, NegZ, None };

struct Cell {
    int x = 0, y = 0, z = 0;
    bool operator==(const Cell&) const = default;
};

// One SSSA module: a chassis cube on `cell` and a connection panel on the face
// towards `attach`, hinged at the chassis centre about `axis`. The panel is
// fixed to the chassis of the neighbour in direction `attach`. The centre
// module has attach = None.
struct Module {
    Cell cell;
    Axis axis = Axis::Fixed;
    Dir attach = Dir::None;
    std::string name;                     // optional label ("leg0.hip")
};

// What is wrong with a robot: the module at fault (-1 = the robot as a whole)
// and a one-line message. Lets file readers point at the module's line.
struct RobotProblem {
    int module = -1;
    std::string message;
};

struct RobotSpec {
    std::string name;
    std::vector<Module> modules;
    int centre = 0;                       // index of the centre module (fitness is measured on it)
    Axis preferred = Axis::Y;             // preferred axis of motion: X or Y

    // Indices of modules with a hinge (axis != Fixed), in module order. The
    // controller's joint vector follows this order.
    std::vector<int> actuated() const;

    // Throws cic::InputError (no file) with a precise message: overlapping cells,
    // attach pointing at an empty cell, disconnected modules (attachment graph
    // not a tree rooted at the centre), centre out of range or attached,
    // preferred axis not X or Y, no modules.
    void validate() const;

    // The first problem validate() would report, or nothing when valid.
    std::optional<RobotProblem> find_problem() const;
};

Cell neighbour(Cell c, Dir d);
std::optional<Axis> axis_from_name(std::string_view s);   // "x" "y" "z" "fixed"
std::optional<Dir> dir_from_name(std::string_view s);     // "+x" "-x" ... "none"
std::string to_string(Axis a);
std::string to_string(Dir d);

// The presets of thesis 7.1.1 / 7.2.4 (R0, R1, R2), with or without middle legs.
// Throws std::invalid_argument for an unknown type.
RobotSpec preset(int robot_type, bool middle_legs);

} // namespace cic::sim
