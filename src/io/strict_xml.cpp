// The strictness policy of every XML reader (see strict_xml.hpp).
#include "cic/io/strict_xml.hpp"

#include <libxml/tree.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

#include "cic/io/did_you_mean.hpp"

namespace cic::io::xml {
namespace detail {
std::string_view shipped_schema(std::string_view format);   // generated: cmake/CicSchemas.cmake
}

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kXsi = "http://www.w3.org/2001/XMLSchema-instance";

// What may stand where, read from the schema: per element path ("robot/module"),
// its attributes, its child elements and whether it holds text.
struct Rule {
    std::vector<std::string> attributes;
    std::vector<std::string> children;
    bool text = false;
};

struct Grammar {
    std::vector<std::string> roots;
    std::map<std::string, Rule> rules;
};

bool is_xs(const Node& n, std::string_view local) { return n.name() == local; }

class GrammarReader {
public:
    explicit GrammarReader(const Document& xsd) {
        for (const Node& n : xsd.root().children())
            if (is_xs(n, "complexType") && n.attribute("name")) types_[*n.attribute("name")] = n;
        for (const Node& n : xsd.root().children())
            if (is_xs(n, "element")) {
                const std::string name = n.attribute("name").value_or("");
                grammar_.roots.push_back(name);
                define(name, n);
            }
    }
    Grammar take() { return std::move(grammar_); }

private:
    void define(const std::string& path, const Node& element) {
        Rule rule;
        if (auto type = element.attribute("type")) {
            if (auto it = types_.find(*type); it != types_.end()) fill(path, it->second, rule);
            else rule.text = true;   // xs:string, xs:int, a named simple type
        } else {
            bool typed = false;
            for (const Node& c : element.children()) {
                if (is_xs(c, "complexType")) fill(path, c, rule), typed = true;
                else if (is_xs(c, "simpleType")) rule.text = true, typed = true;
            }
            if (!typed) rule.text = true;   // xs:anyType
        }
        grammar_.rules[path] = std::move(rule);
    }

    void fill(const std::string& path, const Node& type, Rule& rule) {
        if (type.attribute("mixed").value_or("") == "true") rule.text = true;
        for (const Node& c : type.children()) {
            const std::string_view n = c.name();
            if (n == "element") {
                const std::string name = c.attribute("name").value_or("");
                if (std::find(rule.children.begin(), rule.children.end(), name) == rule.children.end())
                    rule.children.push_back(name);
                define(path + "/" + name, c);
            } else if (n == "attribute") {
                rule.attributes.push_back(c.attribute("name").value_or(""));
            } else if (n == "simpleContent") {
                rule.text = true;
                fill(path, c, rule);
            } else if (n == "extension" || n == "restriction") {
                if (auto it = types_.find(c.attribute("base").value_or("")); it != types_.end())
                    fill(path, it->second, rule);
                fill(path, c, rule);
            } else if (n == "sequence" || n == "choice" || n == "all" || n == "complexContent") {
                fill(path, c, rule);
            }
        }
    }

    std::map<std::string, Node> types_;
    Grammar grammar_;
};

struct Compiled {
    Grammar grammar;
    std::unique_ptr<Schema> schema;
};

// Each format's schema is read and compiled once per process.
const Compiled& compiled(const Format& format) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<Compiled>> cache;
    const std::lock_guard lock(mutex);
    auto& slot = cache[format.name];
    if (!slot) {
        const std::string text = schema_text(format);
        const std::string name = "cic-" + format.name + ".xsd";
        slot = std::make_unique<Compiled>();
        slot->grammar = GrammarReader(Document::parse_string(text, name)).take();
        slot->schema = std::make_unique<Schema>(text, name);
    }
    return *slot;
}

std::string listing(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

int line_of(std::string_view text, std::size_t offset) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

// Step 2: cic reads no DTDs. A bare <!DOCTYPE name> is harmless; one that
// declares anything or names an external DTD is refused, with one message.
void refuse_declarations(const Document& doc, std::string_view text) {
    for (const _xmlDtd* dtd : {doc.get()->intSubset, doc.get()->extSubset}) {
        if (!dtd) continue;
        if (dtd->children || dtd->ExternalID || dtd->SystemID || dtd->entities || dtd->pentities) {
            const auto at = text.find("<!DOCTYPE");
            throw InputError("a DOCTYPE that declares entities or refers to a DTD is not read: cic's files have no "
                             "DTD and no entities; remove the <!DOCTYPE ...> (the format is checked against its XSD)",
                             doc.file(), at == std::string_view::npos ? 0 : line_of(text, at));
        }
    }
}

std::string short_text(std::string s) {
    s = trim(s);
    if (s.size() > 30) s = s.substr(0, 27) + "...";
    return s;
}

// Step 4, for one element and below.
void check_vocabulary(const Node& node, const std::string& path, const Grammar& grammar, const Format& format) {
    const Rule& rule = grammar.rules.at(path);
    for (const _xmlAttr* a = node.get()->properties; a; a = a->next) {
        const std::string name = reinterpret_cast<const char*>(a->name);
        if (a->ns && a->ns->href && reinterpret_cast<const char*>(a->ns->href) == kXsi) continue;   // xsi:noNamespaceSchemaLocation
        if (std::find(rule.attributes.begin(), rule.attributes.end(), name) != rule.attributes.end()) continue;
        if (format.unknown_attribute)
            if (auto msg = format.unknown_attribute(node, name)) throw node.error(*msg);
        throw node.error("<" + std::string(node.name()) + "> has no attribute " + name + did_you_mean(name, rule.attributes) +
                         " (allowed: " + listing(rule.attributes) + ")");
    }
    for (const _xmlNode* c = node.get()->children; c; c = c->next) {
        if (c->type == XML_ELEMENT_NODE) {
            const Node child(const_cast<_xmlNode*>(c));
            const std::string name(child.name());
            if (std::find(rule.children.begin(), rule.children.end(), name) == rule.children.end()) {
                if (format.unknown_element)
                    if (auto msg = format.unknown_element(node, name)) throw child.error(*msg);
                throw child.error("unknown element <" + name + "> in <" + std::string(node.name()) + ">" +
                                  did_you_mean(name, rule.children) + " (allowed: " + listing(rule.children) + ")");
            }
            check_vocabulary(child, path + "/" + name, grammar, format);
        } else if ((c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) && !rule.text) {
            const std::string text = c->content ? reinterpret_cast<const char*>(c->content) : "";
            if (!trim(text).empty())
                throw InputError("stray text \"" + short_text(text) + "\" in <" + std::string(node.name()) +
                                     ">, which holds only elements",
                                 node.file(), static_cast<int>(xmlGetLineNo(const_cast<_xmlNode*>(c))));
        } else if (c->type == XML_ENTITY_REF_NODE) {
            throw node.error("an entity reference (&" + std::string(reinterpret_cast<const char*>(c->name)) +
                             ";) in <" + std::string(node.name()) + ">: cic's files have no entities");
        }
    }
}

const xmlChar* X(const std::string& s) { return reinterpret_cast<const xmlChar*>(s.c_str()); }

// Trims every attribute value and the text of every element that holds one text node.
void trim_values(_xmlNode* first) {
    for (_xmlNode* n = first; n; n = n->next) {
        if (n->type != XML_ELEMENT_NODE) continue;
        for (_xmlAttr* a = n->properties; a; a = a->next) {
            xmlChar* v = xmlNodeListGetString(n->doc, a->children, 1);
            const std::string value = v ? reinterpret_cast<const char*>(v) : "";
            xmlFree(v);
            if (trim(value) != value) xmlSetNsProp(n, a->ns, a->name, X(trim(value)));
        }
        _xmlNode* only = n->children;
        if (only && !only->next && only->type == XML_TEXT_NODE && only->content) {
            const std::string text = reinterpret_cast<const char*>(only->content);
            if (trim(text) != text) xmlNodeSetContent(only, X(trim(text)));   // a text node's content is raw
        }
        trim_values(n->children);
    }
}

} // namespace

std::string schema_text(const Format& format) {
    if (format.schema) return format.schema();
    const std::string_view text = detail::shipped_schema(format.name);
    if (text.empty()) throw std::logic_error("no schema compiled in for format " + format.name);
    return std::string(text);
}

Document parse_strict(std::string_view text, const std::string& name, const Format& format) {
    Document doc = Document::parse_string(text, name);
    refuse_declarations(doc, text);
    const Grammar& grammar = compiled(format).grammar;
    const Node root = doc.root();
    const std::string rname(root.name());
    if (std::find(grammar.roots.begin(), grammar.roots.end(), rname) == grammar.roots.end()) {
        std::string allowed;
        for (const auto& r : grammar.roots) allowed += (allowed.empty() ? "<" : " or <") + r + ">";
        throw root.error("not a " + format.what + ": the root element is <" + rname + ">; a " + format.what +
                         "'s is " + allowed);
    }
    check_vocabulary(root, rname, grammar, format);
    return doc;
}

void check_schema(Document& doc, const Format& format) {
    trim_values(doc.get()->children);
    const auto problem = compiled(format).schema->first_problem(doc);
    if (!problem) return;
    throw InputError("does not match cic-" + format.name + ".xsd: " + problem->message, doc.file(), problem->line);
}

const Format& sweep_format() {
    static const Format f{"sweep", "sweep file", {}, {}, {}};
    return f;
}
const Format& robot_format() {
    static const Format f{"robot", "robot file", {}, {}, {}};
    return f;
}
const Format& population_format() {
    static const Format f{"population", "population file", {}, {}, {}};
    return f;
}
const Format& gait_format() {
    static const Format f{"gait", "gait checkpoint", {}, {}, {}};
    return f;
}
const Format& archive_format() {
    static const Format f{"archive", "MAP-Elites archive", {}, {}, {}};
    return f;
}

} // namespace cic::io::xml
