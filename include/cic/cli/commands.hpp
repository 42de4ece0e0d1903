#pragma once
// Each subcommand lives in its own file and registers itself on the command
// line (command_line.hpp). The action it sets stores the exit code in `exit_code`.
#include <string>

#include "cic/cli/command_line.hpp"

namespace cic::cli {

struct CommandContext {
    int exit_code = 0;
    bool quiet = false;
    bool verbose = false;
    std::string command_line;   // the whole command, for run.log
};

void add_settings_command(Command& app, CommandContext& ctx);   // cmd_settings.cpp
void add_simulate_command(Command& app, CommandContext& ctx);   // cmd_simulate.cpp
void add_worker_command(Command& app, CommandContext& ctx);     // cmd_worker.cpp
void add_render_command(Command& app, CommandContext& ctx);     // cmd_render.cpp
void add_plot_command(Command& app, CommandContext& ctx);       // cmd_plot.cpp
void add_compare_command(Command& app, CommandContext& ctx);    // cmd_compare.cpp
void add_trace_command(Command& app, CommandContext& ctx);      // cmd_trace.cpp
void add_sweep_command(Command& app, CommandContext& ctx);      // cmd_sweep.cpp
void add_assess_command(Command& app, CommandContext& ctx);     // cmd_assess.cpp
void add_transfer_command(Command& app, CommandContext& ctx);   // cmd_transfer.cpp
void add_resume_command(Command& app, CommandContext& ctx);     // cmd_resume.cpp
void add_export_command(Command& app, CommandContext& ctx);     // cmd_export.cpp
void add_verify_command(Command& app, CommandContext& ctx);     // cmd_verify.cpp
void add_eval_command(Command& app, CommandContext& ctx);       // cmd_eval.cpp
void add_report_command(Command& app, CommandContext& ctx);     // cmd_report.cpp
void add_robot_command(Command& app, CommandContext& ctx);      // cmd_robot.cpp
#ifdef CIC_HAVE_VIEWER
void add_view_command(Command& app, CommandContext& ctx);       // cmd_view.cpp
#endif
// `cic man` and `cic completion`: register last, they document every other subcommand.
void add_docs_commands(Command& app, CommandContext& ctx);      // cmd_docs.cpp

} // namespace cic::cli
