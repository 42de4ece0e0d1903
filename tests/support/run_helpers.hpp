#pragma once
// Helpers for end-to-end tests that run the real `cic` binary on a settings file.
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "cic/core/hash.hpp"
#include "files.hpp"

namespace cic::testing {

inline std::string cic_binary() {
    const char* env = std::getenv("CIC_BINARY");
    return env ? env : CIC_BINARY;
}

// Runs a shell command line; returns the exit code; output goes to `log`.
inline int run_command(const std::string& args, const std::filesystem::path& log) {
    const std::string cmd = cic_binary() + " " + args + " > " + log.string() + " 2>&1";
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
}

// The single run folder cic created below `output`.
inline std::filesystem::path only_run(const std::filesystem::path& output) {
    std::filesystem::path found;
    for (const auto& e : std::filesystem::directory_iterator(output))
        if (e.is_directory()) found = e.path();
    return found;
}


// One `cic --quiet --settings DIR/NAME.xml --output DIR/NAME` run of the given settings text.
struct RunResult {
    int rc = -1;
    std::filesystem::path run;   // the run folder it created (empty if none)
    std::string log;             // everything it printed
};

inline RunResult run_settings(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
    write_text(dir / (name + ".xml"), text);
    RunResult r;
    r.rc = run_command("--quiet --settings " + (dir / (name + ".xml")).string() + " --output " + (dir / name).string(),
                       dir / (name + ".log"));
    r.log = read_text(dir / (name + ".log"));
    if (std::filesystem::exists(dir / name)) r.run = only_run(dir / name);
    return r;
}

// `cic --quiet --settings SETTINGS --output OUTPUT [--set EXTRA]` in its own
// process group (as a batch job: a signal can reach cic and its workers), its
// output in `log`; returns its pid without waiting.
inline pid_t start_cic(const std::filesystem::path& settings, const std::filesystem::path& output,
                       const std::filesystem::path& log, const std::string& extra) {
    const pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);
        if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(126);
        const std::string bin = cic_binary(), cfg = settings.string(), out = output.string();
        if (extra.empty())
            execl(bin.c_str(), bin.c_str(), "--quiet", "--settings", cfg.c_str(), "--output", out.c_str(),
                  static_cast<char*>(nullptr));
        else
            execl(bin.c_str(), bin.c_str(), "--quiet", "--settings", cfg.c_str(), "--output", out.c_str(), "--set",
                  extra.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    return pid;
}

// A crash and what a user does next: starts `cic --settings settings` writing
// to dir/killed-K, SIGKILLs it after `at` seconds (with its workers when
// `whole_group`), then runs the same settings to dir/resumed-K from the
// killed run's population.xml, or from the start when it died before its
// first checkpoint. Returns whether the resume exited 0 (its output in
// dir/resumed.log) and sets `resumed` to its run folder and `from` to the
// checkpoint it resumed from (empty: started again).
inline bool kill_then_resume(const std::filesystem::path& dir, const std::filesystem::path& settings, int k, double at,
                             bool whole_group, std::filesystem::path& resumed, std::filesystem::path& from) {
    namespace fs = std::filesystem;
    const fs::path out = dir / ("killed-" + std::to_string(k));
    const pid_t pid = start_cic(settings, out, dir / "killed.log", "");
    if (pid <= 0) return false;
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    kill(whole_group ? -pid : pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    from.clear();
    if (fs::exists(out) && !only_run(out).empty() && fs::exists(only_run(out) / "population.xml"))
        from = only_run(out) / "population.xml";
    const fs::path again_out = dir / ("resumed-" + std::to_string(k));
    const pid_t again = start_cic(settings, again_out, dir / "resumed.log",
                                  from.empty() ? "" : "Control.populationXmlLoadFrom=" + from.string());
    waitpid(again, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return false;
    resumed = only_run(again_out);
    return true;
}

// HyperGP with population 6 on R0 and 2.5 s simulations: seconds, not minutes.
// Elitism 1 (not the thesis's 0), so that the best never falls.
inline std::string tiny_hypergp_settings(int generations, int workers, const std::string& extra_control = "") {
    return R"(<?xml version="1.0"?>
<settings>
  <Experiment><type>hypergp</type><seed>5</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <GP><generatedPopulationSize>6</generatedPopulationSize><tournament_size>3</tournament_size>
      <expectedGeneratedTreeSize>10</expectedGeneratedTreeSize><maximumGeneratedTreeDepth>4</maximumGeneratedTreeDepth>
      <elitism>1</elitism></GP>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
  <Control><maximumIterations>)" + std::to_string(generations) + "</maximumIterations>" + extra_control + R"(</Control>
</settings>
)";
}

// The golden HyperGP run: tiny_hypergp_settings with 4 generations and a speed
// bound so low (1 m/s) that about half the evaluations fail as physics blow-ups.
inline std::string golden_hypergp_settings(int workers) {
    std::string s = tiny_hypergp_settings(4, workers);
    s.replace(s.find("<robot_type>"), 0, "<maxBodySpeed>1</maxBodySpeed>");
    return s;
}

// The golden HyperGP-CPG run: tiny_hypergp_settings on the CPG substrate with
// feedback, two trees (tree 1 gives the feedback gains), 4 generations.
inline std::string golden_cpg_settings(int workers) {
    std::string s = tiny_hypergp_settings(4, workers);
    s.replace(s.find("<elitism>"), 0, "<numberOfTreesInForestGenotype>2</numberOfTreesInForestGenotype>");
    s.replace(s.find("</settings>"), 0,
              "  <Neural><substrate>cpg</substrate><cpgFeedback>2</cpgFeedback></Neural>\n");
    return s;
}

// The golden symbolic-regression run: Nguyen-7, 200 individuals, 6 generations.
inline std::string golden_symreg_settings(int threads) {
    return R"(<settings>
  <Experiment><type>symreg</type><seed>11</seed><workers>)" + std::to_string(threads) + R"(</workers></Experiment>
  <GP><generatedPopulationSize>200</generatedPopulationSize><terminalVariableCount>1</terminalVariableCount>
      <functions>add sub mul div sin cos</functions><tournament_size>5</tournament_size><elitism>1</elitism></GP>
  <BloatControl><bloatControlVariant>1</bloatControlVariant></BloatControl>
  <Control><maximumIterations>6</maximumIterations><minimumFitness>inf</minimumFitness></Control>
  <SymbolicRegression><target>nguyen-7</target></SymbolicRegression>
</settings>
)";
}

// The hashes of golden_hypergp_settings' and golden_symreg_settings' final
// population.xml (tests/experiments/golden_test.cpp, tests/run/mpi_test.cpp).
// Issue 56 changed them all on purpose: format version 2 adds the file's
// contentHash; with it removed and version 1 again, each file is the bytes
// the earlier hashes named (no value changed).
inline const std::string kGoldenHypergp = "64083853d1db56df";
inline const std::string kGoldenSymreg = "a6c8eaf370eeee1a";
inline const std::string kGoldenCpg = "898a3605d05953da";   // golden_cpg_settings

// The golden MAP-Elites runs (docs/quality-diversity.md): HyperGP-gait genotypes
// varied by crossover and subtree mutation, and gait vectors varied by
// Gaussian mutation, on R1's 4-D duty-factor grid (3 bins) with 2.5 s
// simulations: 60 evaluations in batches of 12, the first 24 made from nothing.
inline std::string golden_map_elites_settings(const std::string& type, int workers) {
    return R"(<settings>
  <Experiment><type>)" + type + R"(</type><seed>6</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <MapElites><enabled>1</enabled><bins>3</bins><batch>12</batch><initial>24</initial><evaluations>60</evaluations></MapElites>
  <GP><numberOfTreesInForestGenotype>3</numberOfTreesInForestGenotype></GP>
  <Neural><substrate>gait</substrate><clockInputs>0</clockInputs><frequencyMax>3</frequencyMax></Neural>
  <Simulator><robot_type>1</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
</settings>
)";
}
inline std::string golden_me_hypergp_settings(int workers) { return golden_map_elites_settings("hypergp", workers); }
inline std::string golden_me_gait_settings(int workers) { return golden_map_elites_settings("gait", workers); }
inline const std::string kGoldenMapElitesHypergp = "2f9771a4b8f51763";   // golden_me_hypergp_settings' final population.xml
inline const std::string kGoldenMapElitesGait = "85046310944a0d9e";      // golden_me_gait_settings' final population.xml


// A sweep file of small HyperGP runs on R0 (2.5 s or `seconds` simulations,
// tournament 3): `population` individuals, `generations` generations, the
// given <grid> and `repeats` seeds from 1 (firstSeed), writing to `study`.
inline std::string tiny_sweep_text(const std::string& name, const std::filesystem::path& study, int population,
                                   int generations, double seconds, const std::string& grid, int repeats,
                                   int first_seed = 1) {
    char sample_to[32];
    std::snprintf(sample_to, sizeof sample_to, "%g", seconds);
    return "<sweep name=\"" + name + "\">\n  <base>" +
           (std::filesystem::path(CIC_SOURCE_DIR) / "settings" / "r0_settings.xml").string() + "</base>\n  <output>" +
           study.string() + "</output>\n  <set>GP.generatedPopulationSize=" + std::to_string(population) +
           "</set>\n  <set>GP.tournament_size=3</set>\n  <set>Control.maximumIterations=" +
           std::to_string(generations) + "</set>\n  <set>Simulator.sample_to=" + sample_to +
           "</set>\n  <set>Simulator.delayed_start=0.5</set>\n  " + grid + "\n  <repeats count=\"" +
           std::to_string(repeats) + "\" firstSeed=\"" + std::to_string(first_seed) + "\"/>\n</sweep>\n";
}

// A text's lines, empty ones left out.
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        if (!l.empty()) out.push_back(l);
    return out;
}

// 64-bit FNV-1a of a file's bytes, as 16 hex digits: the golden hashes.
inline std::string file_hash(const std::filesystem::path& p) {
    return hex16(fnv1a_64(read_text(p)));
}

} // namespace cic::testing
