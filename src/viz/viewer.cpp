#include "cic/viz/viewer.hpp"

#include <osg/Timer>
#include <osgGA/GUIEventHandler>
#include <osgGA/OrbitManipulator>
#include <osgViewer/Viewer>

#include <algorithm>
#include <stdexcept>

#include "cic/io/recording_sampler.hpp"
#include "cic/viz/palette.hpp"
#include "src/viz/hud.hpp"
#include "src/viz/scene.hpp"

namespace cic::viz {
namespace {

struct PlayState {
    bool paused = false;
    double speed = 1.0;
    bool restart = false;
    int step_entry = 0;     // +1 next, -1 previous
};

class KeyHandler : public osgGA::GUIEventHandler {
public:
    explicit KeyHandler(PlayState& state) : state_(state) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override {
        if (ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN) return false;
        switch (ea.getKey()) {
        case osgGA::GUIEventAdapter::KEY_Space: state_.paused = !state_.paused; return true;
        case 'r': state_.restart = true; return true;
        case '+': case '=': case osgGA::GUIEventAdapter::KEY_KP_Add:
            state_.speed = std::min(state_.speed * 2, 16.0); return true;
        case '-': case osgGA::GUIEventAdapter::KEY_KP_Subtract:
            state_.speed = std::max(state_.speed / 2, 1.0 / 16); return true;
        case 'n': state_.step_entry = 1; return true;
        case 'p': state_.step_entry = -1; return true;
        default: return false;
        }
    }

private:
    PlayState& state_;
};

} // namespace

Viewer::Viewer(std::vector<ViewEntry> entries, ViewerOptions options)
    : entries_(std::move(entries)), options_(std::move(options)) {
    if (entries_.empty()) throw std::invalid_argument("viewer: nothing to show");
    if (!(options_.speed > 0) || options_.width <= 0 || options_.height <= 0)
        throw std::invalid_argument("viewer: speed, width and height must be positive");
    for (const auto& e : entries_) {
        io::check_recording(e.recording);
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
    PlayState state;
    state.speed = options_.speed;
    viewer.addEventHandler(new KeyHandler(state));
    osg::ref_ptr<osgGA::OrbitManipulator> orbit = new osgGA::OrbitManipulator;
    viewer.setCameraManipulator(orbit, false);
    viewer.realize();
    if (!viewer.isRealized() || !viewer.getCamera()->getGraphicsContext())
        throw std::runtime_error("viewer: cannot open a window (is DISPLAY set? try xvfb-run for screenshots)");
    if (auto* window = dynamic_cast<osgViewer::GraphicsWindow*>(viewer.getCamera()->getGraphicsContext()))
        window->setWindowName(options_.window_title);

    int index = 0;
    auto show = [&](int i) {
        index = i;
        scene.show(entries_[static_cast<std::size_t>(index)]);
        orbit->setHomePosition(scene.default_eye(), scene.focus(), osg::Vec3d(0, 0, 1));
        viewer.home();
    };
    show(0);

    double t = 0;
    osg::Timer_t last = osg::Timer::instance()->tick();
    while (!viewer.done()) {
        const osg::Timer_t now = osg::Timer::instance()->tick();
        const double elapsed = osg::Timer::instance()->delta_s(last, now);
        last = now;
        if (state.step_entry != 0) {
            const int n = static_cast<int>(entries_.size());
            show(((index + state.step_entry) % n + n) % n);
            state.step_entry = 0;
            t = 0;
        }
        if (state.restart) {
            t = 0;
            state.restart = false;
        }
        if (!state.paused) t = std::min(t + elapsed * state.speed, scene.duration());
        const osg::Vec3d before = scene.focus();
        scene.set_time(t);
        orbit->setCenter(orbit->getCenter() + (scene.focus() - before));   // follow, keep the user's orbit
        const auto* vp = viewer.getCamera()->getViewport();
        if (vp) hud.resize(static_cast<int>(vp->width()), static_cast<int>(vp->height()));
        hud.set_text(hud_text(entries_[static_cast<std::size_t>(index)].info, t, scene.duration(), state.speed,
                              state.paused, index, static_cast<int>(entries_.size()), true));
        viewer.frame();
    }
    return 0;
}

} // namespace cic::viz
