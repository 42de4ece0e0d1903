#pragma once
// On-screen text (generation, individual, fitness, time, keys) in a 2D overlay camera.
#include <osg/Camera>
#include <osgText/Text>

#include <string>

namespace cic::viz {

class Hud {
public:
    Hud(int width, int height);
    osg::Camera* camera() const { return camera_.get(); }
    void set_text(const std::string& text);
    void resize(int width, int height);
    // The overlay's extent in window pixels (after set_text and resize).
    osg::BoundingBox text_bounds() const { return text_->getBoundingBox(); }

private:
    osg::ref_ptr<osg::Camera> camera_;
    osg::ref_ptr<osgText::Text> text_;
};

} // namespace cic::viz

#include "cic/viz/viewer.hpp"

namespace cic::viz {

// The overlay's lines: who is shown, the play state, `walked` (a line of its
// own when not empty: the distance walked so far), the keys (when `keys`).
std::string hud_text(const ViewInfo& info, double t, double duration, double speed, bool paused, int index,
                     int count, bool keys, const std::string& walked = {});

} // namespace cic::viz
