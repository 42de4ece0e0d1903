// The tables of `cic compare` (cic/study/compare_table.hpp): summaries per
// configuration and pairwise tests, as Markdown and CSV.
#include "cic/study/compare_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/report/plot.hpp"
#include "cic/report/statistics.hpp"

namespace cic::study {
namespace {

namespace fs = std::filesystem;
namespace stats = report::stats;

struct ConfigResult {
    std::string config;
    std::vector<std::string> values;
    std::size_t runs = 0;       // runs used (after the status filter)
    std::size_t not_done = 0;   // of those, status other than done
    std::vector<double> sample; // the metric of the runs that have it
    std::optional<stats::Descriptive> desc;
    std::size_t reached = 0;    // runs whose best reached the threshold
    std::optional<double> gens_median, evals_median;
    std::optional<double> wall_mean;
};

struct PairResult {
    std::size_t a = 0, b = 0;
    bool tested = false;
    stats::MannWhitney mwu;
    double a12 = 0.5;
    stats::EffectMagnitude effect = stats::EffectMagnitude::Negligible;
    double p_holm = 1;
    bool significant = false;
    std::string verdict;
};

std::optional<double> metric_of(const report::StudyRun& run, const std::string& metric) {
    if (metric == "final_best") return run.final_best;
    if (metric == "best_ever") return run.best_ever;
    if (metric == "generations") return run.generations;
    if (metric == "evaluations") return run.evaluations;
    return run.wall_seconds;
}

// The median over every run, a run that never reached the threshold counting
// as infinitely late: infinite when half the runs or more never reached it.
std::optional<double> median_with_unreached(std::vector<double> reached, std::size_t runs) {
    if (runs == 0) return std::nullopt;
    std::sort(reached.begin(), reached.end());
    reached.resize(runs, std::numeric_limits<double>::infinity());
    const std::size_t n = reached.size();
    if (n % 2) return reached[n / 2];
    const double a = reached[n / 2 - 1], b = reached[n / 2];
    return std::isinf(a) || std::isinf(b) ? std::numeric_limits<double>::infinity() : (a + b) / 2;
}

// Numbers for people: whole numbers in full, others to 4 significant digits
// (one decimal from 1000 on, so that 12345.6 does not turn into 1.235e+04).
std::string num(double v) {
    if (!std::isfinite(v)) return fmt::format("{}", v);
    if (v == std::floor(v) && std::fabs(v) < 1e15) return fmt::format("{:.0f}", v);
    if (std::fabs(v) >= 1000) return fmt::format("{:.1f}", v);
    return fmt::format("{:.4g}", v);
}
std::string num(const std::optional<double>& v) { return v ? num(*v) : "-"; }
std::string pval(double p) { return fmt::format("{:.3g}", p); }

// Numbers for files: the shortest text that reads back to the same double.
std::string csv_num(const std::optional<double>& v) { return v ? fmt::format("{}", *v) : ""; }

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string md_cell(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

std::string md_row(const std::vector<std::string>& cells) {
    std::string row = "|";
    for (const auto& c : cells) row += " " + c + " |";
    return row + "\n";
}

std::vector<ConfigResult> summarise_configs(const report::StudyIndex& index, const CompareRequest& o) {
    std::vector<ConfigResult> out;
    for (const auto& group : report::group_study(index, o.include_unfinished)) {
        ConfigResult c;
        c.config = group.config;
        c.values = group.values;
        c.runs = group.runs.size();
        std::vector<double> gens, evals, walls;
        for (const report::StudyRun* run : group.runs) {
            if (run->status != "done") ++c.not_done;
            if (const auto v = metric_of(*run, o.metric)) c.sample.push_back(*v);
            if (run->wall_seconds) walls.push_back(*run->wall_seconds);
            if (o.has_threshold) {
                for (const report::StatsRow& row : report::read_study_run_stats(index, *run)) {
                    if (row.best >= o.threshold) {
                        ++c.reached;
                        gens.push_back(row.generation);
                        evals.push_back(row.evaluations);
                        break;
                    }
                }
            }
        }
        if (!c.sample.empty()) c.desc = stats::describe(c.sample);
        if (o.has_threshold) {
            c.gens_median = median_with_unreached(gens, c.runs);
            c.evals_median = median_with_unreached(evals, c.runs);
        }
        if (!walls.empty()) c.wall_mean = stats::describe(walls).mean;
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<PairResult> compare_pairs(const std::vector<ConfigResult>& configs, double alpha) {
    std::vector<PairResult> pairs;
    std::vector<double> p_values;
    for (std::size_t a = 0; a < configs.size(); ++a)
        for (std::size_t b = a + 1; b < configs.size(); ++b) {
            PairResult r;
            r.a = a;
            r.b = b;
            if (!configs[a].sample.empty() && !configs[b].sample.empty()) {
                r.tested = true;
                r.mwu = stats::mann_whitney_u(configs[a].sample, configs[b].sample);
                r.a12 = stats::vargha_delaney_a12(configs[a].sample, configs[b].sample);
                r.effect = stats::a12_magnitude(r.a12);
                p_values.push_back(r.mwu.p);
            }
            pairs.push_back(r);
        }
    const auto adjusted = stats::holm_adjust(p_values);
    std::size_t k = 0;
    for (auto& r : pairs) {
        if (!r.tested) {
            r.verdict = "not tested (a configuration has no values)";
            continue;
        }
        r.p_holm = adjusted[k++];
        r.significant = r.p_holm < alpha;
        if (!r.significant) {
            const std::size_t na = configs[r.a].sample.size(), nb = configs[r.b].sample.size();
            const double smallest = stats::smallest_attainable_p(na, nb);
            r.verdict = smallest >= alpha
                ? fmt::format("cannot be significant: with n = {} and {} the smallest attainable p is {:.3g} (alpha {})",
                              na, nb, smallest, alpha)
                : "no significant difference";
            continue;
        }
        const bool a_wins = r.a12 > 0.5;
        const std::string& winner = configs[a_wins ? r.a : r.b].config;
        const std::string& loser = configs[a_wins ? r.b : r.a].config;
        r.verdict = fmt::format("{} > {} (p_holm = {}, A12 = {:.2f} {})", winner, loser, pval(r.p_holm),
                                a_wins ? r.a12 : 1.0 - r.a12, stats::to_string(r.effect));
    }
    return pairs;
}

std::string markdown(const report::StudyIndex& index, const std::vector<ConfigResult>& configs,
                     const std::vector<PairResult>& pairs, const CompareRequest& o) {
    std::size_t used = 0, with_value = 0;
    for (const auto& c : configs) {
        used += c.runs;
        with_value += c.sample.size();
    }
    std::map<std::string, std::size_t> left_out;
    if (!o.include_unfinished)
        for (const auto& run : index.runs)
            if (run.status != "done") ++left_out[run.status];
    fs::path name = index.folder;
    if (!name.has_filename()) name = name.parent_path();

    std::string md = fmt::format("# Comparison of study {}\n\n", fs::weakly_canonical(name).filename().string());
    md += fmt::format("Study `{}`: {} configuration{}, {} of {} runs used ({}", index.folder.string(), configs.size(),
                      configs.size() == 1 ? "" : "s", used, index.runs.size(),
                      o.include_unfinished ? "every status" : "status done");
    if (!left_out.empty()) {
        std::vector<std::string> parts;
        for (const auto& [status, n] : left_out) parts.push_back(fmt::format("{} {}", n, status));
        md += fmt::format("; left out: {}", fmt::join(parts, ", "));
    }
    md += ").";
    if (with_value < used)
        md += fmt::format(" {} of them have no {} value and are left out of its statistics.", used - with_value,
                          o.metric);
    md += "\n";
    md += fmt::format("Metric: `{}`. Tests: two-sided Mann-Whitney U (exact or normal approximation as "
                      "scipy's method=\"auto\"), Vargha-Delaney A12, Holm-adjusted over the pairs, alpha = {}.\n\n",
                      o.metric, o.alpha);

    md += "## Configurations\n\n";
    const std::string th = o.has_threshold ? fmt::format("best >= {}", num(o.threshold)) : "threshold";
    std::vector<std::string> head = {"config"};
    for (const auto& k : index.varied_keys) head.push_back(md_cell(k));
    for (const auto& h :
         {std::string("n"), o.metric + " mean ± sd", std::string("median"), std::string("IQR [Q1, Q3]"),
          "generations to " + th + " (median of all runs)", "evaluations to " + th + " (median of all runs)",
          std::string("reached"),
          std::string("wall s (mean)")})
        head.push_back(h);
    md += md_row(head);
    md += md_row(std::vector<std::string>(head.size(), "---"));
    for (const auto& c : configs) {
        std::vector<std::string> row = {md_cell(c.config)};
        for (std::size_t k = 0; k < index.varied_keys.size(); ++k)
            row.push_back(md_cell(k < c.values.size() ? c.values[k] : ""));
        std::string n = std::to_string(c.sample.size());
        if (o.include_unfinished && c.not_done > 0) n += fmt::format(" ({} not done)", c.not_done);
        row.push_back(n);
        if (c.desc) {
            row.push_back(fmt::format("{} ± {}", num(c.desc->mean), num(c.desc->sd)));
            row.push_back(num(c.desc->median));
            row.push_back(fmt::format("{} [{}, {}]", num(c.desc->iqr), num(c.desc->q1), num(c.desc->q3)));
        } else {
            row.insert(row.end(), {"-", "-", "-"});
        }
        if (o.has_threshold) {
            // never: half the runs or more did not reach it (median over every run).
            const auto when = [](const std::optional<double>& v) {
                return v && std::isinf(*v) ? std::string("never") : num(v);
            };
            row.push_back(when(c.gens_median));
            row.push_back(when(c.evals_median));
            row.push_back(fmt::format("{}/{}", c.reached, c.runs));
        } else {
            row.insert(row.end(), {"-", "-", "-"});
        }
        row.push_back(num(c.wall_mean));
        md += md_row(row);
    }

    md += "\n## Pairs\n\n";
    if (pairs.empty()) {
        md += "Only one configuration: nothing to compare.\n";
        return md;
    }
    md += fmt::format("U is the statistic of A; A12 is the probability that a run of A has a higher {} value than a "
                      "run of B (ties count half).\n\n",
                      o.metric);
    md += md_row({"A", "B", "U", "p", "exact", "A12", "effect", "p_holm", "verdict"});
    md += md_row(std::vector<std::string>(9, "---"));
    for (const auto& r : pairs) {
        const std::string a = md_cell(configs[r.a].config), b = md_cell(configs[r.b].config);
        if (!r.tested) {
            md += md_row({a, b, "-", "-", "-", "-", "-", "-", md_cell(r.verdict)});
            continue;
        }
        md += md_row({a, b, num(r.mwu.u), pval(r.mwu.p), r.mwu.exact ? "yes" : "no", fmt::format("{:.2f}", r.a12),
                      std::string(stats::to_string(r.effect)), pval(r.p_holm), md_cell(r.verdict)});
    }
    return md;
}

std::string configs_csv(const report::StudyIndex& index, const std::vector<ConfigResult>& configs,
                        const CompareRequest& o) {
    std::vector<std::string> head = {"config"};
    for (const auto& k : index.varied_keys) head.push_back(csv_cell(k));
    for (const char* h : {"runs", "not_done", "n", "metric", "mean", "sd", "median", "q1", "q3", "iqr", "min", "max",
                          "threshold", "reached", "generations_to_threshold_median",
                          "evaluations_to_threshold_median", "wall_seconds_mean"})
        head.push_back(h);
    std::string text = fmt::format("{}\n", fmt::join(head, ","));
    for (const auto& c : configs) {
        std::vector<std::string> row = {csv_cell(c.config)};
        for (std::size_t k = 0; k < index.varied_keys.size(); ++k)
            row.push_back(csv_cell(k < c.values.size() ? c.values[k] : ""));
        row.push_back(std::to_string(c.runs));
        row.push_back(std::to_string(c.not_done));
        row.push_back(std::to_string(c.sample.size()));
        row.push_back(o.metric);
        auto d = [&](double stats::Descriptive::*f) -> std::optional<double> {
            if (!c.desc) return std::nullopt;
            return (*c.desc).*f;
        };
        for (auto f : {&stats::Descriptive::mean, &stats::Descriptive::sd, &stats::Descriptive::median,
                       &stats::Descriptive::q1, &stats::Descriptive::q3, &stats::Descriptive::iqr,
                       &stats::Descriptive::min, &stats::Descriptive::max})
            row.push_back(csv_num(d(f)));
        row.push_back(o.has_threshold ? csv_num(o.threshold) : "");
        row.push_back(o.has_threshold ? std::to_string(c.reached) : "");
        row.push_back(csv_num(c.gens_median));
        row.push_back(csv_num(c.evals_median));
        row.push_back(csv_num(c.wall_mean));
        text += fmt::format("{}\n", fmt::join(row, ","));
    }
    return text;
}

std::string pairs_csv(const std::vector<ConfigResult>& configs, const std::vector<PairResult>& pairs,
                      const CompareRequest& o) {
    std::string text = "a,b,metric,n_a,n_b,u,p,exact,a12,effect,p_holm,significant,verdict\n";
    for (const auto& r : pairs) {
        const auto& a = configs[r.a];
        const auto& b = configs[r.b];
        std::vector<std::string> row = {csv_cell(a.config), csv_cell(b.config), o.metric,
                                        std::to_string(a.sample.size()), std::to_string(b.sample.size())};
        if (r.tested) {
            row.insert(row.end(), {csv_num(r.mwu.u), csv_num(r.mwu.p), r.mwu.exact ? "true" : "false",
                                   csv_num(r.a12), std::string(stats::to_string(r.effect)), csv_num(r.p_holm),
                                   r.significant ? "true" : "false"});
        } else {
            row.insert(row.end(), {"", "", "", "", "", "", ""});
        }
        row.push_back(csv_cell(r.verdict));
        text += fmt::format("{}\n", fmt::join(row, ","));
    }
    return text;
}

} // namespace

namespace {

// The index and the two result lists every form of the comparison starts from.
struct Comparison {
    report::StudyIndex index;
    std::vector<ConfigResult> configs;
    std::vector<PairResult> pairs;
};

Comparison compare(const std::filesystem::path& study, const CompareRequest& o) {
    if (!(o.alpha > 0 && o.alpha < 1)) throw InputError(fmt::format("--alpha {} must be between 0 and 1", o.alpha));
    if (o.has_threshold && std::isnan(o.threshold)) throw InputError("--threshold must be a number");
    if (std::find(kCompareMetrics.begin(), kCompareMetrics.end(), o.metric) == kCompareMetrics.end())
        throw InputError(fmt::format("--metric {}: not one of {}", o.metric, fmt::join(kCompareMetrics, ", ")));
    if (!fs::is_directory(study))
        throw InputError("not a folder (give a study folder from cic sweep)", study.string());
    Comparison c{report::read_study_index(study), {}, {}};
    if (c.index.runs.empty()) throw InputError("the study index lists no runs", c.index.file.string());
    c.configs = summarise_configs(c.index, o);
    std::size_t used = 0;
    for (const auto& config : c.configs) used += config.runs;
    if (used == 0)
        throw InputError("no run of the study has status done yet (--include-unfinished uses the others)",
                         c.index.file.string());
    c.pairs = compare_pairs(c.configs, o.alpha);
    return c;
}

} // namespace

CompareTables compare_study(const std::filesystem::path& study, const CompareRequest& o) {
    const Comparison c = compare(study, o);
    return {markdown(c.index, c.configs, c.pairs, o), configs_csv(c.index, c.configs, o),
            pairs_csv(c.configs, c.pairs, o)};
}

CompareData compare_data(const std::filesystem::path& study, const CompareRequest& o) {
    const Comparison c = compare(study, o);
    CompareData d;
    d.metric = o.metric;
    d.alpha = o.alpha;
    for (const ConfigResult& r : c.configs) {
        CompareConfigRow row;
        row.config = r.config;
        if (r.desc) {
            row.n = r.desc->n;
            row.median = r.desc->median, row.q1 = r.desc->q1, row.q3 = r.desc->q3;
            row.mean = r.desc->mean, row.sd = r.desc->sd;
        }
        d.configs.push_back(row);
    }
    for (const PairResult& r : c.pairs) {
        ComparePairRow row;
        row.a = c.configs[r.a].config;
        row.b = c.configs[r.b].config;
        row.tested = r.tested;
        row.verdict = r.verdict;
        if (r.tested) {
            row.p = r.mwu.p, row.p_holm = r.p_holm, row.a12 = r.a12, row.significant = r.significant;
            row.effect = std::string(stats::to_string(r.effect));
            const auto ci = stats::a12_interval(c.configs[r.a].sample, c.configs[r.b].sample);
            row.a12_low = ci.low, row.a12_high = ci.high;
        }
        d.pairs.push_back(row);
    }
    return d;
}

} // namespace cic::study
