#pragma once
// The viewer's play state, apart from any window: what each key does and how
// time advances. Kept free of OpenSceneGraph so the key bindings are unit-tested.
namespace cic::viz {

class Playback {
public:
    static constexpr double kMinSpeed = 1.0 / 16, kMaxSpeed = 16.0;

    // `count` entries (individuals) to switch between; throws std::invalid_argument
    // for count < 1 or a speed outside [kMinSpeed, kMaxSpeed].
    Playback(int count, double speed);

    // Space pause/resume, r restart, + = speed x2, - speed /2, n / p next / previous
    // entry (wrapping; the new entry starts at t = 0), t trail on / off, c camera
    // following / fixed. Returns false for other keys.
    bool press(int key);
    // Advances by `elapsed` wall seconds times the speed, unless paused; clamps to
    // [0, duration] (the last frame stays on screen).
    void advance(double elapsed, double duration);

    double time() const { return t_; }
    double speed() const { return speed_; }
    bool paused() const { return paused_; }
    int entry() const { return entry_; }
    int count() const { return count_; }
    bool trail() const { return trail_; }
    bool fixed_camera() const { return fixed_camera_; }
    void set_view(bool trail, bool fixed_camera) { trail_ = trail, fixed_camera_ = fixed_camera; }

private:
    int count_;
    double speed_;
    double t_ = 0.0;
    bool paused_ = false;
    int entry_ = 0;
    bool trail_ = true;
    bool fixed_camera_ = false;
};

} // namespace cic::viz
