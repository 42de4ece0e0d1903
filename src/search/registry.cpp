// The registry of searches (search/search.hpp).
#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/did_you_mean.hpp"
#include "cic/io/search_names.hpp"
#include "cic/io/settings_extension.hpp"
#include "cic/io/xml.hpp"
#include "cic/search/search.hpp"

namespace cic::search {
namespace {

std::vector<SearchKind>& kinds() {
    static std::vector<SearchKind> k;
    return k;
}

std::string forms_text(const std::vector<io::GenotypeForm>& forms) {
    std::string out;
    for (const auto f : forms) out += (out.empty() ? "" : " and ") + std::string(io::to_string(f));
    return out;
}

bool varies(const SearchKind& k, io::GenotypeForm form) {
    return std::find(k.forms.begin(), k.forms.end(), form) != k.forms.end();
}

// For the settings digest (io::auto_search_pick): "" where `auto` picks nothing.
std::string auto_pick(const io::Settings& as_auto) {
    try {
        return search_of(as_auto).name;
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace

void register_search(SearchKind kind) {
    io::set_auto_search_pick(&auto_pick);
    if (!kind.load || !kind.make)
        throw std::invalid_argument("search '" + kind.name + "': give both load (its checkpoint's reader) and make");
    if (kind.budget_key.empty()) throw std::invalid_argument("search '" + kind.name + "': name its budget key");
    if (kind.claims && kind.claimed_by.empty())
        throw std::invalid_argument("search '" + kind.name + "': a search that claims runs says why (claimed_by)");
    if (std::any_of(kinds().begin(), kinds().end(), [&](const SearchKind& k) { return k.name == kind.name; }))
        throw std::invalid_argument("search '" + kind.name + "' is registered twice");
    // The name first (the built-ins' are known to the settings already): it is
    // checked before anything else changes.
    if (!io::is_builtin_search_name(kind.name)) io::register_search_name({kind.name, kind.doc, kind.forms});
    if (!kind.keys.empty()) io::register_settings_keys(kind.keys);
    if (!kind.checkpoint_root.empty() || kind.best) report::register_checkpoint_reader(kind.checkpoint_root, kind.best);
    kinds().push_back(std::move(kind));
}

const std::vector<SearchKind>& search_kinds() { return kinds(); }

const SearchKind& search_of(const io::Settings& s) {
    const io::GenotypeForm form = io::genotype_form(s);
    const SearchKind* claimer = nullptr;
    for (const auto& k : kinds())
        if (k.claims && k.claims(s)) {
            claimer = &k;
            break;
        }
    auto allowed = [&] {
        std::string names;
        for (const auto& k : kinds())
            if (varies(k, form)) names += (names.empty() ? "" : ", ") + k.name;
        return names;
    };
    const std::string& asked = s.experiment.search;
    if (asked == "auto") {
        if (claimer) return *claimer;
        for (const auto& k : kinds())
            if (k.fallback && varies(k, form)) return k;
        throw InputError(fmt::format("Experiment.search = auto: no registered search varies {} (a build without "
                                     "the search layer?)", io::to_string(form)),
                         s.source_file);
    }
    const auto it = std::find_if(kinds().begin(), kinds().end(), [&](const SearchKind& k) { return k.name == asked; });
    if (it == kinds().end()) {
        std::vector<std::string> names;
        for (const auto& k : kinds()) names.push_back(k.name);
        throw InputError(fmt::format("Experiment.search = {}: no such search{}; allowed: auto, {}", asked,
                                     io::did_you_mean(asked, names), allowed()),
                         s.source_file);
    }
    if (!varies(*it, form))
        throw InputError(fmt::format("Experiment.search = {} varies {}, but Experiment.type {} has {}; allowed for "
                                     "it: auto, {}",
                                     asked, forms_text(it->forms), s.experiment.type, io::to_string(form), allowed()),
                         s.source_file);
    if (it->claims && !it->claims(s))
        throw InputError(fmt::format("Experiment.search = {} needs {}", asked, it->claimed_by), s.source_file);
    if (claimer && claimer != &*it)
        throw InputError(fmt::format("Experiment.search = {}, but {} asks for the search {}; set one of them",
                                     asked, claimer->claimed_by, claimer->name),
                         s.source_file);
    return *it;
}

std::unique_ptr<Checkpoint> load_checkpoint(const SearchKind& kind, const io::Settings& s, const std::string& file) {
    if (!kind.checkpoint_schema.empty()) {
        const io::xml::Schema schema(kind.checkpoint_schema, "the " + kind.name + " checkpoint schema");
        const auto doc = io::xml::Document::load_file(file);
        if (const auto problem = schema.first_problem(doc))
            throw InputError("does not match the " + kind.name + " search's checkpoint schema: " + problem->message,
                             file, problem->line);
    }
    auto c = kind.load(s, file);
    c->file = file;
    return c;
}

std::vector<std::string> budget_keys() {
    std::vector<std::string> out{"Control.minimumFitness"};
    for (const auto& k : kinds())
        if (std::find(out.begin(), out.end(), k.budget_key) == out.end()) out.push_back(k.budget_key);
    return out;
}

} // namespace cic::search
