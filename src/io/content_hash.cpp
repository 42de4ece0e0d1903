// A checkpoint file's content hash (content_hash.hpp).
#include "content_hash.hpp"

#include <libxml/tree.h>

#include <algorithm>

#include "cic/core/hash.hpp"

namespace cic::io::detail {
namespace {

const char* text_of(const xmlChar* s) { return reinterpret_cast<const char*>(s); }

// Appends the element's part of the canonical text: lengths before each piece,
// so that no two documents give the same text.
void append(std::string& out, const xmlNode* n, bool root, std::initializer_list<std::string_view> free_text) {
    auto piece = [&](std::string_view s) {
        out += std::to_string(s.size());
        out += ':';
        out += s;
    };
    const std::string_view name = text_of(n->name);
    out += '<';
    piece(name);
    for (const xmlAttr* a = n->properties; a; a = a->next) {
        const std::string_view attr = text_of(a->name);
        if (root && attr == kContentHash) continue;
        xmlChar* v = xmlNodeListGetString(n->doc, a->children, 1);
        piece(attr);
        piece(v ? text_of(v) : "");
        xmlFree(v);
    }
    bool elements = false;
    for (const xmlNode* c = n->children; c; c = c->next) elements = elements || c->type == XML_ELEMENT_NODE;
    if (!elements && std::find(free_text.begin(), free_text.end(), name) == free_text.end()) {
        out += '=';
        piece(xml::Node(const_cast<xmlNode*>(n)).text());
    }
    for (const xmlNode* c = n->children; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE) append(out, c, false, free_text);
    out += '>';
}

} // namespace

std::string document_hash(const xml::Node& root, std::initializer_list<std::string_view> free_text) {
    std::string text;
    append(text, root.get(), true, free_text);
    return hex16(fnv1a_64(text));
}

void check_document_hash(const xml::Node& root, std::string_view what, std::initializer_list<std::string_view> free_text) {
    const auto stored = root.attribute(kContentHash);
    if (!stored)
        throw root.error("<" + std::string(root.name()) + "> has no contentHash: this " + std::string(what) +
                         "'s format version keeps one over all it stores (a file cut or edited by hand?)");
    if (*stored != document_hash(root, free_text))   // never the expected value: pasted in, it would pass any edit
        throw root.error("<" + std::string(root.name()) + " contentHash=\"" + *stored + "\"> does not match what the " +
                         std::string(what) + " holds (edited by hand?): its values are believed on resume only "
                         "with their hash");
}

} // namespace cic::io::detail
