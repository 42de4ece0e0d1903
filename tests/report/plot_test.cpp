// Plots through gnuplot: stats.csv reading and its error messages, run grouping,
// summaries, real SVG/PNG output, trace CSV round trip and trace plots.
#include <gtest/gtest.h>

#include "support/input_error.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cic/report/plot.hpp"
#include "cic/report/trace_csv.hpp"
#include "cic/core/error.hpp"
#include "cic/io/stats_csv.hpp"
#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;
using cic::testing::input_error;
using namespace cic::report;

fs::path scratch(const std::string& name) { return cic::testing::temp_dir("plot-" + name); }
using cic::testing::read_text;
using cic::testing::write_text;

const std::string kHeader =
    "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,evaluations,wall_seconds\n";

// A run folder with `gens` generations whose best fitness grows by `slope`.
fs::path make_run(const fs::path& parent, const std::string& name, int gens, double slope) {
    const fs::path dir = parent / name;
    fs::create_directories(dir);
    std::string text = kHeader;
    for (int g = 0; g < gens; ++g)
        text += std::to_string(g) + "," + std::to_string(slope * g) + "," + std::to_string(0.5 * slope * g) +
                ",0.1,3.5,7,12.5,40,17,0,50,1.5\n";
    write_text(dir / "stats.csv", text);
    return dir;
}

TEST(StatsCsv, ColumnsMatchTheRunsWriter) {
    // The plot reads the writer's first columns by name; later columns (both
    // forest-depth measures) are for other tools, so older stats.csv files still plot.
    std::string joined;
    for (auto c : kStatsColumns) joined += (joined.empty() ? "" : ",") + std::string(c);
    EXPECT_EQ(std::string(io::kStatsColumns).rfind(joined + ",", 0), 0u) << io::kStatsColumns;
}

TEST(StatsCsv, ReadsRowsByColumnName) {
    const fs::path dir = scratch("read");
    write_text(dir / "stats.csv", kHeader + "0,1.5,0.5,0.4,3,5,10,20,17,0,50,1\n1,2.5,1,0.9,3.5,6,11,22,17,1,100,2\n");
    const auto rows = read_stats_csv(dir / "stats.csv");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].generation, 1);
    EXPECT_DOUBLE_EQ(rows[1].best, 2.5);
    EXPECT_DOUBLE_EQ(rows[1].max_size, 22);
    EXPECT_DOUBLE_EQ(rows[1].wall_seconds, 2);
}

TEST(StatsCsv, ErrorsNameTheFileAndLine) {
    const fs::path dir = scratch("errors");
    const std::string f = (dir / "stats.csv").string();
    EXPECT_NE(input_error([&] { read_stats_csv(dir / "missing.csv"); }).find("missing.csv"), std::string::npos);
    write_text(f, "generation,best\n0,1\n");
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find(f + ":1: header has no column 'mean'"), std::string::npos);
    write_text(f, kHeader + "0,1,1,1,1,1,1,1,1,1,1,1\n1,1,x,1,1,1,1,1,1,1,1,1\n");
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find(f + ":3: column 'mean': 'x' is not a finite number"),
              std::string::npos);
    write_text(f, kHeader + "0,1,1,1,1,1,1,1,1,1,1,1\n1,inf,1,1,1,1,1,1,1,1,1,1\n");
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find(f + ":3: column 'best': 'inf' is not a finite number"),
              std::string::npos);
    write_text(f, kHeader + "0,1,1\n");
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find(f + ":2: 3 values, expected 12"), std::string::npos);
    write_text(f, kHeader);
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find("no data rows"), std::string::npos);
    write_text(f, kHeader + "0.5,1,1,1,1,1,1,1,1,1,1,1\n");
    EXPECT_NE(input_error([&] { read_stats_csv(f); }).find(":2: column 'generation'"), std::string::npos);
}

TEST(PlotRuns, GroupsRunFoldersByNameWithoutTheNumber) {
    EXPECT_EQ(configuration_name("runs/r1-001"), "r1");
    EXPECT_EQ(configuration_name("runs/r1_6legs-012/"), "r1_6legs");
    EXPECT_EQ(configuration_name("runs/plain"), "plain");
    EXPECT_EQ(configuration_name("a-b-3"), "a-b");
    const auto groups = group_runs({"x/r1-001", "x/r2-001", "x/r1-002"});
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].label, "r1");
    EXPECT_EQ(groups[0].runs.size(), 2u);
    EXPECT_EQ(groups[1].label, "r2");
}

TEST(PlotRuns, SummariesAverageRunsPerGeneration) {
    std::vector<StatsRow> a(2), b(1);
    a[0].generation = 0; a[0].best = 1; a[0].mean = 0;
    a[1].generation = 1; a[1].best = 5;
    b[0].generation = 0; b[0].best = 3; b[0].mean = 2;
    const auto s = summarise({a, b});
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].runs, 2);
    EXPECT_DOUBLE_EQ(s[0].best, 2);
    EXPECT_DOUBLE_EQ(s[0].best_sd, std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(s[0].mean, 1);
    EXPECT_EQ(s[1].runs, 1);   // run b stopped early
    EXPECT_DOUBLE_EQ(s[1].best, 5);
    EXPECT_DOUBLE_EQ(s[1].best_sd, 0);
}

TEST(PlotRuns, DrawsAnSvgWithOneSeriesPerConfiguration) {
    const fs::path dir = scratch("svg");
    const std::vector<fs::path> runs = {make_run(dir, "r1-001", 10, 1.0), make_run(dir, "r1-002", 8, 1.2),
                                        make_run(dir, "r2_6legs-001", 10, 0.7)};
    const fs::path out = dir / "fitness.svg";
    PlotOptions options;
    options.title = "R1 vs R2";
    plot_runs(runs, out, options);
    const std::string svg = read_text(out);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    for (const char* title : {"r1 (2 runs)", "r2_6legs", "best fitness", "mean fitness", "r1 (2 runs) max depth",
                              "r2_6legs mean size", "R1 vs R2"})
        EXPECT_NE(svg.find(title), std::string::npos) << title;
}

TEST(PlotRuns, DrawsAPngByExtension) {
    const fs::path dir = scratch("png");
    const fs::path out = dir / "fitness.png";
    plot_runs({make_run(dir, "a-001", 5, 1.0)}, out);
    const std::string png = read_text(out);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

// For papers: a PDF beside SVG and PNG, whole generations on the x axis even
// for a short run (no 0.5 ticks).
TEST(PlotRuns, DrawsAPdfWithWholeGenerationTicks) {
    const fs::path dir = scratch("pdf");
    plot_runs({make_run(dir, "a-001", 3, 1.0)}, dir / "fitness.pdf");
    EXPECT_EQ(read_text(dir / "fitness.pdf").substr(0, 5), "%PDF-");
    plot_runs({make_run(dir, "b-001", 3, 1.0)}, dir / "fitness.svg");
    const std::string svg = read_text(dir / "fitness.svg");
    EXPECT_EQ(svg.find(">0.5<"), std::string::npos) << "a tick between two generations";
    EXPECT_NE(svg.find(">1<"), std::string::npos);
}

TEST(PlotRuns, ReportsBadInputAndGnuplotFailures) {
    const fs::path dir = scratch("fail");
    const fs::path run = make_run(dir, "a-001", 3, 1.0);
    EXPECT_NE(input_error([&] { plot_runs({run}, dir / "x.jpg"); }).find("unsupported plot format '.jpg' (use .svg, .png or .pdf)"),
              std::string::npos);
    EXPECT_NE(input_error([&] { plot_runs({dir / "nothing-001"}, dir / "x.svg"); }).find("stats.csv"),
              std::string::npos);
    EXPECT_THROW(plot_runs({}, dir / "x.svg"), InputError);
    PlotOptions broken;
    broken.gnuplot = "false";   // exits 1 like a failing gnuplot
    EXPECT_THROW(plot_runs({run}, dir / "x.svg", broken), std::runtime_error);
    broken.gnuplot = "cic-no-such-gnuplot";
    try {
        plot_runs({run}, dir / "x.svg", broken);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot start 'cic-no-such-gnuplot'"), std::string::npos) << e.what();
    }
}

std::vector<TraceSample> sample_trace() {
    std::vector<TraceSample> rows;
    for (int k = 0; k < 40; ++k) {
        const double t = 0.05 * k;
        rows.push_back({t, {std::tanh(5 * std::sin(20 * t)), 0.25}, {0.5 * std::sin(3 * t), 0.2},
                        {0.4 * std::sin(3 * t - 0.5), 0.1}, {t, 0.5, 0.3}});
    }
    return rows;
}

TEST(TraceCsv, RoundTrips) {
    const fs::path dir = scratch("trace");
    const auto rows = sample_trace();
    write_trace_csv(dir / "t.csv", rows, {"leg+x-y.0", "hip"});
    EXPECT_EQ(read_text(dir / "t.csv").substr(0, 62), "t,out_leg+x-y.0,out_hip,cmd_leg+x-y.0,cmd_hip,angle_leg+x-y.0,");
    const TraceTable table = read_trace_csv(dir / "t.csv");
    EXPECT_EQ(table.joints, (std::vector<std::string>{"leg+x-y.0", "hip"}));
    ASSERT_EQ(table.rows.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_NEAR(table.rows[i].t, rows[i].t, 1e-6);
        EXPECT_NEAR(table.rows[i].outputs[0], rows[i].outputs[0], 1e-8);
        EXPECT_NEAR(table.rows[i].angles[1], rows[i].angles[1], 1e-8);
        EXPECT_NEAR(table.rows[i].centre[2], rows[i].centre[2], 1e-8);
    }
}

TEST(TraceCsv, RejectsBadInput) {
    const fs::path dir = scratch("trace_bad");
    EXPECT_THROW(write_trace_csv(dir / "t.csv", sample_trace(), {"a,b", "c"}), std::invalid_argument);
    EXPECT_THROW(write_trace_csv(dir / "t.csv", sample_trace(), {"only_one"}), std::invalid_argument);
    EXPECT_THROW(make_trace({sim::TraceRow{}}, {}), std::invalid_argument);
    const std::string f = (dir / "bad.csv").string();
    write_text(f, "t,out_a,cmd_a,angle_a,cx,cy,cz\n0,1,2,3,4,5,6\n0.1,1,2,oops,4,5,6\n");
    EXPECT_NE(input_error([&] { read_trace_csv(f); }).find(f + ":3: column 'angle_a': 'oops'"), std::string::npos);
    write_text(f, "t,out_a,cmd_b,angle_a,cx,cy,cz\n");
    EXPECT_NE(input_error([&] { read_trace_csv(f); }).find(f + ":1:"), std::string::npos);
}

TEST(PlotTrace, DrawsOutputsCommandsAndAnglesPerJoint) {
    const fs::path dir = scratch("trace_plot");
    write_trace_csv(dir / "t.csv", sample_trace(), {"leg+x-y.0", "hip"});
    plot_trace(dir / "t.csv", dir / "t.svg");
    const std::string svg = read_text(dir / "t.svg");
    for (const char* title : {"joint leg+x-y.0", "joint hip", "raw output", "angle [rad]",
                              "grey: raw output (right axis), blue: command, red dashed: angle"})
        EXPECT_NE(svg.find(title), std::string::npos) << title;
    // One legend for the figure (its title), none per panel.
    EXPECT_EQ(svg.find(">command<"), std::string::npos) << "a legend inside a panel";
    TracePlotOptions only;
    only.joints = {"hip"};
    only.from = 0.5;
    plot_trace(dir / "t.csv", dir / "hip.svg", only);
    EXPECT_EQ(read_text(dir / "hip.svg").find("joint leg+x-y.0"), std::string::npos);
    only.joints = {"knee"};
    EXPECT_NE(input_error([&] { plot_trace(dir / "t.csv", dir / "k.svg", only); }).find("no joint 'knee'"),
              std::string::npos);
}

} // namespace
