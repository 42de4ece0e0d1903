// IPOP restarts of the gait search (see restarts.hpp).
#include "cic/experiments/gait/restarts.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "cic/core/error.hpp"

namespace cic::gait {

RestartRule restart_rule_of(const io::Settings& s) {
    RestartRule r;
    r.mode = s.gait.restarts == io::GaitRestarts::Ipop ? Restarts::Ipop : Restarts::None;
    r.patience = s.gait.restart_patience;
    r.tolerance = s.gait.restart_tolerance;
    r.tol_x = s.gait.restart_tol_x;
    return r;
}

Search make_search(const Setup& setup, const RestartRule& rule, std::uint64_t seed) {
    Search search(setup.optimizer, setup.dimension(), setup.population, setup.sigma0, seed, rule);
    if (setup.encoding.centred && !setup.cpg) search.set_box(setup.encoding.lower());
    return search;
}

io::GaitRestartRecord restart_record_of(const Search& search) {
    return {search.restarts(), search.population_size(), search.restart_generations()};
}

Search resume_search(const Setup& setup, const RestartRule& rule, const io::GaitFile& g, const std::string& file) {
    Search search = make_search(setup, rule, g.seed);
    try {
        if (g.handover) search.set_start(g.handover->x);   // Switch-HybrID's first batch was drawn around it
        search.replay(g.history, g.generation);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("the checkpoint does not replay: ") + e.what(), file);
    } catch (const std::overflow_error& e) {
        throw InputError(std::string("the checkpoint does not replay: ") + e.what(), file);
    }
    if (g.restarts) {
        const io::GaitRestartRecord replayed = restart_record_of(search);
        if (replayed.count != g.restarts->count || replayed.population_size != g.restarts->population_size ||
            replayed.generations != g.restarts->generations)
            throw InputError(fmt::format("the checkpoint records {} restart{} (population {}), replaying its history "
                                         "under these settings gives {} (population {}): another Gait.restarts, "
                                         "restartPatience, restartTolerance or restartTolX?",
                                         g.restarts->count, g.restarts->count == 1 ? "" : "s",
                                         g.restarts->population_size, replayed.count, replayed.population_size),
                             file);
    }
    bool same = search.population().size() == g.population.size() && search.champion().x == g.champion.x &&
                search.champion().fitness == g.champion.fitness;
    for (std::size_t i = 0; same && i < g.population.size(); ++i)
        same = search.population()[i].x == g.population[i].x && search.population()[i].fitness == g.population[i].fitness;
    if (!same)
        throw InputError("replaying the checkpoint's history does not give its candidates (edited by hand, made by "
                         "another version of cic or pagmo, or with other restart settings?)",
                         file);
    return search;
}

} // namespace cic::gait
