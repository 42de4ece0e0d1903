#pragma once
// Where `cic --settings NAME.xml` finds NAME.xml: as given (relative to the
// current folder), else among the installed settings (<exe dir>/../share/cic/settings),
// else in the source tree's settings/ folder.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cic/core/error.hpp"

namespace cic::run {

// A settings file found nowhere: bad input like any other (exit 2), which
// Python raises as FileNotFoundError.
class SettingsNotFound : public InputError {
public:
    using InputError::InputError;
};

// The folders searched, in order, when `given` is not found as given:
// <exe dir>/../share/cic/settings, then CIC_SOURCE_DIR/settings.
// `cic_binary` stands for the running binary when the caller is not cic itself
// (the Python package: the cic its workers run); empty = this process's. A
// link under /proc (/proc/self/exe, what cic execs for its workers) is read
// as the file it names.
std::vector<std::filesystem::path> settings_search_folders(const std::filesystem::path& cic_binary = {});

// `given` when it names an existing file; else the first folder of
// settings_search_folders() holding it, announced as
// "cic: settings GIVEN: using FULL_PATH" (to `note`, else on stderr: Python
// hands it to its warnings). Only a relative `given` is looked up elsewhere.
// Throws SettingsNotFound naming every place it looked.
std::filesystem::path find_settings_file(const std::string& given, const std::filesystem::path& cic_binary = {},
                                         const std::function<void(const std::string&)>& note = {});

} // namespace cic::run
