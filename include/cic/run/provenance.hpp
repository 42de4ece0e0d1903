#pragma once
// Where a result came from (issue 23): the build of cic that made it (version,
// git commit and whether the tree differed from it, compiler, build type,
// flags, library versions) and the session (host, start and end, command
// line). Written to run.log and summary.txt, printed by `cic --version`; never
// to population files or anything hashed, since times and hosts differ
// between runs that give the same bytes.
#include <chrono>
#include <filesystem>
#include <string>

namespace cic::run {

struct BuildInfo {
    const char* commit;       // 40 hex digits, or "unknown" (built outside a git checkout)
    bool dirty;               // tracked files differed from the commit when it was built
    const char* version;      // CIC_VERSION
    const char* compiler;     // "GNU 12.2.0"
    const char* build_type;   // "Release"
    const char* flags;        // CMAKE_CXX_FLAGS and those of the build type
    const char* ode;
    const char* libxml2;
    const char* pagmo;
    const char* eigen;
};

// Made at build time (cmake/CicBuildInfo.cmake).
const BuildInfo& build_info();

// "0.1.0, commit 1d5d752 (dirty)": the version and the short commit.
std::string build_label();
// The lines of `cic --version`: version and commit, compiler and flags, libraries.
std::string build_text();

// This machine's host name ("unknown" when it has none).
std::string host_name();
// An instant as ISO 8601 UTC, "2026-12-03T08:30:00Z".
std::string iso_utc(std::chrono::system_clock::time_point t);

// The head of a run.log: build_text() then host, start and the command line.
std::string run_log_head(const std::string& command_line, std::chrono::system_clock::time_point started);
// The lines summary.txt ends with: cic's label, host, start and end.
std::string summary_tail(std::chrono::system_clock::time_point started, std::chrono::system_clock::time_point ended);

// The full commit a run folder's run.log records ("" when none: a run made
// before cic recorded it, or no run.log); with " (dirty)" when it was.
std::string recorded_commit(const std::filesystem::path& run_dir);

} // namespace cic::run
