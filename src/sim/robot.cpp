// RobotSpec queries, validation and the thesis presets (7.1.1, 7.2.4).
#include "cic/sim/robot.hpp"

#include <map>
#include <stdexcept>
#include <tuple>

#include "cic/core/error.hpp"
#include "cic/core/limits.hpp"

namespace cic::sim {

namespace {

std::string describe(const RobotSpec& r, int i) {
    const Module& m = r.modules[static_cast<std::size_t>(i)];
    std::string s = "module " + std::to_string(i);
    if (!m.name.empty()) s += " '" + m.name + "'";
    s += " at (" + std::to_string(m.cell.x) + "," + std::to_string(m.cell.y) + "," +
         std::to_string(m.cell.z) + ")";
    return s;
}

using CellKey = std::tuple<int, int, int>;
CellKey key(Cell c) { return {c.x, c.y, c.z}; }

} // namespace

std::vector<int> RobotSpec::actuated() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < modules.size(); ++i)
        if (modules[i].axis != Axis::Fixed) out.push_back(static_cast<int>(i));
    return out;
}

std::optional<RobotProblem> RobotSpec::find_problem() const {
    const int n = static_cast<int>(modules.size());
    if (n == 0) return RobotProblem{-1, "robot '" + name + "' has no modules"};
    if (modules.size() > limits::kMaxModules)
        return RobotProblem{-1, std::to_string(n) + " modules is past the limit of " +
                                    std::to_string(limits::kMaxModules) + " modules per robot"};
    if (preferred != Axis::X && preferred != Axis::Y)
        return RobotProblem{-1, "preferred axis must be x or y, not " + to_string(preferred)};
    if (centre < 0 || centre >= n)
        return RobotProblem{-1, "no centre: centre index " + std::to_string(centre) +
                                    " is not one of the " + std::to_string(n) + " modules"};

    std::map<CellKey, int> at;
    for (int i = 0; i < n; ++i) {
        auto [it, fresh] = at.emplace(key(modules[static_cast<std::size_t>(i)].cell), i);
        if (!fresh)
            return RobotProblem{i, "overlapping cells: " + describe(*this, i) +
                                       " is on the same cell as " + describe(*this, it->second)};
    }
    const Module& c = modules[static_cast<std::size_t>(centre)];
    if (c.attach != Dir::None)
        return RobotProblem{centre, "the centre " + describe(*this, centre) +
                                        " must not attach to anything (attach=\"none\")"};
    if (c.axis != Axis::Fixed)
        return RobotProblem{centre, "the centre " + describe(*this, centre) +
                                        " has no panel to hinge: its axis must be fixed"};

    // parent[i]: the module i's panel is fixed to.
    std::vector<int> parent(static_cast<std::size_t>(n), -1);
    for (int i = 0; i < n; ++i) {
        const Module& m = modules[static_cast<std::size_t>(i)];
        if (i == centre) continue;
        if (m.attach == Dir::None)
            return RobotProblem{i, "disconnected modules: " + describe(*this, i) +
                                       " attaches to nothing but is not the centre"};
        auto it = at.find(key(neighbour(m.cell, m.attach)));
        if (it == at.end())
            return RobotProblem{i, describe(*this, i) + " attaches " + to_string(m.attach) +
                                       " to an empty cell"};
        parent[static_cast<std::size_t>(i)] = it->second;
    }
    // Every chain of attachments must reach the centre (no cycles).
    for (int i = 0; i < n; ++i) {
        int j = i;
        for (int hops = 0; j != centre; ++hops) {
            if (hops > n)
                return RobotProblem{i, "disconnected modules: the attachments from " +
                                           describe(*this, i) +
                                           " form a cycle and never reach the centre"};
            j = parent[static_cast<std::size_t>(j)];
        }
    }
    return std::nullopt;
}

void RobotSpec::validate() const {
    if (auto p = find_problem()) throw InputError("invalid robot '" + name + "': " + p->message);
}

Cell neighbour(Cell c, Dir d) {
    switch (d) {
    case Dir::PosX: ++c.x; break;
    case Dir::NegX: --c.x; break;
    case Dir::PosY: ++c.y; break;
    case Dir::NegY: --c.y; break;
    case Dir::PosZ: ++c.z; break;
    case Dir::NegZ: --c.z; break;
    case Dir::None: break;
    }
    return c;
}

std::optional<Axis> axis_from_name(std::string_view s) {
    if (s == "x") return Axis::X;
    if (s == "y") return Axis::Y;
    if (s == "z") return Axis::Z;
    if (s == "fixed") return Axis::Fixed;
    return std::nullopt;
}

std::optional<Dir> dir_from_name(std::string_view s) {
    static const std::pair<const char*, Dir> names[] = {
        {"+x", Dir::PosX}, {"-x", Dir::NegX}, {"+y", Dir::PosY}, {"-y", Dir::NegY},
        {"+z", Dir::PosZ}, {"-z", Dir::NegZ}, {"none", Dir::None}};
    for (auto& [n, d] : names)
        if (s == n) return d;
    return std::nullopt;
}

std::string to_string(Axis a) {
    switch (a) {
    case Axis::X: return "x";
    case Axis::Y: return "y";
    case Axis::Z: return "z";
    case Axis::Fixed: return "fixed";
    }
    return "?";
}

std::string to_string(Dir d) {
    switch (d) {
    case Dir::PosX: return "+x";
    case Dir::NegX: return "-x";
    case Dir::PosY: return "+y";
    case Dir::NegY: return "-y";
    case Dir::PosZ: return "+z";
    case Dir::NegZ: return "-z";
    case Dir::None: return "none";
    }
    return "?";
}

namespace {

// A leg from the torso cube at (0, y) outwards along `side` (+1 = +x), joint
// axes listed from the hip out. Each leg module attaches towards the hip.
void add_leg(RobotSpec& r, int y, int side, const std::vector<Axis>& axes, const std::string& label) {
    for (std::size_t k = 0; k < axes.size(); ++k) {
        Module m;
        m.cell = {side * static_cast<int>(k + 1), y, 0};
        m.axis = axes[k];
        m.attach = side > 0 ? Dir::NegX : Dir::PosX;
        m.name = label + "." + std::to_string(k);
        r.modules.push_back(m);
    }
}

} // namespace

RobotSpec preset(int robot_type, bool middle_legs) {
    int torso = 0;
    std::vector<Axis> leg;
    RobotSpec r;
    switch (robot_type) {
    case 0: torso = 5; leg = {Axis::Y, Axis::Y}; r.preferred = Axis::X; break;
    case 1: torso = 7; leg = {Axis::Y, Axis::Z, Axis::Y}; r.preferred = Axis::Y; break;
    case 2: torso = 5; leg = {Axis::Z, Axis::Y, Axis::Y}; r.preferred = Axis::Y; break;
    default:
        throw std::invalid_argument("preset: unknown robot type " + std::to_string(robot_type) +
                                    " (expected 0, 1 or 2)");
    }
    r.name = "R" + std::to_string(robot_type) + (middle_legs ? "-6legs" : "");
    const int half = torso / 2;
    // Torso along y, centre cube first; each torso cube attaches towards the centre.
    r.modules.push_back({{0, 0, 0}, Axis::Fixed, Dir::None, "torso.0"});
    r.centre = 0;
    for (int d = 1; d <= half; ++d) {
        r.modules.push_back({{0, d, 0}, Axis::Fixed, Dir::NegY, "torso.+" + std::to_string(d)});
        r.modules.push_back({{0, -d, 0}, Axis::Fixed, Dir::PosY, "torso.-" + std::to_string(d)});
    }
    std::vector<int> leg_rows = {-half, half};
    if (middle_legs) leg_rows.insert(leg_rows.begin() + 1, 0);
    for (int y : leg_rows)
        for (int side : {1, -1})
            add_leg(r, y, side, leg,
                    std::string("leg") + (side > 0 ? "+x" : "-x") + (y > 0 ? "+y" : y < 0 ? "-y" : "0y"));
    return r;
}

} // namespace cic::sim
