#pragma once
// POV-Ray export of a recorded simulation: one scene file per video frame plus
// shared includes, rendered by scripts/render-video.sh (povray + ffmpeg).
// Knows nothing of OpenSceneGraph; only reads sim::Recording.
#include <filesystem>
#include <string>

#include "cic/sim/recording.hpp"

namespace cic::io {

struct PovrayOptions {
    int centre_body = 0;        // body the camera follows (the robot's centre module)
    double tile = 0.0;          // ground checker tile edge in m; 0 = twice the largest part edge
    std::string title;          // written as a comment into every scene
    bool trail = true;          // the centre's path so far on the ground, a green ring at its start
    bool fixed_camera = false;  // a camera fixed on the world framing the whole path, not following
};

// Writes out_dir/frame_00000.pov ... (the recording resampled at `fps`, first
// and last instants included) and the shared includes camera.inc, lights.inc,
// materials.inc and ground.inc. Coordinates: ODE's z-up right-handed frame is
// mapped to POV-Ray's y-up left-handed one by swapping y and z (no mirror image).
// Returns the number of frames written.
// Throws std::invalid_argument for fps <= 0, an inconsistent recording or a
// centre_body out of range; cic::InputError when out_dir cannot be written or
// already holds frame_*.pov files (stale frames would end up in the video).
int write_povray(const sim::Recording& recording, const std::filesystem::path& out_dir, double fps,
                 const PovrayOptions& options = {});

} // namespace cic::io
