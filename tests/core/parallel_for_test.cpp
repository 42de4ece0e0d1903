#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "cic/core/parallel_for.hpp"

using namespace cic;

TEST(ParallelFor, RunsEveryIndexOnceAndRethrowsTheLowestError) {
    for (int threads : {1, 2, 4}) {
        std::vector<std::atomic<int>> hits(100);
        parallel_for(hits.size(), threads, [&](std::size_t i) { ++hits[i]; });
        for (auto& h : hits) EXPECT_EQ(h.load(), 1);
    }
    try {
        parallel_for(10, 1, [](std::size_t i) { if (i >= 3) throw std::runtime_error(std::to_string(i)); });
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "3");
    }
    EXPECT_THROW(parallel_for(50, 2, [](std::size_t i) { if (i == 7) throw std::logic_error("x"); }), std::logic_error);
    EXPECT_GE(hardware_threads(), 1);
}
