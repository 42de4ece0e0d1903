#pragma once
// The 3D scene shared by the interactive viewer and the offscreen screenshot:
// a sun, a checkered ground grid that follows the robot, the robot's boxes
// (one transform per body), optional shadows.
#include <osg/Group>
#include <osg/LightSource>
#include <osg/MatrixTransform>

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

    // Where the camera looks: above the centre body, at a fixed height so the view does not bob.
    osg::Vec3d focus() const;
    // Eye position for the default view of focus().
    osg::Vec3d default_eye() const;
    double radius() const { return radius_; }

private:
    osg::ref_ptr<osg::Group> root_;
    osg::ref_ptr<osg::Group> robot_;
    osg::ref_ptr<osg::MatrixTransform> ground_;
    std::vector<osg::ref_ptr<osg::MatrixTransform>> bodies_;
    const ViewEntry* entry_ = nullptr;
    double radius_ = 1.0;
    double tile_ = 1.0;
    osg::Vec3d centre_;
};

} // namespace cic::viz
