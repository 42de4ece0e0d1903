// CMA-ME's improvement emitter (M. C. Fontaine, J. Togelius, S. Nikolaidis and
// A. K. Hoover, "Covariance matrix adaptation for the rapid illumination of
// behavior space", GECCO 2020) for gait vectors: MapElites.emitter = cma-me.
//
// One CMA-ES (pagmo's cmaes, stepped a generation at a time as the gait search
// steps it: pagmo_box.hpp) whose population is the batch. A start begins at an
// elite drawn uniformly from the archive, with step size MapElites.sigma. Its
// offspring are ranked by what they did to the archive: those that filled a
// new cell first (by fitness), then those that improved a cell (by the gain),
// then the rest (by how far below the cell's elite they fell). A generation
// that adds nothing to the archive ends the start; the next batch begins
// another at a fresh elite. Offspring outside the unit box are mirrored into
// it for evaluation and the archive (CMA-ES keeps the unmirrored point).
//
// The state in a checkpoint is the current start (its number, the elite it
// began at) and the rank values of each of its generations: a resume replays
// them through pagmo, which is deterministic from its seed.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/cma_me_emitter.hpp"
#include "pagmo_box.hpp"

namespace cic::gait {
namespace {

using detail::BoxProblem;
using detail::key_of;
using detail::Ledger;
using detail::seed32;
using Vector = std::vector<double>;

// The rank groups, far apart: eq. 7.1 values are metres, never near 1e5.
constexpr double kNewCell = 2e6, kImproved = 1e6, kLimit = 5e5;

double rank_value(const gp::Outcome& o) {
    auto bounded = [](double v) { return std::clamp(v, -kLimit, kLimit); };
    switch (o.kind) {
    case gp::Outcome::Kind::NewCell: return kNewCell + bounded(o.fitness);
    case gp::Outcome::Kind::Improved: return kImproved + bounded(o.improvement);
    case gp::Outcome::Kind::NotKept: return bounded(o.improvement);
    case gp::Outcome::Kind::Failed: return -kImproved;
    }
    return -kImproved;
}

double mirrored(double v) {
    v = std::fmod(std::fabs(v), 2.0);
    return v <= 1.0 ? v : 2.0 - v;
}

class CmaMe {
public:
    CmaMe(std::size_t n, int lambda, double sigma0, std::uint64_t seed)
        : n_(n), lambda_(lambda), sigma0_(sigma0), seed_(seed), problem_{n} {}

    std::vector<Vector> ask(Rng& rng, const gp::GridArchive<Vector>& archive, std::size_t count) {
        if (count != static_cast<std::size_t>(lambda_))
            throw std::logic_error(fmt::format("cma-me: a batch of {} for a population of {}", count, lambda_));
        if (!pending_.empty()) throw std::logic_error("cma-me: asked twice without being told");
        if (restart_) begin(archive.at(archive.random_cell(rng))->solution);
        pending_ = next_points();
        std::vector<Vector> out = pending_;
        for (auto& x : out)
            for (double& v : x) v = mirrored(v);
        return out;
    }

    void tell(const std::vector<gp::Outcome>& outcomes) {
        if (outcomes.size() != pending_.size())
            throw std::logic_error(fmt::format("cma-me: told {} outcomes for {} points", outcomes.size(), pending_.size()));
        Vector values;
        bool added = false;
        for (const auto& o : outcomes) {
            values.push_back(rank_value(o));
            added = added || o.kind == gp::Outcome::Kind::NewCell || o.kind == gp::Outcome::Kind::Improved;
        }
        evolve(pending_, values);
        generations_.push_back(std::move(values));
        pending_.clear();
        restart_ = !added;
    }

    std::string save() const {
        if (start_ == 0) return {};
        std::string out = fmt::format("cma-me 1\nstart {}\nrestart {}\nx0", start_, restart_ ? 1 : 0);
        for (double v : x0_) out += fmt::format(" {:.17g}", v);
        for (const auto& g : generations_) {
            out += "\ngeneration";
            for (double v : g) out += fmt::format(" {:.17g}", v);
        }
        return out + "\n";
    }

    // Throws std::invalid_argument for a state this emitter could not have saved.
    void load(const std::string& text) {
        pending_.clear();
        generations_.clear();
        start_ = 0;
        restart_ = true;
        if (text.empty()) return;
        std::istringstream in(text);
        std::string line, word;
        auto bad = [](const std::string& why) { return std::invalid_argument("cma-me emitter state: " + why); };
        auto numbers = [&](std::istringstream& words, const char* what) {
            Vector v;
            for (std::string w; words >> w;) {
                std::size_t used = 0;
                double d = 0;
                try {
                    d = std::stod(w, &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used != w.size() || !std::isfinite(d)) throw bad(std::string(what) + ": '" + w + "' is not a finite number");
                v.push_back(d);
            }
            return v;
        };
        if (!std::getline(in, line) || line != "cma-me 1") throw bad("the first line must be 'cma-me 1'");
        int start = 0, restart = -1;
        if (!std::getline(in, line) || line.rfind("start ", 0) != 0 ||
            std::from_chars(line.data() + 6, line.data() + line.size(), start).ptr != line.data() + line.size() ||
            start < 1 || start > 1000000000 || line != "start " + std::to_string(start))
            throw bad("'start N' with N in [1, 10^9] expected, got '" + line + "'");
        if (!std::getline(in, line) || (line != "restart 0" && line != "restart 1"))
            throw bad("'restart 0' or 'restart 1' expected, got '" + line + "'");
        restart = line.back() - '0';
        if (!std::getline(in, line)) throw bad("no 'x0' line");
        std::istringstream x0(line);
        if (!(x0 >> word) || word != "x0") throw bad("'x0 ...' expected, got '" + line + "'");
        Vector start_point = numbers(x0, "x0");
        if (start_point.size() != n_) throw bad(fmt::format("x0 has {} values for a dimension of {}", start_point.size(), n_));
        for (double v : start_point)
            if (v < 0.0 || v > 1.0) throw bad(fmt::format("x0 holds {}, outside the unit box", v));
        std::vector<Vector> generations;
        while (std::getline(in, line)) {
            std::istringstream g(line);
            if (!(g >> word) || word != "generation") throw bad("'generation ...' expected, got '" + line + "'");
            generations.push_back(numbers(g, "generation"));
            if (generations.back().size() != static_cast<std::size_t>(lambda_))
                throw bad(fmt::format("a generation of {} values for a population of {}", generations.back().size(), lambda_));
        }
        start_ = start - 1;
        begin(start_point);
        for (auto& values : generations) {
            evolve(next_points(), values);
            generations_.push_back(std::move(values));
        }
        restart_ = restart == 1;
    }

private:
    // A new start at x0: a fresh cmaes whose mean is x0 (pagmo starts from the
    // population's best, here lambda copies of x0).
    void begin(Vector x0) {
        ++start_;
        x0_ = std::move(x0);
        generations_.clear();
        algorithm_ = pagmo::algorithm{pagmo::cmaes(1u, -1, -1, -1, -1, sigma0_, 0.0, 0.0, true, false,
                                                   seed32(seed_, static_cast<std::uint64_t>(start_)))};
        population_ = pagmo::population(pagmo::problem{problem_}, 0u, seed32(seed_, 1000003u + static_cast<std::uint64_t>(start_)));
        for (int i = 0; i < lambda_; ++i) population_.push_back(x0_, {0.0});
        restart_ = false;
    }

    // The points the next generation asks for: a generation run on copies.
    std::vector<Vector> next_points() {
        Ledger& ledger = *problem_.ledger;
        ledger = Ledger{};
        ledger.recording = true;
        {
            pagmo::algorithm algorithm = algorithm_;
            pagmo::population population = population_;
            algorithm.evolve(population);
        }
        std::vector<Vector> points = std::move(ledger.asked);
        ledger = Ledger{};
        if (points.size() != static_cast<std::size_t>(lambda_))
            throw std::logic_error(fmt::format("cma-me: pagmo asked for {} points, not {}", points.size(), lambda_));
        return points;
    }

    // The generation for real, the points answered with their rank values.
    void evolve(const std::vector<Vector>& points, const Vector& values) {
        Ledger& ledger = *problem_.ledger;
        ledger = Ledger{};
        for (std::size_t i = 0; i < points.size(); ++i) ledger.known.emplace(key_of(points[i]), values[i]);
        population_ = algorithm_.evolve(population_);
        ledger = Ledger{};
    }

    std::size_t n_;
    int lambda_;
    double sigma0_;
    std::uint64_t seed_;
    BoxProblem problem_;
    pagmo::algorithm algorithm_;
    pagmo::population population_;
    int start_ = 0;           // starts begun
    bool restart_ = true;     // the next batch begins a start
    Vector x0_;
    std::vector<Vector> generations_;   // the current start's rank values, per generation
    std::vector<Vector> pending_;       // asked, not yet told (unmirrored)
};

} // namespace

void check_cma_me(const io::Settings& s) {
    const auto& me = s.map_elites;
    if (me.batch < 5)
        throw InputError(fmt::format("<MapElites> batch = {}: the cma-me emitter's CMA-ES takes the batch as its "
                                     "population, and pagmo's cmaes needs at least 5 (allowed: batch >= 5)",
                                     me.batch),
                         s.source_file);
    if (me.initial % me.batch != 0)
        throw InputError(fmt::format("<MapElites> initial = {}, batch = {}: with the cma-me emitter every varied batch "
                                     "is one CMA-ES generation, so initial must be a multiple of batch",
                                     me.initial, me.batch),
                         s.source_file);
}

gp::Emitter<std::vector<double>> cma_me_emitter(const io::Settings& s, const gp::VectorMapElitesConfig& c) {
    gp::Emitter<Vector> e = gp::gaussian_emitter(c);   // uniform starting points and the size check
    e.vary = nullptr;
    auto cma = std::make_shared<CmaMe>(c.dimension, c.batch, c.sigma, s.experiment.seed);
    e.ask = [cma](Rng& rng, const gp::GridArchive<Vector>& a, std::size_t count) { return cma->ask(rng, a, count); };
    e.tell = [cma](const std::vector<gp::Outcome>& o) { cma->tell(o); };
    e.save = [cma] { return cma->save(); };
    e.load = [cma](const std::string& text) { cma->load(text); };
    return e;
}

} // namespace cic::gait
