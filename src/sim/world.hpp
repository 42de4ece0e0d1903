#pragma once
// Private to cic_sim: one ODE world holding one robot on a flat ground plane.
// Owns world, spaces, contact group, bodies, joints and its own threading
// implementation (ODE's default one is shared by all worlds), released in the
// right order by the destructor.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <ode/ode.h>

#include "cic/sim/config.hpp"
#include "cic/sim/layout.hpp"
#include "cic/sim/recording.hpp"

namespace cic::sim {

// Once per process (thread-safe): dInitODE2. Then per call: ODE data for the calling thread.
void ensure_ode_initialised();

class World {
public:
    World(const BodyLayout& layout, const SimConfig& cfg);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    std::size_t joint_count() const { return joints_.size(); }
    double joint_angle(std::size_t j) const { return dJointGetHingeAngle(joints_[j]); }
    void set_joint_velocity(std::size_t j, double v) { dJointSetHingeParam(joints_[j], dParamVel, v); }

    // One physics step of dt: collide against the ground and, with self-collision,
    // body against body; QuickStep; drop the contacts.
    void step(double dt);

    // Empty when every body is finite, within `bound` (position and velocity) and
    // slower than `max_speed` m/s; otherwise why not. `fastest` gets the top speed.
    std::string check(double bound, double max_speed, double& fastest) const;

    Vec3 geom_position(int geom) const;    // world position of a layout geom's centre
    Pose body_pose(int body) const;
    int body_count() const { return static_cast<int>(bodies_.size()); }
    int last_ground_contacts() const { return ground_contacts_; }
    int last_self_contacts() const { return self_contacts_; }
    double last_ground_depth() const { return ground_depth_; }   // deepest ground contact, m
    // Which layout geoms touched the ground in the last step (1 = touched), kept
    // only once track_ground_geoms(true) asked for it: a replay's duty factors,
    // never the plain evaluation's cost.
    void track_ground_geoms(bool on);
    const std::vector<char>& last_ground_geoms() const { return ground_geoms_; }

private:
    void release();
    int add_contacts(dGeomID a, dGeomID b);
    static void ground_callback(void* data, dGeomID a, dGeomID b);
    static void self_callback(void* data, dGeomID a, dGeomID b);
    static void collect_callback(void* data, dGeomID a, dGeomID b);
    void collide_in_order();
    void sweep_self_pairs();

    const BodyLayout& layout_;
    dContact contact_template_{};
    int max_contacts_ = 4;
    bool self_collision_ = true;
    int collision_space_ = kCollisionSimple;
    // Sap: the candidate pairs of one step, before they are put in order.
    std::vector<std::pair<dGeomID, dGeomID>> pairs_;
    std::vector<int> rank_;            // per layout geom: its place in the order pairs are sorted by
    // Sweep: per layout geom, its bounding box and place (rank) in the space's
    // list; the geoms kept sorted along the sweep axis from one step to the
    // next (they move little per step, so re-sorting is about linear); the
    // candidate pairs as ranks, earlier first, and their start per first rank.
    struct Box {
        std::array<dReal, 6> aabb;
        dGeomID geom;
        int rank;
    };
    std::vector<Box> boxes_;
    std::vector<int> sweep_order_;
    int sweep_axis_ = -1;
    std::vector<dGeomID> by_rank_;
    std::vector<std::pair<int, int>> rank_pairs_, sorted_pairs_;
    std::vector<int> pair_start_;
    void sort_sweep_order(int axis);
    // Body pairs joined by a hinge (key: lower index << 32 | higher), so that a
    // pair of geoms is checked in constant time: ODE's dAreConnectedExcluding
    // walks a body's joint list, and a centipede's torso carries 2P hinges.
    std::unordered_set<std::uint64_t> hinged_;
    bool hinged(dBodyID a, dBodyID b) const;
    int ground_contacts_ = 0;
    int self_contacts_ = 0;
    double ground_depth_ = 0.0;
    bool track_ground_geoms_ = false;
    std::vector<char> ground_geoms_;   // per layout geom, when tracked

    dThreadingImplementationID threading_ = nullptr;
    dWorldID world_ = nullptr;
    dSpaceID robot_space_ = nullptr;
    dGeomID ground_ = nullptr;
    dJointGroupID contact_group_ = nullptr;
    std::vector<dBodyID> bodies_;
    std::vector<dGeomID> geoms_;
    std::vector<dJointID> joints_;
    std::vector<dContact> scratch_;
};

} // namespace cic::sim
