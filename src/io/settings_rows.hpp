#pragma once
// Private to src/io: the row builders of the settings table (settings_table.cpp).
// Each returns a SettingKey whose get/set read and write one Settings member
// through an accessor, FIELD(gp.population_size).
#include <algorithm>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "cic/io/settings_table.hpp"
#include "cic/sim/config.hpp"
#include "settings_values.hpp"

namespace cic::io::rows {

using detail::format_double;
using detail::join;
using detail::split_items;

constexpr double kHuge = std::numeric_limits<double>::max();

// FIELD(gp.population_size) -> an accessor returning a reference into Settings.
#define FIELD(member) [](Settings& s) -> decltype(auto) { return (s.member); }

template <class F>
auto& field(F ref, const Settings& s) { return ref(const_cast<Settings&>(s)); }

inline SettingKey row(std::string section, std::string key, ValueType type, std::string doc) {
    SettingKey k{};
    k.section = std::move(section);
    k.key = std::move(key);
    k.type = type;
    k.doc = std::move(doc);
    return k;
}

template <class F>
inline SettingKey bool_row(std::string sec, std::string key, std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::Bool, std::move(doc));
    k.get = [ref](const Settings& s) { return std::string(field(ref, s) ? "1" : "0"); };
    k.set = [ref](Settings& s, std::string_view t) { ref(s) = detail::parse_bool(t); };
    return k;
}

template <class F>
inline SettingKey int_row(std::string sec, std::string key, long long lo, long long hi, std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::Int, std::move(doc));
    k.min = static_cast<double>(lo);
    k.max = static_cast<double>(hi);
    SettingKey bounds = k;
    k.get = [ref](const Settings& s) { return std::to_string(field(ref, s)); };
    k.set = [ref, bounds](Settings& s, std::string_view t) {
        ref(s) = static_cast<int>(detail::parse_integer(bounds, t));
    };
    return k;
}

// A count too large for int (an evaluation budget), in [lo, hi].
template <class F>
inline SettingKey long_row(std::string sec, std::string key, long long lo, long long hi, std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::Int, std::move(doc));
    k.min = static_cast<double>(lo);
    k.max = static_cast<double>(hi);
    SettingKey bounds = k;
    k.get = [ref](const Settings& s) { return std::to_string(field(ref, s)); };
    k.set = [ref, bounds](Settings& s, std::string_view t) { ref(s) = detail::parse_integer(bounds, t); };
    return k;
}

struct Bounds {
    double min = -kHuge, max = kHuge;
    bool min_exclusive = false, allow_inf = false;
};
constexpr Bounds kAnyFinite{};
constexpr Bounds kPositive{0.0, kHuge, true, false};
constexpr Bounds kNonNegative{0.0, kHuge, false, false};
constexpr Bounds kUnit{0.0, 1.0, false, false};

template <class F>
inline SettingKey double_row(std::string sec, std::string key, Bounds b, std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::Double, std::move(doc));
    k.min = b.min;
    k.max = b.max;
    k.min_exclusive = b.min_exclusive;
    k.allow_inf = b.allow_inf;
    SettingKey bounds = k;
    k.get = [ref](const Settings& s) { return format_double(field(ref, s)); };
    k.set = [ref, bounds](Settings& s, std::string_view t) { ref(s) = detail::parse_number(bounds, t); };
    return k;
}

template <class F>
inline SettingKey string_row(std::string sec, std::string key, ValueType type, bool may_be_empty, std::string doc,
                      F ref) {
    auto k = row(std::move(sec), std::move(key), type, std::move(doc));
    k.min_items = may_be_empty ? 0 : 1;
    k.get = [ref](const Settings& s) { return std::string(field(ref, s)); };
    k.set = [ref](Settings& s, std::string_view t) { ref(s) = std::string(t); };
    return k;
}

template <class E, class F>
inline SettingKey enum_row(std::string sec, std::string key, std::vector<std::pair<E, std::vector<std::string>>> choices,
                    std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::Enum, std::move(doc));
    std::vector<E> values;
    for (auto& [v, spellings] : choices) {
        values.push_back(v);
        k.choices.push_back(spellings);
    }
    SettingKey bounds = k;
    k.get = [ref, values, bounds](const Settings& s) {
        auto it = std::find(values.begin(), values.end(), field(ref, s));
        if (it == values.end()) throw std::invalid_argument("settings: enum value without a name");
        return bounds.choices[static_cast<std::size_t>(it - values.begin())].front();
    };
    k.set = [ref, values, bounds](Settings& s, std::string_view t) {
        ref(s) = values[detail::parse_choice(bounds, t)];
    };
    return k;
}

template <class F>
inline SettingKey double_list_row(std::string sec, std::string key, Bounds b, std::size_t min_items, std::string doc,
                           F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::DoubleList, std::move(doc));
    k.min = b.min;
    k.max = b.max;
    k.min_exclusive = b.min_exclusive;
    k.min_items = min_items;
    SettingKey bounds = k;
    k.get = [ref](const Settings& s) {
        std::vector<std::string> items;
        for (double v : field(ref, s)) items.push_back(format_double(v));
        return join(items);
    };
    k.set = [ref, bounds](Settings& s, std::string_view t) {
        std::vector<double> values;
        for (auto item : split_items(t)) values.push_back(detail::parse_number(bounds, item));
        ref(s) = std::move(values);
    };
    return k;
}

// Space-separated file paths (read as ValueType::Path items); may be empty.
template <class F>
inline SettingKey path_list_row(std::string sec, std::string key, std::string doc, F ref) {
    auto k = row(std::move(sec), std::move(key), ValueType::PathList, std::move(doc));
    k.min_items = 0;
    k.get = [ref](const Settings& s) { return join(field(ref, s)); };
    k.set = [ref](Settings& s, std::string_view t) {
        std::vector<std::string> items;
        for (auto item : split_items(t)) items.emplace_back(item);
        ref(s) = std::move(items);
    };
    return k;
}

// The SimConfig member that f describes, found by name in s.sim.
template <class T>
auto sim_member(std::string_view name) {
    return [name](Settings& s) -> T& {
        T* found = nullptr;
        sim::for_each_field(s.sim, [&](const sim::FieldSpec& f, auto& v) {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, T>)
                if (f.name == name) found = &v;
        });
        return *found;
    };
}

// A <Simulator> row with the key, doc and range of sim::for_each_field.
template <class T>
inline SettingKey sim_row(const sim::FieldSpec& f) {
    std::string key(f.key), doc(f.doc);
    if constexpr (std::is_same_v<T, bool>)
        return bool_row("Simulator", key, doc, sim_member<T>(f.name));
    else if constexpr (std::is_same_v<T, int>)
        return int_row("Simulator", key, static_cast<long long>(f.min), static_cast<long long>(f.max), doc,
                       sim_member<T>(f.name));
    else
        return double_row("Simulator", key, Bounds{f.min, f.max, f.min_exclusive, f.allow_inf}, doc,
                          sim_member<T>(f.name));
}

// The rows of the Neural, SymbolicRegression and Gait sections (settings_rows_neural.cpp).
void neural_rows(std::vector<SettingKey>& t);
void symreg_rows(std::vector<SettingKey>& t);
void gait_rows(std::vector<SettingKey>& t);
void map_elites_rows(std::vector<SettingKey>& t);

} // namespace cic::io::rows
