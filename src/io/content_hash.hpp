#pragma once
// Private to src/io: the content hash of a checkpoint file (issue 56), written
// as its root's contentHash attribute. It covers every value the file stores,
// as text: each element's name, its attributes in order and its text, in
// document order (so fitness, counters, generation and origin alike), but not
// the layout, so re-indenting a file keeps it. A file edited by hand no longer
// matches; a refusal never says the expected value.
#include <initializer_list>
#include <string>
#include <string_view>

#include "cic/io/xml.hpp"

namespace cic::io::detail {

inline constexpr const char* kContentHash = "contentHash";

// The hash of `root`'s document, the root's contentHash attribute left out, and
// the text of elements named in `free_text` too (a population's trees, which a
// person may edit: their individuals' own hashes notice it and have them
// evaluated again).
std::string document_hash(const xml::Node& root, std::initializer_list<std::string_view> free_text = {});

// Throws root.error(...) unless the root's contentHash is the document's
// hash; `what` names the file kind ("population file").
void check_document_hash(const xml::Node& root, std::string_view what,
                         std::initializer_list<std::string_view> free_text = {});

} // namespace cic::io::detail
