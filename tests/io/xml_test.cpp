#include "cic/io/xml.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using cic::InputError;
using cic::io::xml::Document;

namespace {

fs::path temp_dir(const std::string& tag) { return cic::testing::temp_dir("xml-" + tag); }

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST(Xml, ParsesElementsTextAttributesAndLines) {
    auto doc = Document::parse_string("<root>\n  <a k=\"v\">  hello  </a>\n  <!-- c -->\n  <b/>\n</root>\n",
                                      "mem.xml");
    auto root = doc.root();
    EXPECT_EQ(root.name(), "root");
    auto kids = root.children();
    ASSERT_EQ(kids.size(), 2u);
    EXPECT_EQ(kids[0].name(), "a");
    EXPECT_EQ(kids[0].text(), "hello");
    EXPECT_EQ(kids[0].line(), 2);
    EXPECT_EQ(kids[0].attribute("k"), "v");
    EXPECT_FALSE(kids[0].attribute("missing").has_value());
    EXPECT_EQ(kids[1].line(), 4);
    EXPECT_TRUE(root.child("b"));
    EXPECT_FALSE(root.child("zzz"));
    EXPECT_EQ(kids[1].file(), "mem.xml");
    EXPECT_STREQ(kids[1].error("bad thing").what(), "mem.xml:4: bad thing");
}

TEST(Xml, MalformedXmlNamesFileAndLine) {
    std::string m = message_of([] { Document::parse_string("<a>\n<b>\n</a>\n", "broken.xml"); });
    EXPECT_NE(m.find("broken.xml:3: malformed XML"), std::string::npos) << m;
    EXPECT_NE(m.find("mismatch"), std::string::npos) << m;
    try {
        Document::parse_string("<a>\n<b>\n</a>\n", "broken.xml");
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "broken.xml");
        EXPECT_EQ(e.line(), 3);
    }
}

TEST(Xml, EmptyAndMissingFilesAreInputErrors) {
    EXPECT_NE(message_of([] { Document::parse_string("  \n", "e.xml"); }).find("e.xml: empty file"),
              std::string::npos);
    std::string m = message_of([] { Document::load_file("/nonexistent/dir/x.xml"); });
    EXPECT_NE(m.find("/nonexistent/dir/x.xml: cannot read: No such file"), std::string::npos) << m;
    auto d = temp_dir("dir");
    m = message_of([&] { Document::load_file(d); });
    EXPECT_NE(m.find("is a directory"), std::string::npos) << m;
    fs::remove_all(d);
}

TEST(Xml, NoExternalEntities) {
    // An external entity must not be fetched or expanded into the document.
    auto d = temp_dir("ent");
    std::ofstream(d / "secret.txt") << "SECRET-CONTENT";
    std::string text = "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY e SYSTEM \"" + (d / "secret.txt").string() +
                       "\">]>\n<r>&e;</r>\n";
    try {
        auto doc = Document::parse_string(text, "ent.xml");
        EXPECT_EQ(doc.root().text().find("SECRET"), std::string::npos);
        EXPECT_EQ(doc.to_string().find("SECRET"), std::string::npos);
    } catch (const InputError&) {
        // refusing the document is fine too
    }
    fs::remove_all(d);
}

TEST(Xml, BuildSerialiseAndReadBack) {
    auto doc = Document::create("settings");
    auto sec = doc.root().add_element("GP");
    sec.add_comment("a -- comment");
    sec.add_child("key", "a < b & c");
    sec.set_attribute("version", "1");
    std::string text = doc.to_string();
    auto back = Document::parse_string(text, "back.xml");
    auto gp = back.root().child("GP");
    ASSERT_TRUE(gp);
    EXPECT_EQ(gp.attribute("version"), "1");
    EXPECT_EQ(gp.child("key").text(), "a < b & c");
    EXPECT_EQ(back.to_string(), text);
}

TEST(Xml, AtomicWriteReplacesAndLeavesNoTemp) {
    auto d = temp_dir("atomic");
    auto f = d / "out.xml";
    cic::io::xml::write_file_atomically(f, "one");
    cic::io::xml::write_file_atomically(f, "two");
    EXPECT_EQ(cic::io::xml::read_file(f), "two");
    int files = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(d)) ++files;
    EXPECT_EQ(files, 1);
    EXPECT_THROW(cic::io::xml::write_file_atomically(d / "no" / "such" / "f", "x"), std::runtime_error);
    fs::remove_all(d);
}

TEST(Xml, ValidatesAgainstSchema) {
    auto d = temp_dir("xsd");
    std::ofstream(d / "s.xsd") << R"(<?xml version="1.0"?>
<xs:schema xmlns:xs="http://www.w3.org/2001/XMLSchema">
  <xs:element name="r"><xs:complexType><xs:sequence>
    <xs:element name="n" type="xs:int" minOccurs="0"/>
  </xs:sequence></xs:complexType></xs:element>
</xs:schema>)";
    auto good = Document::parse_string("<r><n>3</n></r>", "good.xml");
    EXPECT_TRUE(good.validate(d / "s.xsd").empty());
    auto bad = Document::parse_string("<r>\n<n>x</n></r>", "bad.xml");
    auto errors = bad.validate(d / "s.xsd");
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].rfind("bad.xml:2:", 0), 0u) << errors[0];
    std::ofstream(d / "broken.xsd") << "<xs:schema";
    EXPECT_THROW(good.validate(d / "broken.xsd"), InputError);
    fs::remove_all(d);
}

// Issue 56: a 2.2 GB sparse checkpoint took 4.25 GB of memory before "malformed
// XML"; a file past the limit is refused by its size, before it is read.
TEST(Xml, AHugeFileIsRefusedBeforeItIsRead) {
    const fs::path dir = cic::testing::temp_dir("xml-huge");
    const fs::path file = dir / "population.xml";
    std::ofstream(file) << "<population>";
    fs::resize_file(file, 300ull * 1024 * 1024);   // sparse: no disk taken
    try {
        Document::load_file(file);
        FAIL() << "a 300 MB file was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("past the limit of 268435456 bytes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}
