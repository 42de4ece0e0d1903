// Searches of gait vectors written as ask and tell (search/ask_tell.hpp).
#include "cic/search/ask_tell.hpp"

#include <stdexcept>
#include <string>

namespace cic::search {

VectorAskTell::VectorAskTell(const Services& services)
    : services_(services), setup_(gait::Setup::from_settings(services.settings)),
      descriptor_(services.settings.map_elites.descriptor) {}

VectorAskTell::~VectorAskTell() = default;

std::vector<gp::Evaluation> VectorAskTell::evaluate(const std::vector<std::vector<double>>& batch) {
    if (batch.empty()) throw std::invalid_argument("ask() gave an empty batch");
    for (const auto& x : batch) {
        if (x.size() != setup_.dimension())
            throw std::invalid_argument("ask() gave a point of " + std::to_string(x.size()) +
                                        " numbers; the gait has " + std::to_string(setup_.dimension()));
        for (double v : x)
            if (!(v >= 0.0 && v <= 1.0))
                throw std::invalid_argument("ask() gave a point outside the unit box: " + std::to_string(v));
    }
    if (!evaluator_) evaluator_ = std::make_unique<gait::Evaluator>(services_.context, setup_);
    return evaluator_->described(batch, descriptor_);
}

long VectorAskTell::failed() const { return evaluator_ ? evaluator_->failed() : 0; }

Row VectorAskTell::step() {
    const std::vector<std::vector<double>> batch = ask();
    return tell(batch, evaluate(batch));
}

} // namespace cic::search
