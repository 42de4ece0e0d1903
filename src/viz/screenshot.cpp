// Offscreen rendering of one instant of a recording into a PNG.
#include <osg/Camera>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osgDB/WriteFile>
#include <osgViewer/Viewer>

#include <cmath>
#include <cstdlib>
#include <cstring>
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

namespace {

void check_size(int width, int height) {
    if (width <= 0 || height <= 0 || width > 8192 || height > 8192)
        throw std::invalid_argument("screenshot: width and height must be in [1, 8192]");
}

void check_time(double at_seconds) {
    if (!std::isfinite(at_seconds) || at_seconds < 0) throw std::invalid_argument("screenshot: --at must be >= 0");
}

// One instant rendered offscreen, with the overlay.
osg::ref_ptr<osg::Image> render_image(const ViewEntry& entry, double at_seconds, int width, int height,
                                      const SceneOptions& options) {
    RobotScene scene(options.shadows);
    scene.show(entry);
    scene.set_trail(options.trail);
    scene.set_time(at_seconds);
    Hud hud(width, height);
    hud.set_text(hud_text(entry.info, std::min(at_seconds, scene.duration()), scene.duration(), 1.0, false, 0, 1,
                          false, scene.walked_text()));
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
    constexpr double kFov = 40.0;
    const double aspect = static_cast<double>(width) / height;
    camera->setProjectionMatrixAsPerspective(kFov, aspect, 0.05, 2000.0);
    if (options.camera == CameraMode::Fixed)
        camera->setViewMatrixAsLookAt(scene.path_eye(kFov, aspect), scene.path_focus(), osg::Vec3d(0, 0, 1));
    else
        camera->setViewMatrixAsLookAt(scene.default_eye(), scene.focus(), osg::Vec3d(0, 0, 1));
    osg::ref_ptr<osg::Image> image = new osg::Image;
    camera->setFinalDrawCallback(new Capture(image.get()));
    viewer.setSceneData(root);
    viewer.realize();
    viewer.frame();
    if (!image->data()) throw std::runtime_error("screenshot: nothing was read back from the OpenGL context");
    return image;
}

void write_png(const osg::Image& image, const std::filesystem::path& png_path) {
    if (!osgDB::writeImageFile(image, png_path.string()))
        throw std::runtime_error("screenshot: cannot write " + png_path.string() + " (OSG png plugin missing?)");
}

} // namespace

void screenshot(const ViewEntry& entry, double at_seconds, int width, int height, const std::filesystem::path& png_path,
                const SceneOptions& options) {
    check_size(width, height);
    check_time(at_seconds);
    if (png_path.extension() != ".png") throw std::invalid_argument("screenshot: the file must end in .png");
    write_png(*render_image(entry, at_seconds, width, height, options), png_path);
}

void screenshot_strip(const ViewEntry& entry, const std::vector<double>& times, int width, int height,
                      const std::filesystem::path& png_path, const SceneOptions& options) {
    check_size(width, height);
    if (times.empty() || times.size() > 64) throw std::invalid_argument("screenshot: a strip takes 1 to 64 times");
    if (static_cast<long>(width) * static_cast<long>(times.size()) > 16384)
        throw std::invalid_argument("screenshot: the strip would be wider than 16384 pixels");
    for (double t : times) check_time(t);
    if (png_path.extension() != ".png") throw std::invalid_argument("screenshot: the file must end in .png");
    osg::ref_ptr<osg::Image> strip = new osg::Image;
    const int total = width * static_cast<int>(times.size());
    strip->allocateImage(total, height, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (std::size_t k = 0; k < times.size(); ++k) {
        const osg::ref_ptr<osg::Image> frame = render_image(entry, times[k], width, height, options);
        for (int y = 0; y < height; ++y)
            std::memcpy(strip->data(static_cast<int>(k) * width, y), frame->data(0, y), static_cast<std::size_t>(width) * 3);
    }
    write_png(*strip, png_path);
}

} // namespace cic::viz
