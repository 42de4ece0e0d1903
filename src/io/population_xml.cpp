#include "cic/io/population_xml.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "cic/core/limits.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"
#include "cic/gp/dedup.hpp"
#include "content_hash.hpp"
#include "xml_numbers.hpp"

namespace cic::io {
namespace {

constexpr const char* kFormat = "cic-population";
// Version 2 (issue 56) adds <population contentHash>, over every value but the
// trees and offsets (an individual edited there is evaluated again, its own
// hash tells it apart); version 1 files load as before, their champion's
// replay (report/verify.hpp) the proof of their fitness values.
constexpr int kVersion = 2;
const std::initializer_list<std::string_view> kFreeText = {"tree", "offsets"};

using detail::exact;

std::string hash_text(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::vector<std::string> function_names(const Settings& s) {
    std::vector<std::string> out;
    for (auto op : s.gp.primitives.functions) out.emplace_back(tree::name(op));
    return out;
}

std::string join(const std::vector<std::string>& v) {
    std::string out;
    for (const auto& x : v) out += (out.empty() ? "" : " ") + x;
    return out;
}

template <class T>
T number(const xml::Node& n, std::string_view attr, std::string_view text) {
    T v{};
    const char* b = text.data();
    const char* e = b + text.size();
    std::from_chars_result r{};
    if constexpr (std::is_floating_point_v<T>) {
        // from_chars for double is exact; also accept inf/nan spellings we never write.
        r = std::from_chars(b, e, v);
    } else {
        r = std::from_chars(b, e, v);
    }
    if (text.empty() || r.ec != std::errc() || r.ptr != e)
        throw n.error("<" + std::string(n.name()) + "> attribute " + std::string(attr) + "=\"" + std::string(text) +
                      "\" is not a valid number");
    return v;
}

template <class T>
T required(const xml::Node& n, std::string_view attr) {
    auto a = n.attribute(attr);
    if (!a) throw n.error("<" + std::string(n.name()) + "> is missing attribute " + std::string(attr));
    return number<T>(n, attr, *a);
}

std::string required_text(const xml::Node& n, std::string_view attr) {
    auto a = n.attribute(attr);
    if (!a) throw n.error("<" + std::string(n.name()) + "> is missing attribute " + std::string(attr));
    return *a;
}

gp::IndividualPtr read_individual(const xml::Node& n, int trees, std::size_t offsets, double offset_limit) {
    auto ind = std::make_shared<gp::Individual>();
    ind->id = required<std::uint64_t>(n, "id");
    ind->fitness = required<double>(n, "fitness");
    // Fitness drives selection and stopping: NaN or inf has no place there.
    if (!std::isfinite(ind->fitness))
        throw n.error("individual " + std::to_string(ind->id) + ": fitness=\"" + *n.attribute("fitness") +
                      "\" is not a finite number");
    ind->evaluated = required<int>(n, "evaluated") != 0;
    for (const auto& c : n.children()) {
        const auto name = c.name();
        if (name == "tree") {
            try {
                ind->genotype.push_back(tree::Tree::parse(c.text()));
                if (ind->genotype.back().size() > limits::kMaxTreeNodes)
                    throw InputError("a tree of " + std::to_string(ind->genotype.back().size()) +
                                     " nodes is past the limit of " + std::to_string(limits::kMaxTreeNodes));
            } catch (const InputError& e) {
                throw c.error("individual " + std::to_string(ind->id) + ": bad tree: " + e.message());
            } catch (const std::exception& e) {
                throw c.error("individual " + std::to_string(ind->id) + ": bad tree: " + e.what());
            }
        } else if (name == "offsets") {
            const std::string who = "individual " + std::to_string(ind->id) + ": ";
            if (offsets == 0) throw c.error(who + "<offsets> but the <genotype> declares none (offsets=\"0\")");
            if (!ind->direct.empty()) throw c.error(who + "two <offsets> elements");
            std::istringstream in(c.text());
            std::string tok;
            while (in >> tok) {
                const double d = number<double>(c, "offsets", tok);
                if (!std::isfinite(d) || std::abs(d) > offset_limit)
                    throw c.error(who + "offset " + tok + " is outside [-" + exact(offset_limit) + ", " +
                                  exact(offset_limit) + "]");
                ind->direct.push_back(d);
            }
            if (ind->direct.size() != offsets)
                throw c.error(who + std::to_string(ind->direct.size()) + " offsets, the <genotype> declares " +
                              std::to_string(offsets));
        } else if (name == "parents") {
            std::istringstream in(c.text());
            std::string tok;
            while (in >> tok) ind->parents.push_back(number<std::uint64_t>(c, "parents", tok));
        } else if (name == "attribute") {
            const std::string key = required_text(c, "key");
            const std::string value = c.text();
            auto mark = [&](bool& flag) {
                if (value != "1") throw c.error("<attribute key=\"" + key + "\"> must hold 1, not '" + value + "'");
                flag = true;
            };
            if (key == "illegal") mark(ind->illegal);
            else if (key == "edited") mark(ind->edited);
            else if (key == "failed") {
                ind->failed = true;
                ind->failure = value;
            } else
                throw c.error("unknown attribute key '" + key + "'; allowed: edited, failed, illegal");
        } else {
            throw c.error("unknown element <" + std::string(name) +
                          "> in <individual>; allowed: tree, offsets, parents, attribute");
        }
    }
    if (ind->direct.size() != offsets)
        throw n.error("individual " + std::to_string(ind->id) + " has no <offsets>, the <genotype> declares " +
                      std::to_string(offsets));
    if (static_cast<int>(ind->genotype.size()) != trees)
        throw n.error("individual " + std::to_string(ind->id) + " has " + std::to_string(ind->genotype.size()) +
                      " trees, the file header says " + std::to_string(trees));
    // depth and size are there for people and tools; the hash tells a hand edit
    // apart, and an edited individual is evaluated again instead of keeping a stale fitness.
    if (auto h = n.attribute("hash"); h && *h != hash_text(gp::genotype_hash(ind->genotype, ind->direct))) {
        ind->evaluated = false;
        ind->edited = true;
    }
    return ind;
}

} // namespace

PopulationFile describe(const Settings& s) {
    PopulationFile p;
    p.experiment = s.experiment.type;
    p.settings_digest = settings_digest(s);
    p.variables = s.gp.primitives.variable_count;
    p.functions = function_names(s);
    p.trees = s.gp.trees_per_genotype;
    p.state.seed = s.experiment.seed;
    p.origin = origin_of(s);
    return p;
}

std::string to_xml(const PopulationFile& p) {
    auto doc = xml::Document::create("population");
    auto root = doc.root();
    root.set_attribute("format", kFormat);
    root.set_attribute("version", std::to_string(kVersion));
    root.set_attribute("experiment", p.experiment);
    root.set_attribute("settingsDigest", p.settings_digest);
    root.set_attribute("generation", std::to_string(p.population.generation));
    if (p.origin) write_origin(root, *p.origin);
    auto shape = root.add_element("genotype");
    shape.set_attribute("variables", std::to_string(p.variables));
    shape.set_attribute("functions", join(p.functions));
    shape.set_attribute("trees", std::to_string(p.trees));
    if (p.offsets > 0) {
        shape.set_attribute("offsets", std::to_string(p.offsets));
        shape.set_attribute("offsetLimit", exact(p.offset_limit));
    }
    auto rng = root.add_element("rng");
    rng.set_attribute("seed", std::to_string(p.state.seed));
    rng.set_attribute("state", p.state.rng.state_text());
    auto counters = root.add_element("counters");
    counters.set_attribute("nextId", std::to_string(p.state.next_id));
    counters.set_attribute("evaluations", std::to_string(p.state.evaluations));
    auto bloat = root.add_element("bloat");
    bloat.set_attribute("limit", std::to_string(p.state.bloat.limit));
    bloat.set_attribute("initialMax", std::to_string(p.state.bloat.initial_max));
    bloat.set_attribute("bestFitness", exact(p.state.bloat.best_fitness));
    if (p.switch_clock) {
        auto clock = root.add_element("switch");
        clock.set_attribute("bestFitness", exact(p.switch_clock->best));
        clock.set_attribute("bestGeneration", std::to_string(p.switch_clock->best_generation));
    }
    if (p.body) root.add_element("body").set_attribute("index", std::to_string(*p.body));
    auto list = root.add_element("individuals");
    list.set_attribute("count", std::to_string(p.population.size()));
    for (const auto& ind : p.population) {
        auto n = list.add_element("individual");
        n.set_attribute("id", std::to_string(ind->id));
        n.set_attribute("fitness", exact(ind->fitness));
        n.set_attribute("evaluated", ind->evaluated ? "1" : "0");
        n.set_attribute("depth", std::to_string(ind->depth(gp::ForestDepth::Max)));   // the deepest tree
        n.set_attribute("size", std::to_string(ind->size()));
        if (ind->direct.size() != p.offsets)
            throw std::logic_error("population file: individual " + std::to_string(ind->id) + " has " +
                                   std::to_string(ind->direct.size()) + " offsets, the header " +
                                   std::to_string(p.offsets));
        n.set_attribute("hash", hash_text(gp::genotype_hash(ind->genotype, ind->direct)));
        if (!ind->parents.empty()) {
            std::string ids;
            for (auto id : ind->parents) ids += (ids.empty() ? "" : " ") + std::to_string(id);
            n.add_child("parents", ids);
        }
        // In key order, as files written before the marks were typed.
        if (ind->edited) n.add_child("attribute", "1").set_attribute("key", "edited");
        if (ind->failed) n.add_child("attribute", ind->failure).set_attribute("key", "failed");
        if (ind->illegal) n.add_child("attribute", "1").set_attribute("key", "illegal");
        for (const auto& t : ind->genotype) n.add_child("tree", t.to_string());
        if (!ind->direct.empty()) n.add_child("offsets", detail::exact_list(ind->direct));
    }
    root.set_attribute(detail::kContentHash, detail::document_hash(root, kFreeText));
    return doc.to_string();
}

void save_population(const std::filesystem::path& path, const PopulationFile& p) {
    xml::write_file_atomically(path, to_xml(p));
}

namespace {

// The document has passed the strict reader (elements and attributes known,
// no stray text); these are the population's own rules.
PopulationFile read_population(const xml::Document& doc) {
    const auto root = doc.root();
    if (root.name() != "population" || root.attribute("format").value_or("") != kFormat)
        throw root.error("not a cic population file (expected <population format=\"cic-population\">)");
    const int version = required<int>(root, "version");
    if (version != 1 && version != kVersion)
        throw root.error("population file version " + *root.attribute("version") + " is not supported (this cic reads " +
                         "1 and " + std::to_string(kVersion) + ")");

    PopulationFile p;
    p.experiment = required_text(root, "experiment");
    p.settings_digest = root.attribute("settingsDigest").value_or("");
    p.population.generation = required<int>(root, "generation");
    if (p.population.generation < 0)
        throw root.error("generation=\"" + *root.attribute("generation") + "\" must be >= 0");
    bool have_rng = false, have_shape = false, have_list = false;
    std::size_t declared = 0;
    xml::Node list_node;
    for (const auto& c : root.children()) {
        const auto nm = c.name();
        if (nm == "origin") {
            p.origin = read_origin(c);
        } else if (nm == "genotype") {
            have_shape = true;
            p.variables = required<int>(c, "variables");
            p.trees = required<int>(c, "trees");
            if (p.variables < 0 || p.variables > 65535) throw c.error("variables must be in [0, 65535]");
            if (p.trees < 1 || p.trees > 16) throw c.error("trees must be in [1, 16]");
            const int offsets = c.attribute("offsets") ? required<int>(c, "offsets") : 0;
            if (offsets < 0 || static_cast<std::size_t>(offsets) > limits::kMaxModules)
                throw c.error("offsets must be in [0, " + std::to_string(limits::kMaxModules) + "]");
            p.offsets = static_cast<std::size_t>(offsets);
            if (p.offsets > 0) {
                p.offset_limit = required<double>(c, "offsetLimit");
                if (!std::isfinite(p.offset_limit) || !(p.offset_limit > 0))
                    throw c.error("offsetLimit must be a finite number > 0");
            } else if (c.attribute("offsetLimit")) {
                throw c.error("offsetLimit without offsets");
            }
            std::istringstream in(required_text(c, "functions"));
            std::string f;
            while (in >> f) p.functions.push_back(f);
        } else if (nm == "rng") {
            have_rng = true;
            p.state.seed = required<std::uint64_t>(c, "seed");
            try {
                p.state.rng.set_state(Rng::parse_state(required_text(c, "state")));
            } catch (const std::invalid_argument& e) {
                throw c.error(e.what());
            }
        } else if (nm == "counters") {
            p.state.next_id = required<std::uint64_t>(c, "nextId");
            p.state.evaluations = required<long>(c, "evaluations");
            if (p.state.evaluations < 0) throw c.error("evaluations must be >= 0");
        } else if (nm == "bloat") {
            p.state.bloat.limit = required<int>(c, "limit");
            p.state.bloat.initial_max = required<int>(c, "initialMax");
            p.state.bloat.best_fitness = required<double>(c, "bestFitness");
            if (p.state.bloat.limit < 0 || p.state.bloat.initial_max < 0 || !std::isfinite(p.state.bloat.best_fitness))
                throw c.error("<bloat> needs limit >= 0, initialMax >= 0 and a finite bestFitness");
        } else if (nm == "switch") {
            PopulationFile::SwitchClock clock;
            clock.best = required<double>(c, "bestFitness");
            clock.best_generation = required<int>(c, "bestGeneration");
            if (!std::isfinite(clock.best) || clock.best_generation < 0 ||
                clock.best_generation > p.population.generation)
                throw c.error("<switch> needs a finite bestFitness and bestGeneration in [0, generation]");
            p.switch_clock = clock;
        } else if (nm == "body") {
            p.body = required<std::size_t>(c, "index");
        } else if (nm == "individuals") {
            have_list = true;
            list_node = c;
            declared = required<std::size_t>(c, "count");
            if (declared > limits::kMaxPopulation)
                throw c.error("count=\"" + std::to_string(declared) + "\" is past the population limit of " +
                              std::to_string(limits::kMaxPopulation));
            if (!have_shape) throw c.error("<genotype> must come before <individuals>");
            std::set<std::uint64_t> ids;
            for (const auto& n : c.children()) {
                if (n.name() != "individual") throw n.error("unknown element <" + std::string(n.name()) + "> in <individuals>");
                if (p.population.size() >= declared)
                    throw n.error("more individuals than <individuals count=\"" + std::to_string(declared) + "\">");
                p.population.individuals.push_back(read_individual(n, p.trees, p.offsets, p.offset_limit));
                p.lines[p.population.individuals.back()->id] = n.line();
                if (!ids.insert(p.population.individuals.back()->id).second)
                    throw n.error("individual id " + std::to_string(p.population.individuals.back()->id) +
                                  " appears twice");
            }
        } else {
            throw c.error("unknown element <" + std::string(nm) + "> in <population>; allowed: origin, genotype, rng, counters, bloat, switch, body, individuals");
        }
    }
    if (!have_shape) throw root.error("missing <genotype> element");
    if (!have_rng) throw root.error("missing <rng> element (seed and RNG state)");
    if (!have_list) throw root.error("missing <individuals> element");
    if (declared != p.population.size())
        throw list_node.error("<individuals count=\"" + std::to_string(declared) + "\"> but " +
                              std::to_string(p.population.size()) + " individuals follow (truncated file?)");
    if (p.population.empty()) throw list_node.error("the population is empty");
    std::uint64_t max_id = 0;
    for (const auto& ind : p.population) max_id = std::max(max_id, ind->id);
    if (p.state.next_id <= max_id) p.state.next_id = max_id + 1;
    // Last: what is wrong with a value is said first, and a hand edit after.
    if (version >= 2) detail::check_document_hash(root, "population file", kFreeText);
    return p;
}

} // namespace

PopulationFile load_population(const std::filesystem::path& path) {
    return parse_population(xml::read_file(path), path.string());
}

PopulationFile parse_population(std::string_view text, const std::string& name) {
    return xml::read_strict(text, name, xml::population_format(), read_population);
}


void check_compatible(const PopulationFile& loaded, const Settings& s, const std::string& file) {
    const PopulationFile want = describe(s);
    auto refuse = [&](const std::string& what, const std::string& have, const std::string& need) {
        throw InputError("population was made with " + what + " " + have + " but the settings say " + need +
                         "; use settings that match the population, or start a new population", file);
    };
    if (loaded.experiment != want.experiment) refuse("experiment", loaded.experiment, want.experiment);
    if (loaded.variables != want.variables)
        refuse("terminalVariableCount", std::to_string(loaded.variables), std::to_string(want.variables));
    if (loaded.trees != want.trees)
        refuse("numberOfTreesInForestGenotype", std::to_string(loaded.trees), std::to_string(want.trees));
    if (loaded.functions != want.functions) refuse("functions", "'" + join(loaded.functions) + "'", "'" + join(want.functions) + "'");
    for (const auto& ind : loaded.population) {
        const auto at = loaded.lines.find(ind->id);
        const int line = at == loaded.lines.end() ? 0 : at->second;
        for (const auto& t : ind->genotype)
            for (const auto& node : t.nodes()) {
                if (node.op == tree::Op::Var && node.var >= want.variables)
                    throw InputError("individual " + std::to_string(ind->id) + " uses variable x" + std::to_string(node.var) +
                                     " but terminalVariableCount is " + std::to_string(want.variables), file, line);
                if (tree::arity(node.op) > 0 && std::find(s.gp.primitives.functions.begin(),
                                                          s.gp.primitives.functions.end(),
                                                          node.op) == s.gp.primitives.functions.end())
                    throw InputError("individual " + std::to_string(ind->id) + " uses function " +
                                     std::string(tree::name(node.op)) + ", which is not in the settings' functions '" +
                                     join(want.functions) + "'", file, line);
            }
    }
}

} // namespace cic::io
