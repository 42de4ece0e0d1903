#pragma once
// Private to src/cli: `cic help [COMMAND]` and the "did you mean" of a
// mistyped option or subcommand (cmd_help.cpp).
#include <string>

#include <CLI/CLI.hpp>

#include "cic/cli/commands.hpp"

namespace cic::cli {

void add_help_command(CLI::App& app, CommandContext& ctx);

// For each argument the parser did not take that is near an option of the
// subcommand it follows (or of the main job), or near a subcommand's name:
// "; did you mean --seed?" lines to append to the error; "" when none is near.
std::string near_misses(const CLI::App& app, int argc, char** argv);

// For a command line whose first word is a settings file (`cic settings/r1.xml`,
// --settings left out): the one line that says how to run or check it; else "".
std::string settings_file_hint(const CLI::App& app, int argc, char** argv);

} // namespace cic::cli
