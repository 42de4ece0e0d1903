// Sweep files -> SweepPlan (format: docs/cluster.md; schema: settings/cic-sweep.xsd).
#include <charconv>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "cic/study/sweep.hpp"
#include "cic/core/error.hpp"
#include "cic/core/shell_words.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"

namespace cic::study {
namespace {

namespace fs = std::filesystem;

// A path value in a sweep file, like one in a settings file, is read against
// the file's folder (not the folder cic runs in), and stored absolute.
std::string resolved_path(const std::string& value, const fs::path& folder) {
    if (value.empty() || fs::path(value).is_absolute()) return value;
    return (folder / value).lexically_normal().string();
}

std::string xml_value(const std::string& v) { return io::xml::trim(v); }

bool is_scalar(const io::SettingKey& k) { return !io::is_list(k.type); }

// Each item of a path list resolved as a path value is.
std::string resolved_paths(const std::string& value, const fs::path& folder) {
    std::string out;
    std::istringstream items(value);
    for (std::string item; items >> item;) out += (out.empty() ? "" : " ") + resolved_path(item, folder);
    return out;
}

// "Section.key=value" naming a real key, a path value resolved. A scalar value
// is checked here, so that a bad one is named at its line; lists and the rules
// between keys are checked with the settings of each configuration.
std::string checked_override(const io::xml::Node& n, const std::string& text, const fs::path& folder,
                             bool check_value = true) {
    const std::string element = "<" + std::string(n.name()) + ">";
    const auto eq = text.find('='), dot = text.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq)
        throw n.error(element + " expects Section.key=value, got \"" + text + "\"");
    const std::string section = text.substr(0, dot), key = text.substr(dot + 1, eq - dot - 1);
    const io::SettingKey* k = io::find_setting(section, key);
    if (!k) throw n.error(element + " names no settings key: <" + section + "> " + key);
    if (section == "Experiment" && key == "seed")
        throw n.error(element + " sets Experiment.seed, which a sweep owns: each run's seed comes from <repeats "
                      "firstSeed=\"S\" seeds=\"same|distinct\"/>; remove it here");
    const std::string value = xml_value(text.substr(eq + 1));
    if (check_value && is_scalar(*k)) {
        io::Settings scratch;
        try {
            k->set(scratch, value);
        } catch (const std::exception& e) {
            throw n.error(element + " <" + section + "> " + key + " = \"" + value + "\": " + e.what() +
                          " (allowed: " + io::describe_allowed(*k) + ")");
        }
    }
    if (k->type == io::ValueType::Path) return text.substr(0, eq + 1) + resolved_path(text.substr(eq + 1), folder);
    if (k->type == io::ValueType::PathList) return text.substr(0, eq + 1) + resolved_paths(value, folder);
    return text;
}

std::uint64_t number(const io::xml::Node& n, const char* attr, std::uint64_t fallback, std::uint64_t lo,
                     std::uint64_t hi) {
    const auto a = n.attribute(attr);
    if (!a) return fallback;
    std::uint64_t v = 0;
    const auto r = std::from_chars(a->data(), a->data() + a->size(), v);
    if (a->empty() || r.ec != std::errc() || r.ptr != a->data() + a->size() || v < lo || v > hi)
        throw n.error(fmt::format("<{}> {}=\"{}\": expected an integer in [{}, {}]", n.name(), attr, *a, lo, hi));
    return v;
}

// Keeps letters, digits and _ . = + - ; anything else becomes '-', so that a
// configuration name is a folder name on any file system.
std::string folder_safe(const std::string& s) {
    std::string out;
    for (char c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                        c == '=' || c == '+' || c == '-' || c == '_';
        out += ok ? c : '-';
    }
    return out.empty() ? "-" : out;
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

struct Vary {
    std::string key;                 // Section.key
    std::vector<std::string> values;
};

struct Variant {
    std::string name;
    std::vector<std::string> overrides;
    int line = 0;
};

} // namespace

namespace {

// The document has passed the strict reader (elements and attributes known,
// no stray text); these are the sweep's own rules.
SweepPlan read_sweep(const io::xml::Document& doc, const fs::path& file, const fs::path& output) {
    const io::xml::Node root = doc.root();
    SweepPlan plan;
    plan.file = fs::absolute(file).lexically_normal();
    plan.name = root.attribute("name").value_or(file.stem().string());
    if (plan.name.empty() || folder_safe(plan.name) != plan.name)
        throw root.error("<sweep name=\"" + plan.name + "\">: use letters, digits and . = + - only");
    std::vector<Vary> grid;
    std::vector<Variant> variants;
    bool have_repeats = false;
    int grid_line = 0;
    std::string out_text, store_text;
    for (const auto& c : root.children()) {
        const std::string_view nm = c.name();
        if (nm == "base") {
            if (!plan.base.empty()) throw c.error("<base> is given twice");
            fs::path p = c.text();
            if (p.empty()) throw c.error("<base> is empty: give the base settings file");
            if (p.is_relative()) p = plan.file.parent_path() / p;
            plan.base = p.lexically_normal();
            if (!fs::is_regular_file(plan.base)) throw c.error("<base> " + plan.base.string() + ": no such file");
            plan.base_xml = io::xml::read_file(plan.base);
        } else if (nm == "output") {
            out_text = c.text();
        } else if (nm == "store") {
            store_text = c.text();
            if (store_text.empty()) throw c.error("<store> is empty: give a folder (relative to the study folder)");
        } else if (nm == "set") {
            plan.common.push_back(checked_override(c, c.text(), plan.file.parent_path()));
        } else if (nm == "grid") {
            grid_line = c.line();
            for (const auto& v : c.children()) {
                if (v.name() != "vary") throw v.error("unknown element <" + std::string(v.name()) + "> in <grid>; allowed: vary");
                if (!v.attribute("key")) throw v.error("<vary> needs attribute key=\"Section.key\"");
                Vary vary{*v.attribute("key"), words(v.text())};
                checked_override(v, vary.key + "=", plan.file.parent_path(), false);   // the key alone
                for (auto& value : vary.values)
                    value = checked_override(v, vary.key + "=" + value, plan.file.parent_path()).substr(vary.key.size() + 1);
                if (vary.values.empty()) throw v.error("<vary key=\"" + vary.key + "\"> has no values");
                if (std::set<std::string>(vary.values.begin(), vary.values.end()).size() != vary.values.size())
                    throw v.error("<vary key=\"" + vary.key + "\"> lists a value twice");
                for (const auto& g : grid)
                    if (g.key == vary.key) throw v.error("key " + vary.key + " is varied twice");
                grid.push_back(std::move(vary));
            }
        } else if (nm == "variant") {
            Variant v{c.attribute("name").value_or(""), {}, c.line()};
            if (v.name.empty() || folder_safe(v.name) != v.name)
                throw c.error("<variant name=\"" + v.name + "\">: give a name of letters, digits and _ . = + -");
            for (const auto& o : variants)
                if (o.name == v.name) throw c.error("variant " + v.name + " is given twice");
            for (const auto& s : c.children()) {
                if (s.name() != "set") throw s.error("unknown element <" + std::string(s.name()) + "> in <variant>; allowed: set");
                v.overrides.push_back(checked_override(s, s.text(), plan.file.parent_path()));
            }
            variants.push_back(std::move(v));
        } else if (nm == "repeats") {
            have_repeats = true;
            plan.repeats = static_cast<int>(number(c, "count", 1, 1, 100000));
            plan.first_seed = number(c, "firstSeed", 1, 0, UINT64_MAX - 100000000ULL);
            const std::string rule = c.attribute("seeds").value_or("same");
            if (rule == "same") plan.rule = SeedRule::Same;
            else if (rule == "distinct") plan.rule = SeedRule::Distinct;
            else throw c.error("<repeats seeds=\"" + rule + "\">: allowed: same, distinct");
        } else {
            throw c.error("unknown element <" + std::string(nm) +
                          "> in <sweep>; allowed: base, output, store, set, grid, variant, repeats");
        }
    }
    if (plan.base.empty()) throw root.error("missing <base>: the settings file every run starts from");
    if (!have_repeats) throw root.error("missing <repeats count=\"N\" firstSeed=\"S\"/>");

    // Configurations: every variant (or none) times every grid point, the last key
// fastest. Names: the variant, then short_key=value per grid key, joined by '+'.
    if (variants.empty()) variants.push_back({});
    for (const auto& g : grid) plan.varied_keys.push_back(g.key);
    if (!variants.front().name.empty()) plan.varied_keys.push_back("variant");
    std::size_t points = 1;
    for (const auto& g : grid) points *= g.values.size();
    if (points * variants.size() > 100000) throw root.error("more than 100000 configurations");
    // Each run is a folder and a line of index.csv: a study past a million is a typo.
    if (points * variants.size() * static_cast<std::size_t>(plan.repeats) > 1000000)
        throw root.error(fmt::format("{} configurations x {} repeats is more than 1000000 runs",
                                     points * variants.size(), plan.repeats));
    std::set<std::string> names;
    for (const auto& v : variants)
        for (std::size_t p = 0; p < points; ++p) {
            SweepConfig cfg;
            cfg.line = v.line > 0 ? v.line : grid_line > 0 ? grid_line : root.line();
            std::string name = v.name;
            std::size_t rest = p;
            std::vector<std::size_t> pick(grid.size());
            for (std::size_t k = grid.size(); k-- > 0;) {
                pick[k] = rest % grid[k].values.size();
                rest /= grid[k].values.size();
            }
            for (std::size_t k = 0; k < grid.size(); ++k) {
                const std::string& value = grid[k].values[pick[k]];
                cfg.varied.emplace_back(grid[k].key, value);
                cfg.overrides.push_back(grid[k].key + "=" + value);
                const std::string shortkey = grid[k].key.substr(grid[k].key.find('.') + 1);
                name += (name.empty() ? "" : "+") + folder_safe(shortkey + "=" + value);
            }
            if (!v.name.empty()) cfg.varied.emplace_back("variant", v.name);
            cfg.overrides.insert(cfg.overrides.end(), v.overrides.begin(), v.overrides.end());
            cfg.name = name.empty() ? "base" : name;
            if (!names.insert(cfg.name).second)
                throw root.error("two configurations would share the folder name " + cfg.name);
            plan.configs.push_back(std::move(cfg));
        }
    plan.study = !output.empty() ? fs::path(output) : !out_text.empty() ? fs::path(out_text) : fs::path("runs") / plan.name;
    plan.study = fs::absolute(plan.study).lexically_normal();
    if (!store_text.empty()) plan.store = (plan.study / store_text).lexically_normal();
    return plan;
}

} // namespace

SweepPlan read_sweep_file(const fs::path& file, const fs::path& output) {
    return parse_sweep(io::xml::read_file(file), file, output);
}

SweepPlan parse_sweep(std::string_view text, const fs::path& file, const fs::path& output) {
    return io::xml::read_strict(text, file.string(), io::xml::sweep_format(),
                                [&](const io::xml::Document& doc) { return read_sweep(doc, file, output); });
}


std::vector<SweepTask> SweepPlan::tasks() const {
    std::vector<SweepTask> out;
    const std::size_t n = configs.size();
    for (int r = 0; r < repeats; ++r)
        for (std::size_t c = 0; c < n; ++c) {
            SweepTask t;
            t.index = out.size();
            t.config = c;
            t.repeat = r;
            t.seed = first_seed + static_cast<std::uint64_t>(r) +
                     (rule == SeedRule::Distinct ? static_cast<std::uint64_t>(c) * static_cast<std::uint64_t>(repeats) : 0);
            t.run_dir = fs::path("runs") / configs[c].name / ("s" + std::to_string(t.seed));
            out.push_back(std::move(t));
        }
    return out;
}

std::vector<std::string> SweepPlan::overrides(const SweepTask& task) const {
    std::vector<std::string> out = common;
    const auto& own = configs.at(task.config).overrides;
    out.insert(out.end(), own.begin(), own.end());
    out.push_back("Experiment.seed=" + std::to_string(task.seed));
    return out;
}

std::string SweepPlan::command_line(const SweepTask& task) const {
    std::vector<std::string> argv{"cic", "--settings", base.string()};
    for (const auto& s : overrides(task)) argv.insert(argv.end(), {"--set", s});
    return shell_words(argv);
}

io::Settings SweepPlan::settings(const SweepTask& task, const std::vector<std::string>& extra) const {
    std::vector<std::string> all = overrides(task);
    all.insert(all.end(), extra.begin(), extra.end());
    return io::load_settings_text(base_xml, base, all);
}

} // namespace cic::study
