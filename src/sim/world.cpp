// Building and stepping one robot world (see docs/simulator.md for the model).
#include "world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <stdexcept>

namespace cic::sim {

void ensure_ode_initialised() {
    static std::once_flag once;
    std::call_once(once, [] { dInitODE2(0); });
    dAllocateODEDataForThread(dAllocateMaskAll);
}

World::World(const BodyLayout& layout, const SimConfig& cfg) : layout_(layout) {
    ensure_ode_initialised();
    max_contacts_ = cfg.max_contacts;
    self_collision_ = cfg.self_collision;
    collision_space_ = cfg.collision_space;
    scratch_.resize(static_cast<std::size_t>(max_contacts_));
    dSurfaceParameters& s = contact_template_.surface;
    s.mode = dContactApprox1 | dContactSoftCFM | dContactBounce;
    s.mu = std::isinf(cfg.friction) ? dInfinity : cfg.friction;
    s.soft_cfm = cfg.soft_cfm;
    s.bounce = cfg.bounce;
    s.bounce_vel = 0.1;   // minimum impact speed for a bounce (m/s)

    // Constructed step by step; the destructor copes with a partial world.
    try {
        world_ = dWorldCreate();
        threading_ = dThreadingAllocateSelfThreadedImplementation();
        if (!world_ || !threading_) throw std::runtime_error("ODE: cannot create a world");
        dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                             threading_);
        dWorldSetGravity(world_, 0, 0, -cfg.gravity);
        dWorldSetERP(world_, cfg.erp);
        dWorldSetCFM(world_, cfg.cfm);
        dWorldSetQuickStepNumIterations(world_, cfg.quickstep_iterations);
        switch (collision_space_) {
        case kCollisionSimple: robot_space_ = dSimpleSpaceCreate(nullptr); break;
        case kCollisionSweep: robot_space_ = dSimpleSpaceCreate(nullptr); break;   // searched by sweep_self_pairs
        case kCollisionSap: robot_space_ = dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ); break;
        default: throw std::invalid_argument("World: collision_space must be 0, 1 or 2");
        }
        dSpaceSetCleanup(robot_space_, 1);
        ground_ = dCreatePlane(nullptr, 0, 0, 1, 0);
        contact_group_ = dJointGroupCreate(0);

        for (int b = 0; b < layout.body_count; ++b) {
            dBodyID body = dBodyCreate(world_);
            bodies_.push_back(body);
            const Vec3& c = layout.body_com[b];
            dBodySetPosition(body, c[0], c[1], c[2]);
            dBodySetData(body, reinterpret_cast<void*>(static_cast<std::uintptr_t>(b)));
        }
        // Combined mass per body: each box's mass moved to its offset from the centre of mass.
        std::vector<dMass> mass(bodies_.size());
        for (auto& m : mass) dMassSetZero(&m);
        for (const LayoutGeom& g : layout.geoms) {
            dMass part;
            dMassSetBoxTotal(&part, g.mass, g.size[0], g.size[1], g.size[2]);
            const Vec3& c = layout.body_com[g.body];
            dMassTranslate(&part, g.centre[0] - c[0], g.centre[1] - c[1], g.centre[2] - c[2]);
            dMassAdd(&mass[g.body], &part);

            dGeomID geom = dCreateBox(robot_space_, g.size[0], g.size[1], g.size[2]);
            geoms_.push_back(geom);
            dGeomSetData(geom, reinterpret_cast<void*>(geoms_.size()));   // layout index + 1
            dGeomSetBody(geom, bodies_[g.body]);
            dGeomSetOffsetPosition(geom, g.centre[0] - c[0], g.centre[1] - c[1], g.centre[2] - c[2]);
        }
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            // The centre of mass is the body origin by construction; clear rounding leftovers.
            dMassTranslate(&mass[b], -mass[b].c[0], -mass[b].c[1], -mass[b].c[2]);
            dBodySetMass(bodies_[b], &mass[b]);
        }
        for (const LayoutJoint& lj : layout.joints) {
            dJointID j = dJointCreateHinge(world_, nullptr);
            joints_.push_back(j);
            dJointAttach(j, bodies_[lj.chassis_body], bodies_[lj.panel_body]);
            const auto lo = static_cast<std::uint64_t>(std::min(lj.chassis_body, lj.panel_body));
            const auto hi = static_cast<std::uint64_t>(std::max(lj.chassis_body, lj.panel_body));
            hinged_.insert(lo << 32 | hi);
            dJointSetHingeAnchor(j, lj.anchor[0], lj.anchor[1], lj.anchor[2]);
            const Vec3 a = axis_vector(lj.axis);
            dJointSetHingeAxis(j, a[0], a[1], a[2]);
            dJointSetHingeParam(j, dParamLoStop, -kHingeLimit);
            dJointSetHingeParam(j, dParamHiStop, kHingeLimit);
            dJointSetHingeParam(j, dParamFMax, cfg.max_motor_force);
            dJointSetHingeParam(j, dParamVel, 0.0);
        }
    } catch (...) {
        release();
        throw;
    }
}

World::~World() { release(); }

void World::release() {
    if (contact_group_) dJointGroupDestroy(contact_group_);
    contact_group_ = nullptr;
    if (robot_space_) dSpaceDestroy(robot_space_);   // destroys the robot geoms (cleanup on)
    robot_space_ = nullptr;
    if (ground_) dGeomDestroy(ground_);
    ground_ = nullptr;
    if (world_) {
        dWorldSetStepThreadingImplementation(world_, nullptr, nullptr);
        dWorldDestroy(world_);                        // destroys bodies and hinges
    }
    world_ = nullptr;
    if (threading_) dThreadingFreeImplementation(threading_);
    threading_ = nullptr;
}

// Contacts between two geoms, with the one set of contact parameters.
int World::add_contacts(dGeomID a, dGeomID b) {
    const int n = dCollide(a, b, max_contacts_, &scratch_[0].geom, sizeof(dContact));
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    for (int i = 0; i < n; ++i) {
        dContact c = contact_template_;
        c.geom = scratch_[static_cast<std::size_t>(i)].geom;
        dJointID j = dJointCreateContact(world_, contact_group_, &c);
        dJointAttach(j, ba, bb);
    }
    return n;
}

void World::ground_callback(void* data, dGeomID a, dGeomID b) {
    auto* self = static_cast<World*>(data);
    const int n = self->add_contacts(a, b);
    for (int i = 0; i < n; ++i)
        self->ground_depth_ = std::max(self->ground_depth_, self->scratch_[static_cast<std::size_t>(i)].geom.depth);
    self->ground_contacts_ += n;
    if (self->track_ground_geoms_ && n > 0) {
        const dGeomID robot = a == self->ground_ ? b : a;
        const auto index = reinterpret_cast<std::uintptr_t>(dGeomGetData(robot));
        if (index > 0 && index <= self->ground_geoms_.size()) self->ground_geoms_[index - 1] = 1;
    }
}

void World::track_ground_geoms(bool on) {
    track_ground_geoms_ = on;
    ground_geoms_.assign(on ? geoms_.size() : 0, 0);
}

// A pair of robot geoms whose bounding boxes overlap. ODE's space never offers
// two geoms of one body; bodies joined by a hinge (a module's chassis and its
// panel) touch by construction and are left to the joint.
bool World::hinged(dBodyID a, dBodyID b) const {
    auto ia = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(dBodyGetData(a)));
    auto ib = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(dBodyGetData(b)));
    if (ia > ib) std::swap(ia, ib);
    return hinged_.count(ia << 32 | ib) > 0;
}

void World::self_callback(void* data, dGeomID a, dGeomID b) {
    auto* self = static_cast<World*>(data);
    if (self->hinged(dGeomGetBody(a), dGeomGetBody(b))) return;
    self->self_contacts_ += self->add_contacts(a, b);
}

void World::collect_callback(void* data, dGeomID a, dGeomID b) {
    static_cast<World*>(data)->pairs_.emplace_back(a, b);
}

// Sweep: the simple space's own pairs, found without testing every pair. The
// ground goes first, through the simple space as with kCollisionSimple (that
// also brings every geom's bounding box up to date). Then the robot geoms'
// boxes are swept along the axis where the boxes' centres spread most; a pair
// whose boxes overlap on all three axes (bounds touching count, as in ODE's
// collideAABBs) on two bodies is a candidate, exactly the pairs the simple
// space would offer. They are called back in the simple space's order: by
// their place in its geom list (which ODE reorders as bodies move), the
// earlier geom first. Every step is linear in the geoms and pairs: the sweep
// order is last step's, repaired by insertion, and the pairs are put in order
// by counting on their first rank.
void World::sweep_self_pairs() {
    const int n = dSpaceGetNumGeoms(robot_space_);
    boxes_.resize(geoms_.size());
    by_rank_.resize(static_cast<std::size_t>(n));
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int i = 0; i < n; ++i) {
        const dGeomID g = dSpaceGetGeom(robot_space_, i);
        Box& b = boxes_[reinterpret_cast<std::uintptr_t>(dGeomGetData(g)) - 1];
        b.geom = g;
        b.rank = i;
        by_rank_[static_cast<std::size_t>(i)] = g;
        dGeomGetAABB(g, b.aabb.data());
        for (int k = 0; k < 3; ++k) {
            const double c = 0.5 * (b.aabb[2 * k] + b.aabb[2 * k + 1]);
            lo[k] = std::min(lo[k], c);
            hi[k] = std::max(hi[k], c);
        }
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    sort_sweep_order(axis);

    // Any order by lower bound finds every overlapping pair: the later box of a
    // pair starts inside the earlier one's extent along the axis.
    rank_pairs_.clear();
    const std::size_t count = sweep_order_.size();
    for (std::size_t i = 0; i < count; ++i) {
        const Box& a = boxes_[static_cast<std::size_t>(sweep_order_[i])];
        for (std::size_t j = i + 1; j < count; ++j) {
            const Box& b = boxes_[static_cast<std::size_t>(sweep_order_[j])];
            if (b.aabb[2 * axis] > a.aabb[2 * axis + 1]) break;
            bool overlap = true;
            for (int k = 0; k < 3 && overlap; ++k)
                overlap = !(a.aabb[2 * k] > b.aabb[2 * k + 1] || a.aabb[2 * k + 1] < b.aabb[2 * k]);
            if (!overlap) continue;
            const dBodyID ba = dGeomGetBody(a.geom), bb = dGeomGetBody(b.geom);
            if (ba == bb && ba) continue;
            rank_pairs_.emplace_back(std::min(a.rank, b.rank), std::max(a.rank, b.rank));
        }
    }
    // Counting sort on the first rank; then insertion sort, which only moves a
    // pair within its (short) run of one first rank, orders by the second.
    const auto at = [](auto& v, int i) -> auto& { return v[static_cast<std::size_t>(i)]; };
    pair_start_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const auto& p : rank_pairs_) ++at(pair_start_, p.first + 1);
    for (int r = 0; r < n; ++r) at(pair_start_, r + 1) += at(pair_start_, r);
    sorted_pairs_.resize(rank_pairs_.size());
    for (const auto& p : rank_pairs_) at(sorted_pairs_, at(pair_start_, p.first)++) = p;
    for (std::size_t i = 1; i < sorted_pairs_.size(); ++i)
        for (std::size_t j = i; j > 0 && sorted_pairs_[j] < sorted_pairs_[j - 1]; --j)
            std::swap(sorted_pairs_[j], sorted_pairs_[j - 1]);
    for (const auto& [first, second] : sorted_pairs_) self_callback(this, at(by_rank_, first), at(by_rank_, second));
}

// Layout geoms by lower bound along `axis`: last step's order repaired by
// insertion (bodies move a few millimetres per step, so it is nearly sorted),
// from scratch when the axis changes or the repair grows long.
void World::sort_sweep_order(int axis) {
    const auto low = [this, axis](int g) { return boxes_[static_cast<std::size_t>(g)].aabb[2 * axis]; };
    const auto by_low = [&low](int a, int b) { return low(a) < low(b); };
    if (axis != sweep_axis_ || sweep_order_.size() != boxes_.size()) {
        sweep_order_.resize(boxes_.size());
        for (std::size_t g = 0; g < sweep_order_.size(); ++g) sweep_order_[g] = static_cast<int>(g);
        std::sort(sweep_order_.begin(), sweep_order_.end(), by_low);
        sweep_axis_ = axis;
        return;
    }
    std::size_t moves = 0;
    const std::size_t budget = 8 * sweep_order_.size();
    for (std::size_t i = 1; i < sweep_order_.size(); ++i) {
        const int g = sweep_order_[i];
        const double v = low(g);
        std::size_t j = i;
        for (; j > 0 && low(sweep_order_[j - 1]) > v; --j) sweep_order_[j] = sweep_order_[j - 1];
        sweep_order_[j] = g;
        moves += i - j;
        if (moves > budget) {
            std::sort(sweep_order_.begin(), sweep_order_.end(), by_low);
            return;
        }
    }
}

// Sap: the space only finds the candidate pairs; they are sorted and handed to
// the callbacks in a fixed order, the layout's geom order (sweep-and-prune
// keeps its geoms in arrays of its own, not in the simple space's list).
void World::collide_in_order() {
    const auto layout_index = [](dGeomID g) {
        return static_cast<int>(reinterpret_cast<std::uintptr_t>(dGeomGetData(g)) - 1);
    };
    auto by_rank = [this, &layout_index](const std::pair<dGeomID, dGeomID>& p, const std::pair<dGeomID, dGeomID>& q) {
        const int pa = rank_[static_cast<std::size_t>(layout_index(p.first))];
        const int qa = rank_[static_cast<std::size_t>(layout_index(q.first))];
        if (pa != qa) return pa < qa;
        if (p.second == ground_ || q.second == ground_) return false;
        return rank_[static_cast<std::size_t>(layout_index(p.second))] <
               rank_[static_cast<std::size_t>(layout_index(q.second))];
    };
    pairs_.clear();
    dSpaceCollide2(reinterpret_cast<dGeomID>(robot_space_), ground_, this, &World::collect_callback);
    const std::size_t ground_pairs = pairs_.size();
    if (self_collision_) dSpaceCollide(robot_space_, this, &World::collect_callback);
    if (pairs_.empty()) return;

    rank_.resize(geoms_.size());
    for (std::size_t i = 0; i < rank_.size(); ++i) rank_[i] = static_cast<int>(i);
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
        auto& [a, b] = pairs_[i];
        if (i < ground_pairs) {
            if (a == ground_) std::swap(a, b);   // robot geom first, as the simple space calls back
        } else if (rank_[static_cast<std::size_t>(layout_index(b))] < rank_[static_cast<std::size_t>(layout_index(a))]) {
            std::swap(a, b);
        }
    }
    const auto self_begin = pairs_.begin() + static_cast<std::ptrdiff_t>(ground_pairs);
    std::sort(pairs_.begin(), self_begin, by_rank);
    std::sort(self_begin, pairs_.end(), by_rank);
    for (std::size_t i = 0; i < pairs_.size(); ++i)
        (i < ground_pairs ? &World::ground_callback : &World::self_callback)(this, pairs_[i].first, pairs_[i].second);
}

void World::step(double dt) {
    ground_contacts_ = 0;
    self_contacts_ = 0;
    ground_depth_ = 0.0;
    if (track_ground_geoms_) std::fill(ground_geoms_.begin(), ground_geoms_.end(), 0);
    // Ground contacts first, then the robot against itself: a fixed order, so
    // QuickStep sees the same constraint rows in every run.
    if (collision_space_ == kCollisionSimple) {
        dSpaceCollide2(reinterpret_cast<dGeomID>(robot_space_), ground_, this, &World::ground_callback);
        if (self_collision_) dSpaceCollide(robot_space_, this, &World::self_callback);
    } else if (collision_space_ == kCollisionSweep) {
        dSpaceCollide2(reinterpret_cast<dGeomID>(robot_space_), ground_, this, &World::ground_callback);
        if (self_collision_) sweep_self_pairs();
    } else {
        collide_in_order();
    }
    dWorldQuickStep(world_, dt);
    dJointGroupEmpty(contact_group_);
}

std::string World::check(double bound, double max_speed, double& fastest) const {
    fastest = 0.0;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const dReal* p = dBodyGetPosition(bodies_[b]);
        const dReal* v = dBodyGetLinearVel(bodies_[b]);
        const dReal* w = dBodyGetAngularVel(bodies_[b]);
        for (int k = 0; k < 3; ++k) {
            if (!(std::fabs(p[k]) <= bound)) return "body " + std::to_string(b) + " position out of bounds or NaN";
            if (!(std::fabs(v[k]) <= bound) || !(std::fabs(w[k]) <= bound))
                return "body " + std::to_string(b) + " velocity out of bounds or NaN";
        }
        const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        fastest = std::max(fastest, speed);
        if (speed > max_speed)
            return "body " + std::to_string(b) + " moves at " + std::to_string(speed) + " m/s (maxBodySpeed " +
                   std::to_string(max_speed) + ")";
    }
    return {};
}

Vec3 World::geom_position(int geom) const {
    const dReal* p = dGeomGetPosition(geoms_[static_cast<std::size_t>(geom)]);
    return {p[0], p[1], p[2]};
}

Pose World::body_pose(int body) const {
    const dReal* p = dBodyGetPosition(bodies_[static_cast<std::size_t>(body)]);
    const dReal* q = dBodyGetQuaternion(bodies_[static_cast<std::size_t>(body)]);
    Pose pose;
    pose.pos = {p[0], p[1], p[2]};
    pose.quat = {q[0], q[1], q[2], q[3]};
    return pose;
}

} // namespace cic::sim
