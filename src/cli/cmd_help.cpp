// `cic help [COMMAND]`, and suggestions for a mistyped option or subcommand.
#include "help.hpp"

#include <iostream>

#include "cic/cli/command_guard.hpp"
#include "cic/io/did_you_mean.hpp"

namespace cic::cli {
namespace {

std::vector<std::string> option_names(const CLI::App& app) {
    std::vector<std::string> out;
    for (const CLI::Option* o : app.get_options()) {
        for (const auto& l : o->get_lnames()) out.push_back("--" + l);
        for (const auto& s : o->get_snames()) out.push_back("-" + s);
    }
    return out;
}

} // namespace

void add_help_command(CLI::App& app, CommandContext& ctx) {
    auto topic = std::make_shared<std::string>();
    CLI::App* help = app.add_subcommand("help", "Print the help of cic, or of one command: cic help sweep");
    help->add_option("command", *topic, "the command to explain (default: cic itself)");
    help->callback([&app, &ctx, topic] {
        run_guarded(ctx, "help", [&] {
            if (topic->empty()) {   // App::help() would describe the subcommand selected: this one
                std::cout << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
                return 0;
            }
            for (const CLI::App* sub : app.get_subcommands({}))
                if (sub->get_name() == *topic) {
                    std::cout << sub->help(app.get_name());
                    return 0;
                }
            std::vector<std::string> names;
            for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
            const std::string near = io::nearest_name(*topic, names);
            throw InputError("no command '" + *topic + "'" + (near.empty() ? "" : "; did you mean " + near + "?") +
                             " (cic --help lists them)");
        });
    });
}

std::string near_misses(const CLI::App& app, int argc, char** argv) {
    // The subcommand named on the line, if any: its options are the ones meant.
    const CLI::App* command = &app;
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    std::string text;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (command == &app)
            for (const CLI::App* sub : app.get_subcommands({}))
                if (sub->get_name() == arg) command = sub;
        if (arg.size() > 1 && arg[0] == '-') {
            const std::string name = arg.substr(0, arg.find('='));
            std::vector<std::string> names = option_names(*command);
            if (command->get_fallthrough() || command == &app) {
                const auto main = option_names(app);
                names.insert(names.end(), main.begin(), main.end());
            }
            if (std::find(names.begin(), names.end(), name) != names.end()) continue;
            if (const std::string near = io::nearest_name(name, names); !near.empty())
                text += "\nunknown option " + name + "; did you mean " + near + "?";
        } else if (i == 1 && command == &app && arg.find('.') == std::string::npos) {
            if (const std::string near = io::nearest_name(arg, commands); !near.empty())
                text += "\nunknown command " + arg + "; did you mean " + near + "?";
        }
    }
    return text;
}

std::string settings_file_hint(const CLI::App& app, int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.empty() || arg[0] == '-') return {};   // options first: CLI11's own message
        for (const CLI::App* sub : app.get_subcommands({}))
            if (sub->get_name() == arg) return {};
        if (arg.size() > 4 && arg.compare(arg.size() - 4, 4, ".xml") == 0)
            return "'" + arg + "' is not a command; to run a settings file: cic --settings " + arg +
                   " (to check it: cic settings " + arg + ")";
        return {};
    }
    return {};
}

} // namespace cic::cli
