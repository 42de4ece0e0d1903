#include "settings_values.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace cic::io::detail {
namespace {

constexpr double kHuge = std::numeric_limits<double>::max();

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// XSD allows a leading '+'; std::from_chars does not.
std::string_view strip_plus(std::string_view t) {
    if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
    return t;
}

} // namespace

std::string format_double(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::array<char, 64> buf{};
    auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    if (ec != std::errc()) return std::to_string(v);
    return std::string(buf.data(), end);
}

std::string join(const std::vector<std::string>& items, std::string_view sep) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i) out += sep;
        out += items[i];
    }
    return out;
}

std::vector<std::string_view> split_items(std::string_view text) {
    if (text.find(',') != std::string_view::npos || text.find(';') != std::string_view::npos)
        throw ValueError("list items are separated by spaces, not commas or semicolons");
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && is_space(text[i])) ++i;
        std::size_t b = i;
        while (i < text.size() && !is_space(text[i])) ++i;
        if (i > b) out.push_back(text.substr(b, i - b));
    }
    return out;
}

bool parse_bool(std::string_view t) {
    if (t == "1" || t == "true") return true;
    if (t == "0" || t == "false") return false;
    throw ValueError("not a boolean");
}

long long parse_integer(const SettingKey& k, std::string_view text) {
    std::string_view t = strip_plus(text);
    long long v = 0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec == std::errc::result_out_of_range) throw ValueError("out of range");
    if (ec != std::errc() || end != t.data() + t.size() || t.empty()) {
        double d = 0;
        auto [dend, dec] = std::from_chars(t.data(), t.data() + t.size(), d);
        if (dec == std::errc() && dend == t.data() + t.size())
            throw ValueError("not a whole number");
        throw ValueError("not an integer");
    }
    if (static_cast<double>(v) < k.min || static_cast<double>(v) > k.max) throw ValueError("out of range");
    return v;
}

std::uint64_t parse_uint64(std::string_view text) {
    std::string_view t = strip_plus(text);
    if (!t.empty() && t[0] == '-') throw ValueError("must not be negative");
    std::uint64_t v = 0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec == std::errc::result_out_of_range) throw ValueError("out of range");
    if (ec != std::errc() || end != t.data() + t.size() || t.empty()) throw ValueError("not an integer");
    return v;
}

double parse_number(const SettingKey& k, std::string_view text) {
    std::string_view t = strip_plus(text);
    static constexpr std::array<std::string_view, 6> kInf{"inf", "INF", "infinity", "-inf", "-INF", "-infinity"};
    double v = 0;
    if (auto it = std::find(kInf.begin(), kInf.end(), t); it != kInf.end()) {
        if (!k.allow_inf) throw ValueError("infinity is not allowed here");
        v = t[0] == '-' ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    } else {
        // from_chars would also take "nan" / "inf" spellings we do not want.
        if (t.find(',') != std::string_view::npos) throw ValueError("not a number (the decimal point is '.')");
        if (t.empty() || !(std::isdigit(static_cast<unsigned char>(t.back())) || t.back() == '.'))
            throw ValueError("not a number");
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (ec == std::errc::result_out_of_range && end == t.data() + t.size()) {
            // Too large or too close to 0 for a double: say which (1e-400 underflows).
            const double near = std::strtod(std::string(t).c_str(), nullptr);
            if (std::fabs(near) < 1.0)
                throw ValueError("underflows: it is closer to 0 than a double can hold "
                                 "(about 2.2e-308); write 0 or a larger number");
            throw ValueError("overflows: it is larger than a double can hold (about 1.8e308)");
        }
        if (ec != std::errc() || end != t.data() + t.size()) throw ValueError("not a number");
    }
    bool finite_ok = std::isfinite(v) || k.allow_inf;
    bool below = k.min_exclusive ? !(v > k.min) : v < k.min;
    bool above = v > k.max;
    if (std::isinf(v) && k.allow_inf) {
        below = v < 0 && k.min > -kHuge;
        above = v > 0 && k.max < kHuge;
    }
    if (!finite_ok || below || above) throw ValueError("out of range");
    return v;
}

std::size_t parse_choice(const SettingKey& k, std::string_view text) {
    for (std::size_t i = 0; i < k.choices.size(); ++i)
        for (const auto& spelling : k.choices[i])
            if (spelling == text) return i;
    throw ValueError("not one of the allowed names");
}

} // namespace cic::io::detail
