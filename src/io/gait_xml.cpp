// Gait checkpoints as XML (see gait_xml.hpp).
#include "cic/io/gait_xml.hpp"
#include "cic/io/experiment_types.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cic/core/error.hpp"
#include "cic/core/hash.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"
#include "content_hash.hpp"
#include "xml_numbers.hpp"

namespace cic::io {
namespace {

constexpr const char* kFormat = "cic-gait";
// Version 2 (issue 56): contentHash is over every value the file holds (origin
// and digest included) and required; version 1's, over the search's state
// only and optional, is still checked in the files that have one.
constexpr int kVersion = 2;

using detail::attribute;
using detail::exact;
using detail::exact_list;
using detail::parse_number;

void write_point(xml::Node parent, const char* element, const GaitPoint& p) {
    parent.add_child(element, exact_list(p.x)).set_attribute("fitness", exact(p.fitness));
}

GaitPoint read_point(const xml::Node& n, std::size_t dimension) {
    GaitPoint p;
    p.fitness = attribute<double>(n, "fitness");
    p.x = detail::parse_numbers(n, "parameter", n.text());
    if (p.x.size() != dimension)
        throw n.error("<" + std::string(n.name()) + "> has " + std::to_string(p.x.size()) + " parameters, the file says " +
                      std::to_string(dimension));
    return p;
}

} // namespace

std::string content_hash(const GaitFile& g) {
    std::string text = g.optimizer + " " + std::to_string(g.seed) + " " + std::to_string(g.generation) + " " +
                       std::to_string(g.evaluations) + " " + std::to_string(g.dimension) + "\n";
    auto point = [&](const GaitPoint& p) { text += exact(p.fitness) + ":" + exact_list(p.x) + "\n"; };
    point(g.champion);
    for (const GaitPoint& p : g.population) point(p);
    text += exact_list(g.history) + "\n";
    if (g.restarts) {
        text += std::to_string(g.restarts->count) + " " + std::to_string(g.restarts->population_size);
        for (int v : g.restarts->generations) text += " " + std::to_string(v);
    }
    if (g.handover)   // Switch-HybrID's start point: an edit would change the gait phase's run
        text += "\nhandover " + std::to_string(g.handover->generation) + " " + std::to_string(g.handover->evaluations) +
                " " + exact_list(g.handover->x);
    return hex16(fnv1a_64(text));
}

std::string to_xml(const GaitFile& g) {
    auto doc = xml::Document::create("gaitRun");
    auto root = doc.root();
    root.set_attribute("format", kFormat);
    root.set_attribute("version", std::to_string(kVersion));
    root.set_attribute("optimizer", g.optimizer);
    root.set_attribute("settingsDigest", g.settings_digest);
    root.set_attribute("seed", std::to_string(g.seed));
    root.set_attribute("generation", std::to_string(g.generation));
    root.set_attribute("evaluations", std::to_string(g.evaluations));
    root.set_attribute("dimension", std::to_string(g.dimension));
    if (g.origin) write_origin(root, *g.origin);
    write_point(root, "champion", g.champion);
    auto list = root.add_element("candidates");
    list.set_attribute("count", std::to_string(g.population.size()));
    for (const GaitPoint& p : g.population) write_point(list, "candidate", p);
    root.add_child("history", exact_list(g.history)).set_attribute("count", std::to_string(g.history.size()));
    if (g.restarts) {
        auto r = root.add_element("restarts");
        r.set_attribute("count", std::to_string(g.restarts->count));
        r.set_attribute("populationSize", std::to_string(g.restarts->population_size));
        std::string gens;
        for (int v : g.restarts->generations) gens += (gens.empty() ? "" : " ") + std::to_string(v);
        r.set_attribute("generations", gens);
    }
    if (g.handover) {
        auto h = root.add_child("handover", exact_list(g.handover->x));
        h.set_attribute("generation", std::to_string(g.handover->generation));
        h.set_attribute("evaluations", std::to_string(g.handover->evaluations));
    }
    root.set_attribute(detail::kContentHash, detail::document_hash(root));
    return doc.to_string();
}

namespace {

// The document has passed the strict reader (elements and attributes known,
// no stray text); these are the checkpoint's own rules.
GaitFile read_gait(const xml::Document& doc) {
    const auto root = doc.root();
    if (root.name() != "gaitRun" || root.attribute("format").value_or("") != kFormat)
        throw root.error("not a cic gait checkpoint (expected <gaitRun format=\"cic-gait\">)");
    const int version = attribute<int>(root, "version");
    if (version != 1 && version != kVersion)
        throw root.error("gait checkpoint version " + *root.attribute("version") + " is not supported (this cic reads " +
                         "1 and " + std::to_string(kVersion) + ")");

    GaitFile g;
    g.optimizer = root.attribute("optimizer").value_or("");
    g.settings_digest = root.attribute("settingsDigest").value_or("");
    g.seed = attribute<std::uint64_t>(root, "seed");
    g.generation = attribute<int>(root, "generation");
    g.evaluations = attribute<long>(root, "evaluations");
    g.dimension = attribute<std::size_t>(root, "dimension");
    if (g.generation < 0 || g.evaluations < 0 || g.dimension == 0 || g.dimension > 1000000)
        throw root.error("<gaitRun generation=\"" + *root.attribute("generation") + "\" evaluations=\"" +
                         *root.attribute("evaluations") + "\" dimension=\"" + *root.attribute("dimension") +
                         "\">: generation and evaluations must be >= 0 and dimension in [1, 1000000]");
    bool champion = false, candidates = false, state = false;
    for (const auto& c : root.children()) {
        const auto n = c.name();
        if (n == "origin") {
            g.origin = read_origin(c);
        } else if (n == "champion") {
            g.champion = read_point(c, g.dimension);
            champion = true;
        } else if (n == "candidates") {
            const auto count = attribute<std::size_t>(c, "count");
            for (const auto& p : c.children()) {
                if (p.name() != "candidate") throw p.error("unknown element <" + std::string(p.name()) + "> in <candidates>");
                g.population.push_back(read_point(p, g.dimension));
            }
            if (g.population.size() != count)
                throw c.error("<candidates count=\"" + std::to_string(count) + "\"> holds " +
                              std::to_string(g.population.size()) + " (truncated or edited?)");
            candidates = true;
        } else if (n == "history") {
            const auto count = attribute<std::size_t>(c, "count");
            std::istringstream in(c.text());
            for (std::string tok; in >> tok;) g.history.push_back(parse_number<double>(c, "fitness", tok));
            if (g.history.size() != count)
                throw c.error("<history count=\"" + std::to_string(count) + "\"> holds " +
                              std::to_string(g.history.size()) + " values (truncated or edited?)");
            if (static_cast<long>(count) != g.evaluations)
                throw c.error("the history holds " + std::to_string(count) + " fitness values for " +
                              std::to_string(g.evaluations) + " evaluations");
            state = true;
        } else if (n == "restarts") {
            if (g.restarts) throw c.error("<restarts> appears twice");
            GaitRestartRecord r;
            r.count = attribute<int>(c, "count");
            r.population_size = attribute<int>(c, "populationSize");
            if (r.count < 0 || r.population_size < 1)
                throw c.error("<restarts> count must be >= 0 and populationSize >= 1");
            std::istringstream in(std::string(c.attribute("generations").value_or("")));
            for (std::string tok; in >> tok;) {
                const int v = parse_number<int>(c, "generation", tok);
                if (v < 1 || v > g.generation || (!r.generations.empty() && v <= r.generations.back()))
                    throw c.error("<restarts> generations must rise, each in [1, " + std::to_string(g.generation) +
                                  "]; found " + tok);
                r.generations.push_back(v);
            }
            if (static_cast<int>(r.generations.size()) != r.count)
                throw c.error("<restarts count=\"" + std::to_string(r.count) + "\"> lists " +
                              std::to_string(r.generations.size()) + " generations (truncated or edited?)");
            g.restarts = std::move(r);
        } else if (n == "handover") {
            if (g.handover) throw c.error("<handover> appears twice");
            GaitHandover h;
            h.generation = attribute<int>(c, "generation");
            h.evaluations = attribute<long>(c, "evaluations");
            if (h.generation < 0 || h.evaluations < 0)
                throw c.error("<handover> generation and evaluations must be >= 0");
            h.x = detail::parse_numbers(c, "parameter", c.text());
            if (h.x.size() != g.dimension)
                throw c.error("<handover> has " + std::to_string(h.x.size()) + " parameters, the file says " +
                              std::to_string(g.dimension));
            g.handover = std::move(h);
        } else {
            throw c.error("unknown element <" + std::string(n) +
                          "> in <gaitRun>; allowed: origin, champion, candidates, history, restarts, handover");
        }
    }
    if (!champion || !candidates || !state)
        throw root.error("<gaitRun> needs <champion>, <candidates> and <history> (truncated?)");
    if (g.restarts && static_cast<std::size_t>(g.restarts->population_size) != g.population.size())
        throw root.error("<restarts populationSize=\"" + std::to_string(g.restarts->population_size) + "\"> but " +
                         std::to_string(g.population.size()) + " candidates");
    // An edited point or history value would be believed on resume: refuse it.
    if (version >= 2) detail::check_document_hash(root, "gait checkpoint");
    if (const auto h = root.attribute("contentHash"); version == 1 && h && *h != content_hash(g))
        // Never the expected value: pasted in, it would make any edit pass.
        throw root.error("<gaitRun contentHash=\"" + *h + "\"> does not match the champion, candidates and history "
                         "(edited by hand?): a gait checkpoint cannot be re-evaluated in part");
    return g;
}

} // namespace

GaitFile parse_gait(std::string_view text, const std::string& name) {
    return xml::read_strict(text, name, xml::gait_format(), read_gait);
}

GaitFile load_gait(const std::filesystem::path& path) { return parse_gait(xml::read_file(path), path.string()); }

bool is_gait_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string head(512, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head.find("<gaitRun") != std::string::npos;
}

void check_compatible(const GaitFile& g, const Settings& s, std::size_t dimension, const std::string& file) {
    if (family_of(s) != ExperimentFamily::Gait && !s.neural.switches())
        throw InputError("this is a gait checkpoint; the settings run another experiment type", file);
    if (s.neural.switches() != g.handover.has_value())
        throw InputError(g.handover ? "this checkpoint is a Switch-HybrID run's gait phase; the settings switch never"
                                    : "this gait checkpoint has no <handover>; the settings ask for Switch-HybrID",
                         file);
    const char* names[] = {"cmaes", "xnes", "sade", "sepcmaes"};
    const std::string wanted = names[static_cast<int>(s.gait.optimizer)];
    if (g.optimizer != wanted)
        throw InputError("the checkpoint was made by optimizer " + g.optimizer + ", the settings ask for " + wanted, file);
    if (g.dimension != dimension)
        throw InputError("the checkpoint has " + std::to_string(g.dimension) + " parameters per gait, these settings make " +
                         std::to_string(dimension) + " (another robot or Gait.secondHarmonic?)",
                         file);
}

} // namespace cic::io
