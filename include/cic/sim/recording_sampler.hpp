#pragma once
// Pose arithmetic on recorded frames, shared by the POV-Ray writer and the
// OpenSceneGraph viewer so both show exactly the same motion. Header-only and
// free of any graphics library.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cic/sim/recording.hpp"

namespace cic::sim {

using Quat = std::array<double, 4>;   // w, x, y, z
using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;   // row-major

inline Quat quat_multiply(const Quat& a, const Quat& b) {
    return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

inline Mat3 rotation_matrix(const Quat& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
            2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

inline Vec3 rotate(const Quat& q, const Vec3& v) {
    const Mat3 m = rotation_matrix(q);
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
            m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

// The world pose of a part: its body's pose composed with its offset.
inline sim::Pose compose(const sim::Pose& body, const sim::Pose& offset) {
    const Vec3 r = rotate(body.quat, offset.pos);
    sim::Pose out;
    out.pos = {body.pos[0] + r[0], body.pos[1] + r[1], body.pos[2] + r[2]};
    out.quat = quat_multiply(body.quat, offset.quat);
    return out;
}

// Throws std::invalid_argument when the recording is not self-consistent.
inline void check_recording(const sim::Recording& rec) {
    auto fail = [](const std::string& why) { throw std::invalid_argument("recording: " + why); };
    if (rec.frames.empty()) fail("no frames");
    if (rec.times.size() != rec.frames.size())
        fail("times (" + std::to_string(rec.times.size()) + ") and frames (" +
             std::to_string(rec.frames.size()) + ") differ in length");
    if (rec.body_count <= 0) fail("body_count must be positive");
    for (std::size_t f = 0; f < rec.frames.size(); ++f) {
        if (rec.frames[f].size() != static_cast<std::size_t>(rec.body_count))
            fail("frame " + std::to_string(f) + " has " + std::to_string(rec.frames[f].size()) +
                 " poses, expected " + std::to_string(rec.body_count));
        if (f > 0 && !(rec.times[f] >= rec.times[f - 1])) fail("times decrease at frame " + std::to_string(f));
    }
    for (std::size_t p = 0; p < rec.parts.size(); ++p)
        if (rec.parts[p].body < 0 || rec.parts[p].body >= rec.body_count)
            fail("part " + std::to_string(p) + " rides on body " + std::to_string(rec.parts[p].body) +
                 " of " + std::to_string(rec.body_count));
}

inline double recording_start(const sim::Recording& rec) { return rec.times.front(); }
inline double recording_end(const sim::Recording& rec) { return rec.times.back(); }

// Body poses at time t (clamped to the recorded span): positions interpolated
// linearly, rotations by normalised linear interpolation along the short arc.
// Frames are recorded densely (25+ fps), so nlerp is indistinguishable from slerp.
inline std::vector<sim::Pose> sample_frame(const sim::Recording& rec, double t) {
    const auto& times = rec.times;
    if (t <= times.front()) return rec.frames.front();
    if (t >= times.back()) return rec.frames.back();
    const auto hi = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const std::size_t lo = hi - 1;
    const double span = times[hi] - times[lo];
    const double a = span > 0 ? (t - times[lo]) / span : 0.0;
    std::vector<sim::Pose> out(rec.frames[lo].size());
    for (std::size_t b = 0; b < out.size(); ++b) {
        const sim::Pose& p0 = rec.frames[lo][b];
        const sim::Pose& p1 = rec.frames[hi][b];
        for (int k = 0; k < 3; ++k) out[b].pos[k] = p0.pos[k] + a * (p1.pos[k] - p0.pos[k]);
        double dot = 0;
        for (int k = 0; k < 4; ++k) dot += p0.quat[k] * p1.quat[k];
        const double sign = dot < 0 ? -1.0 : 1.0;
        double norm = 0;
        for (int k = 0; k < 4; ++k) {
            out[b].quat[k] = (1 - a) * p0.quat[k] + a * sign * p1.quat[k];
            norm += out[b].quat[k] * out[b].quat[k];
        }
        norm = std::sqrt(norm);
        if (norm > 0)
            for (int k = 0; k < 4; ++k) out[b].quat[k] /= norm;
        else
            out[b].quat = p0.quat;
    }
    return out;
}

// Number of frames when the recording is resampled at fps (first and last included).
inline int resampled_frame_count(const sim::Recording& rec, double fps) {
    const double span = recording_end(rec) - recording_start(rec);
    return static_cast<int>(std::floor(span * fps + 1e-9)) + 1;
}

// Radius of a sphere around `centre_body` holding the whole robot in frame 0;
// cameras use it to frame robots of any size.
inline double robot_radius(const sim::Recording& rec, int centre_body) {
    const auto& frame = rec.frames.front();
    const Vec3 c = frame.at(static_cast<std::size_t>(centre_body)).pos;
    double r = 0;
    for (const auto& part : rec.parts) {
        const sim::Pose w = compose(frame[static_cast<std::size_t>(part.body)], part.offset);
        const double half = 0.5 * std::sqrt(part.size[0] * part.size[0] + part.size[1] * part.size[1] +
                                            part.size[2] * part.size[2]);
        const double dx = w.pos[0] - c[0], dy = w.pos[1] - c[1], dz = w.pos[2] - c[2];
        r = std::max(r, std::sqrt(dx * dx + dy * dy + dz * dz) + half);
    }
    return r > 0 ? r : 1.0;
}

} // namespace cic::sim
