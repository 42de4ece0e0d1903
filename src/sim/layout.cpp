// Contract rigid links into bodies (union-find) and place every geom.
#include "cic/sim/layout.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace cic::sim {

namespace {

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(int n) : parent(n) {
        std::iota(parent.begin(), parent.end(), 0);
    }
    int find(int i) {
        while (parent[i] != i) {
            auto& p = parent[i];
            p = parent[p];
            i = p;
        }
        return i;
    }
    void join(int a, int b) { parent[find(a)] = find(b); }
};

Vec3 dir_vector(Dir d) {
    switch (d) {
    case Dir::PosX: return {1, 0, 0};
    case Dir::NegX: return {-1, 0, 0};
    case Dir::PosY: return {0, 1, 0};
    case Dir::NegY: return {0, -1, 0};
    case Dir::PosZ: return {0, 0, 1};
    case Dir::NegZ: return {0, 0, -1};
    case Dir::None: break;
    }
    return {0, 0, 0};
}

} // namespace

Vec3 axis_vector(Axis a) {
    switch (a) {
    case Axis::X: return {1, 0, 0};
    case Axis::Y: return {0, 1, 0};
    case Axis::Z: return {0, 0, 1};
    case Axis::Fixed: break;
    }
    throw std::invalid_argument("axis_vector: a fixed module has no hinge axis");
}

BodyLayout make_body_layout(const RobotSpec& robot) {
    robot.validate();
    const int n = static_cast<int>(robot.modules.size());
    std::vector<int> index_of_cell_parent(n, -1);
    for (int i = 0; i < n; ++i) {
        const Module& m = robot.modules[i];
        if (m.attach == Dir::None) continue;
        const Cell target = neighbour(m.cell, m.attach);
        for (int k = 0; k < n; ++k)
            if (robot.modules[k].cell == target) index_of_cell_parent[i] = k;
    }

    // Items: chassis i = i, panel i = n + i.
    UnionFind uf(2 * n);
    for (int i = 0; i < n; ++i) {
        const Module& m = robot.modules[i];
        if (m.attach == Dir::None) continue;
        uf.join(n + i, index_of_cell_parent[i]);   // panel fixed to neighbour
        if (m.axis == Axis::Fixed) uf.join(i, n + i);                        // no hinge: rigid
    }
    // Number bodies in order of first appearance (chassis 0, 1, ..., then panels).
    BodyLayout L;
    std::vector<int> body_of_root(2 * n, -1);
    auto body_of = [&](int item) {
        int& b = body_of_root[uf.find(item)];
        if (b < 0) b = L.body_count++;
        return b;
    };

    for (int i = 0; i < n; ++i) {
        const Module& m = robot.modules[i];
        LayoutGeom g;
        g.body = body_of(i);
        g.module = i;
        g.kind = PartKind::Chassis;
        g.size = {kChassisSide, kChassisSide, kChassisSide};
        g.centre = {m.cell.x * kModulePitch, m.cell.y * kModulePitch, m.cell.z * kModulePitch};
        g.mass = kChassisMass;
        L.chassis_geom.push_back(static_cast<int>(L.geoms.size()));
        L.geoms.push_back(g);
    }
    for (int i = 0; i < n; ++i) {
        const Module& m = robot.modules[i];
        if (m.attach == Dir::None) continue;   // the centre has no panel
        const Vec3 d = dir_vector(m.attach);
        LayoutGeom g;
        g.body = body_of(n + i);
        g.module = i;
        g.kind = PartKind::Panel;
        for (int k = 0; k < 3; ++k) {
            g.size[k] = d[k] != 0 ? kPanelThickness : kChassisSide;
            g.centre[k] =
                L.geoms[i].centre[k] + kPanelOffset * d[k];
        }
        g.mass = kPanelMass;
        L.geoms.push_back(g);
    }

    // Rest just above the ground.
    double lowest = 1e300;
    for (const auto& g : L.geoms) lowest = std::min(lowest, g.centre[2] - g.size[2] / 2);
    for (auto& g : L.geoms) g.centre[2] += kStartClearance - lowest;

    L.body_mass.assign(L.body_count, 0.0);
    L.body_com.assign(L.body_count, Vec3{});
    for (const auto& g : L.geoms) {
        L.body_mass[g.body] += g.mass;
        for (int k = 0; k < 3; ++k)
            L.body_com[g.body][k] += g.mass * g.centre[k];
    }
    for (int b = 0; b < L.body_count; ++b)
        for (double& c : L.body_com[b]) c /= L.body_mass[b];

    for (int i : robot.actuated()) {
        const Module& m = robot.modules[i];
        LayoutJoint j;
        j.module = i;
        j.chassis_body = L.geoms[i].body;
        j.panel_body = body_of(n + i);
        j.axis = m.axis;
        j.anchor = L.geoms[i].centre;
        L.joints.push_back(j);
    }
    L.centre_geom = L.chassis_geom[robot.centre];
    return L;
}

std::vector<Part> BodyLayout::parts() const {
    std::vector<Part> out;
    out.reserve(geoms.size());
    for (const auto& g : geoms) {
        Part p;
        p.body = g.body;
        p.module = g.module;
        p.kind = g.kind;
        p.size = g.size;
        for (int k = 0; k < 3; ++k)
            p.offset.pos[k] =
                g.centre[k] - body_com[g.body][k];
        out.push_back(p);
    }
    return out;
}

} // namespace cic::sim
