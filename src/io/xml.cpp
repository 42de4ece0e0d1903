#include "cic/io/xml.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlerror.h>
#include <libxml/xmlschemas.h>

#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cic::io::xml {
namespace {

const xmlChar* X(const char* s) { return reinterpret_cast<const xmlChar*>(s); }
const char* C(const xmlChar* s) { return reinterpret_cast<const char*>(s); }

// Collects libxml2's structured errors as "FILE:LINE: message" lines.
struct ErrorSink {
    std::string fallback_file;
    std::vector<std::string> lines;
    int first_line = 0;
    std::string first_message;   // the first problem without its place: the cause, as a rule
};

#if LIBXML_VERSION >= 21200
void collect(void* user, const xmlError* e) {
#else
void collect(void* user, xmlErrorPtr e) {
#endif
    auto* sink = static_cast<ErrorSink*>(user);
    if (e == nullptr || e->level == XML_ERR_WARNING) return;
    // One line: libxml2 gives some errors a second line (an encoding error's "Bytes: 0x..").
    std::string msg = e->message ? trim(e->message) : std::string("unknown XML error");
    for (auto p = msg.find('\n'); p != std::string::npos; p = msg.find('\n', p)) msg.replace(p, 1, "; ");
    std::string file = e->file ? e->file : sink->fallback_file;
    if (sink->lines.empty()) sink->first_line = e->line, sink->first_message = msg;
    sink->lines.push_back(file + (e->line > 0 ? ":" + std::to_string(e->line) : std::string()) +
                          ": " + msg);
}

// Installs the sink for the duration of one libxml2 call (libxml2 keeps the
// handler per thread, so this is safe with threads).
class ScopedErrors {
public:
    explicit ScopedErrors(ErrorSink& sink) { xmlSetStructuredErrorFunc(&sink, collect); }
    ~ScopedErrors() { xmlSetStructuredErrorFunc(nullptr, nullptr); }
    ScopedErrors(const ScopedErrors&) = delete;
    ScopedErrors& operator=(const ScopedErrors&) = delete;
};

const std::string kNoFile;

} // namespace

std::string trim(std::string_view s) {
    const char* ws = " \t\r\n\v\f";
    auto b = s.find_first_not_of(ws);
    if (b == std::string_view::npos) return {};
    auto e = s.find_last_not_of(ws);
    return std::string(s.substr(b, e - b + 1));
}

// ---------------------------------------------------------------- Node

std::string_view Node::name() const { return C(node_->name); }

int Node::line() const { return static_cast<int>(xmlGetLineNo(node_)); }

const std::string& Node::file() const {
    if (node_ && node_->doc && node_->doc->_private)
        return *static_cast<const std::string*>(node_->doc->_private);
    return kNoFile;
}

std::string Node::text() const {
    xmlChar* content = xmlNodeGetContent(node_);
    std::string s = content ? trim(C(content)) : std::string();
    xmlFree(content);
    return s;
}

std::optional<std::string> Node::attribute(std::string_view attr) const {
    std::string a(attr);
    xmlChar* v = xmlGetProp(node_, X(a.c_str()));
    if (!v) return std::nullopt;
    std::string s = C(v);
    xmlFree(v);
    return s;
}

std::vector<Node> Node::children() const {
    std::vector<Node> out;
    for (xmlNode* c = node_->children; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE) out.emplace_back(c);
    return out;
}

Node Node::child(std::string_view element) const {
    for (xmlNode* c = node_->children; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE && element == C(c->name)) return Node(c);
    return Node();
}

bool Node::has_element_children() const {
    for (xmlNode* c = node_->children; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE) return true;
    return false;
}

std::optional<std::string> unholdable(std::string_view text) {
    const auto* b = reinterpret_cast<const unsigned char*>(text.data());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned c = b[i];
        auto at = [&](const std::string& what) { return what + " at byte " + std::to_string(i); };
        if (c < 0x80) {
            if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
                char buf[16];
                std::snprintf(buf, sizeof buf, "U+%04X", c);
                return at(buf);
            }
            ++i;
            continue;
        }
        // A well-formed UTF-8 sequence of a character XML allows (no surrogates, no U+FFFE/FFFF).
        const std::size_t len = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
        if (len == 0 || i + len > text.size()) return at("invalid UTF-8");
        unsigned cp = c & (len == 2 ? 0x1F : len == 3 ? 0x0F : 0x07);
        for (std::size_t k = 1; k < len; ++k) {
            if ((b[i + k] & 0xC0) != 0x80) return at("invalid UTF-8");
            cp = (cp << 6) | (b[i + k] & 0x3F);
        }
        const bool overlong = (len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000);
        if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE || cp == 0xFFFF)
            return at("invalid UTF-8");
        i += len;
    }
    return std::nullopt;
}

namespace {
void check_holdable(std::string_view what, std::string_view text) {
    if (auto why = unholdable(text))
        throw std::invalid_argument("XML cannot hold " + std::string(what) + ": it contains " + *why);
}
} // namespace

InputError Node::error(const std::string& message) const {
    return InputError(message, file(), node_ ? line() : 0);
}

Node Node::add_child(std::string_view element, std::string_view text) {
    check_holdable("the text of <" + std::string(element) + ">", text);
    std::string e(element), t(text);
    return Node(xmlNewTextChild(node_, nullptr, X(e.c_str()), X(t.c_str())));
}

Node Node::add_element(std::string_view element) {
    std::string e(element);
    return Node(xmlNewChild(node_, nullptr, X(e.c_str()), nullptr));
}

void Node::set_attribute(std::string_view attr, std::string_view value) {
    check_holdable("attribute " + std::string(attr), value);
    std::string a(attr), v(value);
    xmlSetProp(node_, X(a.c_str()), X(v.c_str()));
}

void Node::add_comment(std::string_view comment) {
    std::string c(comment);
    for (auto p = c.find("--"); p != std::string::npos; p = c.find("--", p)) c.replace(p, 2, "- ");
    if (!c.empty() && c.back() == '-') c += ' ';
    xmlAddChild(node_, xmlNewComment(X(c.c_str())));
}

// ---------------------------------------------------------------- Document

Document::Document(_xmlDoc* doc, std::string file)
    : doc_(doc), file_(std::make_unique<std::string>(std::move(file))) {
    doc_->_private = file_.get();
}

Document::Document(Document&& o) noexcept : doc_(o.doc_), file_(std::move(o.file_)) {
    o.doc_ = nullptr;
}

Document& Document::operator=(Document&& o) noexcept {
    if (this != &o) {
        if (doc_) xmlFreeDoc(doc_);
        doc_ = o.doc_;
        file_ = std::move(o.file_);
        o.doc_ = nullptr;
    }
    return *this;
}

Document::~Document() {
    if (doc_) xmlFreeDoc(doc_);
}

Node Document::root() const { return Node(xmlDocGetRootElement(doc_)); }

std::string read_file(const std::filesystem::path& path) {
    // Refused by its size before it is read: a huge or sparse file would take the memory first.
    constexpr std::uintmax_t kMaxXmlFileBytes = 256ull * 1024 * 1024;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError("cannot read: is a directory", path.string());
    if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxXmlFileBytes)
        throw InputError("cannot read: " + std::to_string(size) + " bytes, past the limit of " +
                             std::to_string(kMaxXmlFileBytes) + " bytes (256 MiB) for an XML input",
                         path.string());
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(std::string("cannot read: ") + std::strerror(errno), path.string());
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError("cannot read: I/O error", path.string());
    return ss.str();
}

Document Document::load_file(const std::filesystem::path& path) {
    return parse_string(read_file(path), path.string());
}

Document Document::parse_string(std::string_view text, const std::string& name) {
    if (trim(text).empty()) throw InputError("empty file: expected an XML document", name);
    ErrorSink sink{name, {}, 0, {}};
    xmlDoc* doc = nullptr;
    {
        ScopedErrors guard(sink);
        doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), name.c_str(), nullptr,
                            XML_PARSE_NONET | XML_PARSE_BIG_LINES);
    }
    if (!doc || !sink.lines.empty()) {
        if (doc) xmlFreeDoc(doc);
        if (sink.lines.empty()) throw InputError("malformed XML", name);
        // The first error is the cause; later ones are usually consequences.
        throw InputError("malformed XML: " + sink.first_message, name, sink.first_line);
    }
    if (!xmlDocGetRootElement(doc)) {
        xmlFreeDoc(doc);
        throw InputError("no root element", name);
    }
    return Document(doc, name);
}

Document Document::create(std::string_view root_element) {
    xmlDoc* doc = xmlNewDoc(X("1.0"));
    std::string r(root_element);
    xmlDocSetRootElement(doc, xmlNewDocNode(doc, nullptr, X(r.c_str()), nullptr));
    return Document(doc, std::string());
}

std::string Document::to_string() const {
    xmlChar* buf = nullptr;
    int size = 0;
    xmlDocDumpFormatMemoryEnc(doc_, &buf, &size, "UTF-8", 1);
    if (!buf) throw std::runtime_error("cannot serialise XML document");
    std::string s(C(buf), static_cast<std::size_t>(size));
    xmlFree(buf);
    return s;
}

void Document::save_atomically(const std::filesystem::path& path) const {
    write_file_atomically(path, to_string());
}

std::vector<std::string> Document::validate(const std::filesystem::path& xsd) const {
    return Schema(read_file(xsd), xsd.string()).validate(*this);
}

// ---------------------------------------------------------------- Schema

namespace {

// Validates doc against a compiled schema, collecting every problem.
ErrorSink run_schema(xmlSchema* schema, const Document& doc) {
    ErrorSink sink{doc.file(), {}, 0, {}};
    ScopedErrors guard(sink);
    std::unique_ptr<xmlSchemaValidCtxt, decltype(&xmlSchemaFreeValidCtxt)> vctx(
        xmlSchemaNewValidCtxt(schema), xmlSchemaFreeValidCtxt);
    xmlSchemaSetValidStructuredErrors(vctx.get(), collect, &sink);
    int rc = xmlSchemaValidateDoc(vctx.get(), doc.get());
    if (rc != 0 && sink.lines.empty()) sink.lines.push_back(doc.file() + ": does not match the schema");
    return sink;
}

} // namespace

Schema::Schema(std::string_view xsd_text, const std::string& name) {
    ErrorSink sink{name, {}, 0, {}};
    ScopedErrors guard(sink);
    std::unique_ptr<xmlSchemaParserCtxt, decltype(&xmlSchemaFreeParserCtxt)> pctx(
        xmlSchemaNewMemParserCtxt(xsd_text.data(), static_cast<int>(xsd_text.size())), xmlSchemaFreeParserCtxt);
    schema_ = pctx ? xmlSchemaParse(pctx.get()) : nullptr;
    if (!schema_) {
        std::string why = sink.lines.empty() ? std::string("cannot load schema") : sink.lines.front();
        throw InputError("invalid XML schema: " + why, name);
    }
}

Schema::~Schema() {
    if (schema_) xmlSchemaFree(schema_);
}

std::vector<std::string> Schema::validate(const Document& doc) const { return run_schema(schema_, doc).lines; }

std::optional<Schema::Problem> Schema::first_problem(const Document& doc) const {
    const ErrorSink sink = run_schema(schema_, doc);
    if (sink.lines.empty()) return std::nullopt;
    return Problem{sink.first_line, sink.first_message.empty() ? "does not match the schema" : sink.first_message};
}


// ---------------------------------------------------------------- files

void write_file_atomically(const std::filesystem::path& path, std::string_view text) {
    auto fail = [&](const std::string& what, const std::filesystem::path& p) {
        throw std::runtime_error("cannot write " + p.string() + ": " + what + ": " +
                                 std::strerror(errno));
    };
    std::filesystem::path tmp = path;
    tmp += ".tmp-" + std::to_string(::getpid());
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail("open", tmp);
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            int saved = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            errno = saved;
            fail("write", tmp);
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    bool synced = ::fsync(fd) == 0;
    int saved = errno;
    if (::close(fd) != 0 && synced) {
        synced = false;
        saved = errno;
    }
    if (!synced) {
        ::unlink(tmp.c_str());
        errno = saved;
        fail("fsync", tmp);
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        int saved = errno;
        ::unlink(tmp.c_str());
        errno = saved;
        fail("rename", path);
    }
}

} // namespace cic::io::xml
