// Subcommands that print documentation made from the same sources as
// --help: `cic man` (the roff man page cic.1) and `cic completion` (the bash
// completion script). Both read the CLI11 App objects at run time (every
// subcommand with its description and options) and the settings table, so the
// installed man page and completion never drift from the binary. The build
// runs them (cmake/CicInstall.cmake) and installs their output.
#include <iostream>

#include <CLI/CLI.hpp>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "docs.hpp"

namespace cic::cli {

void add_docs_commands(Command& root, CommandContext& ctx) {
    CLI::App& app = *root.app();   // introspection: every option and check of every command
    // The build runs them to make cic.1 and the completion; a user may too (`cic man | man -l -`).
    app.add_subcommand("man", "Print the man page cic(1) as roff, made from the command line and settings table")
        ->callback([&app, &ctx] {
            run_guarded(ctx, "man", [&] {
                std::cout << docs::man_page(app);
                return std::cout.flush() ? 0 : 1;
            });
        });
    app.add_subcommand("completion", "Print the bash completion script for cic (source it, or install it as "
                                     "/usr/share/bash-completion/completions/cic)")
        ->callback([&app, &ctx] {
            run_guarded(ctx, "completion", [&] {
                std::cout << docs::completion_script(app);
                return std::cout.flush() ? 0 : 1;
            });
        });
}

} // namespace cic::cli
