#pragma once
// The one strictness policy for every XML file cic reads: settings, sweep,
// robot, population and gait checkpoint files. Each reader names its Format and
// hands its own checks to read_strict, which applies, in this order:
//   1. parsing, with no network and no DTD loading; libxml2's error is one line,
//      "FILE:LINE: malformed XML: ...";
//   2. a DOCTYPE that declares anything (entities above all) or refers to an
//      external DTD is refused: an entity cic would drop makes a value silently
//      empty, and one it would expand could read another file;
//   3. the root element must be one the format's schema declares;
//   4. every element and attribute must be one the schema allows where it
//      stands, with the nearest allowed name suggested ("did you mean axis?"),
//      and text may stand only where the schema allows text;
//   5. the reader's own checks (values, ranges, references, with file and line);
//   6. the whole document against the format's XSD, as a net: a file the
//      schema refuses is never accepted, even where step 5 has no rule.
// Steps 3-4 read the schema itself, so the shipped XSD is the one grammar of
// each format. Step 5 comes before 6 so that a bad value gets the reader's
// message (with the allowed range) rather than libxml2's.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "cic/io/xml.hpp"

namespace cic::io::xml {

struct Format {
    std::string name;          // "robot": the schema is cic-robot.xsd
    std::string what;          // "robot file", for messages
    // The XSD text; the shipped settings/cic-NAME.xsd unless given.
    std::function<std::string()> schema;
    // Optional better messages for a name the schema does not allow (the
    // settings sections and keys have their own, naming the right section).
    std::function<std::optional<std::string>(const Node& parent, std::string_view element)> unknown_element;
    std::function<std::optional<std::string>(const Node& element, std::string_view attribute)> unknown_attribute;
};

// The built-in formats (the settings format is io::settings_format()).
const Format& sweep_format();
const Format& robot_format();
const Format& population_format();
const Format& gait_format();
const Format& archive_format();

// Steps 1-4 on a text; `name` stands for the file in messages.
Document parse_strict(std::string_view text, const std::string& name, const Format& format);
// Step 6: throws InputError "FILE:LINE: does not match cic-NAME.xsd: ...".
// Values are checked as the readers read them, trimmed (libxml2 does not
// collapse the whitespace of a restricted xs:long, as XSD says it should), so
// the document's texts and attributes are trimmed first.
void check_schema(Document& doc, const Format& format);
// The schema text of a format (cic-NAME.xsd as compiled into cic).
std::string schema_text(const Format& format);

// Steps 1-6: the reader gets the document after 1-4 and returns its result.
template <class Read>
auto read_strict(std::string_view text, const std::string& name, const Format& format, Read&& read) {
    Document doc = parse_strict(text, name, format);
    auto result = std::forward<Read>(read)(std::as_const(doc));
    check_schema(doc, format);
    return result;
}

template <class Read>
auto load_strict(const std::filesystem::path& path, const Format& format, Read&& read) {
    return read_strict(read_file(path), path.string(), format, std::forward<Read>(read));
}

} // namespace cic::io::xml
