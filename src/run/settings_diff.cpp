// Which settings a run ran against those asked of it (settings_diff.hpp).
#include "cic/run/settings_diff.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iterator>

#include <fmt/format.h>

#include "cic/io/settings_table.hpp"
#include "cic/search/search.hpp"

namespace cic::run {
namespace {

bool same_file_contents(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    if (!fa || !fb) return false;
    return std::string(std::istreambuf_iterator<char>(fa), {}) == std::string(std::istreambuf_iterator<char>(fb), {});
}

// Two path lists naming files of the same bytes, item by item.
bool same_files_contents(const std::string& a, const std::string& b) {
    std::istringstream ia(a), ib(b);
    std::string x, y;
    while (true) {
        const bool more_a = static_cast<bool>(ia >> x), more_b = static_cast<bool>(ib >> y);
        if (more_a != more_b) return false;
        if (!more_a) return true;
        if (x != y && !same_file_contents(x, y)) return false;
    }
}

} // namespace

io::Settings result_settings(io::Settings s) {
    s.experiment.name.clear();
    s.experiment.output_directory.clear();
    s.experiment.workers = 0;
    s.control.population_load_from.clear();
    return s;
}

std::vector<std::string> settings_differences(const io::Settings& ran_settings, const io::Settings& asked_settings,
                                              std::string_view asker) {
    const io::Settings ran = result_settings(ran_settings), asked = result_settings(asked_settings);
    std::vector<std::string> out;
    for (const auto& k : io::settings_table()) {
        const std::string a = k.get(ran), b = k.get(asked);
        if (io::same_result(k, a, b) || (k.type == io::ValueType::Path && same_file_contents(a, b)) ||
            (k.type == io::ValueType::PathList && same_files_contents(a, b)))
            continue;
        out.push_back(fmt::format("{}.{}: ran '{}', {} asks '{}'", k.section, k.key, a, asker, b));
    }
    return out;
}

bool is_budget_difference(const std::string& difference) {
    for (const auto& key : search::budget_keys())
        if (difference.rfind(key + ":", 0) == 0) return true;
    return false;
}

bool extends(const io::Settings& ran, const io::Settings& asked) {
    const auto diffs = settings_differences(ran, asked, "");
    if (diffs.empty()) return false;
    for (const auto& d : diffs)
        if (!is_budget_difference(d)) return false;
    // No budget shrinks (every registered search's, numbers all).
    const auto keys = search::budget_keys();
    for (const auto& k : io::settings_table())
        if (std::find(keys.begin(), keys.end(), k.section + "." + k.key) != keys.end() &&
            std::stod(k.get(asked)) < std::stod(k.get(ran)))
            return false;
    return true;
}

} // namespace cic::run
