#include "scene.hpp"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightModel>
#include <osg/LineWidth>
#include <osg/Material>
#include <osg/PolygonOffset>
#include <osg/ShapeDrawable>
#include <osg/Texture2D>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cic/sim/recording_sampler.hpp"
#include "cic/viz/palette.hpp"

namespace cic::viz {
namespace {

constexpr unsigned kReceivesShadow = 0x1;
constexpr unsigned kCastsShadow = 0x2;
constexpr double kGroundHalfTiles = 40;   // the ground reaches this many tiles from the robot

osg::Vec4 rgba(const Rgb& c, float a = 1.0f) { return {c[0], c[1], c[2], a}; }

osg::Matrixd pose_matrix(const sim::Pose& p) {
    // ODE stores w, x, y, z; osg::Quat takes x, y, z, w.
    const osg::Quat q(p.quat[1], p.quat[2], p.quat[3], p.quat[0]);
    return osg::Matrixd::rotate(q) * osg::Matrixd::translate(p.pos[0], p.pos[1], p.pos[2]);
}

osg::ref_ptr<osg::Texture2D> texture_from(const std::vector<Rgb>& texels, int side) {
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(side, side, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (int i = 0; i < side * side; ++i)
        for (int k = 0; k < 3; ++k)
            image->data()[i * 3 + k] = static_cast<unsigned char>(std::lround(texels[static_cast<std::size_t>(i)][k] * 255));
    osg::ref_ptr<osg::Texture2D> tex = new osg::Texture2D(image);
    tex->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    tex->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    tex->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    tex->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    return tex;
}

osg::ref_ptr<osg::Material> material(const Rgb& c) {
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setDiffuse(osg::Material::FRONT_AND_BACK, rgba(c));
    m->setAmbient(osg::Material::FRONT_AND_BACK, rgba({c[0] * 0.6f, c[1] * 0.6f, c[2] * 0.6f}));
    m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.25f, 0.25f, 0.25f, 1));
    m->setShininess(osg::Material::FRONT_AND_BACK, 32);
    return m;
}

// A checkered quad (period two tiles) with grid lines on the tile edges, centred on the origin.
osg::ref_ptr<osg::Geode> make_ground(double tile) {
    const double half = kGroundHalfTiles * tile;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;

    osg::ref_ptr<osg::Geometry> quad = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec2Array> tc = new osg::Vec2Array;
    const float h = static_cast<float>(half);
    const float reps = static_cast<float>(half / tile);   // the 2x2 texture spans two tiles
    for (auto [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        v->push_back(osg::Vec3(x * h, y * h, 0));
        tc->push_back(osg::Vec2(x * reps * 0.5f, y * reps * 0.5f));
    }
    quad->setVertexArray(v);
    quad->setTexCoordArray(0, tc);
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    n->push_back(osg::Vec3(0, 0, 1));
    quad->setNormalArray(n, osg::Array::BIND_OVERALL);
    osg::ref_ptr<osg::Vec4Array> c = new osg::Vec4Array;
    c->push_back(osg::Vec4(1, 1, 1, 1));
    quad->setColorArray(c, osg::Array::BIND_OVERALL);
    quad->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    auto* qs = quad->getOrCreateStateSet();
    qs->setTextureAttributeAndModes(0, texture_from({kGroundLight, kGroundDark, kGroundDark, kGroundLight}, 2));
    qs->setAttributeAndModes(material({1, 1, 1}));
    qs->setAttributeAndModes(new osg::PolygonOffset(1.0f, 1.0f));
    geode->addDrawable(quad);

    osg::ref_ptr<osg::Geometry> lines = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> lv = new osg::Vec3Array;
    const int count = static_cast<int>(kGroundHalfTiles);
    for (int i = -count; i <= count; ++i) {
        const float p = static_cast<float>(i * tile);
        lv->push_back(osg::Vec3(p, -h, 0));
        lv->push_back(osg::Vec3(p, h, 0));
        lv->push_back(osg::Vec3(-h, p, 0));
        lv->push_back(osg::Vec3(h, p, 0));
    }
    lines->setVertexArray(lv);
    osg::ref_ptr<osg::Vec4Array> lc = new osg::Vec4Array;
    lc->push_back(rgba(kGridLine));
    lines->setColorArray(lc, osg::Array::BIND_OVERALL);
    lines->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lv->size())));
    auto* ls = lines->getOrCreateStateSet();
    ls->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    geode->addDrawable(lines);
    return geode;
}

} // namespace

RobotScene::RobotScene(bool shadows) {
    osg::ref_ptr<osg::LightSource> sun = new osg::LightSource;
    osg::Light* light = sun->getLight();
    light->setLightNum(0);
    light->setPosition(osg::Vec4(0.9f, -0.35f, 1.1f, 0.0f));   // directional: lights the faces the camera sees
    light->setAmbient(osg::Vec4(0.35f, 0.35f, 0.35f, 1));
    light->setDiffuse(osg::Vec4(0.85f, 0.83f, 0.80f, 1));
    light->setSpecular(osg::Vec4(0.4f, 0.4f, 0.4f, 1));

    if (shadows) {
        osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene;
        scene->setReceivesShadowTraversalMask(kReceivesShadow);
        scene->setCastsShadowTraversalMask(kCastsShadow);
        osg::ref_ptr<osgShadow::ShadowMap> map = new osgShadow::ShadowMap;
        map->setLight(sun.get());
        map->setTextureSize(osg::Vec2s(2048, 2048));
        map->setAmbientBias(osg::Vec2(0.55f, 0.45f));
        scene->setShadowTechnique(map);
        root_ = scene;
    } else {
        root_ = new osg::Group;
    }
    auto* ss = root_->getOrCreateStateSet();
    ss->setMode(GL_LIGHTING, osg::StateAttribute::ON);
    ss->setMode(GL_LIGHT0, osg::StateAttribute::ON);
    ss->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
    osg::ref_ptr<osg::LightModel> model = new osg::LightModel;
    model->setAmbientIntensity(osg::Vec4(0.3f, 0.3f, 0.3f, 1));
    ss->setAttributeAndModes(model);
    // ShadowMap's shader multiplies by texture unit 0: give untextured parts a white texel.
    ss->setTextureAttributeAndModes(0, texture_from({{1, 1, 1}}, 1));
    root_->addChild(sun);

    ground_ = new osg::MatrixTransform;
    ground_->setNodeMask(kReceivesShadow);
    root_->addChild(ground_);
    robot_ = new osg::Group;
    robot_->setNodeMask(kReceivesShadow | kCastsShadow);
    root_->addChild(robot_);
    trail_ = new osg::Group;
    trail_->setNodeMask(kReceivesShadow);
    root_->addChild(trail_);
}

void RobotScene::set_trail(bool on) {
    trail_on_ = on;
    trail_->setNodeMask(on ? kReceivesShadow : 0u);
}

// The centre's recorded positions as a line on the ground, drawn up to the
// current time, and a flat ring where it starts.
void RobotScene::build_trail() {
    trail_->removeChildren(0, trail_->getNumChildren());
    const float lift = static_cast<float>(0.004 * radius_);   // above the ground and its grid lines
    osg::ref_ptr<osg::Vec3Array> points = new osg::Vec3Array;
    for (const osg::Vec3d& p : path_) points->push_back(osg::Vec3(static_cast<float>(p.x()), static_cast<float>(p.y()), lift));
    trail_line_ = new osg::Geometry;
    trail_line_->setVertexArray(points);
    osg::ref_ptr<osg::Vec4Array> colour = new osg::Vec4Array;
    colour->push_back(rgba(kTrail));
    trail_line_->setColorArray(colour, osg::Array::BIND_OVERALL);
    trail_drawn_ = new osg::DrawArrays(GL_LINE_STRIP, 0, 1);
    trail_line_->addPrimitiveSet(trail_drawn_);
    trail_line_->setDataVariance(osg::Object::DYNAMIC);
    trail_line_->setUseDisplayList(false);
    auto* ts = trail_line_->getOrCreateStateSet();
    ts->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    ts->setAttributeAndModes(new osg::LineWidth(4.0f));
    // Drawn last and over everything: a robot walks along its own body, which would hide the path.
    ts->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    ts->setRenderBinDetails(100, "RenderBin");
    // Ring: a triangle strip between two circles around the start.
    osg::ref_ptr<osg::Geometry> ring = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> rv = new osg::Vec3Array;
    const osg::Vec3d start = path_.empty() ? osg::Vec3d() : path_.front();
    const double outer = 0.5 * tile_, inner = 0.32 * tile_;
    for (int k = 0; k <= 48; ++k) {
        const double a = 2 * M_PI * k / 48;
        for (double r : {outer, inner})
            rv->push_back(osg::Vec3(static_cast<float>(start.x() + r * std::cos(a)),
                                    static_cast<float>(start.y() + r * std::sin(a)), lift));
    }
    ring->setVertexArray(rv);
    osg::ref_ptr<osg::Vec4Array> rc = new osg::Vec4Array;
    rc->push_back(rgba(kTrailStart));
    ring->setColorArray(rc, osg::Array::BIND_OVERALL);
    ring->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, static_cast<GLsizei>(rv->size())));
    auto* rs = ring->getOrCreateStateSet();
    rs->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    rs->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(trail_line_);
    geode->addDrawable(ring);
    // Drawn over the ground (which has a polygon offset) without fighting it.
    geode->getOrCreateStateSet()->setAttributeAndModes(new osg::PolygonOffset(-1.0f, -1.0f));
    trail_->addChild(geode);
}

void RobotScene::show(const ViewEntry& entry) {
    sim::check_recording(entry.recording);
    if (entry.centre_body < 0 || entry.centre_body >= entry.recording.body_count)
        throw std::invalid_argument("viewer: centre_body out of range");
    entry_ = &entry;
    radius_ = sim::robot_radius(entry.recording, entry.centre_body);
    double edge = 0;
    for (const auto& part : entry.recording.parts) edge = std::max({edge, part.size[0], part.size[1], part.size[2]});
    tile_ = edge > 0 ? 2 * edge : 0.5;   // the same tile as the POV-Ray ground

    ground_->removeChildren(0, ground_->getNumChildren());
    ground_->addChild(make_ground(tile_));

    path_.clear();
    const auto centre = static_cast<std::size_t>(entry.centre_body);
    for (const auto& frame : entry.recording.frames)
        path_.emplace_back(frame[centre].pos[0], frame[centre].pos[1], frame[centre].pos[2]);
    build_trail();

    robot_->removeChildren(0, robot_->getNumChildren());
    bodies_.clear();
    for (int b = 0; b < entry.recording.body_count; ++b) {
        bodies_.push_back(new osg::MatrixTransform);
        robot_->addChild(bodies_.back());
    }
    const osg::ref_ptr<osg::Material> chassis = material(kChassisColour);
    const osg::ref_ptr<osg::Material> panel = material(kPanelColour);
    for (const auto& part : entry.recording.parts) {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        osg::ref_ptr<osg::ShapeDrawable> box = new osg::ShapeDrawable(
            new osg::Box(osg::Vec3(), static_cast<float>(part.size[0]), static_cast<float>(part.size[1]),
                         static_cast<float>(part.size[2])));
        geode->addDrawable(box);
        geode->getOrCreateStateSet()->setAttributeAndModes(part.kind == sim::PartKind::Chassis ? chassis : panel);
        osg::ref_ptr<osg::MatrixTransform> offset = new osg::MatrixTransform(pose_matrix(part.offset));
        offset->addChild(geode);
        bodies_[static_cast<std::size_t>(part.body)]->addChild(offset);
    }
    set_time(0.0);
}

double RobotScene::duration() const {
    return entry_ ? sim::recording_end(entry_->recording) - sim::recording_start(entry_->recording) : 0.0;
}

void RobotScene::set_time(double t) {
    if (!entry_) return;
    const auto poses = sim::sample_frame(entry_->recording, sim::recording_start(entry_->recording) + std::clamp(t, 0.0, duration()));
    for (std::size_t b = 0; b < bodies_.size(); ++b) bodies_[b]->setMatrix(pose_matrix(poses[b]));
    const auto& c = poses[static_cast<std::size_t>(entry_->centre_body)].pos;
    centre_.set(c[0], c[1], c[2]);
    // The trail up to now: the recorded frames so far, then the centre itself.
    const double now = sim::recording_start(entry_->recording) + std::clamp(t, 0.0, duration());
    const auto& times = entry_->recording.times;
    const auto shown = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), now) - times.begin());
    if (trail_line_ && !path_.empty()) {
        auto* points = static_cast<osg::Vec3Array*>(trail_line_->getVertexArray());
        const std::size_t n = std::clamp<std::size_t>(shown, 1, path_.size());
        // The point after the frames shown follows the centre between frames.
        if (n < path_.size()) (*points)[n].set(static_cast<float>(c[0]), static_cast<float>(c[1]), (*points)[0].z());
        for (std::size_t k = n + 1; k < path_.size(); ++k)
            (*points)[k].set(static_cast<float>(path_[k].x()), static_cast<float>(path_[k].y()), (*points)[0].z());
        trail_drawn_->setCount(static_cast<GLsizei>(std::min(n + 1, path_.size())));
        points->dirty();
        trail_line_->dirtyBound();
    }
    // Keep the finite ground under the robot, moved by whole checker periods so it looks still.
    const double period = 2 * tile_;
    ground_->setMatrix(osg::Matrixd::translate(std::round(c[0] / period) * period,
                                               std::round(c[1] / period) * period, 0));
}

osg::Vec3d RobotScene::focus() const { return {centre_.x(), centre_.y(), 0.35 * radius_}; }

osg::Vec3d RobotScene::path_focus() const {
    if (path_.empty()) return focus();
    osg::BoundingBoxd box;
    for (const osg::Vec3d& p : path_) box.expandBy(p);
    return {box.center().x(), box.center().y(), 0.35 * radius_};
}

osg::Vec3d RobotScene::path_eye(double fov_degrees, double aspect) const {
    osg::BoundingBoxd box;
    for (const osg::Vec3d& p : path_) box.expandBy(osg::Vec3d(p.x(), p.y(), 0));
    // Half the path's extent plus the robot, as seen across a narrower field of view when the frame is tall.
    const double half = 0.5 * std::max(box.xMax() - box.xMin(), box.yMax() - box.yMin()) + radius_;
    const double half_angle = 0.5 * osg::DegreesToRadians(fov_degrees) * std::min(1.0, aspect);
    // From higher than the following camera: the trail on the ground shows beside the robot.
    const osg::Vec3d from(1.2, -1.9, 2.0);
    const double distance = std::max(1.15 * half / std::tan(half_angle), from.length() * radius_);
    osg::Vec3d direction = from;
    direction.normalize();
    return path_focus() + direction * distance;
}

double RobotScene::walked() const {
    if (!entry_ || path_.empty()) return 0.0;
    const osg::Vec3d d = centre_ - path_.front();
    if (entry_->preferred_axis == 0) return std::fabs(d.x());
    if (entry_->preferred_axis == 1) return std::fabs(d.y());
    return std::hypot(d.x(), d.y());
}

std::string RobotScene::walked_text() const {
    if (!entry_) return {};
    const char* along = entry_->preferred_axis == 0 ? " along x" : entry_->preferred_axis == 1 ? " along y" : "";
    return fmt::format("walked {:.2f} m{} from the start", walked(), along);
}

osg::Vec3d RobotScene::default_eye() const {
    // The same view direction as the POV-Ray camera (src/io/povray.cpp), in z-up coordinates.
    return focus() + osg::Vec3d(1.6, -2.4, 0.8) * radius_;
}

} // namespace cic::viz
