// Settings writer (effective settings, documented defaults) and the key listing for --help.
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/xml.hpp"
#include "settings_values.hpp"

namespace cic::io {

std::string write_settings(const Settings& s, bool documented) {
    auto doc = xml::Document::create("settings");
    auto root = doc.root();
    if (documented)
        root.add_comment(
            " cic settings. Every key is optional; a missing key keeps the default shown here. "
            "Keys of the thesis (Appendix B) keep their original names. Any key can be overridden on the "
            "command line with the set option (Section.key=value; see cic help). Schema: settings/cic-settings.xsd ");
    for (const auto& section : settings_sections()) {
        auto sec = root.add_element(section);
        for (const auto& k : settings_table()) {
            if (k.section != section) continue;
            if (documented)
                sec.add_comment(" " + k.doc + ". Allowed: " + describe_allowed(k) + ". Default: \"" +
                                default_text(k) + "\" ");
            sec.add_child(k.key, k.get(s));
        }
    }
    return doc.to_string();
}

std::string settings_key_listing() {
    std::string out =
        "Settings keys (XML <Section><key>value</key></Section>, or --set Section.key=value).\n"
        "`cic settings --defaults` prints a documented file with every default and allowed range.\n"
        "useMatlabPlot (Control) writes gnuplot plots in place of the thesis's Matlab plots.\n";
    for (const auto& section : settings_sections()) {
        std::string line = "  " + section + ":";
        for (const auto& k : settings_table()) {
            if (k.section != section) continue;
            if (line.size() + k.key.size() + 1 > 96) {
                out += line + "\n";
                line = "     ";
            }
            line += " " + k.key;
        }
        out += line + "\n";
    }
    return out;
}

} // namespace cic::io
