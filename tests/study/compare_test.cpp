// `cic compare STUDY` and `cic plot STUDY` on hand-written study folders (index.csv
// plus stats.csv per run, as `cic sweep` leaves them): the index reader and its
// errors, the Markdown and CSV reports through the real binary, exit codes, and
// the per-configuration study plot.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cic/report/plot.hpp"
#include "cic/core/error.hpp"
#include "support/input_error.hpp"
#include "support/run_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;
using namespace cic::report;
using cic::testing::read_text;
using cic::testing::temp_dir;
using cic::testing::write_text;
using cic::testing::input_error;

const std::string kStatsHeader =
    "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,evaluations,wall_seconds,"
    "mean_depth_sum,max_depth_sum,mean_depth_max,max_depth_max,failed\n";
const std::string kIndexHeader =
    "run_dir,config,GP.tournament_size,GP.functions,seed,status,final_best,generations,evaluations,wall_seconds\n";

// A run folder whose stats.csv has one row per entry of `bests` (10 evaluations per generation).
void write_run(const fs::path& study, const std::string& run_dir, const std::vector<double>& bests) {
    const fs::path dir = study / run_dir;
    fs::create_directories(dir);
    std::string text = kStatsHeader;
    for (std::size_t g = 0; g < bests.size(); ++g)
        text += fmt::format("{},{},{},{},{},{},20,40,17,0,{},{},{},{},{},{},0\n", g, bests[g], bests[g] / 2,
                            bests[g] / 2, 2.0 + 0.5 * g, 3 + g, 10 * (g + 1), 1.5 * (g + 1), 4.0 + g, 6 + g,
                            2.0 + 0.5 * g, 3 + g);
    write_text(dir / "stats.csv", text);
}

struct FakeRun {
    std::string config;
    int tournament;
    int seed;
    std::string status;
    std::vector<double> bests;   // per generation; empty = no stats.csv, empty final_best
};

// Three configurations: tour3 beats tour5 everywhere, tour7 beats tour5, tour3
// and tour7 overlap. tour7's fifth run failed. "add,mul" needs CSV quoting.
std::vector<FakeRun> fake_runs() {
    return {
        {"tour3", 3, 1, "done", {0.5, 0.8, 0.91, 0.91, 0.91}},
        {"tour3", 3, 2, "done", {0.6, 0.9, 0.95, 0.95, 0.95}},
        {"tour3", 3, 3, "done", {0.4, 0.7, 0.8, 0.85, 0.88}},
        {"tour3", 3, 4, "done", {0.7, 0.92, 0.97, 0.97, 0.97}},
        {"tour3", 3, 5, "done", {0.5, 0.6, 0.93, 0.93, 0.93}},
        {"tour5", 5, 1, "done", {0.3, 0.5, 0.61}},
        {"tour5", 5, 2, "done", {0.3, 0.5, 0.72}},
        {"tour5", 5, 3, "done", {0.3, 0.5, 0.65}},
        {"tour5", 5, 4, "done", {0.3, 0.5, 0.70}},
        {"tour5", 5, 5, "done", {0.3, 0.5, 0.68}},
        {"tour7", 7, 1, "done", {0.5, 0.90}},
        {"tour7", 7, 2, "done", {0.5, 0.86}},
        {"tour7", 7, 3, "done", {0.5, 0.94}},
        {"tour7", 7, 4, "done", {0.5, 0.89}},
        {"tour7", 7, 5, "failed", {0.2}},
    };
}

fs::path make_study(const std::string& name) {
    const fs::path study = temp_dir("compare-" + name) / "study";
    fs::create_directories(study);
    std::string index = kIndexHeader;
    for (const auto& r : fake_runs()) {
        const std::string run_dir = fmt::format("runs/{}/s{}", r.config, r.seed);
        write_run(study, run_dir, r.bests);
        index += fmt::format("{},{},{},\"add,mul\",{},{},{},{},{},{}\n", run_dir, r.config, r.tournament, r.seed,
                             r.status, r.bests.back(), r.bests.size(), 10 * r.bests.size(),
                             12.5 * static_cast<double>(r.bests.size()));
    }
    write_text(study / "index.csv", index);
    return study;
}

struct Result {
    int rc = -1;
    std::string out, err;
};

// Runs `cic ARGS`; stdout and stderr apart.
Result cic(const std::string& args) {
    const fs::path dir = temp_dir("compare-run");
    const std::string cmd = "'" + cic::testing::cic_binary() + "' " + args + " > " + (dir / "out").string() +
                            " 2> " + (dir / "err").string();
    const int rc = std::system(cmd.c_str());
    Result r;
    r.rc = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    r.out = read_text(dir / "out");
    r.err = read_text(dir / "err");
    return r;
}

// --- the index reader -------------------------------------------------------

TEST(CompareIndex, ReadsColumnsByNameWithQuotedCells) {
    const fs::path study = make_study("index");
    const StudyIndex index = read_study_index(study);
    EXPECT_EQ(index.varied_keys, (std::vector<std::string>{"GP.tournament_size", "GP.functions"}));
    ASSERT_EQ(index.runs.size(), 15u);
    const StudyRun& r = index.runs[0];
    EXPECT_EQ(r.run_dir, "runs/tour3/s1");
    EXPECT_EQ(r.config, "tour3");
    EXPECT_EQ(r.values, (std::vector<std::string>{"3", "add,mul"}));
    EXPECT_EQ(r.seed, "1");
    EXPECT_EQ(r.status, "done");
    ASSERT_TRUE(r.final_best.has_value());
    EXPECT_DOUBLE_EQ(*r.final_best, 0.91);
    EXPECT_DOUBLE_EQ(*r.generations, 5);
    EXPECT_DOUBLE_EQ(*r.evaluations, 50);
    EXPECT_DOUBLE_EQ(*r.wall_seconds, 62.5);
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(index.run_path(r), study / "runs/tour3/s1");
    EXPECT_TRUE(is_study_folder(study));
    EXPECT_FALSE(is_study_folder(study / "runs/tour3/s1"));

    const auto groups = group_study(index, false);
    ASSERT_EQ(groups.size(), 3u);
    EXPECT_EQ(groups[2].config, "tour7");
    EXPECT_EQ(groups[2].runs.size(), 4u);   // the failed run is left out
    EXPECT_EQ(group_study(index, true)[2].runs.size(), 5u);

    // Empty cells (a pending run), a doubled quote, no varied keys, columns in another order.
    write_text(study / "index.csv",
               "config,run_dir,seed,status,final_best,generations,evaluations,wall_seconds\n"
               "\"say \"\"hi\"\"\",runs/a/s1,1,pending,,,,\n");
    const StudyIndex other = read_study_index(study);
    EXPECT_TRUE(other.varied_keys.empty());
    ASSERT_EQ(other.runs.size(), 1u);
    EXPECT_EQ(other.runs[0].config, "say \"hi\"");
    EXPECT_FALSE(other.runs[0].final_best.has_value());
    EXPECT_FALSE(other.runs[0].wall_seconds.has_value());
}

TEST(CompareIndex, ErrorsNameTheFileAndLine) {
    const fs::path study = make_study("index-errors");
    const std::string f = (study / "index.csv").string();
    const std::string row = "runs/a/s1,a,3,x,1,done,0.5,3,30,2.5\n";
    EXPECT_NE(input_error([&] { read_study_index(study / "nothing"); }).find("index.csv"), std::string::npos);
    write_text(f, "run_dir,config,seed,status,final_best,generations,evaluations\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":1: header has no column 'wall_seconds'"),
              std::string::npos);
    write_text(f, kIndexHeader + row + "runs/a/s2,a,3,x,2,done,0.5\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":3: 7 values, expected 10"), std::string::npos);
    write_text(f, kIndexHeader + "runs/a/s1,a,3,x,1,finished,0.5,3,30,2.5\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":2: column 'status': 'finished' is not one of"),
              std::string::npos);
    write_text(f, kIndexHeader + row + "runs/a/s2,a,3,x,2,done,high,3,30,2.5\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":3: column 'final_best': 'high' is not a finite number"),
              std::string::npos);
    // Was read, and printed as "inf ± -nan" by cic compare.
    for (const char* cell : {"inf", "-inf", "nan", "1e999"}) {
        write_text(f, kIndexHeader + row + "runs/a/s2,a,3,x,2,done," + cell + ",3,30,2.5\n");
        EXPECT_NE(input_error([&] { read_study_index(study); })
                      .find(f + ":3: column 'final_best': '" + cell + "' is not a finite number"),
                  std::string::npos)
            << cell;
    }
    write_text(f, kIndexHeader + row + "runs/a/s2,a,3,x,2,done,0.5,3,30,inf\n");
    const Result r = cic("compare " + study.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find(f + ":3: column 'wall_seconds': 'inf' is not a finite number"), std::string::npos) << r.err;
    write_text(f, kIndexHeader + "runs/a/s1,a,3,\"x,1,done,0.5,3,30,2.5\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":2: a quoted cell has no closing quote"),
              std::string::npos);
    write_text(f, kIndexHeader + ",a,3,x,1,done,0.5,3,30,2.5\n");
    EXPECT_NE(input_error([&] { read_study_index(study); }).find(f + ":2: column 'run_dir' is empty"),
              std::string::npos);
}

// --- cic compare ------------------------------------------------------------

TEST(CompareCommand, MarkdownReportsConfigurationsAndPairs) {
    const fs::path study = make_study("markdown");
    const Result r = cic("compare " + study.string() + " --threshold 0.9");
    ASSERT_EQ(r.rc, 0) << r.err;
    const std::string& md = r.out;
    EXPECT_NE(md.find("14 of 15 runs used (status done; left out: 1 failed)"), std::string::npos) << md;
    EXPECT_NE(md.find("| config | GP.tournament_size | GP.functions | n | final_best mean ± sd | median | IQR [Q1, Q3] |"
                      " generations to best >= 0.9 (median of all runs) | evaluations to best >= 0.9 (median of all runs) |"
                      " reached |"
                      " wall s (mean) |"),
              std::string::npos)
        << md;
    // tour3: mean 0.928, sd 0.03493 (n-1), median 0.93, Q1 0.91, Q3 0.95; best >= 0.9 first at
    // generations 2, 1, never, 1, 2: the median of all five runs is 2 (evaluations 30); wall 62.5 s each.
    EXPECT_NE(md.find("| tour3 | 3 | add,mul | 5 | 0.928 ± 0.03493 | 0.93 | 0.04 [0.91, 0.95] | 2 | 30 | 4/5 | "
                      "62.5 |"),
              std::string::npos)
        << md;
    // Half the runs or more never reached it: the median over all runs is "never".
    EXPECT_NE(md.find("| tour5 | 5 | add,mul | 5 | 0.672 ± 0.04324 | 0.68 | 0.05 [0.65, 0.7] | never | never | 0/5 | 37.5 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| tour7 | 7 | add,mul | 4 | 0.8975 ± 0.03304 | 0.895 | 0.0275 [0.8825, 0.91] | never | never | 2/4 |"
                      " 25 |"),
              std::string::npos)
        << md;
    // Exact p: 2/C(10,5) = 0.00794, 2/C(9,4) = 0.0159, and 0.286; Holm: x3, x2, x1.
    EXPECT_NE(md.find("| tour3 | tour5 | 25 | 0.00794 | yes | 1.00 | large | 0.0238 | "
                      "tour3 > tour5 (p_holm = 0.0238, A12 = 1.00 large) |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| tour3 | tour7 | 15 | 0.286 | yes | 0.75 | large | 0.286 | no significant difference |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| tour5 | tour7 | 0 | 0.0159 | yes | 0.00 | large | 0.0317 | "
                      "tour7 > tour5 (p_holm = 0.0317, A12 = 1.00 large) |"),
              std::string::npos)
        << md;
}

TEST(CompareCommand, WithoutThresholdShowsDashes) {
    const fs::path study = make_study("nothreshold");
    const Result r = cic("compare " + study.string());
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("| tour5 | 5 | add,mul | 5 | 0.672 ± 0.04324 | 0.68 | 0.05 [0.65, 0.7] | - | - | - | 37.5 |"),
              std::string::npos)
        << r.out;
    // A stricter alpha turns the two differences into none.
    const Result strict = cic("compare " + study.string() + " --alpha 0.01");
    ASSERT_EQ(strict.rc, 0) << strict.err;
    EXPECT_EQ(strict.out.find(" > tour5"), std::string::npos) << strict.out;
}

TEST(CompareCommand, IncludeUnfinishedCountsTheFailedRun) {
    const fs::path study = make_study("unfinished");
    const Result r = cic("compare " + study.string() + " --include-unfinished");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("15 of 15 runs used (every status)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| tour7 | 7 | add,mul | 5 (1 not done) |"), std::string::npos) << r.out;
}

TEST(CompareCommand, OtherMetricsFromTheIndex) {
    const fs::path study = make_study("metric");
    const Result r = cic("compare " + study.string() + " --metric generations");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("| generations mean ± sd |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| tour3 | 3 | add,mul | 5 | 5 ± 0 | 5 |"), std::string::npos) << r.out;
    EXPECT_EQ(cic("compare " + study.string() + " --metric fitness").rc, 2);
}

TEST(CompareCommand, OutWritesMarkdownAndCsvFiles) {
    const fs::path study = make_study("out");
    const fs::path prefix = study.parent_path() / "report";
    const Result r = cic("--quiet compare " + study.string() + " --threshold 0.9 --out " + prefix.string());
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_EQ(read_text(prefix.string() + ".md"), r.out);
    const std::string configs = read_text(prefix.string() + "-configs.csv");
    EXPECT_EQ(configs.substr(0, configs.find('\n')),
              "config,GP.tournament_size,GP.functions,runs,not_done,n,metric,mean,sd,median,q1,q3,iqr,min,max,"
              "threshold,reached,generations_to_threshold_median,evaluations_to_threshold_median,wall_seconds_mean");
    EXPECT_NE(configs.find("\ntour3,3,\"add,mul\",5,0,5,final_best,0.92799999999999"), std::string::npos)
        << configs;
    EXPECT_NE(configs.find(",0.9,4,2,30,62.5\n"), std::string::npos) << configs;
    EXPECT_NE(configs.find(",0.9,2,inf,inf,25\n"), std::string::npos) << configs;   // tour7: 2 of 4
    EXPECT_NE(configs.find("\ntour5,5,\"add,mul\",5,0,5,final_best,"), std::string::npos) << configs;
    const std::string pairs = read_text(prefix.string() + "-pairs.csv");
    EXPECT_EQ(pairs.substr(0, pairs.find('\n')), "a,b,metric,n_a,n_b,u,p,exact,a12,effect,p_holm,significant,verdict");
    EXPECT_NE(pairs.find("\ntour3,tour5,final_best,5,5,25,0.007936507936507936,true,1,large,0.023809523809523808,true,"
                         "\"tour3 > tour5 (p_holm = 0.0238, A12 = 1.00 large)\"\n"),
              std::string::npos)
        << pairs;
    EXPECT_NE(pairs.find("\ntour3,tour7,final_best,5,4,15,"), std::string::npos) << pairs;
    EXPECT_NE(pairs.find(",large,0.2857142857142857,false,no significant difference\n"), std::string::npos) << pairs;
    for (const auto& e : fs::directory_iterator(study.parent_path()))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// Three runs a side cannot give p < 0.05 whatever they hold (2 / C(6, 3) = 0.1):
// the verdict says so instead of "no significant difference".
TEST(CompareCommand, SaysWhenTheSampleCannotShowADifference) {
    const fs::path study = temp_dir("compare-small") / "study";
    std::string index = kIndexHeader;
    for (int seed = 1; seed <= 3; ++seed)
        for (const char* config : {"tour3", "tour5"}) {
            const std::string run_dir = fmt::format("runs/{}/s{}", config, seed);
            const double best = std::string(config) == "tour3" ? 0.9 + seed / 100.0 : 0.5 + seed / 100.0;
            write_run(study, run_dir, {best});
            index += fmt::format("{},{},{},\"add,mul\",{},done,{},1,10,1\n", run_dir, config, config[4] - '0', seed, best);
        }
    write_text(study / "index.csv", index);
    const Result r = cic("compare " + study.string());
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("| cannot be significant: with n = 3 and 3 the smallest attainable p is 0.1 (alpha 0.05) |"),
              std::string::npos)
        << r.out;
}

TEST(CompareCommand, BadInputExitsWithTwo) {
    const fs::path study = make_study("broken");
    const std::string f = (study / "index.csv").string();
    write_text(f, kIndexHeader + "runs/tour3/s1,tour3,3,x,1,done,0.91,5,50,62.5\nruns/tour3/s2,tour3,3,x,2\n");
    Result r = cic("compare " + study.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("cic compare: " + f + ":3: 5 values, expected 10"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;

    write_text(f, "run_dir,config,seed\n");
    r = cic("compare " + study.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find(f + ":1: header has no column"), std::string::npos) << r.err;

    EXPECT_EQ(cic("compare " + (study / "missing").string()).rc, 2);
    EXPECT_EQ(cic("compare").rc, 2);

    // Only failed runs: nothing to compare unless asked.
    write_text(f, kIndexHeader + "runs/tour3/s1,tour3,3,x,1,failed,0.91,5,50,62.5\n");
    r = cic("compare " + study.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("no run of the study has status done"), std::string::npos) << r.err;
    r = cic("compare " + study.string() + " --include-unfinished");
    EXPECT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("Only one configuration: nothing to compare."), std::string::npos) << r.out;

    // A done run without stats.csv cannot say when it reached a threshold.
    write_text(f, kIndexHeader + "runs/none/s1,none,3,x,1,done,0.91,5,50,62.5\n");
    r = cic("compare " + study.string() + " --threshold 0.5");
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find((study / "runs/none/s1/stats.csv").string()), std::string::npos) << r.err;

    EXPECT_EQ(cic("compare " + study.string() + " --alpha 1.5").rc, 2);
}

// --- cic plot STUDY -----------------------------------------------------------

TEST(ComparePlotStudy, BandsPerGenerationMeanOrMedian) {
    std::vector<StatsRow> a(2), b(2), c(1);
    a[0].generation = 0; a[0].best = 1; a[0].max_depth = 4;
    a[1].generation = 1; a[1].best = 5;
    b[0].generation = 0; b[0].best = 3; b[0].max_depth = 6;
    b[1].generation = 1; b[1].best = 7;
    c[0].generation = 0; c[0].best = 8; c[0].max_depth = 5;
    const auto mean = summarise_bands({a, b, c}, false);
    ASSERT_EQ(mean.size(), 2u);
    EXPECT_EQ(mean[0].runs, 3);
    EXPECT_DOUBLE_EQ(mean[0].best.centre, 4);
    EXPECT_DOUBLE_EQ(mean[0].best.low, 4 - std::sqrt(13.0));   // sd of 1, 3, 8
    EXPECT_DOUBLE_EQ(mean[0].best.high, 4 + std::sqrt(13.0));
    EXPECT_DOUBLE_EQ(mean[0].max_depth.centre, 5);
    EXPECT_EQ(mean[1].runs, 2);   // run c stopped early
    EXPECT_DOUBLE_EQ(mean[1].best.centre, 6);
    const auto median = summarise_bands({a, b, c}, true);
    EXPECT_DOUBLE_EQ(median[0].best.centre, 3);
    EXPECT_DOUBLE_EQ(median[0].best.low, 2);     // numpy: quantile([1, 3, 8], 0.25)
    EXPECT_DOUBLE_EQ(median[0].best.high, 5.5);
    EXPECT_DOUBLE_EQ(median[0].max_depth.high, 5.5);
}

TEST(ComparePlotStudy, DrawsOneColourPerConfiguration) {
    const fs::path study = make_study("plot");
    const fs::path out = study.parent_path() / "study.svg";
    StudyPlotOptions options;
    plot_study(study, out, options);
    const std::string svg = read_text(out);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    for (const char* title : {"tour3 (5 runs)", "tour5 (5 runs)", "tour7 (4 runs)", "best fitness (mean, +-1 sd band)",
                              "max depth (mean, +-1 sd band)", "mean depth", "study study"})
        EXPECT_NE(svg.find(title), std::string::npos) << title;
    options.median = true;
    options.include_unfinished = true;
    options.title = "Tournaments";
    plot_study(study, out, options);
    const std::string median = read_text(out);
    for (const char* title : {"tour7 (5 runs)", "best fitness (median, IQR band)", "Tournaments"})
        EXPECT_NE(median.find(title), std::string::npos) << title;
}

TEST(ComparePlotStudy, ThroughTheCommandLine) {
    const fs::path study = make_study("plot-cli");
    const fs::path out = study.parent_path() / "study.png";
    Result r = cic("plot " + study.string() + " --median --out " + out.string());
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_EQ(read_text(out).substr(1, 3), "PNG");
    EXPECT_NE(r.err.find("tour3: 5 run(s)"), std::string::npos) << r.err;
    // A run folder still plots as before; --median is for studies only.
    r = cic("plot " + (study / "runs/tour3/s1").string() + " --out " + out.string());
    EXPECT_EQ(r.rc, 0) << r.err;
    EXPECT_EQ(cic("plot " + (study / "runs/tour3/s1").string() + " --median --out " + out.string()).rc, 2);
    EXPECT_EQ(cic("plot " + study.string() + " " + (study / "runs/tour3/s1").string() + " --out " + out.string()).rc,
              2);
    // A broken index names its line.
    write_text(study / "index.csv", kIndexHeader + "runs/tour3/s1,tour3,3,x,1,maybe,0.91,5,50,62.5\n");
    r = cic("plot " + study.string() + " --out " + out.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find((study / "index.csv").string() + ":2:"), std::string::npos) << r.err;
}

// --- cic plot --by-evaluations STUDY... -----------------------------------------

// Rows at the given cumulative evaluation counts with the given generation bests.
std::vector<StatsRow> rows_at(const std::vector<double>& evaluations, const std::vector<double>& bests) {
    std::vector<StatsRow> rows(bests.size());
    for (std::size_t g = 0; g < bests.size(); ++g) {
        rows[g].generation = static_cast<int>(g);
        rows[g].evaluations = evaluations[g];
        rows[g].best = bests[g];
    }
    return rows;
}

TEST(ComparePlotByEvaluations, BestSoFarAtEvenlySpacedCosts) {
    // a: 50 per generation, loses its best at 150 (no elitism); b: 30 per
    // generation, stops at 60; c: its first generation all failed (NaN).
    const auto a = rows_at({50, 100, 150, 200}, {1, 4, 2, 3});
    const auto b = rows_at({30, 60}, {2, 6});
    const auto c = rows_at({50, 100, 150, 200}, {NAN, 1, 1, 5});
    const auto bands = summarise_by_evaluations({a, b, c}, true, 4);   // at 50, 100, 150, 200
    ASSERT_EQ(bands.size(), 4u);
    EXPECT_DOUBLE_EQ(bands[0].evaluations, 50);
    EXPECT_EQ(bands[0].runs, 2);                           // a: 1, b: 2 (c has no finite best yet)
    EXPECT_DOUBLE_EQ(bands[0].best_so_far.centre, 1.5);
    EXPECT_EQ(bands[1].runs, 3);                           // a: 4, b: 6 (kept after it stopped), c: 1
    EXPECT_DOUBLE_EQ(bands[1].best_so_far.centre, 4);
    EXPECT_DOUBLE_EQ(bands[2].best_so_far.centre, 4);      // a keeps 4 although its generation best fell to 2
    EXPECT_DOUBLE_EQ(bands[3].best_so_far.centre, 5);      // 4, 6, 5
    EXPECT_DOUBLE_EQ(bands[3].best_so_far.low, 4.5);
    EXPECT_DOUBLE_EQ(bands[3].best_so_far.high, 5.5);
    const auto mean = summarise_by_evaluations({a, b}, false, 2);   // at 100, 200
    ASSERT_EQ(mean.size(), 2u);
    EXPECT_DOUBLE_EQ(mean[1].best_so_far.centre, 5);
    EXPECT_DOUBLE_EQ(mean[1].best_so_far.low, 5 - std::sqrt(2.0));
    EXPECT_THROW(summarise_by_evaluations({a}, true, 0), std::invalid_argument);
    EXPECT_TRUE(summarise_by_evaluations({}, true, 10).empty());
}

TEST(ComparePlotByEvaluations, SeveralStudiesOnOnePanel) {
    const fs::path one = make_study("by-evaluations-a");
    const fs::path two = make_study("by-evaluations-b");
    const fs::path out = one.parent_path() / "curves.svg";
    EvaluationPlotOptions options;
    options.median = true;
    options.configs = {"tour3", "tour7"};
    plot_studies_by_evaluations({one, two}, out, options);
    const std::string svg = read_text(out);
    for (const char* label : {"study: tour3 (5 runs)", "study: tour7 (4 runs)", "evaluations",
                              "best fitness so far (median, IQR band)"})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
    EXPECT_EQ(svg.find("tour5"), std::string::npos);
    // One configuration per study: the curves are named by their study.
    options.configs = {"tour5"};
    options.title = "tour5 everywhere";
    plot_studies_by_evaluations({one}, out, options);
    EXPECT_NE(read_text(out).find("study (5 runs)"), std::string::npos);
    // A configuration a study lacks names the study's index and what it has.
    options.configs = {"tour9"};
    const std::string message = input_error([&] { plot_studies_by_evaluations({one}, out, options); });
    EXPECT_NE(message.find((one / "index.csv").string()), std::string::npos) << message;
    EXPECT_NE(message.find("it has: tour3, tour5, tour7"), std::string::npos) << message;
    EXPECT_THROW(plot_studies_by_evaluations({}, out, {}), InputError);
}

TEST(ComparePlotByEvaluations, ThroughTheCommandLine) {
    const fs::path one = make_study("by-evaluations-cli-a");
    const fs::path two = make_study("by-evaluations-cli-b");
    const fs::path out = one.parent_path() / "curves.svg";
    Result r = cic("plot --by-evaluations " + one.string() + " " + two.string() + " --config tour3 --median --out " +
                   out.string());
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(read_text(out).find("<svg"), std::string::npos);
    // A run folder is not a study; --config needs --by-evaluations; no trace.
    r = cic("plot --by-evaluations " + (one / "runs/tour3/s1").string() + " --out " + out.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("study folders"), std::string::npos) << r.err;
    EXPECT_EQ(cic("plot " + one.string() + " --config tour3 --out " + out.string()).rc, 2);
    EXPECT_EQ(cic("plot --by-evaluations --trace x.csv --out " + out.string()).rc, 2);
    r = cic("plot --by-evaluations " + one.string() + " --config nope --out " + out.string());
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("no configuration 'nope'"), std::string::npos) << r.err;
}

// best_ever (the best of any generation) is read when the index has it, and
// can be the metric; an index written before the column existed still reads.
TEST(CompareStudy, BestEverIsAMetricWhenTheIndexHasIt) {
    const fs::path study = make_study("best-ever");
    const StudyIndex old = read_study_index(study);
    EXPECT_FALSE(old.runs[0].best_ever.has_value());
    // Rewrite the index with the column: tour5's runs lost their best at the end.
    std::string index = kIndexHeader.substr(0, kIndexHeader.size() - 1) + ",best_ever\n";
    for (const auto& r : fake_runs()) {
        const std::string run_dir = fmt::format("runs/{}/s{}", r.config, r.seed);
        const double last = r.config == "tour5" ? 0.1 : r.bests.back();
        index += fmt::format("{},{},{},\"add,mul\",{},{},{},{},{},{},{}\n", run_dir, r.config, r.tournament, r.seed,
                             r.status, last, r.bests.size(), 10 * r.bests.size(),
                             12.5 * static_cast<double>(r.bests.size()),
                             *std::max_element(r.bests.begin(), r.bests.end()));
    }
    write_text(study / "index.csv", index);
    const StudyIndex with = read_study_index(study);
    ASSERT_TRUE(with.runs[5].best_ever.has_value());
    EXPECT_DOUBLE_EQ(*with.runs[5].best_ever, 0.61);
    EXPECT_DOUBLE_EQ(*with.runs[5].final_best, 0.1);
    EXPECT_TRUE(with.varied_keys == old.varied_keys);
    const Result r = cic("compare '" + study.string() + "' --metric best_ever");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("Metric: `best_ever`"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| 5 | 0.672 ± "), std::string::npos) << r.out;   // tour5: the mean of 0.61 .. 0.72
}

} // namespace
