// What the CLI11 objects of cic's commands say, for the man page and the completion.
#include "docs.hpp"

#include <algorithm>
#include <set>
#include <string>

namespace cic::cli::docs {

bool hidden(const CLI::App* sub) { return sub->get_group().empty() || sub->get_name().empty(); }

bool takes_value(const CLI::Option* opt) { return opt->get_items_expected_max() > 0; }

bool repeatable(const CLI::Option* opt) { return opt->get_items_expected_max() > 1; }

// Every spelling of an option: -j, --jobs (or the positional's name).
std::vector<std::string> option_names(const CLI::Option* opt) {
    std::vector<std::string> names;
    for (const auto& s : opt->get_snames()) names.push_back("-" + s);
    for (const auto& l : opt->get_lnames()) names.push_back("--" + l);
    if (names.empty()) names.push_back(opt->get_name(true));
    return names;
}

// "FLOAT:POSITIVE" -> "FLOAT" (the placeholder) and "POSITIVE" (the check).
std::string value_type(const CLI::Option* opt) {
    const std::string t = opt->get_type_name();
    return t.substr(0, t.find(':'));
}
std::string value_check(const CLI::Option* opt) {
    const std::string t = opt->get_type_name();
    const auto colon = t.find(':');
    if (colon == std::string::npos) return {};
    std::string check = t.substr(colon + 1);   // "INT in [1 - 4096]" -> "in [1 - 4096]"
    if (check.rfind(value_type(opt) + " ", 0) == 0) check.erase(0, value_type(opt).size() + 1);
    return check;
}

std::vector<const CLI::Option*> positionals(const CLI::App& app) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : app.get_options())
        if (opt->get_positional() && opt->get_lnames().empty() && opt->get_snames().empty()) out.push_back(opt);
    return out;
}

std::vector<const CLI::Option*> named_options(const CLI::App& app) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : app.get_options())
        if (!opt->get_lnames().empty() || !opt->get_snames().empty()) out.push_back(opt);
    return out;
}

// Options whose value is a word, not a file (everything else that takes TEXT
// completes file names). Keep in step with new word-valued options.
bool word_valued(const std::string& name) {
    static const std::set<std::string> words{"--seed",  "--seeds",      "--individual", "--controller",
                                             "--title", "--joints",     "--metric",     "--set"};
    return words.count(name) > 0;
}

// What a value of `opt` is: "keys" (Section.key=), "file", "dir" or "" (no completion).
std::string value_kind(const CLI::Option* opt) {
    const std::string name = option_names(opt).back();
    if (name == "--set") return "keys";
    if (word_valued(name) || value_type(opt) != "TEXT") return "";
    const std::string& d = opt->get_description();
    const bool folder = d.find("folder") != std::string::npos || d.find("DIR") != std::string::npos;
    const bool file = d.find("file") != std::string::npos || d.find("XML") != std::string::npos;
    return folder && !file ? "dir" : "file";
}

} // namespace cic::cli::docs
