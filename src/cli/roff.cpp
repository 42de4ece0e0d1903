// roff for the man page: escaping, and one option or usage line of a command.
#include "docs.hpp"

#include <cstdio>
#include <string>

namespace cic::cli::docs {

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

} // namespace cic::cli::docs
