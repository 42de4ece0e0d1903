// TEMPORARY placeholder so the binary links while the real command is written.
#include "cic/app/commands.hpp"

namespace cic::app {
void add_plot_command(CLI::App&, CommandContext&) {}
} // namespace cic::app
