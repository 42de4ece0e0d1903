// A run's best genotype on other robots (transfer.hpp).
#include "cic/report/transfer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/sim/evaluate.hpp"

namespace cic::report {
namespace fs = std::filesystem;

namespace {

// A joint's place: its row along the preferred axis and its place across it.
struct Place {
    int row = 0;                     // the cell coordinate along the preferred axis
    std::tuple<int, int> across{};   // the other horizontal coordinate and z
};

std::vector<Place> places(const sim::RobotSpec& r) {
    std::vector<Place> out;
    for (int i : r.actuated()) {
        const sim::Cell& c = r.modules[static_cast<std::size_t>(i)].cell;
        out.push_back(r.preferred == sim::Axis::Y ? Place{c.y, {c.x, c.z}} : Place{c.x, {c.y, c.z}});
    }
    return out;
}

// The distinct rows of the joints, lowest first.
std::vector<int> rows_of(const std::vector<Place>& ps) {
    std::vector<int> rows;
    for (const Place& p : ps) rows.push_back(p.row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    return rows;
}

std::size_t index_of(const std::vector<int>& rows, int row) {
    return static_cast<std::size_t>(std::lower_bound(rows.begin(), rows.end(), row) - rows.begin());
}

std::string joint_label(const sim::RobotSpec& r, std::size_t joint) {
    const auto& m = r.modules[static_cast<std::size_t>(r.actuated()[joint])];
    return m.name.empty() ? fmt::format("joint {}", joint) : m.name;
}

// Source joints by place across the body: row index -> joint.
using ByRow = std::map<std::size_t, std::size_t>;
std::map<std::tuple<int, int>, ByRow> by_place(const std::vector<Place>& ps, const std::vector<int>& rows) {
    std::map<std::tuple<int, int>, ByRow> out;
    for (std::size_t j = 0; j < ps.size(); ++j) out[ps[j].across][index_of(rows, ps[j].row)] = j;
    return out;
}

// Where rows lie along the body, normalised to [-1, 1] over the robot's
// extent along the preferred axis (the substrate's normalisation).
struct Along {
    int lo = 0, hi = 0;
    explicit Along(const sim::RobotSpec& r) {
        bool first = true;
        for (const auto& m : r.modules) {
            const int v = r.preferred == sim::Axis::Y ? m.cell.y : m.cell.x;
            lo = first ? v : std::min(lo, v);
            hi = first ? v : std::max(hi, v);
            first = false;
        }
    }
    double operator()(int row) const {
        return hi == lo ? 0.0 : static_cast<double>(2 * row - lo - hi) / static_cast<double>(hi - lo);
    }
};

const ByRow& counterparts(const std::map<std::tuple<int, int>, ByRow>& source, const sim::RobotSpec& target,
                          std::size_t joint, const Place& p, const sim::RobotSpec& source_robot) {
    const auto it = source.find(p.across);
    if (it == source.end())
        throw InputError(fmt::format("target joint {} ({}) has no counterpart in {}: no hinge of it stands at the "
                                     "same place across the body",
                                     joint_label(target, joint), target.name, source_robot.name));
    return it->second;
}

} // namespace

std::vector<std::size_t> tile_joints(const sim::RobotSpec& source, const sim::RobotSpec& target) {
    const auto sp = places(source), tp = places(target);
    const auto srows = rows_of(sp), trows = rows_of(tp);
    if (sp.empty() || tp.empty()) throw InputError("tiling needs robots with hinges");
    const auto src = by_place(sp, srows);
    std::vector<std::size_t> out;
    for (std::size_t j = 0; j < tp.size(); ++j) {
        const ByRow& rows = counterparts(src, target, j, tp[j], source);
        const std::size_t want = index_of(trows, tp[j].row) % srows.size();
        // The nearest source row holding this place; the lower on a tie.
        std::size_t best = rows.begin()->first, best_gap = SIZE_MAX;
        for (const auto& [row, joint] : rows) {
            const std::size_t gap = row > want ? row - want : want - row;
            if (gap < best_gap) best = row, best_gap = gap;
        }
        out.push_back(rows.at(best));
    }
    return out;
}

std::vector<JointBlend> interpolate_joints(const sim::RobotSpec& source, const sim::RobotSpec& target) {
    const auto sp = places(source), tp = places(target);
    const auto srows = rows_of(sp);
    const auto src = by_place(sp, srows);
    const Along along_source(source), along_target(target);
    std::vector<JointBlend> out;
    for (std::size_t j = 0; j < tp.size(); ++j) {
        const ByRow& rows = counterparts(src, target, j, tp[j], source);
        const double u = along_target(tp[j].row);
        // The source hinges at this place, by where they lie along the body.
        std::vector<std::pair<double, std::size_t>> line;
        for (const auto& [row, joint] : rows) line.emplace_back(along_source(srows[row]), joint);
        JointBlend b;
        if (u <= line.front().first) {
            b.a = b.b = line.front().second;
        } else if (u >= line.back().first) {
            b.a = b.b = line.back().second;
        } else {
            std::size_t k = 1;
            while (line[k].first < u) ++k;
            b.a = line[k - 1].second;
            b.b = line[k].second;
            b.weight_b = (u - line[k - 1].first) / (line[k].first - line[k - 1].first);
        }
        out.push_back(b);
    }
    return out;
}

ReplayItem replay_transferred(const TransferSource& source, const TransferTarget& target, OffsetRule rule,
                              double fps, bool trace, std::string* how) {
    io::Settings s = source.settings;
    s.robot.robot_file = target.file;
    // One body: the target alone (not the source run's other bodies or growth schedule).
    s.robot.extra_robot_files.clear();
    s.robot.grow_robot_files.clear();
    s.robot.grow_at.clear();
    if (target.file.empty()) {
        if (target.preset < 0 || target.preset > 2)
            throw std::invalid_argument("replay_transferred: a target without a file needs a preset 0..2");
        s.robot.robot_type = target.preset;
        s.neural.middle_legs = target.middle_legs;
    }
    std::string rule_text;
    ReplayItem item;
    if (source.trees.empty()) {
        // A direct gait: one block of numbers per joint after the frequency.
        const gait::Setup setup = gait::Setup::from_settings(s);
        const gait::Setup own = gait::Setup::from_settings(source.settings);
        const std::size_t per = (own.dimension() - 1) / own.robot.actuated().size();
        if (own.cpg || per * own.robot.actuated().size() + 1 != own.dimension())
            throw InputError("only the sine gait (Gait.controller sine) can be tiled onto another robot",
                             source.run);
        const auto map = tile_joints(source.robot, setup.robot);
        std::vector<double> x{source.gait.at(0)};
        for (std::size_t from : map)
            for (std::size_t k = 0; k < per; ++k) x.push_back(source.gait.at(1 + from * per + k));
        item = replay_gait_vector(s, x, fps, trace);
        rule_text = "tiled";
    } else {
        std::vector<double> offsets;
        const hypergp::Model model = hypergp::Model::from_settings(s);
        if (!source.offsets.empty()) {
            if (rule == OffsetRule::None) {
                s.neural.direct_offsets = false;
                rule_text = "offsets-dropped";
            } else {
                for (const JointBlend& b : interpolate_joints(source.robot, model.robot))
                    offsets.push_back((1 - b.weight_b) * source.offsets.at(b.a) + b.weight_b * source.offsets.at(b.b));
                rule_text = "offsets-interpolated";
            }
        } else {
            rule_text = "unchanged";
        }
        item = replay_genotype(s, source.trees, offsets, fps, trace);
    }
    if (how) *how = rule_text;
    return item;
}

} // namespace cic::report
