#include "cic/experiments/map_elites_grid.hpp"

#include <cmath>
#include <string>

#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/evaluate.hpp"

namespace cic::experiments {

gp::GridSpec map_elites_grid(const io::Settings& s, const sim::RobotSpec& robot) {
    const auto& me = s.map_elites;
    gp::GridSpec g;
    std::size_t dims = 2;
    double lo = -me.omni_range, hi = me.omni_range;
    if (me.descriptor == sim::Descriptor::DutyFactor) {
        dims = sim::branch_ends(robot).size();
        lo = 0.0;
        hi = 1.0;
        if (dims == 0)
            throw io::key_error(s, {"MapElites.descriptor"},
                                "robot '" + robot.name + "' has no branch end (foot) to measure; use descriptor omni");
    }
    double cells = 1;
    for (std::size_t d = 0; d < dims; ++d) {
        g.bins.push_back(me.bins);
        g.lo.push_back(lo);
        g.hi.push_back(hi);
        cells *= me.bins;
    }
    if (cells > static_cast<double>(gp::GridSpec::kMaxCells))
        throw io::key_error(s, {"MapElites.bins", "MapElites.descriptor"},
                            std::to_string(me.bins) + " bins over " + std::to_string(dims) + " dimensions (" +
                                sim::to_string(me.descriptor) + " of robot '" + robot.name + "') make " +
                                std::to_string(static_cast<long long>(cells)) + " cells, past the limit of " +
                                std::to_string(gp::GridSpec::kMaxCells));
    g.validate();
    return g;
}

} // namespace cic::experiments
