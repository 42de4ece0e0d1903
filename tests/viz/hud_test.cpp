// The viewer's overlay fits its window: in a screenshot strip's small frames
// the lines wrap and the letters shrink instead of running off the edge.
#include <gtest/gtest.h>

#include "hud.hpp"

namespace cic::viz {
namespace {

TEST(Hud, TheOverlayStaysInsideSmallAndLargeWindows) {
    ViewInfo info;
    info.generation = 48;
    info.individual = "2800";
    info.fitness = 12.345678;
    const std::string text = hud_text(info, 11.0, 15.0, 1.0, false, 0, 1, true);
    for (const auto& [w, h] : {std::pair{240, 180}, std::pair{320, 240}, std::pair{1024, 768}}) {
        Hud hud(w, h);
        hud.set_text(text);
        const osg::BoundingBox box = hud.text_bounds();
        ASSERT_TRUE(box.valid());
        EXPECT_GE(box.xMin(), 0.0f) << w;
        EXPECT_LE(box.xMax(), static_cast<float>(w)) << w << "x" << h << ": the overlay runs past the right edge";
        EXPECT_GE(box.yMin(), 0.0f) << w;
        EXPECT_LE(box.yMax(), static_cast<float>(h)) << w;
    }
}

TEST(Hud, TheDistanceWalkedHasALineOfItsOwn) {
    ViewInfo info;
    info.generation = 3;
    info.individual = "best cmaes gait";
    const std::string text = hud_text(info, 1.0, 2.0, 1.0, false, 0, 1, false, "walked 0.42 m along y from the start");
    EXPECT_NE(text.find("generation 3  |  individual best cmaes gait"), std::string::npos);
    EXPECT_NE(text.find("\nwalked 0.42 m along y from the start"), std::string::npos);
    EXPECT_EQ(hud_text(info, 1.0, 2.0, 1.0, false, 0, 1, false).find("walked"), std::string::npos);
}

} // namespace
} // namespace cic::viz
