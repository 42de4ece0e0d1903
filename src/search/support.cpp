// What searches share (search/support.hpp).
#include "cic/search/support.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"

namespace cic::search {

void fill_fitness_stats(gp::GenerationRecord& r, std::vector<double> f) {
    if (f.empty()) return;
    std::sort(f.begin(), f.end());
    r.best = f.back();
    double sum = 0;
    for (double v : f) sum += v;
    r.mean = sum / static_cast<double>(f.size());
    const std::size_t n = f.size();
    r.median = n % 2 ? f[n / 2] : 0.5 * (f[n / 2 - 1] + f[n / 2]);
}

std::string eq71_line(double distance, double elevation) {
    return fmt::format("best, eq. 7.1: distance {:.4f} m + elevation {:.4f} m\n", distance, elevation);
}

std::string search_note(const std::string& file_digest, const io::Settings& s, const std::string& from) {
    const std::string now = io::settings_digest(s);
    if (file_digest == now || file_digest == io::settings_digest(s, io::DigestRule::Legacy)) return {};
    return fmt::format("note: {} was made with other settings (digest {}, now {}); its origin (robot, simulator, "
                       "controller) is these settings', so its fitness values hold; the budget and the search's own "
                       "settings are now these",
                       from, file_digest, now);
}

void refuse_if_reached(double best, const io::Settings& s, const std::string& file) {
    if (best >= s.control.minimum_fitness)
        throw InputError(fmt::format("the run reached Control.minimumFitness {} (best {}); to go on, raise it with "
                                     "--set Control.minimumFitness=F",
                                     s.control.minimum_fitness, best),
                         file);
}

void say_checkpoint_notes(const Checkpoint& c, const Services& services) {
    if (!c.origin_note.empty()) services.say(c.origin_note);
    if (!c.search_note.empty()) services.say(c.search_note);
}

} // namespace cic::search
