// Plots that fit each search (GP, gait CMA-ES with IPOP, MAP-Elites), the
// archive heatmap's labels and best-cell frame, the centre's path from above,
// and one meaning of "best" (stats.csv's best_so_far, the gait replay's
// generation), on real tiny runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/report/archive_plot.hpp"
#include "cic/report/path_plot.hpp"
#include "cic/report/plot.hpp"
#include "cic/report/replay.hpp"
#include "support/png_image.hpp"
#include "support/run_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;
using namespace cic::report;
using cic::testing::read_text;

// IPOP CMA-ES on R0 that restarts (as golden_test's), and the golden MAP-Elites gait run.
std::string ipop_settings() {
    return R"(<settings>
  <Experiment><type>gait</type><seed>4</seed><workers>2</workers></Experiment>
  <Gait><optimizer>cmaes</optimizer><evaluations>150</evaluations><populationSize>7</populationSize>
      <bounds>reflect</bounds><restarts>ipop</restarts><restartPatience>3</restartPatience></Gait>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
</settings>
)";
}

class SearchPlots : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(cic::testing::temp_dir("search-plots"));
        const auto gp = cic::testing::run_settings(*dir_, "gp", cic::testing::tiny_hypergp_settings(3, 2));
        const auto gait = cic::testing::run_settings(*dir_, "ipop", ipop_settings());
        const auto me = cic::testing::run_settings(*dir_, "me", cic::testing::golden_me_gait_settings(2));
        ASSERT_EQ(gp.rc, 0) << gp.log;
        ASSERT_EQ(gait.rc, 0) << gait.log;
        ASSERT_EQ(me.rc, 0) << me.log;
        gp_ = new fs::path(gp.run);
        gait_ = new fs::path(gait.run);
        me_ = new fs::path(me.run);
    }
    static void TearDownTestSuite() {
        fs::remove_all(*dir_);
        delete dir_, delete gp_, delete gait_, delete me_;
    }
    static inline fs::path *dir_ = nullptr, *gp_ = nullptr, *gait_ = nullptr, *me_ = nullptr;
};

TEST_F(SearchPlots, KnowsEachRunsSearch) {
    EXPECT_EQ(search_kind_of(*gp_), SearchKind::GP);
    EXPECT_EQ(search_kind_of(*gait_), SearchKind::Gait);
    EXPECT_EQ(search_kind_of(*me_), SearchKind::MapElites);
    EXPECT_EQ(x_axis_name(SearchKind::MapElites), "batch");
    EXPECT_TRUE(restart_generations(*gp_).empty());
    const auto restarts = restart_generations(*gait_);
    ASSERT_FALSE(restarts.empty()) << "the IPOP run should restart";
    EXPECT_GT(restarts.front(), 0);
    EXPECT_TRUE(is_archive_run(*me_));
    EXPECT_FALSE(is_archive_run(*gait_));
}

TEST_F(SearchPlots, GaitStatsHoldBothBestsAndAgreeWithTheChampion) {
    const auto rows = read_stats_csv(*gait_ / "stats.csv");
    ASSERT_GT(rows.size(), 3u);
    EXPECT_NE(read_text(*gait_ / "stats.csv").find(",failed,best_so_far\n"), std::string::npos);
    double so_far = -INFINITY;
    bool differ = false;
    for (const auto& r : rows) {
        so_far = std::max(so_far, r.best);
        EXPECT_EQ(r.best_so_far, so_far) << "generation " << r.generation;
        differ = differ || r.best != r.best_so_far;
    }
    EXPECT_TRUE(differ) << "a run whose generations' bests never fall cannot show the two columns apart";
    // The replay's fitness is the last best so far, and it names the generation that found it.
    const auto items = replay(gait_->string(), "best", 1, 10.0, false);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].stored_fitness, rows.back().best_so_far);
    const auto found = std::find_if(rows.begin(), rows.end(), [&](const StatsRow& r) { return r.best == rows.back().best_so_far; });
    ASSERT_NE(found, rows.end());
    EXPECT_EQ(items[0].generation, found->generation);
    EXPECT_NE(items[0].label.find("found in generation " + std::to_string(found->generation)), std::string::npos)
        << items[0].label;
    // The run log's last line agrees too ("champion" is the best so far).
    EXPECT_NE(read_text(*gait_ / "run.log").find(fmt::format("champion {:.17g}", rows.back().best_so_far)),
              std::string::npos);
}

TEST_F(SearchPlots, StatsWithoutBestSoFarGetTheRunningMaximum) {
    const auto rows = read_stats_csv(*gp_ / "stats.csv");
    double so_far = -INFINITY;
    for (const auto& r : rows) {
        so_far = std::max(so_far, r.best);
        EXPECT_EQ(r.best_so_far, so_far);
        EXPECT_TRUE(std::isnan(r.qd_score));
    }
    const auto me = read_stats_csv(*me_ / "stats.csv");
    EXPECT_GT(me.back().qd_score, 0.0);
    EXPECT_GT(me.back().coverage, 0.0);
    EXPECT_LE(me.back().coverage, 1.0);
}

TEST_F(SearchPlots, EachSearchGetsItsOwnPanelsAndXAxis) {
    const fs::path gp = *dir_ / "gp.svg", gait = *dir_ / "gait.svg", me = *dir_ / "me.svg";
    plot_runs({*gp_}, gp);
    plot_runs({*gait_}, gait);
    plot_runs({*me_}, me);
    const std::string g = read_text(gp), c = read_text(gait), m = read_text(me);
    EXPECT_NE(g.find("depth (solid: max"), std::string::npos);
    EXPECT_NE(g.find(">generation<"), std::string::npos);
    // Gait: best so far and each generation's best, restarts marked; no tree panels.
    EXPECT_NE(c.find("solid: so far, dashed: each generation"), std::string::npos);
    EXPECT_NE(c.find("IPOP restarts"), std::string::npos);
    EXPECT_EQ(c.find("depth"), std::string::npos);
    EXPECT_EQ(c.find("size (solid"), std::string::npos);
    // MAP-Elites: QD-score, coverage, the best elite, per batch; no tree panels.
    EXPECT_NE(m.find("QD-score"), std::string::npos);
    EXPECT_NE(m.find("coverage (share of cells filled)"), std::string::npos);
    EXPECT_NE(m.find("best elite"), std::string::npos);
    EXPECT_NE(m.find(">batch<"), std::string::npos);
    EXPECT_EQ(m.find(">generation<"), std::string::npos);
    EXPECT_EQ(m.find("depth"), std::string::npos);
    // Runs of two searches do not share panels.
    EXPECT_THROW(plot_runs({*gp_, *gait_}, *dir_ / "mixed.svg"), InputError);
}

// A study of gait runs: best so far, each generation's best, the restarts marked; no tree panels.
TEST_F(SearchPlots, AGaitStudyGetsTheGaitPanelsWithRestarts) {
    cic::testing::write_text(*dir_ / "ipop-base.xml", ipop_settings());
    cic::testing::write_text(*dir_ / "ipop-sweep.xml",
                             "<sweep name=\"ipop\">\n  <base>" + (*dir_ / "ipop-base.xml").string() +
                                 "</base>\n  <output>" + (*dir_ / "ipop-study").string() +
                                 "</output>\n  <grid><vary key=\"Gait.restartPatience\">2 3</vary></grid>\n"
                                 "  <repeats count=\"1\" firstSeed=\"4\"/>\n</sweep>\n");
    const fs::path log = *dir_ / "ipop-sweep.log";
    ASSERT_EQ(cic::testing::run_command("--quiet sweep " + (*dir_ / "ipop-sweep.xml").string() + " --jobs 2", log), 0)
        << read_text(log);
    const fs::path svg = *dir_ / "ipop-study.svg";
    plot_study(*dir_ / "ipop-study", svg);
    const std::string text = read_text(svg);
    EXPECT_NE(text.find("best fitness so far (dotted: IPOP restarts)"), std::string::npos);
    EXPECT_NE(text.find("each generation's best"), std::string::npos);
    EXPECT_EQ(text.find("depth"), std::string::npos);
}

TEST_F(SearchPlots, PlotOnAnArchiveRunAlsoDrawsTheHeatmap) {
    const fs::path log = *dir_ / "plot.log";
    ASSERT_EQ(cic::testing::run_command("plot " + me_->string() + " --out " + (*dir_ / "curves.svg").string(), log), 0)
        << read_text(log);
    EXPECT_TRUE(fs::exists(*dir_ / "curves.svg"));
    ASSERT_TRUE(fs::exists(*dir_ / "curves-archive.svg")) << read_text(log);
    EXPECT_NE(read_text(*dir_ / "curves-archive.svg").find("(framed)"), std::string::npos);
}

TEST_F(SearchPlots, HeatmapShowsEveryDimensionLabelsBinsAndFramesTheBestCell) {
    const io::ArchiveFile a = io::load_archive(*me_ / "population.xml");
    ASSERT_EQ(a.grid.dimensions(), 4u);
    const ArchiveSlices l = slice_layout(a.grid, 0, 1);
    EXPECT_EQ(l.outer, (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(l.blocks_x, 3);
    EXPECT_EQ(l.blocks_y, 3);
    EXPECT_EQ(l.centre_of({2, 1, 0, 0}), (std::array<double, 2>{2.5, 1.5}));
    EXPECT_EQ(l.centre_of({0, 0, 1, 2}), (std::array<double, 2>{4.5, 8.5}));
    EXPECT_THROW(slice_layout(a.grid, 0, 0), InputError);
    EXPECT_THROW(slice_layout(a.grid, 0, 4), InputError);

    const fs::path svg = *dir_ / "heat.svg";
    plot_archive(*me_, svg);
    const std::string text = read_text(svg);
    const io::ArchiveElite* best = a.best();
    EXPECT_NE(text.find("in cell " + a.grid.cell_name(best->cell) + " (framed)"), std::string::npos);
    for (int d = 1; d <= 4; ++d)
        EXPECT_NE(text.find("dimension " + std::to_string(d) + " (duty factor, foot"), std::string::npos) << d;
    EXPECT_NE(text.find("block: bin of dimension 3"), std::string::npos);
    EXPECT_NE(text.find("block: bin of dimension 4"), std::string::npos);

    // The frame's pixels: magenta, centred on the best cell's place in the plot area.
    ArchivePlotOptions o;
    o.width = 900;
    o.height = 760;
    const fs::path png = *dir_ / "heat.png";
    plot_archive(*me_, png, o);
    const auto image = cic::testing::read_png(png);
    ASSERT_EQ(image.width, 900);
    double sx = 0, sy = 0;
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto c = image.at(x, y);
            if (c[0] > 230 && c[2] > 230 && c[1] < 60) sx += x, sy += y, ++n;
        }
    ASSERT_GT(n, 40) << "no magenta frame";
    const auto centre = l.centre_of(a.grid.coordinates(best->cell));
    const double px = (kHeatmapArea[0] + (centre[0] + 0.5) / (l.width() + 1) * (kHeatmapArea[1] - kHeatmapArea[0])) * 900;
    // Image rows run from the top, the plot's y from the bottom.
    const double py =
        (1 - (kHeatmapArea[2] + (centre[1] + 0.5) / (l.height() + 1) * (kHeatmapArea[3] - kHeatmapArea[2]))) * 760;
    const double cell_px = (kHeatmapArea[1] - kHeatmapArea[0]) * 900 / (l.width() + 1);
    EXPECT_NEAR(sx / n, px, cell_px / 3);
    EXPECT_NEAR(sy / n, py, cell_px / 3);
}

TEST_F(SearchPlots, PathFromAboveMarksThePreferredAxis) {
    const auto items = replay(gp_->string(), "best", 1, 10.0, true);
    const CentrePath p = centre_path(items.front(), "gp");
    EXPECT_EQ(p.xy.size(), items.front().trace.size());
    EXPECT_EQ(p.preferred_axis, 0);   // R0 walks along x
    EXPECT_EQ(p.xy.back()[0], items.front().trace.back().centre[0]);
    EXPECT_NEAR(std::fabs(p.measured_to[0] - p.measured_from[0]), p.distance, 1e-12);
    const auto paths = best_paths({*gp_, *gait_});
    ASSERT_EQ(paths.size(), 2u);
    EXPECT_EQ(paths[0].label, gp_->filename().string());
    EXPECT_EQ(paths[0].xy, p.xy);
    const fs::path svg = *dir_ / "path.svg";
    plot_paths(paths, svg);
    const std::string text = read_text(svg);
    EXPECT_NE(text.find("preferred axis x (eq. 7.1)"), std::string::npos);
    EXPECT_NE(text.find(paths[1].label + ": "), std::string::npos);
    EXPECT_THROW(plot_paths({}, svg), std::invalid_argument);
    ReplayItem empty;
    EXPECT_THROW(centre_path(empty, "x"), std::invalid_argument);
    // Through the command line, with a bad combination refused (exit 2).
    const fs::path log = *dir_ / "path.log";
    EXPECT_EQ(cic::testing::run_command("plot --path " + gp_->string() + " --out " + (*dir_ / "p.png").string(), log), 0)
        << read_text(log);
    EXPECT_TRUE(fs::exists(*dir_ / "p.png"));
    EXPECT_EQ(cic::testing::run_command("plot --path --archive " + me_->string(), log), 2);
}

// A max depth that stays at the top of its range (10, a tic) was drawn on the
// panel's frame and could not be seen; the panels keep room above and below.
TEST(PlotPanels, AConstantLineStaysOffTheFrame) {
    const fs::path dir = cic::testing::temp_dir("constant-line");
    fs::create_directories(dir / "flat-001");
    std::string text = "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,evaluations,"
                       "wall_seconds\n";
    for (int g = 0; g < 6; ++g)
        text += fmt::format("{},{},1,1,{},10,5,9,17,0,{},1\n", g, 1 + g, 2 + g * 1.6, 10 * (g + 1));
    cic::testing::write_text(dir / "flat-001" / "stats.csv", text);
    PlotOptions o;
    o.width = 800;
    o.height = 600;
    plot_runs({dir / "flat-001"}, dir / "flat.png", o);
    const auto image = cic::testing::read_png(dir / "flat.png");
    // The depth panel is the bottom left quarter: find its rows that are mostly
    // the series' blue (the constant max line) and mostly black (the frame's top).
    int line_row = -1, frame_row = -1;
    for (int y = image.height / 2; y < image.height; ++y) {
        int blue = 0, black = 0;
        for (int x = 0; x < image.width / 2; ++x) {
            const auto c = image.at(x, y);
            blue += std::abs(c[0] - 0x1f) < 40 && std::abs(c[1] - 0x77) < 40 && std::abs(c[2] - 0xb4) < 40;
            black += c[0] < 60 && c[1] < 60 && c[2] < 60;
        }
        if (blue > image.width / 10 && line_row < 0) line_row = y;
        if (black > image.width / 5 && frame_row < 0) frame_row = y;
    }
    ASSERT_GE(line_row, 0) << "no constant line in the depth panel: " << (dir / "flat.png");
    ASSERT_GE(frame_row, 0) << "no frame found";
    EXPECT_GT(line_row - frame_row, 5) << "the constant line lies on the frame";
    fs::remove_all(dir);
}

// A GP run whose best falls (no elitism) shows the best so far beside each
// generation's best; one whose best never falls keeps the single curve.
TEST(PlotPanels, AGpRunWhoseBestFallsShowsTheBestSoFar) {
    const fs::path dir = cic::testing::temp_dir("best-falls");
    const std::string header = "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,"
                               "evaluations,wall_seconds\n";
    for (const auto& [name, bests] : {std::pair<std::string, std::array<int, 3>>{"falls-001", {3, 1, 2}},
                                      std::pair<std::string, std::array<int, 3>>{"climbs-001", {1, 2, 3}}}) {
        std::string text = header;
        for (int g = 0; g < 3; ++g) text += fmt::format("{},{},1,1,3,5,5,9,17,0,{},1\n", g, bests[static_cast<std::size_t>(g)], 10 * (g + 1));
        fs::create_directories(dir / name);
        cic::testing::write_text(dir / name / "stats.csv", text);
        plot_runs({dir / name}, dir / (name + ".svg"));
    }
    EXPECT_NE(read_text(dir / "falls-001.svg").find("dashed: so far"), std::string::npos);
    EXPECT_NE(read_text(dir / "falls-001.svg").find("falls so far"), std::string::npos);
    EXPECT_EQ(read_text(dir / "climbs-001.svg").find("so far"), std::string::npos);
    fs::remove_all(dir);
}

// Horizontal runs of dark pixels in a row between x0 and x1: their lengths.
std::vector<int> dark_runs(const cic::testing::RgbImage& image, int y, int x0, int x1) {
    std::vector<int> runs;
    int run = 0;
    for (int x = x0; x <= x1; ++x) {
        const auto c = image.at(x, y);
        if (c[0] < 110 && c[1] < 110 && c[2] < 110) {
            ++run;
        } else if (run > 0) {
            runs.push_back(run);
            run = 0;
        }
    }
    if (run > 0) runs.push_back(run);
    return runs;
}

// The key's box was as tall as its text, and in PNG output its bottom edge
// covered the underscores of the last label ("l_l_l_l" looked like "l l l l").
// Now the underscores are ink of their own, above the box's bottom edge.
TEST(PlotPanels, TheKeyShowsTheUnderscoresOfItsLastLabelInPng) {
    const fs::path dir = cic::testing::temp_dir("underscore");
    std::string text = "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,evaluations,"
                       "wall_seconds\n";
    for (int g = 0; g < 4; ++g) text += fmt::format("{},{},1,1,3,5,5,9,17,0,{},1\n", g, 1 + g, 10 * (g + 1));
    fs::create_directories(dir / "l_l_l_l-001");
    cic::testing::write_text(dir / "l_l_l_l-001" / "stats.csv", text);
    PlotOptions o;
    o.width = 800;
    o.height = 600;
    plot_runs({dir / "l_l_l_l-001"}, dir / "key.png", o);
    const auto image = cic::testing::read_png(dir / "key.png");
    // The top left panel's key: the rows with one dark run of 50 to 250 pixels are its top and bottom edges.
    const int x1 = image.width / 2 - 10;
    std::vector<int> edges;
    for (int y = 0; y < image.height / 2; ++y) {
        const auto runs = dark_runs(image, y, 0, x1);
        if (std::any_of(runs.begin(), runs.end(), [](int r) { return r >= 50 && r <= 250; })) edges.push_back(y);
    }
    ASSERT_GE(edges.size(), 2u) << "no key box found";
    const int bottom = edges.back();
    // The box's left and right edges: where its bottom edge's run starts and ends.
    int left = -1, right = -1;
    for (int x = 0, run = 0; x <= x1; ++x) {
        const auto c = image.at(x, bottom);
        run = c[0] < 110 && c[1] < 110 && c[2] < 110 ? run + 1 : 0;
        if (run == 50) left = x - 49;
        if (run >= 50) right = x;
    }
    ASSERT_GT(right, left);
    // The lowest row inside the box with ink wider than the l's stems (1 or 2 pixels): the
    // underscores, three runs of at least 4 pixels, clear of the bottom edge.
    int lowest = -1;
    for (int y = bottom - 1; y > edges.front() && lowest < 0; --y) {
        const auto runs = dark_runs(image, y, left + 2, right - 2);
        if (std::any_of(runs.begin(), runs.end(), [](int r) { return r >= 3; })) lowest = y;
    }
    ASSERT_GT(lowest, 0) << "no underscore (no ink wider than the l's stems) above the key's bottom edge";
    const auto runs = dark_runs(image, lowest, left + 2, right - 2);
    EXPECT_GE(std::count_if(runs.begin(), runs.end(), [](int r) { return r >= 4 && r < 50; }), 3)
        << "row " << lowest << " (key bottom " << bottom << ") has no underscores";
    EXPECT_LT(lowest, bottom - 1) << "the underscores touch the key's edge";
    fs::remove_all(dir);
}

} // namespace
