// The running binary's path (see self_path.hpp).
#include "cic/run/self_path.hpp"

#include <filesystem>
#include <string_view>

namespace cic::run {

namespace fs = std::filesystem;

std::string self_path(const char* argv0) {
    std::error_code ec;
    std::string p = fs::read_symlink("/proc/self/exe", ec).string();
    if (!ec && !p.empty()) {
        constexpr std::string_view kDeleted = " (deleted)";
        if (p.size() > kDeleted.size() && p.compare(p.size() - kDeleted.size(), kDeleted.size(), kDeleted) == 0)
            p.resize(p.size() - kDeleted.size());
        return p;
    }
    if (argv0) {
        const fs::path a = fs::absolute(argv0, ec);
        if (!ec) return a.string();
    }
    return "cic";
}

std::string self_exec_path() {
    std::error_code ec;
    return fs::exists("/proc/self/exe", ec) ? std::string("/proc/self/exe") : self_path();
}

} // namespace cic::run
