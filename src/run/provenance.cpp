// Where a result came from (provenance.hpp).
#include "cic/run/provenance.hpp"

#include <unistd.h>

#include <ctime>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

namespace cic::run {
namespace {

constexpr std::string_view kCommitLine = "commit: ";

} // namespace

std::string build_label() {
    const BuildInfo& b = build_info();
    const std::string commit(b.commit);
    return fmt::format("{}, commit {}{}", b.version, commit == "unknown" ? commit : commit.substr(0, 12),
                       b.dirty ? " (dirty)" : "");
}

std::string build_text() {
    const BuildInfo& b = build_info();
    return fmt::format("cic {}\n{}{}{}\nbuilt: {}, {}, flags \"{}\"\nlibraries: ODE {}, libxml2 {}, pagmo2 {}, Eigen {}\n",
                       b.version, kCommitLine, b.commit, b.dirty ? " (dirty)" : "", b.compiler, b.build_type, b.flags,
                       b.ode, b.libxml2, b.pagmo, b.eigen);
}

std::string host_name() {
    char buf[256] = {};
    if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "unknown";
    return buf;
}

std::string iso_utc(std::chrono::system_clock::time_point t) {
    const std::time_t s = std::chrono::system_clock::to_time_t(t);
    std::tm tm{};
    ::gmtime_r(&s, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string run_log_head(const std::string& command_line, std::chrono::system_clock::time_point started) {
    return build_text() + fmt::format("host: {}\nstarted: {}\ncommand: {}\n", host_name(), iso_utc(started), command_line);
}

std::string summary_tail(std::chrono::system_clock::time_point started, std::chrono::system_clock::time_point ended) {
    return fmt::format("cic: {}\nhost: {}\nstarted: {}\nended: {}\n", build_label(), host_name(), iso_utc(started),
                       iso_utc(ended));
}

std::string recorded_commit(const std::filesystem::path& run_dir) {
    std::ifstream in(run_dir / "run.log");
    std::string line;
    // The head's commit line; a resumed run's log holds one per session: the last counts.
    std::string found;
    while (std::getline(in, line))
        if (line.rfind(kCommitLine, 0) == 0) found = line.substr(kCommitLine.size());
    return found;
}

} // namespace cic::run
