// `cic sweep FILE --status`: where a study stands, from its run folders alone
// (so it works the same on a local study and on one Slurm runs elsewhere).
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "cic/study/sweep.hpp"
#include "cic/study/sweep_runner.hpp"

namespace cic::study {
namespace {

std::string duration(double seconds) {
    if (seconds < 10) return fmt::format("{:.1f} s", seconds);
    if (seconds < 90) return fmt::format("{:.0f} s", seconds);
    if (seconds < 5400) return fmt::format("{:.0f} min", seconds / 60);
    return fmt::format("{:.1f} h", seconds / 3600);
}

} // namespace

int print_status(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs) {
    std::map<TaskStatus, int> count;
    std::vector<std::string> failed;
    double done_seconds = 0, running_seconds = 0;
    for (const SweepTask& t : tasks) {
        const TaskState st = task_state(plan, t);
        ++count[st.status];
        if (st.status == TaskStatus::Done) done_seconds += st.wall_seconds;
        if (st.status == TaskStatus::Running) running_seconds += st.wall_seconds;
        if (st.status == TaskStatus::Failed || st.status == TaskStatus::Mismatched)
            failed.push_back(fmt::format("{} ({})", t.run_dir.string(), to_string(st.status)));
    }
    const int done = count[TaskStatus::Done];
    const int running = count[TaskStatus::Running];
    // Runs still to start (or to continue, after an interruption or a raised budget).
    const int waiting = count[TaskStatus::Pending] + count[TaskStatus::Interrupted] + count[TaskStatus::Extend];
    fmt::print("study {}: {} runs{}\n", plan.study.string(), tasks.size(),
               tasks.size() != plan.tasks().size() ? " (the ones --config selects)" : "");
    std::string line;
    for (const TaskStatus status : {TaskStatus::Done, TaskStatus::Running, TaskStatus::Pending, TaskStatus::Interrupted,
                                    TaskStatus::Extend, TaskStatus::Failed, TaskStatus::Mismatched})
        if (count[status] > 0) line += fmt::format("{}{} {}", line.empty() ? "" : ", ", count[status], to_string(status));
    fmt::print("{}\n", line);
    for (const auto& f : failed) fmt::print("  not run: {}\n", f);
    if (done == 0) {
        fmt::print("time left: unknown until a run has finished\n");
    } else if (waiting + running == 0) {
        fmt::print("time left: none (every run that can run has finished)\n");
    } else {
        // The finished runs' mean time for every run still to go, `jobs` at a
        // time; a running run is counted with the time it has had already.
        const double mean = done_seconds / done;
        const double left = std::max(0.0, (waiting + running) * mean - running_seconds) / std::max(1, jobs);
        fmt::print("time left: about {} ({} to go, {} at a time, {} per finished run)\n", duration(left),
                   waiting + running, std::max(1, jobs), duration(mean));
    }
    return 0;
}

} // namespace cic::study
