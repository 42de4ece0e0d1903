#pragma once
// Words of a POSIX shell command line that cic shows people (dry runs) or
// writes into scripts (Slurm job arrays, completion, strips): one quoting rule
// for all of them, so a path with a space or a quote runs as written.
#include <string>
#include <string_view>
#include <vector>

namespace cic {

// S in single quotes, each ' in it written '\''.
inline std::string shell_quote(std::string_view s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string_view("'\\''") : std::string_view(&c, 1);
    return out + "'";
}

// S as it is when it holds only letters, digits and _ - . / = : (and is not
// empty), else shell_quote(S).
inline std::string shell_word(std::string_view s) {
    const bool plain = !s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789_-./=:") == std::string_view::npos;
    return plain ? std::string(s) : shell_quote(s);
}

// The words, each by shell_word, joined by spaces.
inline std::string shell_words(const std::vector<std::string>& argv) {
    std::string out;
    for (const auto& a : argv) out += (out.empty() ? "" : " ") + shell_word(a);
    return out;
}

} // namespace cic
