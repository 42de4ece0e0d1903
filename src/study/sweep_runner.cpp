// Running a study (cic/study/sweep_runner.hpp): N tasks at a time as child
// processes, a dry run, a Slurm job array, and the --config selection.
#include "cic/study/sweep_runner.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <map>
#include <regex>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/core/shell_words.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/run/settings_diff.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/run.hpp"
#include "cic/run/self_path.hpp"

namespace cic::study {
namespace {

namespace fs = std::filesystem;

volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void on_sweep_signal(int sig) {
    if (g_stop_signal == 0) g_stop_signal = sig;
}

// `program`: self_path() where the command is shown or written down,
// self_exec_path() where it is run.
std::vector<std::string> task_argv(const SweepPlan& plan, const SweepTask& t, int workers,
                                   const std::string& program = run::self_path()) {
    return {program, "--quiet",  "sweep", plan.file.string(), "--task", std::to_string(t.index), "--workers",
            std::to_string(workers), "--output", plan.study.string()};
}

} // namespace

// Loads and checks the settings of every configuration (seeds change no input)
// before anything is written; a refusal names the line that defines the
// configuration. Two configurations that would run the same settings are
// refused too, naming both: they would only repeat each other's runs.
void check_every_configuration(const SweepPlan& plan) {
    std::vector<bool> seen(plan.configs.size());
    std::map<std::string, std::size_t> by_settings;   // every key's value, seed aside -> configuration
    for (const SweepTask& t : plan.tasks()) {
        if (seen[t.config]) continue;
        seen[t.config] = true;
        const SweepConfig& config = plan.configs[t.config];
        io::Settings settings;
        try {
            settings = plan.settings(t);
            run::prepare_run(settings);
        } catch (const InputError& e) {
            throw InputError(fmt::format("configuration {}: {}", config.name, e.what()), plan.file.string(),
                             config.line);
        }
        settings = run::result_settings(settings);
        settings.experiment.seed = 0;
        std::string text;
        for (const auto& k : io::settings_table()) text += k.section + "." + k.key + "=" + k.get(settings) + "\n";
        if (auto [it, fresh] = by_settings.emplace(text, t.config); !fresh) {
            const SweepConfig& first = plan.configs[it->second];
            throw InputError(fmt::format("configurations {} (line {}) and {} would run the same settings; remove "
                                         "one, or make them differ",
                                         first.name, first.line, config.name),
                             plan.file.string(), config.line);
        }
    }
}

// The tasks --config selects, in plan order: every task when none is named. An
// unknown name is refused with the names the sweep has.
std::vector<SweepTask> selected_tasks(const SweepPlan& plan, const std::vector<std::string>& names) {
    std::vector<bool> wanted(plan.configs.size(), names.empty());
    for (const auto& n : names) {
        std::size_t i = 0;
        while (i < plan.configs.size() && plan.configs[i].name != n) ++i;
        if (i == plan.configs.size()) {
            std::string allowed;
            for (const auto& c : plan.configs) allowed += (allowed.empty() ? "" : ", ") + c.name;
            throw InputError(fmt::format("--config {}: the sweep has no such configuration (it has: {})", n, allowed),
                             plan.file.string());
        }
        wanted[i] = true;
    }
    std::vector<SweepTask> out;
    for (const SweepTask& t : plan.tasks())
        if (wanted[t.config]) out.push_back(t);
    return out;
}

int dry_run(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int workers, DryRunFormat format) {
    if (format == DryRunFormat::Csv) {   // for programs: index.csv's columns, nothing else on stdout
        fmt::print("{}", index_text(plan, tasks, IndexColumns::WithTaskAndCommand));
        return 0;
    }
    fmt::print("sweep {} ({}): {} configurations x {} repeats = {} runs; base {}\nstudy {}\n", plan.name,
               plan.file.string(), plan.configs.size(), plan.repeats, plan.tasks().size(), plan.base.string(),
               plan.study.string());
    if (!plan.store.empty()) fmt::print("run store {} (runs another study has done are reused)\n", plan.store.string());
    if (tasks.size() != plan.tasks().size()) fmt::print("listed: the {} runs --config selects\n", tasks.size());
    std::map<std::string, int> counts;
    for (const SweepTask& t : tasks) {
        const TaskState state = task_state(plan, t);
        const TaskStatus st = state.status;
        ++counts[to_string(st)];
        fmt::print("{:>5} {:<12} {} key={} {}\n", t.index, to_string(st), t.run_dir.string(), run_key(plan, t),
                   st == TaskStatus::Done ? std::string("(skipped)") : plan.command_line(t));
        for (const auto& d : state.mismatch) fmt::print("{:>5} {:<12}   {}\n", "", "", d);
    }
    std::string summary;
    for (const auto& [k, n] : counts) summary += fmt::format("{}{} {}", summary.empty() ? "" : ", ", n, k);
    fmt::print("{}; {} worker process{} per run\n", summary, workers, workers == 1 ? "" : "es");
    return 0;
}

void check_slurm_options(const SlurmOptions& o) {
    auto refuse = [](const std::string& option, const std::string& value, const std::string& takes) {
        throw InputError(fmt::format("--slurm-{} \"{}\": {}", option, value, takes));
    };
    static const std::regex name("[A-Za-z0-9_.+-]+");
    static const std::regex time("[0-9]+(:[0-9]{1,2}){0,2}|[0-9]+-[0-9]{1,2}(:[0-9]{1,2}){0,2}");
    static const std::regex mem("[0-9]+[KMGT]?");
    if (!o.partition.empty() && !std::regex_match(o.partition, name))
        refuse("partition", o.partition, "a partition name (letters, digits, _ . + -)");
    if (!o.time.empty() && !std::regex_match(o.time, time))
        refuse("time", o.time, "a time limit: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS");
    if (!o.mem.empty() && !std::regex_match(o.mem, mem)) refuse("mem", o.mem, "memory per node: N, NK, NM, NG or NT");
    if (!o.account.empty() && !std::regex_match(o.account, name))
        refuse("account", o.account, "an account name (letters, digits, _ . + -)");
    for (const auto& e : o.extra)
        if (e.size() < 2 || e[0] != '-' || e.find_first_of("\n\r") != std::string::npos)
            throw InputError("--sbatch \"" + e + "\": one sbatch option on one line, e.g. --qos=long");
}

int write_slurm_script(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs, int workers,
                       const SlurmOptions& slurm) {
    check_slurm_options(slurm);
    std::string cluster;   // the options the cluster asks for, as given
    if (!slurm.partition.empty()) cluster += "#SBATCH --partition=" + slurm.partition + "\n";
    if (!slurm.time.empty()) cluster += "#SBATCH --time=" + slurm.time + "\n";
    if (!slurm.mem.empty()) cluster += "#SBATCH --mem=" + slurm.mem + "\n";
    if (!slurm.account.empty()) cluster += "#SBATCH --account=" + slurm.account + "\n";
    for (const auto& e : slurm.extra) cluster += "#SBATCH " + e + "\n";
    // Array ids are the plan's task indices, so a --config selection is a list of them.
    std::string ids = fmt::format("0-{}", plan.tasks().size() - 1);
    if (tasks.size() != plan.tasks().size()) {
        ids.clear();
        for (const SweepTask& t : tasks) ids += (ids.empty() ? "" : ",") + std::to_string(t.index);
    }
    fs::create_directories(plan.study / "slurm");
    std::vector<std::string> argv = task_argv(plan, tasks.front(), workers);
    argv[5] = "\"$SLURM_ARRAY_TASK_ID\"";
    std::string command = shell_words({argv.begin(), argv.begin() + 5}) + " " + argv[5] + " " +
                          shell_words({argv.begin() + 6, argv.end()});
    const std::string script = fmt::format(
        "#!/bin/bash\n"
        "# Slurm job array for the cic study {name}: one array task per run.\n"
        "# Made by `cic sweep {file} --slurm`. Submit with: sbatch {script}\n"
        "# Every task runs the same resumable command: a requeued or preempted task\n"
        "# resumes from its checkpoint. cic treats SIGTERM like Ctrl-C: it finishes\n"
        "# the generation, writes the checkpoint and exits 143.\n"
        "#SBATCH --job-name=cic-{name}\n"
        "#SBATCH --array={ids}%{at_once}\n"
        "#SBATCH --ntasks=1\n"
        "#SBATCH --cpus-per-task={workers}\n"
        "#SBATCH --output={study}/slurm/%A_%a.out\n"
        "#SBATCH --open-mode=append\n"
        "#SBATCH --requeue\n"
        "#SBATCH --signal=B:TERM@120\n"
        "{cluster}"
        "exec {command}\n",
        fmt::arg("name", plan.name), fmt::arg("file", plan.file.string()),
        fmt::arg("script", (plan.study / "slurm.sh").string()), fmt::arg("ids", ids),
        fmt::arg("at_once", std::max(1, jobs)), fmt::arg("workers", workers), fmt::arg("study", plan.study.string()),
        fmt::arg("command", command), fmt::arg("cluster", cluster));
    io::xml::write_file_atomically(plan.study / "slurm.sh", script);
    fs::permissions(plan.study / "slurm.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
    write_index(plan);
    fmt::print("wrote {} ({} array tasks, at most {} at once, {} CPU{} each)\nsubmit with: sbatch {}\n",
               (plan.study / "slurm.sh").string(), tasks.size(), std::max(1, jobs), workers, workers == 1 ? "" : "s",
               (plan.study / "slurm.sh").string());
    return 0;
}

// Runs the tasks not done yet, `jobs` at a time, as child processes (each one
// `cic sweep FILE --task I`), rebuilding index.csv as they finish.
int run_locally(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs, int workers, bool quiet) {
    std::vector<SweepTask> todo;
    for (const SweepTask& t : tasks)
        if (task_state(plan, t).status != TaskStatus::Done) todo.push_back(t);
    const std::size_t total = tasks.size();
    if (!quiet)
        std::fprintf(stderr, "cic sweep: %s: %zu of %zu runs to do, %d at a time, %d worker%s each; study %s\n",
                     plan.name.c_str(), todo.size(), total, jobs, workers, workers == 1 ? "" : "s",
                     plan.study.c_str());
    g_stop_signal = 0;
    // Without SA_RESTART (std::signal sets it), so that the wait below wakes up and a
    // SIGTERM sent to the sweep alone reaches the running tasks now, not when the
    // next of them happens to finish.
    struct sigaction stop {}, old_int {}, old_term {};
    stop.sa_handler = on_sweep_signal;
    sigemptyset(&stop.sa_mask);
    stop.sa_flags = 0;
    ::sigaction(SIGINT, &stop, &old_int);
    ::sigaction(SIGTERM, &stop, &old_term);
    std::map<pid_t, SweepTask> running;
    std::size_t next = 0;
    int rc = 0;
    bool forwarded = false;
    while (next < todo.size() || !running.empty()) {
        while (g_stop_signal == 0 && next < todo.size() && static_cast<int>(running.size()) < jobs) {
            const SweepTask& t = todo[next++];
            const auto argv = task_argv(plan, t, workers, run::self_exec_path());
            std::vector<char*> args;
            for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
            args.push_back(nullptr);
            const pid_t pid = ::fork();
            if (pid < 0) throw std::runtime_error("cic sweep: fork failed");
            if (pid == 0) {
                // The run's summary is in its folder; the console keeps the sweep's own lines.
                const int null = ::open("/dev/null", O_WRONLY);
                if (null >= 0) ::dup2(null, 1);
                ::execv(args[0], args.data());
                ::_exit(127);
            }
            running.emplace(pid, t);
        }
        if (g_stop_signal == SIGTERM && !forwarded) {   // a terminal's Ctrl-C reaches the children itself
            for (const auto& [pid, t] : running) ::kill(pid, SIGTERM);
            forwarded = true;
        }
        // Polled, so that a signal landing between the check above and the wait
        // cannot be missed; the sleep ends early when one arrives.
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, WNOHANG);
        if (pid == 0) {
            const timespec tick{0, 100'000'000};
            ::nanosleep(&tick, nullptr);
            continue;
        }
        if (pid < 0) {
            if (errno == EINTR) continue;
            break;
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const SweepTask t = it->second;
        running.erase(it);
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        const TaskState st = task_state(plan, t);
        if (!quiet)
            std::fprintf(stderr, "cic sweep: task %zu %s (%s, seed %llu): %s%s\n", t.index, to_string(st.status).c_str(),
                         plan.configs[t.config].name.c_str(), static_cast<unsigned long long>(t.seed),
                         st.final_best.empty() ? "" : ("best " + st.final_best).c_str(),
                         code == 0 ? "" : fmt::format(" (exit {})", code).c_str());
        if (code != 0 && code != 130 && code != 143 && rc == 0) rc = 1;
    }
    write_index(plan);
    ::sigaction(SIGINT, &old_int, nullptr);
    ::sigaction(SIGTERM, &old_term, nullptr);
    if (g_stop_signal != 0) {
        std::fprintf(stderr, "cic sweep: interrupted; rerun the same command to resume\n");
        return g_stop_signal == SIGTERM ? 143 : 130;
    }
    return rc;
}

} // namespace cic::study
