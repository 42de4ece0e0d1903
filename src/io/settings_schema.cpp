// XSD schema generated from the settings table (`cic settings --schema`,
// committed as settings/cic-settings.xsd). Accepts what the reader accepts,
// except checks XSD cannot express (duplicates in name lists, cross-field rules).
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/xml.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

using detail::format_double;
using xml::Node;

constexpr double kHuge = std::numeric_limits<double>::max();

void facet(Node restriction, const char* name, const std::string& value) {
    restriction.add_element(name).set_attribute("value", value);
}

// Adds an anonymous simple type for one number (bounds from k) under `parent`.
void number_type(Node parent, const SettingKey& k, bool integer) {
    auto st = parent.add_element("xs:simpleType");
    auto r = st.add_element("xs:restriction");
    r.set_attribute("base", integer ? "xs:long" : "xs:double");
    if (integer) {
        facet(r, "xs:minInclusive", std::to_string(static_cast<long long>(k.min)));
        facet(r, "xs:maxInclusive", std::to_string(static_cast<long long>(k.max)));
        return;
    }
    if (k.min_exclusive)
        facet(r, "xs:minExclusive", format_double(k.min));
    else if (k.min > -kHuge || !k.allow_inf)
        facet(r, "xs:minInclusive", format_double(k.min));
    if (k.max < kHuge || !k.allow_inf) facet(r, "xs:maxInclusive", format_double(k.max));
}

void enumeration(Node parent, const std::vector<std::string>& values) {
    auto r = parent.add_element("xs:simpleType").add_element("xs:restriction");
    r.set_attribute("base", "xs:token");
    for (const auto& v : values) facet(r, "xs:enumeration", v);
}

// list of item type, with item-count bounds.
void list_type(Node parent, const SettingKey& k, const std::function<void(Node)>& item) {
    auto r = parent.add_element("xs:simpleType").add_element("xs:restriction");
    auto list = r.add_element("xs:simpleType").add_element("xs:list");
    item(list);
    if (k.min_items > 0) facet(r, "xs:minLength", std::to_string(k.min_items));
    if (k.max_items < std::numeric_limits<std::size_t>::max()) facet(r, "xs:maxLength", std::to_string(k.max_items));
}

std::vector<std::string> all_spellings(const SettingKey& k) {
    std::vector<std::string> v;
    for (const auto& c : k.choices) v.insert(v.end(), c.begin(), c.end());
    return v;
}

void key_element(Node all, const SettingKey& k) {
    auto e = all.add_element("xs:element");
    e.set_attribute("name", k.key);
    e.set_attribute("minOccurs", "0");
    e.add_element("xs:annotation").add_child("xs:documentation", k.doc + ". Allowed: " + describe_allowed(k) +
                                                                      ". Default: \"" + default_text(k) + "\"");
    switch (k.type) {
    case ValueType::Bool: e.set_attribute("type", "xs:boolean"); break;
    case ValueType::UInt64: e.set_attribute("type", "xs:unsignedLong"); break;
    case ValueType::Int: number_type(e, k, true); break;
    case ValueType::Double:
        if (!k.allow_inf) {
            number_type(e, k, false);
        } else {
            auto u = e.add_element("xs:simpleType").add_element("xs:union");
            number_type(u, k, false);
            std::vector<std::string> inf;
            if (k.max >= kHuge) inf.insert(inf.end(), {"inf", "infinity"});
            if (k.min <= -kHuge) inf.insert(inf.end(), {"-inf", "-infinity"});
            enumeration(u, inf);
        }
        break;
    case ValueType::String:
    case ValueType::Path:
        if (k.min_items == 0) {
            e.set_attribute("type", "xs:string");
        } else {
            auto r = e.add_element("xs:simpleType").add_element("xs:restriction");
            r.set_attribute("base", "xs:string");
            facet(r, "xs:minLength", "1");
        }
        break;
    case ValueType::Enum: enumeration(e, all_spellings(k)); break;
    case ValueType::NameList: list_type(e, k, [&](Node l) { enumeration(l, all_spellings(k)); }); break;
    case ValueType::DoubleList: list_type(e, k, [&](Node l) { number_type(l, k, false); }); break;
    case ValueType::IntList: list_type(e, k, [&](Node l) { number_type(l, k, true); }); break;
    case ValueType::PathList: list_type(e, k, [](Node l) { l.set_attribute("itemType", "xs:string"); }); break;
    }
}

} // namespace

std::string settings_schema() {
    auto doc = xml::Document::create("xs:schema");
    auto schema = doc.root();
    schema.set_attribute("xmlns:xs", "http://www.w3.org/2001/XMLSchema");
    schema.add_comment(" Generated from the settings table (cic settings, option schema); do not edit by hand. ");
    // The root is <settings>; <cic> is accepted too.
    for (const char* name : {"settings", "cic"}) {
        auto root = schema.add_element("xs:element");
        root.set_attribute("name", name);
        root.set_attribute("type", "SettingsFile");
    }
    auto root_type = schema.add_element("xs:complexType");
    root_type.set_attribute("name", "SettingsFile");
    auto root_all = root_type.add_element("xs:all");
    for (const auto& section : settings_sections()) {
        auto sec = root_all.add_element("xs:element");
        sec.set_attribute("name", section);
        sec.set_attribute("minOccurs", "0");
        // A choice, not xs:all: a key may repeat with the same value (thesis table
        // B.1 lists functionProbabilities twice); the reader refuses another value.
        auto keys = sec.add_element("xs:complexType").add_element("xs:choice");
        keys.set_attribute("minOccurs", "0");
        keys.set_attribute("maxOccurs", "unbounded");
        for (const auto& k : settings_table())
            if (k.section == section) key_element(keys, k);
    }
    return doc.to_string();
}

} // namespace cic::io
