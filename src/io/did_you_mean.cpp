#include "cic/io/did_you_mean.hpp"

#include <algorithm>
#include <cctype>

namespace cic::io {
namespace {

bool is_subsequence(std::string_view part, std::string_view whole) {
    std::size_t i = 0;
    for (char c : whole)
        if (i < part.size() && part[i] == c) ++i;
    return i == part.size();
}

} // namespace

// Optimal string alignment: Levenshtein plus a swap of two neighbours as one
// edit (cuont -> count), the commonest slip after a missing letter.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    auto same = [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    };
    std::vector<std::size_t> before(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                cur[j] = std::min(cur[j], before[j - 2] + 1);
        }
        std::swap(before, prev);
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string nearest_name(std::string_view given, const std::vector<std::string>& names) {
    std::string best;
    std::size_t best_d = std::string::npos;
    for (const auto& n : names) {
        const std::size_t d = edit_distance(given, n);
        if (d < best_d || (d == best_d && is_subsequence(given, n) && !is_subsequence(given, best)))
            best_d = d, best = n;
    }
    return best_d > 0 && best_d <= std::max<std::size_t>(1, given.size() / 3) ? best : std::string();
}

std::string did_you_mean(std::string_view given, const std::vector<std::string>& names) {
    const std::string near = nearest_name(given, names);
    return near.empty() ? std::string() : "; did you mean " + near + "?";
}

} // namespace cic::io
