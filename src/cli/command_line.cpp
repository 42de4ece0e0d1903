// The one place where subcommands' option declarations meet CLI11.
#include "cic/cli/command_line.hpp"

#include <CLI/CLI.hpp>

#include <vector>

namespace cic::cli {

Option& Option::required() {
    option_->required();
    return *this;
}

Option& Option::show_default() {
    option_->capture_default_str();
    return *this;
}

Option& Option::positive() {
    option_->check(CLI::PositiveNumber);
    return *this;
}

Option& Option::non_negative() {
    option_->check(CLI::NonNegativeNumber);
    return *this;
}

template <class Number>
Option& Option::range(Number low, Number high) {
    option_->check(CLI::Range(low, high));
    return *this;
}
template Option& Option::range<int>(int, int);
template Option& Option::range<long>(long, long);
template Option& Option::range<double>(double, double);

Option& Option::delimiter(char separator) {
    option_->delimiter(separator);
    return *this;
}

std::size_t Option::count() const { return option_->count(); }

Command Command::subcommand(const std::string& name, const std::string& description) {
    return Command(app_->add_subcommand(name, description));
}

template <class T>
Option Command::option(const std::string& names, T& value, const std::string& description) {
    return Option(app_->add_option(names, value, description));
}
template Option Command::option<int>(const std::string&, int&, const std::string&);
template Option Command::option<long>(const std::string&, long&, const std::string&);
template Option Command::option<double>(const std::string&, double&, const std::string&);
template Option Command::option<std::string>(const std::string&, std::string&, const std::string&);
template Option Command::option<std::vector<std::string>>(const std::string&, std::vector<std::string>&,
                                                          const std::string&);

Option Command::flag(const std::string& names, bool& value, const std::string& description) {
    return Option(app_->add_flag(names, value, description));
}

void Command::on_run(std::function<void()> action) { app_->callback(std::move(action)); }

void Command::hide() { app_->group(""); }

} // namespace cic::cli
