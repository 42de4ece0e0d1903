// `cic report RUN|STUDY`: one self-contained HTML page. Its text holds every
// section and no reference outside the file; headless Chromium renders it to a
// screenshot that is not blank and its network log shows the page asked for
// nothing (a page with an outside image is caught by the same check).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

#include "cic/study/html_report.hpp"
#include "support/child_env.hpp"
#include "support/png_image.hpp"
#include "support/run_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using cic::testing::read_text;
using cic::testing::run_command;
using cic::testing::write_text;

std::string gait_settings() {
    return R"(<settings>
  <Experiment><type>gait</type><seed>4</seed><workers>2</workers></Experiment>
  <Gait><optimizer>cmaes</optimizer><evaluations>42</evaluations><populationSize>7</populationSize></Gait>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
</settings>
)";
}

class Report : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(cic::testing::temp_dir("report"));
        const auto run = cic::testing::run_settings(*dir_, "gait", gait_settings());
        ASSERT_EQ(run.rc, 0) << run.log;
        run_ = new fs::path(run.run);
        study_ = new fs::path(*dir_ / "study");
        write_text(*dir_ / "sweep.xml",
                   cic::testing::tiny_sweep_text("tiny", *study_, 6, 2, 2.5,
                                                 "<grid><vary key=\"GP.tournament_size\">2 3</vary></grid>", 2));
        ASSERT_EQ(run_command("--quiet sweep " + (*dir_ / "sweep.xml").string() + " --jobs 2", *dir_ / "sweep.log"), 0)
            << read_text(*dir_ / "sweep.log");
    }
    static void TearDownTestSuite() {
        fs::remove_all(*dir_);
        delete dir_, delete run_, delete study_;
    }
    static inline fs::path *dir_ = nullptr, *run_ = nullptr, *study_ = nullptr;
};

// Every src=, href= and url( target in the page, and any @import: only data
// URIs may be there. (A plain scan: std::regex recurses per character and the
// data URIs are long.)
std::vector<std::string> outside_references(const std::string& html) {
    std::string lower = html;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::vector<std::string> found;
    if (lower.find("@import") != std::string::npos) found.push_back("@import");
    for (const std::string key : {"src=", "href=", "url("}) {
        for (std::size_t at = lower.find(key); at != std::string::npos; at = lower.find(key, at + 1)) {
            std::size_t i = at + key.size();
            while (i < html.size() && (html[i] == ' ' || html[i] == '"' || html[i] == '\'')) ++i;
            const std::size_t end = html.find_first_of("\"' >)", i);
            const std::string target = html.substr(i, std::min(end, html.size()) - i);
            if (target.rfind("data:", 0) != 0) found.push_back(target);
        }
    }
    return found;
}

TEST(ReportPieces, Base64AndEscapesFollowTheStandards) {
    EXPECT_EQ(cic::study::base64(""), "");
    EXPECT_EQ(cic::study::base64("f"), "Zg==");
    EXPECT_EQ(cic::study::base64("fo"), "Zm8=");
    EXPECT_EQ(cic::study::base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(cic::study::base64(std::string("\xff\x00\x10", 3)), "/wAQ");
    EXPECT_EQ(cic::study::html_escape("<a href=\"x\">&'</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
    EXPECT_EQ(outside_references("<img src=\"data:image/png;base64,AA\"><a href='http://x'>"),
              std::vector<std::string>{"http://x"});
}

TEST_F(Report, ARunsPageHoldsEverySectionAndNothingOutside) {
    const fs::path out = *dir_ / "run.html";
    ASSERT_EQ(run_command("report " + run_->string() + " --out " + out.string(), *dir_ / "run.log"), 0)
        << read_text(*dir_ / "run.log");
    const std::string html = read_text(out);
    for (const char* part : {"<h2>Provenance</h2>", "commit: ", "<h2>Curves</h2>", "data:image/svg+xml;base64,",
                             "The best gait of each configuration", "cic assess: <b>", "<h2>Runs</h2>",
                             "found in generation"})
        EXPECT_NE(html.find(part), std::string::npos) << part;
    // A strip, or a sentence saying why there is none.
    EXPECT_TRUE(html.find("alt=\"strip of ") != std::string::npos || html.find("No strip: ") != std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(outside_references(html), std::vector<std::string>{});
    // Bad input: exit 2, nothing written.
    EXPECT_EQ(run_command("report " + (*dir_ / "nothing").string() + " --out " + (*dir_ / "x.html").string(),
                          *dir_ / "bad.log"),
              2);
    EXPECT_EQ(run_command("report " + run_->string() + " --out " + (*dir_ / "x.txt").string(), *dir_ / "bad.log"), 2);
    EXPECT_FALSE(fs::exists(*dir_ / "x.html"));
    EXPECT_FALSE(fs::exists(*dir_ / "x.txt"));
}

TEST_F(Report, AStudysPageHoldsTheCompareTableAndEachConfiguration) {
    const fs::path out = *dir_ / "study.html";
    ASSERT_EQ(run_command("report " + study_->string() + " --no-strips --out " + out.string(), *dir_ / "study.log"), 0)
        << read_text(*dir_ / "study.log");
    const std::string html = read_text(out);
    for (const char* part : {"<h2>Comparison</h2>", "<th>median</th>", "<th>IQR</th>", "<th>p (Holm)</th>",
                             "<th>A12 [95% interval]</th>", "Commits that made the study", "tournament_size=2 (best run",
                             "tournament_size=3 (best run", "No strip: none were asked for", "<h3>All paths</h3>",
                             "<td>runs/tournament_size=3/s2</td>"})
        EXPECT_NE(html.find(part), std::string::npos) << part;
    EXPECT_EQ(outside_references(html), std::vector<std::string>{});
}

// The URLs a page loaded in headless Chromium asked for (its network log's
// requests made on behalf of the file:// page; Chromium's own background
// requests have another isolation key).
std::set<std::string> requests_of(const fs::path& html, const fs::path& png, const fs::path& work) {
    const fs::path netlog = work / "netlog.json";
    const std::string cmd =
        cic::testing::without_leak_check() + "timeout 120 chromium --headless --no-sandbox --disable-gpu "
        "--hide-scrollbars --no-first-run --disable-background-networking --disable-component-update "
        "--disable-sync --disable-extensions --user-data-dir='" + (work / "profile").string() + "' --log-net-log='" +
        netlog.string() + "' --net-log-capture-mode=Everything --window-size=1200,2400 --screenshot='" + png.string() +
        "' 'file://" + fs::absolute(html).string() + "' > '" + (work / "chromium.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << read_text(work / "chromium.log");
    std::set<std::string> urls;
    std::istringstream log(read_text(netlog));
    for (std::string line; std::getline(log, line);) {
        if (line.find("\"network_isolation_key\":\"file://") == std::string::npos) continue;
        const std::size_t at = line.find("\"url\":\"");
        if (at == std::string::npos) continue;
        const std::size_t start = at + 7, end = line.find('"', start);
        const std::string u = line.substr(start, end - start);
        if (u.rfind("data:", 0) != 0) urls.insert(u);
    }
    return urls;
}

TEST_F(Report, RendersInHeadlessChromiumAndRequestsNothing) {
    if (std::system("command -v chromium >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium; scripts/install-deps.sh all adds it)";
    const fs::path out = *dir_ / "chromium.html";
    // Without strips: the figures cic draws itself, the same in every build (a sanitizer
    // build's offscreen viewer may leave the strips out; they are tested above).
    ASSERT_EQ(run_command("report " + study_->string() + " --no-strips --out " + out.string(),
                          *dir_ / "chromium-report.log"),
              0)
        << read_text(*dir_ / "chromium-report.log");
    const fs::path work = *dir_ / "chromium";
    fs::create_directories(work);
    const fs::path png = work / "page.png";
    EXPECT_EQ(requests_of(out, png, work), std::set<std::string>{});
    const auto image = cic::testing::read_png(png);
    ASSERT_EQ(image.width, 1200);
    std::set<int> colours;
    long inked = 0;
    for (int y = 0; y < image.height; y += 2)
        for (int x = 0; x < image.width; x += 2) {
            const auto c = image.at(x, y);
            colours.insert(c[0] << 16 | c[1] << 8 | c[2]);
            inked += c[0] + c[1] + c[2] < 600;
        }
    EXPECT_GT(colours.size(), 200u) << "a blank page";
    EXPECT_GT(inked, 600 * 1200 / 40) << "too little drawn: figures missing?";

    // The same check catches a page that asks for an outside image.
    const fs::path outside = work / "outside.html";
    write_text(outside, "<!DOCTYPE html><html><body><p>x</p><img src=\"http://example.invalid/x.png\"></body></html>\n");
    fs::remove_all(work / "profile");
    const auto urls = requests_of(outside, work / "outside.png", work);
    EXPECT_EQ(urls.count("http://example.invalid/x.png"), 1u);
}

} // namespace
