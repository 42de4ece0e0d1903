// MAP-Elites archives as XML (see archive_xml.hpp).
#include "cic/io/archive_xml.hpp"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/core/hash.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"
#include "cic/sim/evaluate.hpp"
#include "content_hash.hpp"
#include "xml_numbers.hpp"

namespace cic::io {
namespace {

constexpr const char* kFormat = "cic-archive";
// Version 2 (issue 56) adds <archive contentHash>, over every value the file
// holds (counters, random state, origin, emitter state); version 1 files load
// as before, their best elite's replay the proof of their fitness values.
constexpr int kVersion = 2;

using detail::attribute;
using detail::exact;
using detail::exact_list;
using detail::parse_numbers;

ArchiveElite read_elite(const xml::Node& e, const gp::GridSpec& grid, bool& gait, bool& hypergp) {
    ArchiveElite a;
    a.line = e.line();
    a.cell = attribute<std::size_t>(e, "cell");
    a.fitness = attribute<double>(e, "fitness");
    a.descriptor = parse_numbers(e, "descriptor", e.attribute("descriptor").value_or(""));
    if (a.cell >= grid.cells())
        throw e.error("<elite cell=\"" + std::to_string(a.cell) + "\"> is past the grid's " +
                      std::to_string(grid.cells()) + " cells");
    if (a.descriptor.size() != grid.dimensions())
        throw e.error("<elite> has a descriptor of " + std::to_string(a.descriptor.size()) + " values for a grid of " +
                      std::to_string(grid.dimensions()) + " dimensions");
    // A descriptor past the grid would be clamped into an edge cell: not one the run measured.
    for (std::size_t d = 0; d < a.descriptor.size(); ++d)
        if (a.descriptor[d] < grid.lo[d] || a.descriptor[d] > grid.hi[d])
            throw e.error(fmt::format("<elite cell=\"{}\"> descriptor value {} of dimension {} is outside the grid's [{}, {}]",
                                      a.cell, exact(a.descriptor[d]), d, exact(grid.lo[d]), exact(grid.hi[d])));
    if (grid.cell_of(a.descriptor) != a.cell)
        throw e.error("<elite cell=\"" + std::to_string(a.cell) + "\"> has a descriptor of cell " +
                      std::to_string(grid.cell_of(a.descriptor)) + " (edited?)");
    for (const auto& c : e.children()) {
        if (c.name() == "x") {
            if (!a.x.empty()) throw c.error("<elite> has two <x>");
            a.x = parse_numbers(c, "parameter", c.text());
            if (a.x.empty()) throw c.error("<x> holds no parameter");
            gait = true;
        } else if (c.name() == "tree") {
            try {
                a.genotype.push_back(tree::Tree::parse(c.text()));
            } catch (const std::exception& ex) {
                throw c.error(std::string("<tree>: ") + ex.what());
            }
            hypergp = true;
        }
    }
    if (a.x.empty() == a.genotype.empty()) throw e.error("<elite> needs either <x> or <tree> elements");
    for (double v : a.x)
        if (v < 0.0 || v > 1.0)
            throw e.error(fmt::format("<elite cell=\"{}\"> has parameter {} outside the unit box [0, 1]", a.cell, exact(v)));
    if (const auto h = e.attribute("hash"); h && *h != elite_hash(a))
        throw e.error(fmt::format("<elite cell=\"{}\" hash=\"{}\"> does not match its fitness, descriptor and solution "
                                  "(edited by hand?): an archive's elites cannot be re-evaluated in place",
                                  a.cell, *h));   // never the expected value: pasted in, it would make any edit pass
    return a;
}

// The document has passed the strict reader; these are the archive's own rules.
ArchiveFile read_archive(const xml::Document& doc) {
    const auto root = doc.root();
    if (root.name() != "archive" || root.attribute("format").value_or("") != kFormat)
        throw root.error("not a cic MAP-Elites archive (expected <archive format=\"cic-archive\">)");
    const int version = attribute<int>(root, "version");
    if (version != 1 && version != kVersion)
        throw root.error("archive version " + *root.attribute("version") + " is not supported (this cic reads " +
                         "1 and " + std::to_string(kVersion) + ")");

    ArchiveFile a;
    a.line = root.line();
    a.experiment = root.attribute("experiment").value_or("");
    a.settings_digest = root.attribute("settingsDigest").value_or("");
    a.seed = attribute<std::uint64_t>(root, "seed");
    a.batches = attribute<int>(root, "batches");
    a.evaluations = attribute<long>(root, "evaluations");
    a.failed = attribute<long>(root, "failed");
    if (a.batches < 1 || a.evaluations < a.batches || a.failed < 0 || a.failed > a.evaluations)
        throw root.error("<archive batches=\"" + std::to_string(a.batches) + "\" evaluations=\"" + std::to_string(a.evaluations) +
                         "\" failed=\"" + std::to_string(a.failed) +
                         "\">: batches must be >= 1, evaluations >= batches and failed in [0, evaluations]");
    try {
        a.rng = Rng::parse_state(std::string(root.attribute("rng").value_or("")));
    } catch (const std::invalid_argument& e) {
        throw root.error(std::string("<archive> rng: ") + e.what());
    }
    std::optional<gp::GridSpec> grid;
    bool gait = false, hypergp = false;
    for (const auto& c : root.children()) {
        if (c.name() == "origin") {
            a.origin = read_origin(c);
        } else if (c.name() == "grid") {
            a.descriptor = c.attribute("descriptor").value_or("");
            try {
                (void)sim::descriptor_from(a.descriptor);
            } catch (const std::invalid_argument& e) {
                throw c.error(std::string("<grid> descriptor: ") + e.what());
            }
            for (const auto& d : c.children()) {
                a.grid.bins.push_back(attribute<int>(d, "bins"));
                a.grid.lo.push_back(attribute<double>(d, "lo"));
                a.grid.hi.push_back(attribute<double>(d, "hi"));
            }
            try {
                a.grid.validate();
                grid = a.grid;
            } catch (const std::invalid_argument& e) {
                throw c.error(std::string("<grid>: ") + e.what());
            }
        } else if (c.name() == "elites") {
            if (!grid) throw c.error("<elites> before <grid>");
            const auto count = attribute<std::size_t>(c, "count");
            for (const auto& e : c.children()) {
                a.elites.push_back(read_elite(e, *grid, gait, hypergp));
                if (a.elites.size() > 1 && a.elites[a.elites.size() - 2].cell >= a.elites.back().cell)
                    throw e.error("elites must be in rising cell order, each cell once");
            }
            if (a.elites.size() != count)
                throw c.error("<elites count=\"" + std::to_string(count) + "\"> holds " +
                              std::to_string(a.elites.size()) + " (truncated or edited?)");
        } else if (c.name() == "emitter") {
            a.emitter = c.attribute("name").value_or("");
            a.emitter_state = c.text();
            if (a.emitter.empty() || a.emitter_state.empty())
                throw c.error("<emitter> needs a name and its state (truncated or edited?)");
        }
    }
    if (!grid) throw root.error("<archive> needs a <grid> (truncated?)");
    if (gait && hypergp) throw root.error("<archive> holds either parameter vectors or trees, not both");
    if (static_cast<long>(a.elites.size()) > a.evaluations - a.failed)
        throw root.error(fmt::format("<archive> holds {} elites but only {} successful evaluations (evaluations - failed)",
                                     a.elites.size(), a.evaluations - a.failed));
    // Last: what is wrong with a value is said first, and a hand edit after.
    if (version >= 2) detail::check_document_hash(root, "MAP-Elites archive");
    return a;
}

} // namespace

std::string elite_hash(const ArchiveElite& e) {
    std::string text = std::to_string(e.cell) + " " + exact(e.fitness) + " " + exact_list(e.descriptor) + "\n" +
                       exact_list(e.x) + "\n";
    for (const auto& t : e.genotype) text += t.to_string() + "\n";
    return hex16(fnv1a_64(text));
}

const ArchiveElite* ArchiveFile::best() const {
    const ArchiveElite* out = nullptr;
    for (const auto& e : elites)
        if (!out || e.fitness > out->fitness) out = &e;
    return out;
}

const ArchiveElite* ArchiveFile::at(std::size_t cell) const {
    for (const auto& e : elites)
        if (e.cell == cell) return &e;
    return nullptr;
}

std::string to_xml(const ArchiveFile& a) {
    auto doc = xml::Document::create("archive");
    auto root = doc.root();
    root.set_attribute("format", kFormat);
    root.set_attribute("version", std::to_string(kVersion));
    root.set_attribute("experiment", a.experiment);
    root.set_attribute("settingsDigest", a.settings_digest);
    root.set_attribute("seed", std::to_string(a.seed));
    root.set_attribute("batches", std::to_string(a.batches));
    root.set_attribute("evaluations", std::to_string(a.evaluations));
    root.set_attribute("failed", std::to_string(a.failed));
    Rng rng;
    rng.set_state(a.rng);
    root.set_attribute("rng", rng.state_text());
    if (a.origin) write_origin(root, *a.origin);
    auto grid = root.add_element("grid");
    grid.set_attribute("descriptor", a.descriptor);
    for (std::size_t d = 0; d < a.grid.dimensions(); ++d) {
        auto dim = grid.add_element("dimension");
        dim.set_attribute("bins", std::to_string(a.grid.bins[d]));
        dim.set_attribute("lo", exact(a.grid.lo[d]));
        dim.set_attribute("hi", exact(a.grid.hi[d]));
    }
    auto list = root.add_element("elites");
    list.set_attribute("count", std::to_string(a.elites.size()));
    for (const ArchiveElite& e : a.elites) {
        auto el = list.add_element("elite");
        el.set_attribute("cell", std::to_string(e.cell));
        el.set_attribute("fitness", exact(e.fitness));
        el.set_attribute("descriptor", exact_list(e.descriptor));
        el.set_attribute("hash", elite_hash(e));
        if (!e.x.empty()) el.add_child("x", exact_list(e.x));
        for (const auto& t : e.genotype) el.add_child("tree", t.to_string());
    }
    if (!a.emitter_state.empty()) {
        auto em = root.add_child("emitter", a.emitter_state);
        em.set_attribute("name", a.emitter);
    }
    root.set_attribute(detail::kContentHash, detail::document_hash(root));
    return doc.to_string();
}

ArchiveFile parse_archive(std::string_view text, const std::string& name) {
    return xml::read_strict(text, name, xml::archive_format(), read_archive);
}

ArchiveFile load_archive(const std::filesystem::path& path) {
    return parse_archive(xml::read_file(path), path.string());
}

namespace {

// The elites' solutions against the settings' genotype (read_elite has checked the file's own rules).
void check_elites(const ArchiveFile& a, const Settings& s, std::size_t gait_dimension, const std::string& file) {
    const int variables = s.gp.primitives.variable_count;
    const auto& functions = s.gp.primitives.functions;
    for (const ArchiveElite& e : a.elites) {
        auto refuse = [&](const std::string& why) {
            throw InputError(fmt::format("<elite cell=\"{}\"> {}", e.cell, why), file, e.line);
        };
        if (gait_dimension > 0) {
            if (e.x.size() != gait_dimension)
                refuse(fmt::format("has {} parameters, these settings make {}", e.x.size(), gait_dimension));
            continue;
        }
        if (!e.x.empty()) refuse("holds a parameter vector; these settings evolve trees");
        if (static_cast<int>(e.genotype.size()) != s.gp.trees_per_genotype)
            refuse(fmt::format("has {} trees, GP.numberOfTreesInForestGenotype is {}", e.genotype.size(),
                               s.gp.trees_per_genotype));
        for (const auto& t : e.genotype)
            for (const auto& node : t.nodes()) {
                if (node.op == tree::Op::Var && node.var >= variables)
                    refuse(fmt::format("uses variable x{}, but GP.terminalVariableCount is {}", node.var, variables));
                if (tree::arity(node.op) > 0 && std::find(functions.begin(), functions.end(), node.op) == functions.end())
                    refuse(fmt::format("uses function {}, which is not in GP.functions", tree::name(node.op)));
            }
    }
}

} // namespace

void check_compatible(const ArchiveFile& a, const Settings& s, const gp::GridSpec& grid, std::size_t gait_dimension,
                      const std::string& file) {
    if (!s.map_elites.enabled)
        throw InputError("this is a MAP-Elites archive; the settings do not enable MapElites", file);
    if (a.experiment != s.experiment.type)
        throw InputError("the archive was made by a " + a.experiment + " run, the settings run " + s.experiment.type,
                         file);
    if (a.descriptor != sim::to_string(s.map_elites.descriptor))
        throw InputError("the archive's descriptor is " + a.descriptor + ", the settings ask for " +
                             sim::to_string(s.map_elites.descriptor),
                         file);
    const std::string emitter(resolved_emitter(s));
    if (!a.emitter.empty() && a.emitter != emitter)
        throw InputError("the archive holds the state of a " + a.emitter + " emitter, the settings vary elites with " +
                             emitter + " (MapElites.emitter)",
                         file);
    if (a.grid.bins != grid.bins || a.grid.lo != grid.lo || a.grid.hi != grid.hi)
        throw InputError("the archive's grid differs from the one these settings make (MapElites.bins, omniRange, "
                         "or another robot?)",
                         file);
    // Every batch is whole (the loop stops before a batch the budget cannot hold).
    if (a.evaluations != static_cast<long>(a.batches) * s.map_elites.batch)
        throw InputError(fmt::format("<archive evaluations=\"{}\"> is not its {} batches of MapElites.batch {} ({})",
                                     a.evaluations, a.batches, s.map_elites.batch,
                                     static_cast<long>(a.batches) * s.map_elites.batch),
                         file, a.line);
    check_elites(a, s, gait_dimension, file);
}

} // namespace cic::io
