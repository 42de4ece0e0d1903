// One sweep task in its own run folder, resumable in place, and the study's
// index.csv, derived from the run folders alone (so any task, on any node,
// can rebuild it).
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <tuple>

#include <fmt/format.h>

#include "cic/run/provenance.hpp"
#include "cic/run/run.hpp"
#include "cic/run/run_history.hpp"
#include "cic/run/run_status.hpp"
#include "cic/run/settings_diff.hpp"
#include "cic/study/sweep.hpp"
#include "cic/core/error.hpp"
#include "cic/core/hash.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/xml.hpp"

namespace cic::study {
namespace {

namespace fs = std::filesystem;

// An exclusive flock on `path` for this object's lifetime (advisory: shared by
// every cic on every node that sees the file system, where flock works).
class FileLock {
public:
    FileLock(const fs::path& path, bool wait) {
        fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
        if (fd_ < 0) throw std::runtime_error("cannot open lock file " + path.string());
        if (::flock(fd_, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
            ::close(fd_);
            fd_ = -1;
        }
    }
    ~FileLock() {
        if (fd_ >= 0) ::close(fd_);   // closing releases the lock
    }
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    bool held() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
    return out;
}

// Generations, last best, best ever, evaluations and wall time (summed over
// sessions: the column restarts from 0 when a run is resumed) from a run's stats.csv.
void read_progress(const fs::path& stats, TaskState& st) {
    std::ifstream in(stats);
    std::string line;
    if (!std::getline(in, line)) return;
    const auto header = split(line);
    auto column = [&](const std::string& name) {
        for (std::size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return static_cast<long>(i);
        return -1L;
    };
    const long best = column("best"), evals = column("evaluations"), wall = column("wall_seconds");
    double session = 0, best_ever = -std::numeric_limits<double>::infinity();
    while (std::getline(in, line)) {
        const auto cells = split(line);
        if (best < 0 || evals < 0 || wall < 0 || static_cast<long>(cells.size()) <= std::max({best, evals, wall}))
            continue;
        ++st.generations;
        st.final_best = cells[static_cast<std::size_t>(best)];
        // Kept as written (17 digits), so the index holds the exact value.
        if (const double b = std::atof(st.final_best.c_str()); b > best_ever) {
            best_ever = b;
            st.best_ever = st.final_best;
        }
        st.evaluations = std::atol(cells[static_cast<std::size_t>(evals)].c_str());
        const double w = std::atof(cells[static_cast<std::size_t>(wall)].c_str());
        if (w < session) st.wall_seconds += session;   // a new session began
        session = w;
    }
    st.wall_seconds += session;
}

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

std::string to_string(TaskStatus s) {
    switch (s) {
    case TaskStatus::Pending: return "pending";
    case TaskStatus::Running: return "running";
    case TaskStatus::Done: return "done";
    case TaskStatus::Interrupted: return "interrupted";
    case TaskStatus::Failed: return "failed";
    case TaskStatus::Mismatched: return "mismatched";
    case TaskStatus::Extend: return "extend";
    }
    return "?";
}

TaskState task_state(const SweepPlan& plan, const SweepTask& task) {
    // A stored task is read from the store folder of its settings, whatever the link
    // says: before the link is made (dry runs), or while it still names the run of
    // settings the sweep no longer has.
    fs::path dir = plan.study / task.run_dir;
    const bool stored = !plan.store.empty() && (fs::is_symlink(dir) || !fs::exists(dir));
    if (stored) dir = store_dir(plan, task);
    TaskState st;
    bool extend = false;
    if (!fs::exists(dir / "settings.xml")) {
        st.status = fs::exists(dir / "failed.txt") ? TaskStatus::Failed : TaskStatus::Pending;
        return st;
    }
    if (!stored) {
        // A run folder of the study's own holds whatever ran there: if the sweep file or
        // its base settings were edited since, it is not this task's run, done or not.
        io::Settings ran;
        try {
            ran = io::read_settings(dir / "settings.xml");
        } catch (const std::exception& e) {
            st.status = TaskStatus::Mismatched;
            st.mismatch = {std::string("its settings.xml cannot be read: ") + e.what()};
            return st;
        }
        const io::Settings asked = plan.settings(task);
        st.mismatch = run::settings_differences(ran, asked, "the sweep");
        if (!st.mismatch.empty() && !run::extends(ran, asked)) {
            st.status = TaskStatus::Mismatched;
            return st;
        }
        extend = !st.mismatch.empty();   // a raised budget: the run goes on from its checkpoint
        st.mismatch.clear();
    }
    read_progress(dir / "stats.csv", st);
    if (fs::exists(dir / "failed.txt")) {
        st.status = TaskStatus::Failed;
    } else if (extend) {
        const FileLock probe(dir / ".lock", false);
        st.status = probe.held() ? TaskStatus::Extend : TaskStatus::Running;
    } else if (fs::exists(dir / "summary.txt")) {
        st.status = run::run_end_of_summary(io::xml::read_file(dir / "summary.txt")) == run::RunEnd::Interrupted
                        ? TaskStatus::Interrupted
                        : TaskStatus::Done;
    } else {
        // No summary: running if some process holds the task's lock, else killed.
        const FileLock probe(dir / ".lock", false);
        st.status = probe.held() ? TaskStatus::Interrupted : TaskStatus::Running;
    }
    return st;
}

namespace {

std::string mismatch_text(const SweepPlan& plan, const SweepTask& task, const TaskState& st) {
    std::string text = "  " + (plan.study / task.run_dir).string();
    for (const auto& d : st.mismatch) text += "\n    " + d;
    return text;
}

constexpr const char* kMismatchAdvice =
    "the sweep file or its base settings changed since these runs were made. Move the folders away (or delete "
    "them) to run the tasks with the new settings, or undo the edit; with a <store>, new studies keep every "
    "version of a run apart";

} // namespace

void refuse_mismatched_runs(const SweepPlan& plan) {
    std::string found;
    std::size_t n = 0;
    for (const SweepTask& t : plan.tasks())
        if (const TaskState st = task_state(plan, t); st.status == TaskStatus::Mismatched) {
            if (++n <= 5) found += "\n" + mismatch_text(plan, t, st);
        }
    if (n == 0) return;
    if (n > 5) found += fmt::format("\n  ... and {} more (cic sweep {} --dry-run lists them)", n - 5, plan.file.string());
    throw InputError(fmt::format("{} run folder{} of the study hold{} runs of other settings than the sweep asks:{}\n{}",
                                 n, n == 1 ? "" : "s", n == 1 ? "s" : "", found, kMismatchAdvice),
                     plan.file.string());
}

std::vector<fs::path> runs_outside_the_plan(const SweepPlan& plan) {
    std::set<fs::path> planned;
    for (const SweepTask& t : plan.tasks()) planned.insert(t.run_dir);
    std::vector<fs::path> out;
    std::error_code ec;
    const fs::path runs = plan.study / "runs";
    for (const auto& config : fs::directory_iterator(runs, ec)) {
        if (!config.is_directory(ec)) continue;
        for (const auto& run : fs::directory_iterator(config.path(), ec)) {
            const fs::path rel = fs::path("runs") / config.path().filename() / run.path().filename();
            if (!planned.count(rel) && fs::exists(run.path() / "settings.xml", ec)) out.push_back(plan.study / rel);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string index_text(const SweepPlan& plan, const std::vector<SweepTask>& tasks, IndexColumns columns) {
    const bool dry = columns == IndexColumns::WithTaskAndCommand;
    std::string text = dry ? "task,run_dir,config" : "run_dir,config";
    for (const auto& k : plan.varied_keys) text += "," + csv_cell(k);
    // best_ever last: it came after the others, and readers find columns by name.
    text += ",seed,status,final_best,generations,evaluations,wall_seconds,best_ever,commit,run_key";
    text += dry ? ",command\n" : "\n";
    for (const SweepTask& t : tasks) {
        const TaskState st = task_state(plan, t);
        const SweepConfig& cfg = plan.configs[t.config];
        if (dry) text += fmt::format("{},", t.index);
        text += csv_cell(t.run_dir.string()) + "," + csv_cell(cfg.name);
        for (const auto& [key, value] : cfg.varied) text += "," + csv_cell(value);
        text += fmt::format(",{},{},{},{},{},{:.3f},{},{},{}", t.seed, to_string(st.status), st.final_best,
                            st.generations, st.evaluations, st.wall_seconds, st.best_ever,
                            csv_cell(run::recorded_commit(plan.study / t.run_dir)), run_key(plan, t));
        if (dry) text += "," + csv_cell(plan.command_line(t));
        text += "\n";
    }
    return text;
}

void write_index(const SweepPlan& plan) {
    fs::create_directories(plan.study);
    const FileLock lock(plan.study / ".index.lock", true);
    io::xml::write_file_atomically(plan.study / "index.csv", index_text(plan, plan.tasks()));
}

namespace {

// A file key's value in a fingerprint: the file's bytes, not where it lies, as
// run::settings_differences compares them. A study run from another checkout
// (its robot file at another absolute path) finds its stored runs; a robot file
// edited after its runs does not. The path itself only when the file cannot be
// read (a store copied from a machine without it).
std::string path_fingerprint(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return path;
    return "bytes " + hex16(fnv1a_64(std::string(std::istreambuf_iterator<char>(in), {})));
}

std::string paths_fingerprint(const std::string& paths) {
    std::string out;
    std::istringstream items(paths);
    for (std::string item; items >> item;) out += (out.empty() ? "" : " ") + path_fingerprint(item);
    return out;
}

// The fingerprint of a run: cic's version and every key whose value differs
// from its default, but for those that change no result (the run's name,
// output folder, worker count, resume file). Keys at their defaults are left
// out, so that a key added to cic later (whose default keeps the old
// behaviour) does not change the fingerprint of the runs already stored; so
// are values that compute as the default (io::computes_as_default).
std::string run_fingerprint(const io::Settings& settings) {
    const io::Settings s = run::result_settings(settings);
    std::string text = std::string("cic ") + CIC_VERSION + "\n";
    for (const auto& k : io::settings_table())
        if (const std::string v = k.get(s); !io::computes_as_default(k, v))
            text += k.section + "." + k.key + "=" + (k.type == io::ValueType::Path       ? path_fingerprint(v)
                                                     : k.type == io::ValueType::PathList ? paths_fingerprint(v)
                                                                                         : v) +
                    "\n";
    return hex16(fnv1a_64(text));
}

// Fingerprint -> folder of every run in a store, from the settings.xml each
// holds: a store folder is found by what it ran, whatever name an older cic
// gave it. Read once per store and process.
const std::map<std::string, fs::path>& store_index(const fs::path& store) {
    static std::map<fs::path, std::map<std::string, fs::path>> cache;
    auto [it, fresh] = cache.try_emplace(store);
    if (fresh && fs::is_directory(store))
        for (const auto& e : fs::directory_iterator(store)) {
            if (!fs::exists(e.path() / "settings.xml")) continue;
            try {
                it->second.emplace(run_fingerprint(io::read_settings(e.path() / "settings.xml")), e.path());
            } catch (const std::exception&) {
                // not a run folder cic can read: never reused
            }
        }
    return it->second;
}

} // namespace

std::string run_key(const SweepPlan& plan, const SweepTask& task) { return run_fingerprint(plan.settings(task)); }

fs::path store_dir(const SweepPlan& plan, const SweepTask& task) {
    if (plan.store.empty()) throw std::logic_error("store_dir: the sweep has no <store>");
    const std::string key = run_key(plan, task);
    if (fs::exists(plan.store / key)) return plan.store / key;
    const auto& known = store_index(plan.store);
    if (auto it = known.find(key); it != known.end()) return it->second;
    return plan.store / key;
}

void link_to_store(const SweepPlan& plan, StoreLinks which) {
    if (plan.store.empty()) return;
    for (const SweepTask& task : plan.tasks()) {
        const fs::path link = plan.study / task.run_dir;
        const bool linked = fs::is_symlink(link);
        if (!linked && fs::exists(link)) continue;   // a run folder of its own (a study made before its store)
        const fs::path target = store_dir(plan, task);
        if (which == StoreLinks::StoredRunsOnly && !fs::exists(target / "settings.xml")) continue;
        fs::create_directories(target);
        if (linked && fs::exists(link) && fs::equivalent(link, target)) continue;
        // New, or the sweep's settings changed since the link was made (an edited sweep
        // or base file): point it at the run these settings make, never at the old one.
        // Replaced by rename, atomically, since other tasks of the study may look at it.
        fs::create_directories(link.parent_path());
        const fs::path fresh = link.string() + ".link-" + std::to_string(::getpid());
        fs::remove(fresh);
        fs::create_directory_symlink(target.lexically_relative(link.parent_path()), fresh);
        fs::rename(fresh, link);
    }
}

namespace {

// A stored task whose budget the sweep has raised: its store folder (of the new
// settings) starts as a copy of the longest stored run it extends, so that it
// goes on from that run's checkpoint rather than from scratch. The shorter run
// stays as it was, for the studies that link to it.
void start_from_a_shorter_stored_run(const SweepPlan& plan, const SweepTask& task, const fs::path& target) {
    if (plan.store.empty() || fs::exists(target / "settings.xml") || !fs::is_directory(plan.store)) return;
    const io::Settings asked = plan.settings(task);
    fs::path longest;
    std::tuple<int, long, long> longest_budget{-1, -1, -1};
    for (const auto& e : fs::directory_iterator(plan.store)) {
        const fs::path run = e.path();
        if (fs::equivalent(run, target) || !fs::exists(run / "population.xml") || fs::exists(run / "failed.txt"))
            continue;
        io::Settings ran;
        try {
            ran = io::read_settings(run / "settings.xml");
        } catch (const std::exception&) {
            continue;
        }
        if (!run::extends(ran, asked)) continue;
        const std::tuple<int, long, long> budget{ran.control.maximum_iterations, ran.gait.evaluations,
                                                 ran.map_elites.evaluations};
        if (budget > longest_budget) longest_budget = budget, longest = run;
    }
    if (longest.empty()) return;
    for (const auto& e : fs::directory_iterator(longest))
        if (e.path().filename() != ".lock")
            fs::copy(e.path(), target / e.path().filename(),
                     fs::copy_options::recursive | fs::copy_options::copy_symlinks | fs::copy_options::overwrite_existing);
}

} // namespace

int run_task(const SweepPlan& plan, const SweepTask& task, int workers, bool quiet, const std::string& executable) {
    const fs::path dir = plan.study / task.run_dir;
    link_to_store(plan);
    fs::create_directories(dir);
    const FileLock lock(dir / ".lock", false);
    if (!lock.held()) {
        if (!quiet) std::fprintf(stderr, "cic sweep: task %zu (%s) is running elsewhere; skipped\n", task.index, dir.c_str());
        return 0;
    }
    const TaskState state = task_state(plan, task);
    if (state.status == TaskStatus::Done) return 0;
    if (state.status == TaskStatus::Mismatched)
        throw InputError(fmt::format("task {} holds a run of other settings than the sweep asks:\n{}\n{}", task.index,
                                     mismatch_text(plan, task, state), kMismatchAdvice),
                         plan.file.string());

    if (!plan.store.empty()) start_from_a_shorter_stored_run(plan, task, fs::canonical(dir));
    std::vector<std::string> extra;
    if (workers > 0) extra.push_back("Experiment.workers=" + std::to_string(workers));
    extra.push_back("Experiment.name=s" + std::to_string(task.seed));
    // The checkpoint it goes on from, checked against the folder's history (run_history.hpp).
    const std::optional<run::ResumePoint> point =
        fs::exists(dir / "settings.xml") ? run::resume_point(dir) : std::nullopt;
    const bool resume = point.has_value();
    if (resume) extra.push_back("Control.populationXmlLoadFrom=" + point->file.string());

    run::PreparedRun prepared = run::prepare_run(plan.settings(task, extra));
    if (resume && prepared.resume) {
        prepared.resume->search_note.clear();   // a task goes on with its own settings, or a raised budget only
        run::check_agrees_with_folder(*prepared.resume, *point, dir);
        run::remove_stale_temporaries(dir);
    }
    fs::remove(dir / "failed.txt");
    if (!resume)   // a fresh start: clear what a run killed before its first checkpoint left
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().filename() != ".lock") fs::remove_all(e.path());
    {   // The settings it runs with now (an extended task: the raised budget).
        io::Settings stored = prepared.settings;
        stored.control.population_load_from.clear();
        io::xml::write_file_atomically(dir / "settings.xml", io::write_settings(stored));
    }
    {   // Each session of the run (a fresh start or a resume, on whichever node) says where it came from.
        const std::string command = fmt::format("cic sweep {} --task {} ({}, seed {})", plan.file.string(), task.index,
                                                plan.configs[task.config].name, task.seed);
        std::ofstream(dir / "run.log", resume ? std::ios::app : std::ios::trunc)
            << (resume ? "resumed in place from " + point->file.lexically_relative(dir).string() + "\n" +
                             (point->note.empty() ? "" : point->note + "\n")
                       : "")
            << run::run_log_head(command, std::chrono::system_clock::now());
    }
    run::RunOptions opt;
    opt.run_dir = dir;
    opt.quiet = quiet;
    opt.worker_executable = executable;
    opt.continue_in_place = resume;
    opt.resume_command = "cic sweep " + plan.file.string() + " (the task goes on from its checkpoint)";
    int rc = 1;
    try {
        rc = run::run_experiment(std::move(prepared), opt);
    } catch (const std::exception& e) {
        io::xml::write_file_atomically(dir / "failed.txt", std::string(e.what()) + "\n");
        write_index(plan);
        throw;
    }
    write_index(plan);
    return rc;
}

} // namespace cic::study
