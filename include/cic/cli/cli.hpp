#pragma once
// The `cic` command line: the main job and its subcommands.
namespace cic::cli {

// Returns the process exit code: 0 ok, 1 run failure, 2 bad input / usage.
int main(int argc, char** argv);

} // namespace cic::cli
