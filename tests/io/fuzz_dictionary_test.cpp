// fuzz/settings.dict, the dictionary that steers fuzz_settings toward real
// keys, is written from the settings table (scripts/fuzz-settings-dict.py):
// a key or choice added to the table without writing it again fails here,
// so the fuzzer never stops seeing the newest sections.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cic/io/settings_table.hpp"

namespace {

std::string dictionary() {
    std::ifstream in(std::filesystem::path(CIC_SOURCE_DIR) / "fuzz" / "settings.dict");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(FuzzDictionary, SettingsDictionaryHasEveryKeyAndChoice) {
    const std::string dict = dictionary();
    ASSERT_FALSE(dict.empty()) << "fuzz/settings.dict is missing";
    const std::string fix = "\nwrite it again: scripts/fuzz-settings-dict.py build/cic > fuzz/settings.dict";
    for (const auto& k : cic::io::settings_table()) {
        for (const std::string& tag : {k.section, k.key})
            EXPECT_NE(dict.find("=\"<" + tag + ">\"\n"), std::string::npos) << k.section << "." << k.key << fix;
        for (const auto& spellings : k.choices)
            for (const auto& s : spellings)
                EXPECT_NE(dict.find("\"" + s + "\"\n"), std::string::npos)
                    << k.section << "." << k.key << " choice " << s << fix;
    }
}

} // namespace
