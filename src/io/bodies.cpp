// The bodies of a run beyond its robot (bodies.hpp).
#include "cic/io/bodies.hpp"

#include <cmath>
#include <stdexcept>

namespace cic::io {

bool several_bodies(const Settings& s) { return !s.robot.extra_robot_files.empty(); }

bool grows(const Settings& s) { return !s.robot.grow_robot_files.empty(); }

std::size_t growing_bodies(const Settings& s) { return 1 + s.robot.grow_robot_files.size(); }

int grow_generation(const Settings& s, std::size_t body) {
    if (body == 0 || body > s.robot.grow_at.size())
        throw std::out_of_range("grow_generation: no body " + std::to_string(body));
    // 0.7 * 10 is 7.000000000000001 in doubles: that is generation 7, not 8.
    const double at = s.robot.grow_at[body - 1] * s.control.maximum_iterations;
    return static_cast<int>(std::ceil(at - 1e-9));
}

std::size_t body_of_generation(const Settings& s, int generation) {
    std::size_t body = 0;
    while (body + 1 < growing_bodies(s) && body + 1 <= s.robot.grow_at.size() &&
           generation >= grow_generation(s, body + 1))
        ++body;
    return body;
}

} // namespace cic::io
