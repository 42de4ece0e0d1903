#include "cic/viz/viewer.hpp"

#include <osg/Timer>
#include <osgGA/GUIEventHandler>
#include <osgGA/OrbitManipulator>
#include <osgViewer/Viewer>

#include <algorithm>
#include <stdexcept>

#include "cic/sim/recording_sampler.hpp"
#include "cic/viz/palette.hpp"
#include "hud.hpp"
#include "playback.hpp"
#include "scene.hpp"

namespace cic::viz {
namespace {

// Maps OpenSceneGraph key events onto the play state's keys.
class KeyHandler : public osgGA::GUIEventHandler {
public:
    explicit KeyHandler(Playback& playback) : playback_(playback) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override {
        if (ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN) return false;
        switch (ea.getKey()) {
        case osgGA::GUIEventAdapter::KEY_Space: return playback_.press(' ');
        case osgGA::GUIEventAdapter::KEY_KP_Add: return playback_.press('+');
        case osgGA::GUIEventAdapter::KEY_KP_Subtract: return playback_.press('-');
        default: return playback_.press(ea.getKey());
        }
    }

private:
    Playback& playback_;
};

} // namespace

Viewer::Viewer(std::vector<ViewEntry> entries, ViewerOptions options)
    : entries_(std::move(entries)), options_(std::move(options)) {
    if (entries_.empty()) throw std::invalid_argument("viewer: nothing to show");
    if (options_.width <= 0 || options_.height <= 0)
        throw std::invalid_argument("viewer: width and height must be positive");
    static_cast<void>(Playback(static_cast<int>(entries_.size()), options_.speed));   // checks the speed
    for (const auto& e : entries_) {
        sim::check_recording(e.recording);
        if (e.centre_body < 0 || e.centre_body >= e.recording.body_count)
            throw std::invalid_argument("viewer: centre_body out of range");
    }
}

int Viewer::run() {
    RobotScene scene(options_.shadows);
    Hud hud(options_.width, options_.height);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(scene.root());
    root->addChild(hud.camera());

    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer.setLightingMode(osg::View::NO_LIGHT);   // the scene has its own sun
    viewer.setUpViewInWindow(60, 60, options_.width, options_.height);
    viewer.getCamera()->setClearColor(osg::Vec4(kSky[0], kSky[1], kSky[2], 1));
    viewer.getCamera()->setProjectionMatrixAsPerspective(
        40.0, static_cast<double>(options_.width) / options_.height, 0.05, 2000.0);
    viewer.setSceneData(root);
    Playback playback(static_cast<int>(entries_.size()), options_.speed);
    viewer.addEventHandler(new KeyHandler(playback));
    osg::ref_ptr<osgGA::OrbitManipulator> orbit = new osgGA::OrbitManipulator;
    viewer.setCameraManipulator(orbit, false);
    viewer.realize();
    if (!viewer.isRealized() || !viewer.getCamera()->getGraphicsContext())
        throw std::runtime_error("viewer: cannot open a window (is DISPLAY set? try xvfb-run for screenshots)");
    if (auto* window = dynamic_cast<osgViewer::GraphicsWindow*>(viewer.getCamera()->getGraphicsContext()))
        window->setWindowName(options_.window_title);

    playback.set_view(options_.trail, options_.camera == CameraMode::Fixed);
    int shown = -1;
    bool fixed = !playback.fixed_camera();   // differs: the first frame sets the home view
    osg::Timer_t last = osg::Timer::instance()->tick();
    while (!viewer.done()) {
        const osg::Timer_t now = osg::Timer::instance()->tick();
        const double elapsed = osg::Timer::instance()->delta_s(last, now);
        last = now;
        if (playback.entry() != shown || playback.fixed_camera() != fixed) {
            shown = playback.entry();
            fixed = playback.fixed_camera();
            scene.show(entries_[static_cast<std::size_t>(shown)]);
            scene.set_time(playback.time());
            const double aspect = static_cast<double>(options_.width) / options_.height;
            if (fixed)
                orbit->setHomePosition(scene.path_eye(40.0, aspect), scene.path_focus(), osg::Vec3d(0, 0, 1));
            else
                orbit->setHomePosition(scene.default_eye(), scene.focus(), osg::Vec3d(0, 0, 1));
            viewer.home();
        }
        scene.set_trail(playback.trail());
        playback.advance(elapsed, scene.duration());
        const osg::Vec3d before = scene.focus();
        scene.set_time(playback.time());
        if (!fixed) orbit->setCenter(orbit->getCenter() + (scene.focus() - before));   // follow, keep the user's orbit
        const auto* vp = viewer.getCamera()->getViewport();
        if (vp) hud.resize(static_cast<int>(vp->width()), static_cast<int>(vp->height()));
        hud.set_text(hud_text(entries_[static_cast<std::size_t>(shown)].info, playback.time(), scene.duration(),
                              playback.speed(), playback.paused(), shown, playback.count(), true,
                              scene.walked_text()));
        viewer.frame();
    }
    return 0;
}

} // namespace cic::viz
