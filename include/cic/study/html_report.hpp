#pragma once
// `cic report RUN|STUDY --out report.html`: one self-contained page to share a
// run or a study. Every figure is inside the file (SVG and PNG as data URIs),
// nothing is fetched, no script runs: provenance, the compare table (studies),
// the curves, for each configuration the best gait's strip, path and `assess`
// verdict, the MAP-Elites heatmaps where there are archives, and a table of
// runs.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cic::study {

struct ReportOptions {
    std::string gnuplot = "gnuplot";
    std::string metric = "final_best";   // the compare table's (kCompareMetrics)
    bool include_unfinished = false;
    // Writes a strip of the run's best gait at these seconds to the PNG, or
    // returns why it cannot (e.g. a build without the viewer); empty = done.
    // Without it the page says why there is none: no_strip_reason.
    std::function<std::string(const std::filesystem::path& run, const std::vector<double>& times,
                              const std::filesystem::path& png)>
        strip;
    std::string no_strip_reason = "this cic was built without the viewer (CIC_WITH_VIEWER), which draws strips";
};

// The page's text. Throws cic::InputError for a folder that is neither a run
// folder (settings.xml and stats.csv) nor a study folder (index.csv), and for
// a study without a done run.
std::string report_html(const std::filesystem::path& run_or_study, const ReportOptions& options = {});

// Standard base64 (RFC 4648, with padding), for data URIs.
std::string base64(const std::string& bytes);
// Text with &, <, >, " and ' escaped for HTML.
std::string html_escape(const std::string& text);

} // namespace cic::study
