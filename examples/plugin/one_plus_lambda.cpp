// A search of your own, built outside cic against the installed package
// (docs/extending.md, "A new search"): a (1+lambda)-ES with the 1/5th success
// rule (Rechenberg 1973; Beyer & Schwefel 2002) over the gait vector of any
// gait-type settings. One file registers it; cic's own run loop drives it:
// worker processes or MPI ranks, stats.csv, the progress line, checkpoints,
// stop signals, `cic resume` and sweeps, the same bytes for 1 or N workers.
//
//   <Experiment><search>one-plus-lambda</search></Experiment>
//   <OnePlusLambda><lambda>8</lambda><sigma>0.1</sigma><evaluations>400</evaluations></OnePlusLambda>
//
// Its checkpoint is its own XML file, written whole and read back strictly:
// every attribute present and in range, nothing unknown, and the run's origin
// (robot, simulator, controller) proved by io::write_origin / check_origin.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/core/rng.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/population_xml.hpp"   // io::settings_digest
#include "cic/io/settings_extension.hpp"
#include "cic/io/xml.hpp"
#include "cic/search/ask_tell.hpp"
#include "cic/search/support.hpp"

namespace {

using namespace cic;

constexpr const char* kSection = "OnePlusLambda";
constexpr const char* kFormat = "cic-one-plus-lambda";
constexpr int kVersion = 1;

// The checkpoint's schema: the run validates a file against it before
// read_checkpoint reads it (search::load_checkpoint), which then checks what an
// XSD cannot (the parent's length, the origin's digest).
constexpr const char* kSchema = R"(<?xml version="1.0" encoding="UTF-8"?>
<xs:schema xmlns:xs="http://www.w3.org/2001/XMLSchema">
  <xs:simpleType name="Numbers"><xs:list itemType="xs:double"/></xs:simpleType>
  <xs:element name="one-plus-lambda">
    <xs:complexType>
      <xs:sequence>
        <xs:element name="origin">
          <xs:complexType>
            <xs:sequence>
              <xs:element name="part" minOccurs="0" maxOccurs="unbounded">
                <xs:complexType>
                  <xs:simpleContent>
                    <xs:extension base="xs:string"><xs:attribute name="name" type="xs:string" use="required"/></xs:extension>
                  </xs:simpleContent>
                </xs:complexType>
              </xs:element>
            </xs:sequence>
            <xs:attribute name="digest" type="xs:string" use="required"/>
          </xs:complexType>
        </xs:element>
        <xs:element name="parent">
          <xs:complexType>
            <xs:simpleContent>
              <xs:extension base="Numbers"><xs:attribute name="fitness" type="xs:double" use="required"/></xs:extension>
            </xs:simpleContent>
          </xs:complexType>
        </xs:element>
      </xs:sequence>
      <xs:attribute name="format" type="xs:string" fixed="cic-one-plus-lambda" use="required"/>
      <xs:attribute name="version" type="xs:integer" use="required"/>
      <xs:attribute name="settingsDigest" type="xs:string" use="required"/>
      <xs:attribute name="generation" type="xs:nonNegativeInteger" use="required"/>
      <xs:attribute name="evaluations" type="xs:positiveInteger" use="required"/>
      <xs:attribute name="sigma" type="xs:double" use="required"/>
      <xs:attribute name="rng" type="xs:string" use="required"/>
    </xs:complexType>
  </xs:element>
</xs:schema>
)";

// The search's whole state: with the settings, it fixes the rest of the run.
struct State {
    std::vector<double> parent;   // in the unit box
    double fitness = 0;
    double sigma = 0;
    int generation = 0;
    long evaluations = 0;
    Rng::State rng{};
};

std::string numbers(const std::vector<double>& xs) {
    std::string out;
    for (double x : xs) out += (out.empty() ? "" : " ") + fmt::format("{:.17g}", x);
    return out;
}

std::string to_xml(const State& st, const io::Settings& s, const io::CheckpointOrigin& origin) {
    auto doc = io::xml::Document::create("one-plus-lambda");
    auto root = doc.root();
    root.set_attribute("format", kFormat);
    root.set_attribute("version", std::to_string(kVersion));
    root.set_attribute("settingsDigest", io::settings_digest(s));
    root.set_attribute("generation", std::to_string(st.generation));
    root.set_attribute("evaluations", std::to_string(st.evaluations));
    root.set_attribute("sigma", fmt::format("{:.17g}", st.sigma));
    Rng rng;
    rng.set_state(st.rng);
    root.set_attribute("rng", rng.state_text());
    io::write_origin(root, origin);
    auto parent = root.add_child("parent", numbers(st.parent));
    parent.set_attribute("fitness", fmt::format("{:.17g}", st.fitness));
    return doc.to_string();
}

double number(const io::xml::Node& n, const char* attr, double lo, double hi) {
    const auto text = n.attribute(attr);
    if (!text) throw n.error(fmt::format("<{}> has no {} attribute", n.name(), attr));
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(*text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text->size() || !std::isfinite(v) || v < lo || v > hi)
        throw n.error(fmt::format("<{}> {}=\"{}\": expected a number in [{}, {}]", n.name(), attr, *text, lo, hi));
    return v;
}

// The strict reader: throws cic::InputError with file and line.
State read_checkpoint(const std::string& file, const io::Settings& s, std::size_t dimension, std::string& origin_note,
                      std::string& digest) {
    const auto doc = io::xml::Document::load_file(file);
    const auto root = doc.root();
    if (root.name() != "one-plus-lambda" || root.attribute("format").value_or("") != kFormat)
        throw root.error("not a one-plus-lambda checkpoint (root <one-plus-lambda format=\"cic-one-plus-lambda\">)");
    if (root.attribute("version").value_or("") != std::to_string(kVersion))
        throw root.error(fmt::format("version {} is not this search's ({})", root.attribute("version").value_or("?"),
                                     kVersion));
    static const std::set<std::string> known{"format", "version", "settingsDigest", "generation", "evaluations",
                                             "sigma", "rng"};
    for (const char* a : {"settingsDigest", "generation", "evaluations", "sigma", "rng"})
        if (!root.attribute(a)) throw root.error(fmt::format("<one-plus-lambda> has no {} attribute", a));
    State st;
    st.generation = static_cast<int>(number(root, "generation", 0, 1e9));
    st.evaluations = static_cast<long>(number(root, "evaluations", 1, 1e12));
    st.sigma = number(root, "sigma", 1e-12, 1.0);
    try {
        st.rng = Rng::parse_state(*root.attribute("rng"));
    } catch (const std::invalid_argument& e) {
        throw root.error(std::string("rng: ") + e.what());
    }
    digest = *root.attribute("settingsDigest");
    std::optional<io::CheckpointOrigin> origin;
    io::xml::Node parent;
    for (const auto& child : root.children()) {
        if (child.name() == "origin" && !origin) origin = io::read_origin(child);
        else if (child.name() == "parent" && !parent) parent = child;
        else throw child.error(fmt::format("unexpected element <{}> (expected one <origin> and one <parent>)", child.name()));
    }
    if (!parent) throw root.error("no <parent> element");
    origin_note = io::check_origin(origin, s, file);
    st.fitness = number(parent, "fitness", -1e300, 1e300);
    std::istringstream in(parent.text());
    for (std::string item; in >> item;) {
        std::size_t used = 0;
        double v = -1;
        try {
            v = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || !(v >= 0.0 && v <= 1.0))
            throw parent.error(fmt::format("<parent> value '{}' is not a number in [0, 1]", item));
        st.parent.push_back(v);
    }
    if (st.parent.size() != dimension)
        throw parent.error(fmt::format("<parent> holds {} numbers but the settings' gait has {}", st.parent.size(),
                                       dimension));
    return st;
}

class OnePlusLambdaCheckpoint : public search::Checkpoint {
public:
    State state;
    void check_goes_on(const io::Settings& s) const override {
        search::refuse_if_reached(state.fitness, s, file);
        const long lambda = io::extra_integer(s, kSection, "lambda");
        const long budget = io::extra_integer(s, kSection, "evaluations");
        if (state.evaluations + lambda > budget)
            throw InputError(fmt::format("the run has spent {} evaluations; a budget of {} adds no generation of {} "
                                         "(ask for --set OnePlusLambda.evaluations={} or more)",
                                         state.evaluations, budget, lambda, state.evaluations + lambda), file);
    }
};

// Mirrored into [0, 1], as Gait.bounds = reflect reads a sample.
double reflect(double x) {
    x = std::fmod(std::fabs(x), 2.0);
    return x > 1.0 ? 2.0 - x : x;
}

// Written as ask and tell (search::VectorAskTell): each step asks for lambda
// children and is told their fitness; the base evaluates them in the run's workers.
class OnePlusLambda : public search::VectorAskTell {
public:
    OnePlusLambda(const search::Services& services, std::unique_ptr<OnePlusLambdaCheckpoint> resume)
        : VectorAskTell(services), resume_(std::move(resume)),
          origin_(io::origin_of(services.settings, setup().robot)),
          lambda_(static_cast<int>(io::extra_integer(services.settings, kSection, "lambda"))),
          budget_(io::extra_integer(services.settings, kSection, "evaluations")) {}

    search::StatsLayout stats_layout() const override {
        search::StatsLayout l{"sigma", std::nullopt};
        if (resume_ && services().continue_in_place) l.continue_after = resume_->state.generation;
        return l;
    }

    std::optional<search::Row> start() override {
        const io::Settings& s = services().settings;
        services().say(fmt::format("one-plus-lambda: (1+{})-ES over {} gait parameters, sigma {:g}, budget {} "
                                  "evaluations, seed {}, {} worker{}",
                                  lambda_, setup().dimension(), io::extra_number(s, kSection, "sigma"), budget_,
                                  s.experiment.seed, services().context.workers,
                                  services().context.workers == 1 ? "" : "s"));
        if (resume_) {
            search::say_checkpoint_notes(*resume_, services());
            state_ = resume_->state;
            rng_.set_state(state_.rng);
            services().say(fmt::format("resuming from {} at generation {}", resume_->file, state_.generation));
            return std::nullopt;
        }
        rng_ = Rng(s.experiment.seed);
        state_.sigma = io::extra_number(s, kSection, "sigma");
        for (std::size_t i = 0; i < setup().dimension(); ++i) state_.parent.push_back(rng_.uniform());
        step_started_ = std::chrono::steady_clock::now();
        state_.fitness = evaluate({state_.parent}).front().fitness;
        state_.evaluations = 1;
        return row({state_.fitness});
    }

    search::Stop stop(bool signal) override {
        if (state_.fitness >= services().settings.control.minimum_fitness) return {"minimum fitness reached", false};
        if (signal) return {"interrupted", true};
        if (state_.evaluations + lambda_ > budget_) return {"evaluation budget", false};
        return {};
    }

    bool checkpoint_due(const search::Stop& stop) override {
        const bool stepped = std::exchange(stepped_, false);
        const int interval = std::max(1, services().settings.experiment.checkpoint_interval);
        return stop.done() || (stepped && (state_.generation + 1) % interval == 0);
    }

    search::CheckpointText checkpoint() const override {
        State st = state_;
        st.rng = rng_.state();
        return {st.generation, to_xml(st, services().settings, origin_)};
    }

    // Lambda children: the parent plus sigma N(0, I), mirrored into the unit box.
    std::vector<std::vector<double>> ask() override {
        step_started_ = std::chrono::steady_clock::now();
        std::vector<std::vector<double>> children(static_cast<std::size_t>(lambda_), state_.parent);
        for (auto& child : children)
            for (double& x : child) x = reflect(x + state_.sigma * rng_.normal());
        return children;
    }

    // The first best child replaces the parent when it is at least as good;
    // the 1/5th rule: sigma grows on a success, shrinks four times slower otherwise.
    search::Row tell(const std::vector<std::vector<double>>& children,
                     const std::vector<gp::Evaluation>& evaluations) override {
        std::vector<double> f;
        for (const auto& e : evaluations) f.push_back(e.fitness);
        const auto best = static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin());
        const bool success = f[best] > state_.fitness;
        if (f[best] >= state_.fitness) {
            state_.parent = children[best];
            state_.fitness = f[best];
        }
        state_.sigma = std::clamp(state_.sigma * std::exp(success ? 0.8 : -0.2), 1e-6, 1.0);
        state_.evaluations += lambda_;
        ++state_.generation;
        return row(f);
    }

    std::string summary(const search::Stop& stop) override {
        return fmt::format("stopped: {} at generation {}\nbest: fitness {:.17g} ((1+{})-ES; robot {})\n"
                           "evaluations: {}\nbest gait: {}\n",
                           stop.reason, state_.generation, state_.fitness, lambda_, setup().robot.name,
                           state_.evaluations, setup().describe(state_.parent));
    }

private:
    search::Row row(const std::vector<double>& fitness) {
        search::Row r;
        r.record.generation = state_.generation;
        search::fill_fitness_stats(r.record, fitness);
        r.record.best = state_.fitness;   // the parent: the best so far
        r.record.evaluations = state_.evaluations;
        r.record.failed = static_cast<int>(failed() - failed_before_);
        failed_before_ = failed();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - step_started_).count();
        r.record.generation_seconds = seconds;
        r.record.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
        r.extra = fmt::format("{:.17g}", state_.sigma);
        r.log = fmt::format("gen {} best {:.17g} sigma {:.6g} evaluations {}", state_.generation, state_.fitness,
                            state_.sigma, state_.evaluations);
        r.progress.generation = state_.generation;
        r.progress.max_generations = static_cast<int>((budget_ - 1) / lambda_) + 1;
        r.progress.best = state_.fitness;
        r.progress.mean = r.record.mean;
        r.progress.evaluations_per_second = seconds > 0 ? static_cast<double>(fitness.size()) / seconds : 0.0;
        r.progress.eta_seconds = seconds * std::max(0, r.progress.max_generations - state_.generation - 1);
        stepped_ = true;
        return r;
    }

    std::unique_ptr<OnePlusLambdaCheckpoint> resume_;
    io::CheckpointOrigin origin_;
    int lambda_;
    long budget_;
    State state_;
    Rng rng_;
    long failed_before_ = 0;
    bool stepped_ = false;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now(), step_started_ = started_;
};

const search::Registrar registrar{search::SearchKind{
    .name = "one-plus-lambda",
    .doc = "a (1+lambda)-ES with the 1/5th success rule over the gait vector (examples/plugin)",
    .forms = {io::GenotypeForm::Vector},
    .keys = {io::extra_integer_key(kSection, "lambda", 8, 1, 10000, "children per generation"),
             io::extra_number_key(kSection, "sigma", 0.1, 1e-6, 1.0,
                                  "the first mutation step, in the unit box (each parameter's range is 1)"),
             io::extra_integer_key(kSection, "evaluations", 400, 1, 100000000,
                                   "budget of evaluations, whole generations only")},
    .budget_key = "OnePlusLambda.evaluations",
    .budget_unit = "evaluations",
    .claims = {},
    .claimed_by = {},
    .fallback = false,
    .load = [](const io::Settings& s, const std::string& file) -> std::unique_ptr<search::Checkpoint> {
        auto c = std::make_unique<OnePlusLambdaCheckpoint>();
        c->file = file;
        c->state = read_checkpoint(file, s, gait::Setup::from_settings(s).dimension(), c->origin_note,
                                   c->settings_digest);
        c->generations = c->state.generation + 1;
        return c;
    },
    .checkpoint_schema = kSchema,
    // view, assess, trace and render replay its parent: the best gait of the run.
    .checkpoint_root = "one-plus-lambda",
    .best = [](const io::Settings& s, const std::string& file) {
        std::string note, digest;
        const State st = read_checkpoint(file, s, gait::Setup::from_settings(s).dimension(), note, digest);
        return report::CheckpointBest{st.parent, st.fitness, st.generation,
                                      fmt::format("best (1+{})-ES gait", io::extra_integer(s, kSection, "lambda"))};
    },
    .make = [](const search::Services& services, std::unique_ptr<search::Checkpoint> resume)
        -> std::unique_ptr<search::Search> {
        return std::make_unique<OnePlusLambda>(
            services, std::unique_ptr<OnePlusLambdaCheckpoint>(static_cast<OnePlusLambdaCheckpoint*>(resume.release())));
    },
}};

} // namespace
