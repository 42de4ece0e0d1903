// The centipede robots of the scaling study (see centipede.hpp).
#include "cic/sim/centipede.hpp"

#include <stdexcept>
#include <string>

#include "cic/core/limits.hpp"

namespace cic::sim {

int max_centipede_pairs() { return static_cast<int>((limits::kMaxModules + 1) / 8); }

RobotSpec centipede(int pairs, bool irregular) {
    if (pairs < 1 || pairs > max_centipede_pairs())
        throw std::invalid_argument("centipede: pairs " + std::to_string(pairs) + " is outside 1.." +
                                    std::to_string(max_centipede_pairs()));
    RobotSpec r;
    r.name = "centipede-" + std::to_string(pairs) + (irregular ? "-irregular" : "");
    r.preferred = Axis::Y;
    r.centre = 0;
    // Torso along y, centre cube first, then outwards in both directions; each
    // cube attaches towards the centre (as the presets' torsos do).
    const int half = pairs - 1;
    r.modules.push_back({{0, 0, 0}, Axis::Fixed, Dir::None, "torso.0"});
    for (int d = 1; d <= half; ++d) {
        r.modules.push_back({{0, d, 0}, Axis::Fixed, Dir::NegY, "torso.+" + std::to_string(d)});
        r.modules.push_back({{0, -d, 0}, Axis::Fixed, Dir::PosY, "torso.-" + std::to_string(d)});
    }
    const Axis leg[] = {Axis::Y, Axis::Z, Axis::Y};   // R1's leg, hip out
    const int short_from = pairs - (pairs + 1) / 2;    // the front ceil(P/2) pairs
    for (int k = 0; k < pairs; ++k) {
        const int y = 2 * k - half;
        for (int side : {1, -1}) {
            const bool shortened = irregular && side < 0 && k >= short_from;
            const int length = shortened ? 2 : 3;
            const std::string label = "pair" + std::to_string(k) + (side > 0 ? "+x" : "-x");
            for (int j = 0; j < length; ++j)
                r.modules.push_back({{side * (j + 1), y, 0}, leg[j], side > 0 ? Dir::NegX : Dir::PosX,
                                     label + "." + std::to_string(j)});
        }
    }
    r.validate();
    return r;
}

} // namespace cic::sim
