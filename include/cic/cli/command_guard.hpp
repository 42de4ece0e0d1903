#pragma once
// Runs a subcommand's body and turns exceptions into the CLI's exit codes:
// cic::InputError -> message, exit 2; any other std::exception -> message, exit 1.
#include <exception>
#include <functional>
#include <iostream>
#include <string_view>

#include "cic/cli/commands.hpp"
#include "cic/core/error.hpp"

namespace cic::cli {

inline void run_guarded(CommandContext& ctx, std::string_view command, const std::function<int()>& body) {
    try {
        ctx.exit_code = body();
    } catch (const InputError& e) {
        std::cerr << "cic " << command << ": " << e.what() << '\n';
        ctx.exit_code = 2;
    } catch (const std::exception& e) {
        std::cerr << "cic " << command << ": " << e.what() << '\n';
        ctx.exit_code = 1;
    }
}

} // namespace cic::cli
