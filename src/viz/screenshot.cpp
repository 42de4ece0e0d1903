// Offscreen rendering of one instant of a recording into a PNG.
#include <osg/Camera>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osgDB/WriteFile>
#include <osgViewer/Viewer>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "cic/sim/recording_sampler.hpp"
#include "cic/viz/palette.hpp"
#include "cic/viz/viewer.hpp"
#include "hud.hpp"
#include "scene.hpp"

namespace cic::viz {
namespace {

// Reads the colour buffer after the last draw of the frame.
struct Capture : osg::Camera::DrawCallback {
    explicit Capture(osg::Image* image) : image_(image) {}
    void operator()(osg::RenderInfo& info) const override {
        const osg::Viewport* vp = info.getCurrentCamera()->getViewport();
        image_->readPixels(static_cast<int>(vp->x()), static_cast<int>(vp->y()), static_cast<int>(vp->width()),
                           static_cast<int>(vp->height()), GL_RGB, GL_UNSIGNED_BYTE);
    }
    osg::Image* image_;
};

osg::ref_ptr<osg::GraphicsContext> offscreen_context(int width, int height) {
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("screenshot: no X display (DISPLAY is unset); run under `xvfb-run -a`");
    for (bool pbuffer : {true, false}) {
        osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
        traits->readDISPLAY();
        traits->setUndefinedScreenDetailsToDefaultScreen();
        traits->x = 0;
        traits->y = 0;
        traits->width = width;
        traits->height = height;
        traits->red = traits->green = traits->blue = 8;
        traits->alpha = 0;
        traits->depth = 24;
        traits->doubleBuffer = !pbuffer;
        traits->pbuffer = pbuffer;
        traits->windowDecoration = false;
        traits->useCursor = false;
        traits->sharedContext = nullptr;
        osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
        if (gc && gc->valid()) return gc;
    }
    throw std::runtime_error("screenshot: cannot create an OpenGL context on display " +
                             std::string(std::getenv("DISPLAY")) + " (no pbuffer and no window)");
}

} // namespace

void screenshot(const ViewEntry& entry, double at_seconds, int width, int height, const std::filesystem::path& png_path,
                bool shadows) {
    if (width <= 0 || height <= 0 || width > 8192 || height > 8192)
        throw std::invalid_argument("screenshot: width and height must be in [1, 8192]");
    if (!std::isfinite(at_seconds) || at_seconds < 0) throw std::invalid_argument("screenshot: --at must be >= 0");
    if (png_path.extension() != ".png") throw std::invalid_argument("screenshot: the file must end in .png");

    RobotScene scene(shadows);
    scene.show(entry);
    scene.set_time(at_seconds);
    Hud hud(width, height);
    hud.set_text(hud_text(entry.info, std::min(at_seconds, scene.duration()), scene.duration(), 1.0, false, 0, 1,
                          false));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(scene.root());
    root->addChild(hud.camera());

    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer.setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::GraphicsContext> gc = offscreen_context(width, height);
    osg::Camera* camera = viewer.getCamera();
    camera->setGraphicsContext(gc.get());
    camera->setViewport(new osg::Viewport(0, 0, width, height));
    const GLenum buffer = gc->getTraits()->doubleBuffer ? GL_BACK : GL_FRONT;
    camera->setDrawBuffer(buffer);
    camera->setReadBuffer(buffer);
    camera->setClearColor(osg::Vec4(kSky[0], kSky[1], kSky[2], 1));
    camera->setProjectionMatrixAsPerspective(40.0, static_cast<double>(width) / height, 0.05, 2000.0);
    camera->setViewMatrixAsLookAt(scene.default_eye(), scene.focus(), osg::Vec3d(0, 0, 1));
    osg::ref_ptr<osg::Image> image = new osg::Image;
    camera->setFinalDrawCallback(new Capture(image.get()));
    viewer.setSceneData(root);
    viewer.realize();
    viewer.frame();
    if (!image->data()) throw std::runtime_error("screenshot: nothing was read back from the OpenGL context");
    if (!osgDB::writeImageFile(*image, png_path.string()))
        throw std::runtime_error("screenshot: cannot write " + png_path.string() + " (OSG png plugin missing?)");
}

} // namespace cic::viz
