#pragma once
// The OpenSceneGraph viewer: plays recorded simulations (it never steps the
// physics itself, so what it shows is the motion that earned the fitness),
// and takes offscreen screenshots of them.
#include <filesystem>
#include <string>
#include <vector>

#include "cic/sim/recording.hpp"

namespace cic::viz {

// What the on-screen text says about an entry.
struct ViewInfo {
    int generation = -1;          // < 0: not from a run (e.g. a preset under a sine gait)
    std::string individual;       // id or a label
    double fitness = 0.0;
};

struct ViewEntry {
    ViewInfo info;
    sim::Recording recording;
    int centre_body = 0;          // body the camera follows and the trail marks
    int preferred_axis = -1;      // 0 = x, 1 = y: the overlay's distance is along it; -1: on the ground plane
};

// Where the camera looks from: following the robot's centre (the user may
// orbit around it), or fixed on the world, framing the centre's whole path.
enum class CameraMode { Follow, Fixed };

// What a picture shows besides the robot. The defaults show movement best in
// a still or a strip: the trail on and a fixed camera.
struct SceneOptions {
    bool shadows = true;          // osgShadow::ShadowMap from the sun
    bool trail = true;            // the centre's path so far on the ground, a ring at its start
    CameraMode camera = CameraMode::Fixed;
};

struct ViewerOptions {
    int width = 1024, height = 768;
    double speed = 1.0;           // playback speed, 1 = real time; 1/16 to 16
    bool shadows = true;          // osgShadow::ShadowMap from the sun
    bool trail = true;            // the centre's path so far, a ring at its start (key t toggles it)
    CameraMode camera = CameraMode::Follow;   // key c switches
    std::string window_title = "cic";
};

// Keys: space pause, r restart, + / - speed x2 / /2, n / p next / previous
// entry, t trail on / off, c camera following / fixed, Esc quit. The mouse
// orbits and zooms around the robot (or the path, with a fixed camera).
class Viewer {
public:
    // Throws std::invalid_argument for no entries or an inconsistent recording.
    explicit Viewer(std::vector<ViewEntry> entries, ViewerOptions options = {});
    // Opens the window and plays until it is closed. Returns 0, or throws
    // std::runtime_error when no window can be opened (no X display).
    int run();

private:
    std::vector<ViewEntry> entries_;
    ViewerOptions options_;
};

// Renders `entry` at `at_seconds` after the recording's start (clamped to its
// span) into a width x height PNG without showing a window: an offscreen
// pbuffer, or an undecorated window when the X server offers no pbuffer. Needs
// an X display; under CI run it inside `xvfb-run -a` (Mesa software GL works).
// Throws std::invalid_argument for bad arguments, std::runtime_error when no
// OpenGL context can be made or the PNG cannot be written.
void screenshot(const ViewEntry& entry, double at_seconds, int width, int height,
                const std::filesystem::path& png_path, const SceneOptions& options = {});

// Frames at `times` (seconds after the start) side by side in one PNG of
// times.size() * width x height, each with the overlay and the distance
// walked so far; with a fixed camera every frame has the same view, so the
// robot is seen to move. Throws as screenshot(), and std::invalid_argument
// for no times or more than 64.
void screenshot_strip(const ViewEntry& entry, const std::vector<double>& times, int width, int height,
                      const std::filesystem::path& png_path, const SceneOptions& options = {});

} // namespace cic::viz
