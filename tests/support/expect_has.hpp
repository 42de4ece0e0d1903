// EXPECT_HAS(text, part): the text holds the part; on failure, says which part and shows the text.
#pragma once

#include <string>

#include <gtest/gtest.h>

#define EXPECT_HAS(text, part) \
    EXPECT_NE((text).find(part), std::string::npos) << "no '" << (part) << "' in:\n" << (text)
