#include "hud.hpp"

#include <algorithm>

#include <osg/Geode>
#include <osgText/Font>

#include <filesystem>

namespace cic::viz {
namespace {

// A TrueType font when the system has one; osgText's built-in font otherwise.
osg::ref_ptr<osgText::Font> hud_font() {
    for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                             "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf"})
        if (std::filesystem::exists(path))
            if (osg::ref_ptr<osgText::Font> font = osgText::readRefFontFile(path)) return font;
    return osgText::Font::getDefaultFont();
}

} // namespace

Hud::Hud(int width, int height) {
    camera_ = new osg::Camera;
    camera_->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    camera_->setClearMask(GL_DEPTH_BUFFER_BIT);
    camera_->setRenderOrder(osg::Camera::POST_RENDER);
    camera_->setAllowEventFocus(false);
    camera_->setViewMatrix(osg::Matrix::identity());

    text_ = new osgText::Text;
    text_->setFont(hud_font());
    text_->setCharacterSize(16.0f);
    text_->setColor(osg::Vec4(0.05f, 0.05f, 0.1f, 1));
    text_->setBackdropType(osgText::Text::OUTLINE);
    text_->setBackdropColor(osg::Vec4(1, 1, 1, 0.8f));
    text_->setAlignment(osgText::Text::LEFT_TOP);
    text_->setDataVariance(osg::Object::DYNAMIC);
    // A pale box behind the lines: readable over the ground as over the sky.
    text_->setDrawMode(osgText::Text::TEXT | osgText::Text::FILLEDBOUNDINGBOX);
    text_->setBoundingBoxColor(osg::Vec4(1, 1, 1, 0.7f));
    text_->setBoundingBoxMargin(3.0f);

    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(text_);
    auto* ss = geode->getOrCreateStateSet();
    ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
    ss->setMode(GL_BLEND, osg::StateAttribute::ON);
    camera_->addChild(geode);
    resize(width, height);
}

void Hud::set_text(const std::string& text) { text_->setText(text, osgText::String::ENCODING_UTF8); }

void Hud::resize(int width, int height) {
    camera_->setProjectionMatrix(osg::Matrix::ortho2D(0, width, 0, height));
    // Smaller letters in a small window (a screenshot strip's frames), and lines
    // wrapped at its edge: the overlay is never cut off.
    const float margin = 12.0f;
    text_->setCharacterSize(std::clamp(static_cast<float>(width) / 48.0f, 9.0f, 16.0f));
    text_->setMaximumWidth(std::max(1.0f, static_cast<float>(width) - 2 * margin));
    text_->setPosition(osg::Vec3(margin, static_cast<float>(height) - margin, 0));
}

} // namespace cic::viz

#include <fmt/format.h>

namespace cic::viz {

std::string hud_text(const ViewInfo& info, double t, double duration, double speed, bool paused, int index,
                     int count, bool keys, const std::string& walked) {
    std::string who = info.generation >= 0
                          ? fmt::format("generation {}  |  individual {}", info.generation, info.individual)
                          : info.individual;
    std::string text = fmt::format("{}  |  fitness {:.4f}\n", who, info.fitness);
    text += fmt::format("t = {:.2f} / {:.2f} s   speed {:g}x{}", t, duration, speed, paused ? "   [paused]" : "");
    if (count > 1) text += fmt::format("   entry {}/{}", index + 1, count);
    if (!walked.empty()) text += "\n" + walked;
    if (keys)
        text += "\nspace pause  |  r restart  |  + / - speed  |  n / p next / previous  |  t trail  |  c camera  |  "
                "Esc quit";
    return text;
}

} // namespace cic::viz
