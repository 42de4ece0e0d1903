// SimConfig's one field description: ranges and cross-field rules.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "cic/sim/config.hpp"

using namespace cic::sim;

namespace {

bool names(const std::vector<ConfigProblem>& problems, std::string_view field) {
    for (const auto& p : problems)
        for (auto f : p.fields)
            if (f == field) return true;
    return false;
}

} // namespace

TEST(SimConfig, DefaultsHaveNoProblem) { EXPECT_TRUE(config_problems(SimConfig{}).empty()); }

TEST(SimConfig, EveryNumberOutsideItsRangeIsAProblemNamingIt) {
    int checked = 0;
    const SimConfig defaults;
    for_each_field(defaults, [&](const FieldSpec& spec, const auto& member) {
        using T = std::decay_t<decltype(member)>;
        if constexpr (!std::is_same_v<T, bool>) {
            auto with = [&](double v) {
                SimConfig c;
                for_each_field(c, [&](const FieldSpec& f, auto& m) {
                    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, T>)
                        if (f.name == spec.name) m = static_cast<T>(v);
                });
                return config_problems(c);
            };
            if (spec.min != -std::numeric_limits<double>::max()) {
                const double below = spec.min_exclusive ? spec.min : spec.min - 1;
                EXPECT_TRUE(names(with(below), spec.name)) << spec.name << " = " << below;
            }
            if (spec.max != std::numeric_limits<double>::max()) {
                EXPECT_TRUE(names(with(spec.max + 1), spec.name)) << spec.name << " = " << spec.max + 1;
            }
            if constexpr (std::is_same_v<T, double>) {
                EXPECT_TRUE(names(with(std::nan("")), spec.name)) << spec.name;
                EXPECT_EQ(names(with(std::numeric_limits<double>::infinity()), spec.name), !spec.allow_inf)
                    << spec.name;
            }
            ++checked;
        }
    });
    EXPECT_EQ(checked, 19);   // 21 fields, 2 of them bools
}

TEST(SimConfig, CrossFieldRules) {
    SimConfig c;
    c.delayed_start = c.sample_to;   // the start point must lie before the end
    EXPECT_TRUE(names(config_problems(c), "delayed_start"));
    c = SimConfig{};
    c.sample_from = 20;
    EXPECT_TRUE(names(config_problems(c), "sample_to"));
    c = SimConfig{};
    c.sample_step = 0.5;             // 0.5 s physics step: past the stability bound
    auto p = config_problems(c);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NE(p[0].why.find("0.5 s is above the stability bound 0.025 s"), std::string::npos) << p[0].why;
    c.step_divider = 20;
    EXPECT_TRUE(config_problems(c).empty());
    c.step_divider = 1;
    c.allow_coarse_step = true;
    EXPECT_TRUE(config_problems(c).empty());
}
