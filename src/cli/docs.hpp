#pragma once
// Private to src/cli: the documentation `cic man` and `cic completion` make
// from the CLI11 objects of every command (cmd_docs.cpp registers them).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace cic::cli::docs {

// ---- what the CLI11 objects say (cli_introspection.cpp) ----
bool hidden(const CLI::App* sub);
bool takes_value(const CLI::Option* opt);
bool repeatable(const CLI::Option* opt);
std::vector<std::string> option_names(const CLI::Option* opt);   // -j, --jobs (or the positional's name)
std::string value_type(const CLI::Option* opt);    // "FLOAT:POSITIVE" -> "FLOAT"
std::string value_check(const CLI::Option* opt);   // "FLOAT:POSITIVE" -> "POSITIVE"
std::vector<const CLI::Option*> positionals(const CLI::App& app);
std::vector<const CLI::Option*> named_options(const CLI::App& app);
std::string value_kind(const CLI::Option* opt);    // "keys" (Section.key=), "file", "dir" or ""

// ---- roff (roff.cpp) ----
std::string roff(const std::string& text);        // escaped: backslashes, hyphens, non-ASCII, leading . or '
std::string roff_lines(const std::string& text);  // each input line a line of its own
std::string roff_option_label(const CLI::Option* opt);
std::string roff_option(const CLI::Option* opt, bool positional);
std::string usage(const CLI::App& sub);
std::string short_description(const CLI::App& app);   // the NAME line

// The roff man page cic(1) (man_page.cpp).
std::string man_page(CLI::App& app);

// The bash completion script (completion_script.cpp), ending in the fixed
// shell functions of completion_functions.cpp.
std::string completion_script(CLI::App& app);
extern const char* const kCompletionFunctions;

} // namespace cic::cli::docs
