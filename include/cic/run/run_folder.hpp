#pragma once
// Run folders: OUTPUT/NAME-NNN, always a fresh one, never an existing run.
#include <filesystem>
#include <string>

#include "cic/io/settings.hpp"

namespace cic::run {

// The run name: settings' Experiment.name, else the settings file's stem, else "run".
std::string run_name(const io::Settings& settings);

// Creates OUTPUT (with parents) and in it a new folder NAME-NNN, NNN one past
// the highest number already used for NAME (001 for the first run). mkdir is
// atomic, so two runs started together get different folders. Throws
// cic::InputError naming the folder when OUTPUT cannot be created or written.
std::filesystem::path create_run_folder(const std::filesystem::path& output_dir, const std::string& name);

} // namespace cic::run
