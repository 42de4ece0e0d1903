#include "playback.hpp"

#include <algorithm>
#include <stdexcept>

namespace cic::viz {

Playback::Playback(int count, double speed) : count_(count), speed_(speed) {
    if (count < 1) throw std::invalid_argument("viewer: nothing to show");
    if (!(speed >= kMinSpeed && speed <= kMaxSpeed))
        throw std::invalid_argument("viewer: speed must be in [1/16, 16]");
}

bool Playback::press(int key) {
    switch (key) {
    case ' ': paused_ = !paused_; return true;
    case 'r': t_ = 0.0; return true;
    case '+': case '=': speed_ = std::min(speed_ * 2, kMaxSpeed); return true;
    case '-': speed_ = std::max(speed_ / 2, kMinSpeed); return true;
    case 'n': entry_ = (entry_ + 1) % count_; t_ = 0.0; return true;
    case 'p': entry_ = (entry_ + count_ - 1) % count_; t_ = 0.0; return true;
    case 't': trail_ = !trail_; return true;
    case 'c': fixed_camera_ = !fixed_camera_; return true;
    default: return false;
    }
}

void Playback::advance(double elapsed, double duration) {
    if (!paused_) t_ += std::max(elapsed, 0.0) * speed_;
    t_ = std::clamp(t_, 0.0, std::max(duration, 0.0));
}

} // namespace cic::viz
