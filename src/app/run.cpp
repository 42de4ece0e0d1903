// TEMPORARY placeholder: the evolution loop lands here (lead engineer).
#include "cic/app/run.hpp"

#include <stdexcept>

namespace cic::app {
int run_experiment(const io::Settings&, const RunOptions&) {
    throw std::logic_error("run_experiment: not built yet");
}
} // namespace cic::app
