#pragma once
// Private to src/io: numbers in cic's XML files (checkpoints and archives),
// written with 17 significant digits (an exact round trip) and read strictly:
// the whole text must be the number, and a double must be finite.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "cic/io/xml.hpp"

namespace cic::io::detail {

inline std::string exact(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Space-separated, each exact.
inline std::string exact_list(const std::vector<double>& values) {
    std::string out;
    for (double v : values) out += (out.empty() ? "" : " ") + exact(v);
    return out;
}

// `what` names the value in the message: "<elite> fitness "x" is not a valid number".
template <class T>
T parse_number(const xml::Node& n, std::string_view what, std::string_view text) {
    T v{};
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if constexpr (std::is_floating_point_v<T>) {
        if (r.ec == std::errc::result_out_of_range && r.ptr == text.data() + text.size())
            throw n.error("<" + std::string(n.name()) + "> " + std::string(what) + " \"" + std::string(text) + "\" " +
                          (std::fabs(std::strtod(std::string(text).c_str(), nullptr)) < 1.0
                               ? "underflows: it is closer to 0 than a double can hold"
                               : "overflows: it is larger than a double can hold"));
    }
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
        throw n.error("<" + std::string(n.name()) + "> " + std::string(what) + " \"" + std::string(text) +
                      "\" is not a valid number");
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(v)) throw n.error("<" + std::string(n.name()) + "> " + std::string(what) + " is not finite");
    }
    return v;
}

// A required attribute's number.
template <class T>
T attribute(const xml::Node& n, std::string_view name) {
    const auto a = n.attribute(name);
    if (!a) throw n.error("<" + std::string(n.name()) + "> is missing attribute " + std::string(name));
    return parse_number<T>(n, name, *a);
}

// Space-separated doubles, each checked as parse_number does.
inline std::vector<double> parse_numbers(const xml::Node& n, std::string_view what, std::string_view text) {
    std::vector<double> out;
    std::istringstream in{std::string(text)};
    for (std::string tok; in >> tok;) out.push_back(parse_number<double>(n, what, tok));
    return out;
}

} // namespace cic::io::detail
