// A run folder's history, checked before a resume goes on (run_history.hpp).
#include "cic/run/run_history.hpp"

#include <signal.h>
#include <sys/types.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/xml.hpp"
#include "cic/report/plot.hpp"

namespace cic::run {
namespace {

namespace fs = std::filesystem;

// N of a file named gen-NNNN.xml (at least four digits), or -1.
int checkpoint_number(const std::string& name) {
    if (name.size() < 12 || name.rfind("gen-", 0) != 0 || name.substr(name.size() - 4) != ".xml") return -1;
    const char* b = name.data() + 4;
    const char* e = name.data() + name.size() - 4;
    int n = -1;
    const auto [end, ec] = std::from_chars(b, e, n);
    return ec == std::errc() && end == e && n >= 0 ? n : -1;
}

// The run's checkpoints in populations/, by number. A folder that cannot be
// read is refused with its path (a loop of symbolic links, no permission).
std::vector<std::pair<int, fs::path>> checkpoints_in(const fs::path& dir) {
    std::vector<std::pair<int, fs::path>> out;
    const fs::path populations = dir / "populations";
    std::error_code ec;
    const fs::file_status st = fs::status(populations, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        throw InputError("cannot read the run's checkpoints: " + ec.message(), populations.string());
    if (!fs::exists(st)) return out;
    if (!fs::is_directory(st)) throw InputError("not a folder (a run keeps its checkpoints here)", populations.string());
    fs::directory_iterator it(populations, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const int n = checkpoint_number(it->path().filename().string());
        if (n < 0) continue;
        if (!it->is_regular_file(ec) || ec)
            throw InputError("a checkpoint that is not a regular file", it->path().string());
        out.emplace_back(n, it->path());
    }
    if (ec) throw InputError("cannot read the run's checkpoints: " + ec.message(), populations.string());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

std::optional<ResumePoint> resume_point(const fs::path& dir) {
    std::error_code ec;
    const fs::file_status st = fs::status(dir, ec);
    if (ec) throw InputError("cannot read the run folder: " + ec.message(), dir.string());
    if (!fs::is_directory(st)) throw InputError("not a run folder", dir.string());
    const fs::path latest = dir / "population.xml";
    const fs::file_status ls = fs::symlink_status(latest, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        throw InputError("cannot read: " + ec.message(), latest.string());
    const bool have_latest = fs::exists(ls);
    if (have_latest && !fs::is_regular_file(ls))
        throw InputError("the run's latest checkpoint is not a regular file (a folder, a link or a device?); "
                         "remove it, and the run goes on from its last populations/gen-NNNN.xml",
                         latest.string());
    const auto gens = checkpoints_in(dir);
    if (gens.empty()) {
        if (!have_latest) return std::nullopt;
        return ResumePoint{latest, -1, {}};
    }
    const auto& [n, last] = gens.back();
    if (!have_latest)
        return ResumePoint{last, n,
                           fmt::format("population.xml is missing: going on from the last checkpoint, {}",
                                       last.string())};
    const std::string text = io::xml::read_file(latest);
    if (text == io::xml::read_file(last)) return ResumePoint{latest, n, {}};
    // Stopped between writing gen-NNNN.xml and pointing population.xml at it:
    // population.xml is the checkpoint before, and the run goes on from the last.
    if (gens.size() >= 2 && text == io::xml::read_file(gens[gens.size() - 2].second))
        return ResumePoint{last, n,
                           fmt::format("population.xml is one checkpoint behind (the run stopped while saving): "
                                       "going on from the last checkpoint, {}",
                                       last.string())};
    throw InputError(fmt::format("differs from the run's last checkpoint, {}: a resume goes on from the last "
                                 "checkpoint and never rewrites the run's history (edited by hand? restore it: "
                                 "cp {} {})",
                                 last.string(), last.string(), latest.string()),
                     latest.string());
}

void check_agrees_with_folder(const search::Checkpoint& c, const ResumePoint& at, const fs::path& dir) {
    if (c.number < 0) return;   // a search that does not say where it stands
    if (at.number >= 0 && c.number != at.number)
        throw InputError(fmt::format("the checkpoint says it is number {} (its generation or batch) but it is the "
                                     "run's last checkpoint, populations/gen-{:04d}.xml: a resume never rewrites the "
                                     "run's history (edited by hand?)",
                                     c.number, at.number),
                         c.file);
    const fs::path stats = dir / "stats.csv";
    if (!fs::exists(stats)) return;   // a folder made by hand from a checkpoint: nothing to agree with
    const std::vector<report::StatsRow> rows = report::read_stats_csv(stats);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.generation == c.number; });
    if (row == rows.end())
        throw InputError(fmt::format("stats.csv has no row for generation {}, the checkpoint's ({}); its rows end at "
                                     "{}: the checkpoint and the run's statistics disagree",
                                     c.number, c.file, rows.back().generation),
                         stats.string());
    if (c.evaluations >= 0 && std::llround(row->evaluations) != c.evaluations)
        throw InputError(fmt::format("the checkpoint counts {} evaluations at generation {} but stats.csv's row {} "
                                     "counts {}: a resume never rewrites the run's history (edited by hand?)",
                                     c.evaluations, c.number, c.number, std::llround(row->evaluations)),
                         c.file);
}

void remove_stale_temporaries(const fs::path& dir) {
    // FILE.xml.tmp-PID or FILE.xml.link-PID of a process that is gone (a live
    // one, such as another run writing here, keeps its file).
    auto stale = [](const std::string& name) {
        for (const char* mark : {".xml.tmp-", ".xml.link-"}) {
            const std::size_t at = name.rfind(mark);
            if (at == std::string::npos) continue;
            const char* b = name.data() + at + std::strlen(mark);
            const char* e = name.data() + name.size();
            pid_t pid = 0;
            const auto [end, ec] = std::from_chars(b, e, pid);
            if (ec != std::errc() || end != e || pid <= 0) return false;
            return ::kill(pid, 0) != 0 && errno == ESRCH;
        }
        return false;
    };
    auto sweep = [&](const fs::path& folder) {
        std::error_code ec;
        for (fs::directory_iterator it(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
            std::error_code ignored;
            if (stale(it->path().filename().string()) && it->is_regular_file(ignored)) fs::remove(it->path(), ignored);
        }
    };
    sweep(dir);
    sweep(dir / "populations");
}

} // namespace cic::run
