// The MAP-Elites grid archive (gp/grid_archive.hpp): bad arguments throw, the
// same seed draws the same elites, and saving then restoring the elites gives
// the same archive; binning, replacement and the QD measures.
#include <gtest/gtest.h>

#include "cic/gp/grid_archive.hpp"

namespace cic::gp {
namespace {

GridSpec duty_factors(int legs, int bins) {
    return GridSpec{std::vector<int>(static_cast<std::size_t>(legs), bins), std::vector<double>(static_cast<std::size_t>(legs), 0.0),
                    std::vector<double>(static_cast<std::size_t>(legs), 1.0)};
}

TEST(GridArchive, BadArgumentsThrow) {
    EXPECT_THROW(GridArchive<int>(GridSpec{}), std::invalid_argument);
    EXPECT_THROW(GridArchive<int>(GridSpec{{5, 5}, {0}, {1, 1}}), std::invalid_argument);
    EXPECT_THROW(GridArchive<int>(GridSpec{{0}, {0}, {1}}), std::invalid_argument);
    EXPECT_THROW(GridArchive<int>(GridSpec{{5}, {1}, {1}}), std::invalid_argument);
    EXPECT_THROW(GridArchive<int>(GridSpec{{5}, {0}, {INFINITY}}), std::invalid_argument);
    EXPECT_THROW(GridArchive<int>(duty_factors(8, 10)), std::invalid_argument);   // 10^8 cells
    GridArchive<int> a(duty_factors(2, 5));
    EXPECT_THROW(a.cell_of({0.5}), std::invalid_argument);
    EXPECT_THROW(a.cell_of({0.5, NAN}), std::invalid_argument);
    EXPECT_THROW(a.offer({0.5, 0.5}, INFINITY, 1), std::invalid_argument);
    EXPECT_THROW(a.coordinates(25), std::invalid_argument);
    Rng rng(1);
    EXPECT_THROW(a.random_cell(rng), std::logic_error);
}

TEST(GridArchive, BinsAreRowMajorAndEdgesClamp) {
    GridArchive<int> a(duty_factors(2, 5));   // Cully et al.'s 5 bins per leg
    EXPECT_EQ(a.cells(), 25u);
    EXPECT_EQ(a.cell_of({0.0, 0.0}), 0u);
    EXPECT_EQ(a.cell_of({0.0, 0.2}), 1u);     // the last dimension fastest
    EXPECT_EQ(a.cell_of({0.2, 0.0}), 5u);
    EXPECT_EQ(a.cell_of({1.0, 1.0}), 24u);    // the upper bound is in the last bin
    EXPECT_EQ(a.cell_of({-3.0, 7.0}), 4u);    // outside the range: the nearest bin
    // Far outside: no overflow on the way (fuzz/regressions/archive/ubsan-*).
    EXPECT_EQ(a.cell_of({5e15, -1e300}), 20u);
    EXPECT_EQ(a.cell_of({-1e300, 1e300}), 4u);
    EXPECT_EQ(a.coordinates(a.cell_of({0.45, 0.9})), (std::vector<int>{2, 4}));
}

TEST(GridArchive, AFitterSolutionReplacesTheElite) {
    GridArchive<std::string> a(duty_factors(2, 5));
    EXPECT_TRUE(a.offer({0.1, 0.1}, 1.0, "first"));
    EXPECT_FALSE(a.offer({0.15, 0.1}, 1.0, "tie"));        // a tie keeps the incumbent
    EXPECT_FALSE(a.offer({0.1, 0.15}, 0.5, "worse"));
    EXPECT_TRUE(a.offer({0.12, 0.12}, 2.0, "better"));
    EXPECT_TRUE(a.offer({0.9, 0.9}, -1.0, "elsewhere"));
    EXPECT_EQ(a.filled(), 2u);
    EXPECT_EQ(a.at(0)->solution, "better");
    EXPECT_EQ(a.at(0)->descriptor, (std::vector<double>{0.12, 0.12}));
    EXPECT_DOUBLE_EQ(a.coverage(), 2.0 / 25.0);
    EXPECT_DOUBLE_EQ(a.qd_score(-10.0), (2.0 + 10.0) + (-1.0 + 10.0));
    EXPECT_EQ(a.best()->solution, "better");
}

TEST(GridArchive, TheSameSeedDrawsTheSameElites) {
    GridArchive<int> a(duty_factors(4, 5));
    Rng fill(7);
    for (int i = 0; i < 500; ++i)
        a.offer({fill.uniform(), fill.uniform(), fill.uniform(), fill.uniform()}, fill.normal(), i);
    Rng r1(3), r2(3), r3(4);
    std::vector<std::size_t> d1, d2, d3;
    for (int i = 0; i < 50; ++i) {
        d1.push_back(a.random_cell(r1));
        d2.push_back(a.random_cell(r2));
        d3.push_back(a.random_cell(r3));
    }
    EXPECT_EQ(d1, d2);
    EXPECT_NE(d1, d3);
    for (std::size_t c : d1) EXPECT_NE(a.at(c), nullptr);
}

TEST(GridArchive, RestoringTheSavedElitesGivesTheSameArchive) {
    GridArchive<int> a(duty_factors(3, 4));
    Rng fill(11);
    for (int i = 0; i < 200; ++i) a.offer({fill.uniform(), fill.uniform(), fill.uniform()}, fill.normal(), i);
    GridArchive<int> b(a.spec());
    for (const auto& [cell, e] : a.elites()) b.restore(cell, e);
    ASSERT_EQ(b.filled(), a.filled());
    for (const auto& [cell, e] : a.elites()) {
        EXPECT_EQ(b.at(cell)->solution, e.solution);
        EXPECT_EQ(b.at(cell)->fitness, e.fitness);
    }
    EXPECT_EQ(b.qd_score(-5), a.qd_score(-5));
    // A saved elite in the wrong cell, or twice, is refused.
    const auto& [cell, e] = *a.elites().begin();
    EXPECT_THROW(b.restore(cell, e), std::invalid_argument);
    GridArchive<int> c(a.spec());
    EXPECT_THROW(c.restore(cell + 1, e), std::invalid_argument);
}

} // namespace
} // namespace cic::gp
