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
    int centre_body = 0;          // body the camera follows
};

struct ViewerOptions {
    int width = 1024, height = 768;
    double speed = 1.0;           // playback speed, 1 = real time; 1/16 to 16
    bool shadows = true;          // osgShadow::ShadowMap from the sun
    std::string window_title = "cic";
};

// Keys: space pause, r restart, + / - speed x2 / /2, n / p next / previous
// entry, Esc quit. The mouse orbits and zooms around the robot, which the
// camera follows.
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
                const std::filesystem::path& png_path, bool shadows = true);

} // namespace cic::viz
