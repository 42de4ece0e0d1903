// The main job (cic/run/main_job.hpp): a settings file and its overrides
// become one run folder per seed.
#include "cic/run/main_job.hpp"

#include <fstream>
#include <iostream>

#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/run.hpp"
#include "cic/run/provenance.hpp"
#include "cic/run/run_folder.hpp"
#include "cic/run/self_path.hpp"

namespace cic::run {
namespace {

namespace fs = std::filesystem;

// "3-7" -> 3 4 5 6 7; "1,5,9" -> 1 5 9. Each seed is then checked by the settings table.
std::vector<std::string> expand_seeds(const std::string& text) {
    std::vector<std::string> out;
    auto number = [&](const std::string& t) {
        if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 19)
            throw InputError("--seeds: '" + t + "' is not a seed; expected A-B or a comma list such as 1,5,9");
        return std::stoull(t);
    };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        const std::size_t dash = item.find('-');
        if (dash == std::string::npos) {
            out.push_back(std::to_string(number(item)));
        } else {
            const auto a = number(item.substr(0, dash)), b = number(item.substr(dash + 1));
            if (b < a || b - a >= 100000)
                throw InputError("--seeds: range '" + item + "' must go up and hold at most 100000 seeds");
            for (auto v = a; v <= b; ++v) out.push_back(std::to_string(v));
        }
        start = comma + 1;
    }
    return out;
}


// The main job. Everything that can be wrong with the input is checked before
// anything is written.
int run_one(const MainJob& o, const std::string& seed) {
    std::vector<std::string> overrides = o.sets;
    if (!seed.empty()) overrides.push_back("Experiment.seed=" + seed);
    if (!o.output.empty()) overrides.push_back("Experiment.outputDirectory=" + o.output);
    io::Settings settings = io::load_settings(o.settings_file, overrides);
    settings.experiment.name = run_name(settings);
    PreparedRun prepared = prepare_run(std::move(settings));   // every input checked: nothing written yet
    const io::Settings& s = prepared.settings;
    const std::string effective = io::write_settings(s);

    const fs::path run_dir = create_run_folder(s.experiment.output_directory, s.experiment.name);
    io::xml::write_file_atomically(run_dir / "settings.xml", effective);
    {
        std::ofstream log(run_dir / "run.log");
        log << run_log_head(o.command_line, std::chrono::system_clock::now()) << "settings: " << o.settings_file
            << " (effective settings in settings.xml)\n";
        if (!log) throw std::runtime_error("cannot write " + (run_dir / "run.log").string());
    }
    if (!o.quiet) std::cerr << "cic: run folder " << run_dir.string() << '\n';

    RunOptions run;
    run.run_dir = run_dir;
    run.quiet = o.quiet;
    run.verbose = o.verbose;
    run.worker_executable = self_exec_path();
    return run_experiment(std::move(prepared), run);
}

} // namespace

int run_main_job(const MainJob& o) {
    if (o.seeds.empty()) return run_one(o, o.seed);
    if (!o.seed.empty()) throw InputError("--seed and --seeds: give one of them");
    const auto seeds = expand_seeds(o.seeds);
    {   // check the settings for every seed before the first run writes anything
        std::vector<std::string> overrides = o.sets;
        if (!o.output.empty()) overrides.push_back("Experiment.outputDirectory=" + o.output);
        for (const auto& sd : seeds) {
            overrides.push_back("Experiment.seed=" + sd);
            prepare_run(io::load_settings(o.settings_file, overrides));
            overrides.pop_back();
        }
    }
    int rc = 0;
    for (const auto& sd : seeds) {
        const int r = run_one(o, sd);
        if (r == 130 || r == 143) return r;   // interrupted: stop the sweep
        if (rc == 0) rc = r;
    }
    return rc;
}

} // namespace cic::run
