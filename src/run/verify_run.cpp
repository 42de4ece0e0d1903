// `cic verify RUN` (verify_run.hpp).
#include "cic/run/verify_run.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/report/verify.hpp"
#include "cic/run/run_history.hpp"
#include "cic/search/search.hpp"

namespace cic::run {

namespace fs = std::filesystem;

int verify_run(const fs::path& run_dir, bool quiet) {
    const fs::path dir = fs::absolute(run_dir);
    const fs::path settings_file = dir / "settings.xml";
    std::error_code ec;
    if (!fs::is_directory(dir, ec) && !ec) throw InputError("no such run folder", dir.string());
    int disagreements = 0;
    auto disagree = [&](const std::string& line) {
        ++disagreements;
        std::printf("mismatch: %s\n", line.c_str());
    };
    std::optional<ResumePoint> point;
    try {
        point = resume_point(dir);
    } catch (const InputError& e) {   // the folder disagrees with itself: said, and population.xml checked alone
        if (!fs::is_regular_file(dir / "population.xml", ec)) throw;
        disagree(e.what());
        point = ResumePoint{dir / "population.xml", -1, {}};
    }
    if (!fs::is_regular_file(settings_file, ec)) throw InputError("not a run folder (no settings.xml)", dir.string());
    if (!point) throw InputError("the run has written no checkpoint yet: nothing to verify", dir.string());
    const std::string file = point->file.string();
    if (!quiet && !point->note.empty()) std::fprintf(stderr, "cic verify: %s\n", point->note.c_str());
    const io::Settings s = io::read_settings(settings_file);
    const search::SearchKind& kind = search::search_of(s);
    try {   // a checkpoint its search refuses (a gait history that does not replay) is said, and replayed still
        const std::unique_ptr<search::Checkpoint> c = search::load_checkpoint(kind, s, file);
        check_agrees_with_folder(*c, *point, dir);
    } catch (const InputError& e) {
        disagree(e.what());
    }
    if (const std::string problem = report::handover_problem(s, file); !problem.empty()) disagree(problem);
    std::size_t checked = 0;
    report::replay_all(s, file, [&](const report::ReplayCheck& check) {
        ++checked;
        if (!check.agrees()) disagree(report::mismatch_text(check, file));
        if (!quiet) std::fprintf(stderr, "\rcic verify: %zu replayed", checked);
    });
    if (!quiet) std::fprintf(stderr, "\n");
    std::printf("%s: %zu stored value%s replayed, %d disagreement%s\n", file.c_str(), checked,
                checked == 1 ? "" : "s", disagreements, disagreements == 1 ? "" : "s");
    return disagreements == 0 ? 0 : 1;
}

} // namespace cic::run
