#pragma once
// A small RAII wrapper over libxml2 shared by the settings, population and
// robot readers/writers. Parse errors and reader errors are cic::InputError
// with "FILE:LINE: message"; files are written atomically (temp + rename).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cic/core/error.hpp"

struct _xmlDoc;   // libxml2's xmlDoc / xmlNode / xmlSchema, kept out of this header
struct _xmlNode;
struct _xmlSchema;

namespace cic::io::xml {

// Why XML 1.0 cannot hold `text` ("U+0001 at byte 5", "invalid UTF-8 at byte 3"),
// or nothing when it can. Writers refuse such text rather than write a file
// that no reader would take back.
std::optional<std::string> unholdable(std::string_view text);

// A non-owning handle on one element of a Document (valid while it lives).
class Node {
public:
    Node() = default;
    explicit Node(_xmlNode* node) : node_(node) {}

    explicit operator bool() const { return node_ != nullptr; }
    _xmlNode* get() const { return node_; }

    std::string_view name() const;
    int line() const;                                   // 1-based source line, 0 if built in memory
    const std::string& file() const;                    // document's file (or given name)
    std::string text() const;                           // text content, whitespace-trimmed
    std::optional<std::string> attribute(std::string_view attr) const;
    std::vector<Node> children() const;                 // element children only, in order
    Node child(std::string_view element) const;         // first element child so named, or null
    bool has_element_children() const;

    // An InputError naming this node's file and line: "FILE:LINE: message".
    InputError error(const std::string& message) const;

    // Building documents. Text and values are escaped; text XML cannot hold
    // (see unholdable) throws std::invalid_argument.
    Node add_child(std::string_view element, std::string_view text = {});
    Node add_element(std::string_view element);          // no text; for nested elements
    void set_attribute(std::string_view attr, std::string_view value);
    void add_comment(std::string_view comment);          // "--" is replaced to stay valid XML

private:
    _xmlNode* node_ = nullptr;
};

// An owned libxml2 document.
class Document {
public:
    // Reads and parses a file with XML_PARSE_NONET. A missing/unreadable file,
    // malformed XML or an empty document throws InputError "FILE:LINE: message".
    static Document load_file(const std::filesystem::path& path);
    // Parses text; `name` stands for the file in messages (tests, --set, stdin).
    static Document parse_string(std::string_view text, const std::string& name = "<string>");
    // A new empty document with the given root element.
    static Document create(std::string_view root_element);

    Document(Document&&) noexcept;
    Document& operator=(Document&&) noexcept;
    ~Document();

    Node root() const;
    const std::string& file() const { return *file_; }
    _xmlDoc* get() const { return doc_; }

    std::string to_string() const;                              // indented, UTF-8, with declaration
    void save_atomically(const std::filesystem::path& path) const;

    // Validates against an XSD file; returns one "FILE:LINE: message" per problem
    // (empty = valid). An unreadable or broken schema throws InputError.
    std::vector<std::string> validate(const std::filesystem::path& xsd) const;

private:
    Document(_xmlDoc* doc, std::string file);
    _xmlDoc* doc_ = nullptr;
    std::unique_ptr<std::string> file_;   // stable address: doc_->_private points at it
};

// A compiled XSD schema. Compile once and share: validating does not change it.
class Schema {
public:
    // `name` stands for the schema in messages. A broken schema throws InputError.
    Schema(std::string_view xsd_text, const std::string& name);
    Schema(const Schema&) = delete;
    Schema& operator=(const Schema&) = delete;
    ~Schema();

    // One "FILE:LINE: message" per problem (empty = valid).
    std::vector<std::string> validate(const Document& doc) const;
    // The first problem, the cause as a rule: its line (0 if unknown) and message.
    struct Problem {
        int line = 0;
        std::string message;
    };
    std::optional<Problem> first_problem(const Document& doc) const;

private:
    _xmlSchema* schema_ = nullptr;
};

// Writes FILE.tmp-<pid>, fsyncs it, then renames it over FILE, so readers never
// see a half-written file. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

// Reads a whole file; throws InputError "FILE: cannot read: reason".
std::string read_file(const std::filesystem::path& path);

// Helper for readers: the trimmed copy of s.
std::string trim(std::string_view s);

} // namespace cic::io::xml
