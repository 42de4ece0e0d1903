// Hidden subcommands that print documentation made from the same sources as
// --help: `cic man` (the roff man page cic.1) and `cic completion` (the bash
// completion script). Both read the CLI11 App objects at run time (every
// subcommand with its description and options) and the settings table, so the
// installed man page and completion never drift from the binary. The build
// runs them (cmake/CicInstall.cmake) and installs their output.
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cic/app/command_guard.hpp"
#include "cic/app/commands.hpp"
#include "cic/io/settings_table.hpp"

namespace cic::app {
namespace {

// ---- what the CLI11 objects say ---------------------------------------------

bool hidden(const CLI::App* sub) { return sub->get_group().empty() || sub->get_name().empty(); }

bool takes_value(const CLI::Option* opt) { return opt->get_items_expected_max() > 0; }

bool repeatable(const CLI::Option* opt) { return opt->get_items_expected_max() > 1; }

// Every spelling of an option: -j, --jobs (or the positional's name).
std::vector<std::string> option_names(const CLI::Option* opt) {
    std::vector<std::string> names;
    for (const auto& s : opt->get_snames()) names.push_back("-" + s);
    for (const auto& l : opt->get_lnames()) names.push_back("--" + l);
    if (names.empty()) names.push_back(opt->get_name(true));
    return names;
}

// "FLOAT:POSITIVE" -> "FLOAT" (the placeholder) and "POSITIVE" (the check).
std::string value_type(const CLI::Option* opt) {
    const std::string t = opt->get_type_name();
    return t.substr(0, t.find(':'));
}
std::string value_check(const CLI::Option* opt) {
    const std::string t = opt->get_type_name();
    const auto colon = t.find(':');
    if (colon == std::string::npos) return {};
    std::string check = t.substr(colon + 1);   // "INT in [1 - 4096]" -> "in [1 - 4096]"
    if (check.rfind(value_type(opt) + " ", 0) == 0) check.erase(0, value_type(opt).size() + 1);
    return check;
}

std::vector<const CLI::Option*> positionals(const CLI::App& app) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : app.get_options())
        if (opt->get_positional() && opt->get_lnames().empty() && opt->get_snames().empty()) out.push_back(opt);
    return out;
}

std::vector<const CLI::Option*> named_options(const CLI::App& app) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : app.get_options())
        if (!opt->get_lnames().empty() || !opt->get_snames().empty()) out.push_back(opt);
    return out;
}

// Options whose value is a word, not a file (everything else that takes TEXT
// completes file names). Keep in step with new word-valued options.
bool word_valued(const std::string& name) {
    static const std::set<std::string> words{"--seed",  "--seeds",      "--individual", "--controller",
                                             "--title", "--joints",     "--metric",     "--set"};
    return words.count(name) > 0;
}

// What a value of `opt` is: "keys" (Section.key=), "file", "dir" or "" (no completion).
std::string value_kind(const CLI::Option* opt) {
    const std::string name = option_names(opt).back();
    if (name == "--set") return "keys";
    if (word_valued(name) || value_type(opt) != "TEXT") return "";
    const std::string& d = opt->get_description();
    const bool folder = d.find("folder") != std::string::npos || d.find("DIR") != std::string::npos;
    const bool file = d.find("file") != std::string::npos || d.find("XML") != std::string::npos;
    return folder && !file ? "dir" : "file";
}

// ---- roff --------------------------------------------------------------------

// Escapes text for roff: backslashes, hyphens (as \- so options copy and paste),
// non-ASCII characters (as \[uXXXX]), and a leading . or ' (read as a request).
std::string roff(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else if (c < 0x80) {
            if ((c == '.' || c == '\'') && (out.empty() || out.back() == '\n')) out += "\\&";
            out += static_cast<char>(c);
        } else {   // one UTF-8 sequence
            int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
            unsigned cp = extra == 3 ? c & 0x07u : extra == 2 ? c & 0x0Fu : extra == 1 ? c & 0x1Fu : '?';
            for (; extra > 0 && i + 1 < text.size(); --extra)
                cp = (cp << 6) | (static_cast<unsigned char>(text[++i]) & 0x3Fu);
            char buf[16];
            std::snprintf(buf, sizeof buf, "\\[u%04X]", cp);
            out += buf;
        }
    }
    return out;
}

// One paragraph: each input line becomes a line of its own (.br between them).
std::string roff_lines(const std::string& text) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        const auto start = line.find_first_not_of(' ');
        if (start == std::string::npos) continue;
        if (!first) out += ".br\n";
        out += roff(line.substr(start)) + '\n';
        first = false;
    }
    return out;
}

// "-q, --quiet" in bold, then the value placeholder in italics.
std::string roff_option_label(const CLI::Option* opt) {
    std::string label;
    for (const auto& n : option_names(opt)) label += (label.empty() ? "" : ", ") + ("\\fB" + roff(n) + "\\fR");
    if (takes_value(opt)) label += " \\fI" + roff(value_type(opt)) + "\\fR" + (repeatable(opt) ? "\\ ..." : "");
    return label;
}

std::string roff_option(const CLI::Option* opt, bool positional) {
    std::string out = ".TP\n";
    if (positional)
        out += "\\fI" + roff(opt->get_name(true)) + "\\fR" + (repeatable(opt) ? "\\ ..." : "") + "\n";
    else
        out += roff_option_label(opt) + "\n";
    std::string text = opt->get_description();
    std::vector<std::string> notes;
    if (opt->get_required()) notes.push_back("required");
    if (!value_check(opt).empty()) notes.push_back(value_check(opt));
    if (!opt->get_default_str().empty()) notes.push_back("default: " + opt->get_default_str());
    for (const CLI::Option* ex : opt->get_excludes()) notes.push_back("not with " + option_names(ex).back());
    if (!notes.empty()) {
        text += " (";
        for (std::size_t i = 0; i < notes.size(); ++i) text += (i ? "; " : "") + notes[i];
        text += ")";
    }
    return out + roff(text) + "\n";
}

std::string usage(const CLI::App& sub) {
    std::string u = "cic " + sub.get_name() + " [OPTIONS]";
    for (const CLI::Option* p : positionals(sub)) {
        std::string name = p->get_name(true) + (repeatable(p) ? "..." : "");
        u += " " + (p->get_required() ? name : "[" + name + "]");
    }
    return u;
}

// The NAME line: the first line of the app's description without "cic: " and
// its parenthesis ("evolutionary robotics with HyperGP, and symbolic regression").
std::string short_description(const CLI::App& app) {
    std::string d = app.get_description();
    d = d.substr(0, d.find('\n'));
    if (d.rfind("cic: ", 0) == 0) d = d.substr(5);
    const auto open = d.find(" (");
    const auto close = d.find(')', open == std::string::npos ? 0 : open);
    if (open != std::string::npos && close != std::string::npos) d.erase(open, close - open + 1);
    while (!d.empty() && (d.back() == '.' || d.back() == ' ')) d.pop_back();
    return d;
}

std::string man_page(CLI::App& app) {
    std::ostringstream m;
    m << ".\\\" Generated by `cic man` from the command line and the settings table; do not edit.\n"
      << ".TH CIC 1 \"\" \"cic " << CIC_VERSION << "\" \"User Commands\"\n"
      << ".nh\n.ad l\n"   // no hyphenation of paths and keys; ragged right
      << ".SH NAME\ncic \\- " << roff(short_description(app)) << "\n"
      << ".SH SYNOPSIS\n"
      << ".B cic\n\\fB\\-\\-settings\\fR \\fIFILE\\fR [\\fIOPTIONS\\fR]\n.br\n"
      << ".B cic\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIARGUMENTS\\fR]\n"
      << ".SH DESCRIPTION\n"
      << roff_lines(app.get_description())
      << ".PP\n"
      << roff("A settings file given to --settings that is not found as given (relative to the current "
              "folder) is looked up among the installed settings (PREFIX/share/cic/settings, next to the "
              "binary) and then in the source tree's settings folder; cic then names the file it uses on "
              "standard error. So `cic --settings r1_settings.xml` runs the shipped R1 experiment from any "
              "folder.")
      << "\n.PP\n"
      << roff("Each command below has its own --help. `cic man` prints this page and `cic completion` the bash "
              "completion script; both are made from the same command line and settings table as --help.")
      << "\n.SH OPTIONS\n";
    for (const CLI::Option* opt : named_options(app)) m << roff_option(opt, false);

    m << ".SH COMMANDS\n";
    for (const CLI::App* sub : app.get_subcommands({})) {
        if (hidden(sub)) continue;
        m << ".SS " << sub->get_name() << "\n"
          << ".B " << roff(usage(*sub)) << "\n.PP\n"
          << roff(sub->get_description()) << "\n";
        for (const CLI::Option* p : positionals(*sub)) m << roff_option(p, true);
        for (const CLI::Option* opt : named_options(*sub)) m << roff_option(opt, false);
    }

    m << ".SH SETTINGS\n"
      << roff("A settings file is XML: <settings><Section><key>value</key></Section>...</settings>. Every key "
              "not given takes its default. On the command line, --set Section.key=value overrides one key "
              "(repeatable). `cic settings --defaults` prints a complete documented file, `cic settings --schema` "
              "the XSD, and `cic settings FILE` checks FILE and prints its effective settings. A relative path "
              "in a file is resolved against that file's folder, one given with --set against the current folder.")
      << "\n";
    for (const auto& section : io::settings_sections()) {
        m << ".SS " << section << "\n";
        for (const auto& k : io::settings_table()) {
            if (k.section != section) continue;
            const std::string def = io::default_text(k);
            m << ".TP\n\\fB" << roff(k.section + "." + k.key) << "\\fR\n"
              << roff(k.doc) << ".\n.br\n"
              << "Default: " << (def.empty() ? std::string("(empty)") : "\\fB" + roff(def) + "\\fR")
              << "; allowed: " << roff(io::describe_allowed(k)) << ".\n";
        }
    }

    m << ".SH EXIT STATUS\n"
      << ".TP\n.B 0\nDone.\n"
      << ".TP\n.B 1\n" << roff("Run failure (a simulation, worker, file system or other run-time error).") << "\n"
      << ".TP\n.B 2\n" << roff("Bad input: an unknown option, a bad settings value, a missing or malformed file. "
                               "Checked before anything is written.") << "\n"
      << ".TP\n.B 130\n" << roff("Interrupted by SIGINT (Ctrl-C): the generation under way was finished and "
                                 "checkpointed; resume from population.xml.") << "\n"
      << ".TP\n.B 143\n" << roff("Terminated by SIGTERM (for example by a batch scheduler): checkpointed as for "
                                 "SIGINT.") << "\n";

    auto file = [&](const std::string& path, const std::string& text) {
        m << ".TP\n.I " << roff(path) << "\n" << roff(text) << "\n";
    };
    m << ".SH FILES\n"
      << roff("PREFIX is the installation prefix: /usr for the Debian package, /usr/local by default for "
              "cmake --install.") << "\n";
    file("PREFIX/share/cic/settings/*.xml",
         "the shipped settings files (the thesis's table B.1 experiments and symbolic regression); "
         "--settings NAME.xml finds them from any folder");
    file("PREFIX/share/cic/settings/robots/*.xml", "robot files, found by the settings files that name them");
    file("PREFIX/share/cic/settings/cic-settings.xsd", "XML schema of settings files (also `cic settings --schema`)");
    file("PREFIX/share/cic/settings/cic-sweep.xsd", "XML schema of sweep files (cic sweep)");
    file("PREFIX/share/cic/examples/*.xml", "example sweep files");
    file("PREFIX/share/doc/cic/", "the documentation (README.md and the guides)");
    file("PREFIX/share/bash-completion/completions/cic", "bash completion (made by `cic completion`)");
    file("OUTPUT/NAME-NNN/",
         "a run's folder: settings.xml (the effective settings), run.log, stats.csv, populations/gen-NNNN.xml "
         "checkpoints, population.xml (the latest) and summary.txt");

    m << ".SH SEE ALSO\n"
      << ".BR gnuplot (1),\n.BR povray (1),\n.BR ffmpeg (1),\n.BR mpirun (1),\n.BR sbatch (1)\n.PP\n"
      << roff("README.md and docs/*.md in PREFIX/share/doc/cic, in particular settings.md, install.md, "
              "statistics.md and mpi.md.")
      << "\n";
    return m.str();
}

// ---- bash completion -----------------------------------------------------------

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : " ") + i;
    return s;
}

// Shell-safe: option and command names are plain words; quote anyway.
std::string quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

struct Scope {
    std::string name;   // "" for the main command
    std::vector<std::string> options;
    std::vector<std::pair<std::string, std::string>> value_options;   // name, kind: keys, settings, file, dir, ""
    std::string positional_kind;                                      // "file", "dir" or ""
};

Scope scope_of(const CLI::App& app, const std::string& name) {
    Scope s;
    s.name = name;
    for (const CLI::Option* opt : named_options(app)) {
        for (const auto& n : option_names(opt)) {
            s.options.push_back(n);
            // The main job's --settings also finds the installed settings by name (settings_lookup.hpp).
            if (takes_value(opt))
                s.value_options.emplace_back(n, name.empty() && n == "--settings" ? "settings" : value_kind(opt));
        }
    }
    for (const CLI::Option* p : positionals(app)) {
        const std::string kind = value_kind(p).empty() ? std::string("file") : value_kind(p);
        if (s.positional_kind.empty() || kind == "file") s.positional_kind = kind;
    }
    return s;
}

std::string completion_script(CLI::App& app) {
    std::vector<Scope> scopes{scope_of(app, "")};
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) {
        if (hidden(sub)) continue;
        commands.push_back(sub->get_name());
        scopes.push_back(scope_of(*sub, sub->get_name()));
    }
    std::vector<std::string> keys;
    for (const auto& k : io::settings_table()) keys.push_back(k.section + "." + k.key + "=");

    std::ostringstream b;
    b << "# bash completion for cic                                  -*- shell-script -*-\n"
      << "# Generated by `cic completion` (cic " << CIC_VERSION << ") from its command line and settings\n"
      << "# table; do not edit. Install as share/bash-completion/completions/cic, or source it.\n\n"
      << "_cic_commands=" << quoted(join(commands)) << "\n"
      << "_cic_keys=" << quoted(join(keys)) << "\n\n";

    b << "# Options of the main command (\"\") and of each subcommand.\n_cic_options() {\n    case \"$1\" in\n";
    for (const auto& s : scopes) b << "        " << quoted(s.name) << ") echo " << quoted(join(s.options)) << " ;;\n";
    b << "    esac\n}\n\n";

    b << "# What the value of option $2 in scope $1 is: keys, settings, file, dir, word; empty = a flag.\n"
      << "_cic_value_kind() {\n    case \"$1 $2\" in\n";
    for (const auto& s : scopes)
        for (const auto& [name, kind] : s.value_options)
            b << "        " << quoted(s.name + " " + name) << ") echo " << (kind.empty() ? "word" : kind) << " ;;\n";
    b << "    esac\n}\n\n";

    b << "# What the positional arguments of scope $1 are: file, dir, or nothing.\n"
      << "_cic_positional_kind() {\n    case \"$1\" in\n";
    for (const auto& s : scopes)
        if (!s.positional_kind.empty()) b << "        " << quoted(s.name) << ") echo " << s.positional_kind << " ;;\n";
    b << "    esac\n}\n\n";

    b << "# Values of settings key $1 with a fixed set of them.\n_cic_key_values() {\n    case \"$1\" in\n";
    for (const auto& k : io::settings_table()) {
        std::vector<std::string> values;
        if (k.type == io::ValueType::Bool) values = {"0", "1"};
        if (k.type == io::ValueType::Enum)
            for (const auto& choice : k.choices) values.insert(values.end(), choice.begin(), choice.end());
        if (!values.empty())
            b << "        " << quoted(k.section + "." + k.key) << ") echo " << quoted(join(values)) << " ;;\n";
    }
    b << "    esac\n}\n\n";

    b << R"BASH(# COMPREPLY from the words in $1 that start with $cur. When $cur holds
# an '=' (a word break for bash), only the part after it is replaced.
_cic_reply() {
    local w prefix=""
    COMPREPLY=()
    [[ $cur == *=* && $COMP_WORDBREAKS == *=* ]] && prefix=${cur%=*}=
    for w in $1; do
        [[ $w == "$cur"* ]] && COMPREPLY+=("${w#"$prefix"}")
    done
}

_cic_files() {   # $1: file or dir
    local IFS=$'\n'
    compopt -o filenames 2>/dev/null
    if [[ $1 == dir ]]; then
        COMPREPLY=($(compgen -d -- "$cur"))
    else
        COMPREPLY=($(compgen -f -- "$cur"))
    fi
}

# Files, and the installed settings files by name (cic --settings NAME.xml finds them).
_cic_settings_files() {
    _cic_files file
    local exe f
    exe=$(type -P cic) || return 0
    for f in "$(dirname "$(readlink -f "$exe")")"/../share/cic/settings/*.xml; do
        [[ -f $f ]] || continue
        f=${f##*/}
        [[ $f == "$cur"* && ! -e $f ]] && COMPREPLY+=("$f")
    done
}

_cic() {
    # Words as typed (quotes aside), not split at '=' as COMP_WORDS is.
    local line=${COMP_LINE:0:COMP_POINT}
    local -a words
    read -r -a words <<< "$line"
    local cur=""
    [[ $line == *[[:space:]] ]] || { cur=${words[-1]}; unset 'words[-1]'; }

    local scope="" i w kind expect=""
    for ((i = 1; i < ${#words[@]}; i++)); do
        w=${words[i]}
        if [[ -n $expect ]]; then expect=""; continue; fi
        if [[ $w == -* && $w != *=* ]]; then
            kind=$(_cic_value_kind "$scope" "$w")
            [[ -z $kind ]] && [[ -n $scope ]] && kind=$(_cic_value_kind "" "$w")
            [[ -n $kind ]] && expect=$w
        elif [[ -z $scope && " $_cic_commands " == *" $w "* ]]; then
            scope=$w
        fi
    done

    # The value of an option: the option word before, or --opt=value.
    local opt=$expect
    if [[ -z $opt && $cur == --*=* ]]; then
        opt=${cur%%=*}
        cur=${cur#*=}
    fi
    if [[ -n $opt ]]; then
        kind=$(_cic_value_kind "$scope" "$opt")
        [[ -z $kind ]] && kind=$(_cic_value_kind "" "$opt")
        case $kind in
            keys)
                if [[ $cur == *=* ]]; then
                    local key=${cur%%=*} v values=""
                    for v in $(_cic_key_values "$key"); do values+=" $key=$v"; done
                    _cic_reply "$values"
                else
                    _cic_reply "$_cic_keys"
                    compopt -o nospace 2>/dev/null
                fi ;;
            settings) _cic_settings_files ;;
            file | dir) _cic_files "$kind" ;;
            *) COMPREPLY=() ;;
        esac
        return 0
    fi

    if [[ $cur == -* ]]; then
        _cic_reply "$(_cic_options "$scope")"
    elif [[ -z $scope ]]; then
        _cic_reply "$_cic_commands"
    else
        kind=$(_cic_positional_kind "$scope")
        if [[ -n $kind ]]; then _cic_files "$kind"; else COMPREPLY=(); fi
    fi
    return 0
}

complete -F _cic cic
)BASH";
    return b.str();
}

} // namespace

void add_docs_commands(Command& root, CommandContext& ctx) {
    CLI::App& app = *root.app();   // introspection: every option and check of every command
    // group(""): hidden from --help; the build runs them to make cic.1 and the completion.
    app.add_subcommand("man", "Print the man page cic(1) as roff, made from the command line and settings table")
        ->group("")
        ->callback([&app, &ctx] {
            run_guarded(ctx, "man", [&] {
                std::cout << man_page(app);
                return std::cout.flush() ? 0 : 1;
            });
        });
    app.add_subcommand("completion", "Print the bash completion script for cic")
        ->group("")
        ->callback([&app, &ctx] {
            run_guarded(ctx, "completion", [&] {
                std::cout << completion_script(app);
                return std::cout.flush() ? 0 : 1;
            });
        });
}

} // namespace cic::app
