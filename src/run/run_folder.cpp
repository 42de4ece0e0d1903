#include "cic/run/run_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "cic/core/error.hpp"

namespace cic::run {

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

// A full disk can still hold a new folder but not a file in it: then nothing is
// kept. The probe is as large as a run's first files (settings.xml and run.log),
// and is written and synced like them before it is removed.
void keep_only_if_writable(const fs::path& dir) {
    const fs::path probe = dir / ".cic-write-test";
    std::string why;
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        why = std::strerror(errno);
    } else {
        const std::string block(64 * 1024, '\n');
        std::size_t left = block.size();
        while (left > 0 && why.empty()) {
            const ssize_t n = ::write(fd, block.data() + (block.size() - left), left);
            if (n < 0 && errno != EINTR) why = std::strerror(errno);
            if (n > 0) left -= static_cast<std::size_t>(n);
        }
        if (why.empty() && ::fsync(fd) != 0) why = std::strerror(errno);
        if (::close(fd) != 0 && why.empty()) why = std::strerror(errno);
        ::unlink(probe.c_str());
    }
    if (why.empty()) return;
    std::error_code ec;
    fs::remove_all(dir, ec);
    throw InputError("cannot write in the output folder: " + why + "; nothing was kept", dir.parent_path().string());
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
        if (fs::create_directory(dir, ec)) {   // false: someone else just took it
            keep_only_if_writable(dir);
            return dir;
        }
        if (ec == std::errc::file_exists) continue;
        if (ec) throw InputError("cannot create the run folder: " + ec.message(), dir.string());
    }
}

} // namespace cic::run
