// `cic settings`: the documented defaults, the XSD schema, the key table, or
// the effective settings of a file (+ --set overrides) after validation.
#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/run/run.hpp"
#include "cic/run/settings_lookup.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/xml.hpp"

namespace cic::cli {
namespace {

// One Markdown table row per key (the key table of docs/settings.md is made from this).
std::string key_table() {
    std::string out = "| key | default | allowed | meaning |\n|---|---|---|---|\n";
    for (const auto& k : io::settings_table()) {
        std::string def = io::default_text(k);
        std::string allowed = io::describe_allowed(k);
        for (auto p = allowed.find('|'); p != std::string::npos; p = allowed.find('|', p + 2))
            allowed.insert(p, "\\");   // a bare | would split the Markdown cell
        out += "| `" + k.section + "." + k.key + "` | `" + (def.empty() ? std::string(" ") : def) + "` | " +
               allowed + " | " + k.doc + " |\n";
    }
    return out;
}

} // namespace

void add_settings_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::string file;
        std::vector<std::string> sets;
        std::string validate_xsd;
        bool defaults = false, schema = false, keys = false;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "settings", "Print the documented default settings, the XSD schema or the key table; with FILE, "
                    "check it and print its effective settings (every key, defaults filled in)");
    cmd.option("file", opts->file, "settings file to check");
    cmd.option("--set", opts->sets, "override Section.key=value (repeatable)");
    cmd.flag("--defaults", opts->defaults, "print a complete settings file with every default, documented");
    cmd.flag("--schema", opts->schema, "print the XSD schema (settings/cic-settings.xsd)");
    cmd.flag("--keys", opts->keys, "print every key with default, allowed values and meaning (Markdown)");
    cmd.option("--xsd", opts->validate_xsd, "also validate FILE against this XSD with libxml2");
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "settings", [&] {
            if (opts->defaults + opts->schema + opts->keys + !opts->file.empty() != 1)
                throw InputError("give exactly one of FILE, --defaults, --schema, --keys");
            if (opts->defaults) {
                std::cout << io::write_settings(io::Settings{}, true);
            } else if (opts->schema) {
                std::cout << io::settings_schema();
            } else if (opts->keys) {
                std::cout << key_table();
            } else {
                // Found as --settings finds it (the installed settings too), then
                // the same checks as a run: robot, dataset, population to resume from.
                const std::string file = run::find_settings_file(opts->file).string();
                auto settings = run::prepare_run(io::load_settings(file, opts->sets)).settings;
                if (!opts->validate_xsd.empty()) {
                    auto problems = io::xml::Document::load_file(file).validate(opts->validate_xsd);
                    if (!problems.empty()) throw InputError("schema: " + problems.front());
                }
                std::cout << io::write_settings(settings);
            }
            return 0;
        });
    });
}

} // namespace cic::cli
