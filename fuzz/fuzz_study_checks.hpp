#pragma once
// What the sweep and study-index fuzz targets check, shared by the libFuzzer
// targets (fuzz/fuzz_sweep.cpp, fuzz/fuzz_index.cpp) and the regression test
// (tests/study/fuzz_study_regression_test.cpp). Same verdicts as fuzz_checks.hpp:
// a std::exception is a correct rejection; an accepted input must keep the
// reader's promises, else Verdict::Bug. These readers have no writer to round
// trip through, so the promises are checked instead.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include "cic/report/plot.hpp"
#include "cic/study/sweep.hpp"
#include "fuzz_checks.hpp"

namespace cic::fuzz {

// The folder a fuzzed sweep file stands in: it holds base.xml, the settings
// file the seeds name (<base>base.xml</base>).
inline const std::filesystem::path& sweep_folder() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / "cic-fuzz-sweep";
        std::filesystem::create_directories(d);
        std::ofstream(d / "base.xml") << "<settings><Experiment><type>symreg</type></Experiment></settings>\n";
        return d;
    }();
    return dir;
}

// Sweep files: parse_sweep; an accepted plan has uniquely named configurations,
// configurations x repeats tasks, distinct seeds within a configuration, and
// each task's overrides end with its seed.
inline Outcome check_sweep(std::string_view input) {
    study::SweepPlan plan;
    try {
        plan = study::parse_sweep(input, sweep_folder() / "s.xml", sweep_folder() / "study");
    } catch (const std::exception&) {
        return {};
    }
    if (plan.configs.empty()) return bug("sweep: accepted with no configuration");
    std::set<std::string> names;
    for (const auto& c : plan.configs)
        if (!names.insert(c.name).second) return bug("sweep: two configurations named " + c.name);
    // The per-task promises on studies of up to 20000 runs: listing a million
    // tasks (the reader's limit) takes seconds, past libFuzzer's timeout.
    if (plan.configs.size() * static_cast<std::size_t>(plan.repeats) > 20000) return {Verdict::Accepted, {}};
    const auto tasks = plan.tasks();
    if (tasks.size() != plan.configs.size() * static_cast<std::size_t>(plan.repeats))
        return bug("sweep: " + std::to_string(tasks.size()) + " tasks for " + std::to_string(plan.configs.size()) +
                   " configurations x " + std::to_string(plan.repeats) + " repeats");
    std::set<std::pair<std::size_t, std::uint64_t>> seeds;
    for (const auto& t : tasks) {
        if (!seeds.emplace(t.config, t.seed).second) return bug("sweep: a configuration runs seed " + std::to_string(t.seed) + " twice");
        const auto o = plan.overrides(t);
        if (o.empty() || o.back() != "Experiment.seed=" + std::to_string(t.seed))
            return bug("sweep: a task's overrides do not end with its seed");
        for (std::size_t i = 0; i + 1 < o.size(); ++i)
            if (o[i].rfind("Experiment.seed=", 0) == 0) return bug("sweep: a seed set outside <repeats>: " + o[i]);
    }
    return {Verdict::Accepted, {}};
}

// Study indexes: parse_study_index; every number an accepted index holds is
// finite, and grouping keeps every run (with the unfinished) in its configuration.
inline Outcome check_index(std::string_view input) {
    report::StudyIndex index;
    try {
        index = report::parse_study_index(input, "/fuzz-study");
    } catch (const std::exception&) {
        return {};
    }
    std::size_t grouped = 0;
    for (const auto& run : index.runs) {
        for (const auto* v : {&run.final_best, &run.best_ever, &run.generations, &run.evaluations, &run.wall_seconds})
            if (*v && !std::isfinite(**v)) return bug("index: a non-finite number was accepted at line " + std::to_string(run.line));
        if (run.values.size() != index.varied_keys.size()) return bug("index: a run has the wrong number of varied values");
    }
    for (const auto& g : report::group_study(index, true)) {
        for (const auto* r : g.runs)
            if (r->config != g.config) return bug("index: a run grouped under another configuration");
        grouped += g.runs.size();
    }
    if (grouped != index.runs.size()) return bug("index: grouping lost or added runs");
    return {Verdict::Accepted, {}};
}

} // namespace cic::fuzz
