#include "cic/run/run_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>

#include <fmt/format.h>

#include "cic/core/error.hpp"

namespace cic::app {

namespace fs = std::filesystem;

std::string run_name(const io::Settings& s) {
    if (!s.experiment.name.empty()) return s.experiment.name;
    std::string stem = fs::path(s.source_file).stem().string();
    return stem.empty() ? "run" : stem;
}

namespace {

// The number N of an entry named NAME-N, or 0.
int run_number(const std::string& entry, const std::string& name) {
    if (entry.size() <= name.size() + 1 || entry.compare(0, name.size(), name) != 0 || entry[name.size()] != '-')
        return 0;
    const char* b = entry.data() + name.size() + 1;
    const char* e = entry.data() + entry.size();
    int n = 0;
    auto [end, ec] = std::from_chars(b, e, n);
    return ec == std::errc() && end == e ? n : 0;
}

} // namespace

fs::path create_run_folder(const fs::path& output_dir, const std::string& name) {
    std::error_code ec;
    fs::create_directories(output_dir, ec);
    if (ec) throw InputError("cannot create the output folder: " + ec.message(), output_dir.string());
    if (!fs::is_directory(output_dir)) throw InputError("the output folder is not a folder", output_dir.string());
    if (::access(output_dir.c_str(), W_OK | X_OK) != 0)
        throw InputError(std::string("cannot write to the output folder: ") + std::strerror(errno),
                         output_dir.string());
    int highest = 0;
    for (const auto& entry : fs::directory_iterator(output_dir, ec))
        highest = std::max(highest, run_number(entry.path().filename().string(), name));
    for (int n = highest + 1;; ++n) {
        fs::path dir = output_dir / fmt::format("{}-{:03d}", name, n);
        if (fs::create_directory(dir, ec)) return dir;   // false: someone else just took it
        if (ec == std::errc::file_exists) continue;
        if (ec) throw InputError("cannot create the run folder: " + ec.message(), dir.string());
    }
}

} // namespace cic::app
