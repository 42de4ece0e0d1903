#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cic/core/shell_words.hpp"

using cic::shell_quote;
using cic::shell_word;
using cic::shell_words;

TEST(ShellWords, PlainWordsStayAsTheyAre) {
    EXPECT_EQ(shell_words({"cic", "--settings", "/a/b_c-1.xml", "--set", "GP.elitism=1", "x:y"}),
              "cic --settings /a/b_c-1.xml --set GP.elitism=1 x:y");
}

TEST(ShellWords, OtherWordsAreQuoted) {
    EXPECT_EQ(shell_word("a b"), "'a b'");
    EXPECT_EQ(shell_word(""), "''");
    EXPECT_EQ(shell_word("it's"), "'it'\\''s'");
    EXPECT_EQ(shell_quote("plain"), "'plain'");
}

// What a shell makes of the line is the words given, whatever they hold.
TEST(ShellWords, AShellReadsBackTheSameWords) {
    const std::vector<std::string> words{"printf", "%s\\n", "plain", "with space", "it's", "$HOME", "a\"b", "",
                                         "`x`", "tab\there", "semi;colon", "*"};
    const std::string line = shell_words(words);
    FILE* sh = popen(("/bin/sh -c " + shell_quote(line)).c_str(), "r");
    ASSERT_NE(sh, nullptr);
    std::string out;
    char buf[256];
    while (const std::size_t n = std::fread(buf, 1, sizeof buf, sh)) out.append(buf, n);
    ASSERT_EQ(pclose(sh), 0) << line;
    std::string want;
    for (std::size_t i = 2; i < words.size(); ++i) want += words[i] + "\n";
    EXPECT_EQ(out, want) << line;
}
