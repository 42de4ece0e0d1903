#pragma once
// How a subcommand declares its options, without CLI11. Only
// src/cli/command_line.cpp, src/cli/cli.cpp, the help (help.hpp) and the
// documentation generators (docs.hpp: man page, completion, cmd_docs.cpp)
// include CLI11: its header alone costs each file that includes it about 5 s
// of compile time (over 25 s under ASan), and every subcommand's file used to.
#include <functional>
#include <string>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace cic::cli {

// One option or flag of a command; each call returns the option for chaining.
class Option {
public:
    explicit Option(CLI::Option* option) : option_(option) {}
    Option& required();
    Option& show_default();                 // the help shows the value it starts with
    Option& positive();                     // > 0
    Option& non_negative();                 // >= 0
    template <class Number>                 // int, long or double
    Option& range(Number low, Number high); // in [low, high]
    Option& delimiter(char separator);      // "--joints a,b" as two values
    std::size_t count() const;              // how often it was given (after parsing)

private:
    CLI::Option* option_;
};

// A command or subcommand: its options and what it does.
class Command {
public:
    explicit Command(CLI::App* app) : app_(app) {}
    Command subcommand(const std::string& name, const std::string& description);
    // A positional when `names` has no leading dash. T: int, long, double,
    // std::string or std::vector<std::string> (repeatable). No unsigned types:
    // CLI11 2.1 wraps "-1" round to the largest value instead of refusing it, so
    // seeds travel as text and the settings table checks them.
    template <class T>
    Option option(const std::string& names, T& value, const std::string& description);
    Option flag(const std::string& names, bool& value, const std::string& description);
    void on_run(std::function<void()> action);   // after a successful parse
    void hide();                                 // left out of --help (internal commands)
    CLI::App* app() const { return app_; }       // for cli.cpp and the documentation generator

private:
    CLI::App* app_;
};

} // namespace cic::cli
