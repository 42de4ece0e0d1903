// `cic --settings NAME.xml` from any folder: the shipped settings files are
// found next to the installed binary or in the source tree (docs/install.md).
#include "cic/run/settings_lookup.hpp"

#include "cic/run/self_path.hpp"

#include <algorithm>
#include <iostream>
#include <iterator>
#include <system_error>

#include "cic/core/error.hpp"
#include "cic/io/did_you_mean.hpp"

namespace cic::run {

namespace fs = std::filesystem;

namespace {

// The binary's real file: a worker path such as /proc/self/exe (what cic execs
// for its workers, self_exec_path) is a link whose folder, /proc/self, says
// nothing about where cic is installed.
fs::path real_binary(const fs::path& cic_binary) {
    if (cic_binary.empty() || cic_binary == "/proc/self/exe") return self_path();
    if (cic_binary.string().starts_with("/proc/")) {
        std::error_code ec;
        const fs::path target = fs::canonical(cic_binary, ec);
        if (!ec) return target;
    }
    return cic_binary;
}

} // namespace

std::vector<fs::path> settings_search_folders(const fs::path& cic_binary) {
    const fs::path exe = real_binary(cic_binary);
    std::vector<fs::path> out;
    if (exe.has_parent_path())
        out.push_back((exe.parent_path() / ".." / "share" / "cic" / "settings").lexically_normal());
#if defined(CIC_SOURCE_DIR) && defined(CIC_BINARY_DIR)
    // Only a binary still in its build folder looks in the source tree: an
    // installed one (or a .deb's) never reads files of the machine it was built on.
    const fs::path build = fs::path(CIC_BINARY_DIR);
    if (!exe.empty() && std::mismatch(build.begin(), build.end(), exe.begin(), exe.end()).first == build.end())
        out.push_back(fs::path(CIC_SOURCE_DIR) / "settings");
#endif
    return out;
}

fs::path find_settings_file(const std::string& given, const fs::path& cic_binary,
                            const std::function<void(const std::string&)>& note) {
    if (given.empty()) throw InputError("--settings: the file name is empty");
    const fs::path p(given);
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return p;
    if (fs::exists(p, ec)) throw InputError("--settings " + given + ": not a regular file");

    std::string looked = (p.is_absolute() ? p : fs::absolute(p, ec)).string();
    std::vector<std::string> shipped;   // the names in the folders searched, for "did you mean"
    if (p.is_relative()) {
        // "settings/NAME.xml" (the source tree's spelling) is NAME.xml in a settings folder, not settings/settings/.
        const fs::path inside = *p.begin() == "settings" && std::distance(p.begin(), p.end()) > 1
            ? p.lexically_relative("settings") : p;
        for (const auto& dir : settings_search_folders(cic_binary)) {
            const fs::path candidate = (dir / inside).lexically_normal();
            if (fs::is_regular_file(candidate, ec)) {
                fs::path full = fs::weakly_canonical(candidate, ec);
                if (ec) full = candidate;
                const std::string line = "cic: settings " + given + ": using " + full.string();
                if (note) note(line);
                else std::cerr << line << '\n';
                return full;
            }
            looked += ", " + candidate.string();
            for (const auto& e : fs::directory_iterator(dir, ec))
                if (e.path().extension() == ".xml") shipped.push_back(e.path().filename().string());
        }
    }
    const std::string near = io::nearest_name(p.filename().string(), shipped);
    throw SettingsNotFound("settings file " + given + " not found; looked in: " + looked +
                           (near.empty() ? "" : "; did you mean " + near + "?"));
}

} // namespace cic::run
