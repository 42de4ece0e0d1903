#pragma once
// The 3D scene shared by the interactive viewer and the offscreen screenshot:
// a sun, a checkered ground grid that follows the robot, the robot's boxes
// (one transform per body), optional shadows, and the centre's path so far as
// a trail on the ground with a ring at its start.
#include <osg/Group>
#include <osg/LightSource>
#include <osg/MatrixTransform>

#include <osg/Geometry>

#include <string>
#include <vector>

#include "cic/viz/viewer.hpp"

namespace cic::viz {

class RobotScene {
public:
    explicit RobotScene(bool shadows);

    osg::Node* root() const { return root_.get(); }

    // Shows this entry's robot (rebuilds the body transforms) at time 0.
    void show(const ViewEntry& entry);
    // Time since the recording's start, clamped to [0, duration()].
    void set_time(double t);
    double duration() const;

    // The trail and its start ring shown or hidden.
    void set_trail(bool on);
    bool trail() const { return trail_on_; }

    // Where the camera looks: above the centre body, at a fixed height so the view does not bob.
    osg::Vec3d focus() const;
    // Eye position for the default view of focus().
    osg::Vec3d default_eye() const;
    // A camera fixed on the world: the middle of the centre's whole path, and
    // an eye from the same direction as default_eye() far enough back to
    // frame the path and the robot (vertical field of view fov_degrees, aspect w/h).
    osg::Vec3d path_focus() const;
    osg::Vec3d path_eye(double fov_degrees, double aspect) const;
    double radius() const { return radius_; }
    // The centre's displacement from the start at the current time, m: along
    // the entry's preferred axis when it has one, else on the ground plane;
    // and the overlay's line saying it.
    double walked() const;
    std::string walked_text() const;

private:
    void build_trail();

    osg::ref_ptr<osg::Group> root_;
    osg::ref_ptr<osg::Group> robot_;
    osg::ref_ptr<osg::MatrixTransform> ground_;
    std::vector<osg::ref_ptr<osg::MatrixTransform>> bodies_;
    osg::ref_ptr<osg::Group> trail_;                // the trail and the start ring
    osg::ref_ptr<osg::Geometry> trail_line_;
    osg::ref_ptr<osg::DrawArrays> trail_drawn_;     // the first points up to the current time
    std::vector<osg::Vec3d> path_;                  // the centre in each recorded frame
    bool trail_on_ = true;
    const ViewEntry* entry_ = nullptr;
    double radius_ = 1.0;
    double tile_ = 1.0;
    osg::Vec3d centre_;
};

} // namespace cic::viz
