// The open registry of experiment types (experiments/registry.hpp) and the
// settings keys a registered type brings (io/settings_extension.hpp).
#include <gtest/gtest.h>

#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/controller.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/map_elites_emitters.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_extension.hpp"
#include "cic/io/settings_io.hpp"

namespace {

using namespace cic;
using experiments::ExperimentKind;
using experiments::JobHandler;
using experiments::WorkerContext;

// A symreg-family type with a section of its own, registered once for this
// test program (registrations are for the life of the process).
std::unique_ptr<experiments::Experiment> no_experiment(const experiments::Context&) { return nullptr; }

ExperimentKind test_kind() {
    ExperimentKind k;
    k.type = {"registry-test", io::ExperimentFamily::Symreg, "RegistryTest", "a type made by registry_test.cpp"};
    k.keys = {io::extra_number_key("RegistryTest", "weight", 1.5, 0.0, 10.0, "A weight"),
              io::extra_integer_key("RegistryTest", "rounds", 3, 1, 9, "Rounds"),
              io::extra_choice_key("RegistryTest", "mode", {"fast", "slow"}, "fast", "A mode")};
    k.make = &no_experiment;
    k.job_kinds = {{"registry-echo", [](const WorkerContext&) -> JobHandler {
                        return [](const std::string& body) { return "echo " + body; };
                    }}};
    return k;
}

const experiments::Registrar registrar{test_kind()};

const char* kFile = R"(<settings>
  <RegistryTest>
    <weight>2.25</weight>
  </RegistryTest>
</settings>
)";

TEST(Registry, TheBuiltInTypesRegisterThemselves) {
    for (const char* name : {"hypergp", "symreg", "gait"}) {
        const ExperimentKind& k = experiments::experiment_kind(name);
        EXPECT_EQ(k.type.name, name);
        EXPECT_TRUE(k.check_inputs) << name;
    }
    EXPECT_TRUE(experiments::experiment_kind("hypergp").make);
    EXPECT_FALSE(experiments::experiment_kind("gait").make) << "the gait loop is the run layer's";
    const auto handlers = experiments::make_job_handlers(WorkerContext{});
    for (const char* job : {"sine", "hypergp", "gait", "cpg", "registry-echo"}) EXPECT_TRUE(handlers.count(job)) << job;
    EXPECT_EQ(handlers.at("registry-echo")("x"), "echo x");
}

TEST(Registry, BadRegistrationsThrow) {
    auto twice = test_kind();
    EXPECT_THROW(experiments::register_experiment(twice), std::invalid_argument);   // name taken

    auto same_job = test_kind();
    same_job.type.name = "registry-other";
    same_job.type.section = "";
    same_job.keys.clear();
    EXPECT_THROW(experiments::register_experiment(same_job), std::invalid_argument);   // job kind served

    auto no_make = same_job;
    no_make.job_kinds.clear();
    no_make.make = nullptr;
    EXPECT_THROW(experiments::register_experiment(no_make), std::invalid_argument);    // GP family needs make

    auto sine = same_job;
    sine.job_kinds = {{"sine", [](const WorkerContext&) -> JobHandler { return {}; }}};
    EXPECT_THROW(experiments::register_experiment(sine), std::invalid_argument);       // the simulator's own

    auto bad_name = same_job;
    bad_name.job_kinds.clear();
    bad_name.type.name = "Bad Name";
    EXPECT_THROW(experiments::register_experiment(bad_name), std::invalid_argument);

    auto builtin = same_job;
    builtin.job_kinds.clear();
    builtin.type.name = "gait";
    builtin.type.family = io::ExperimentFamily::HyperGP;
    EXPECT_THROW(experiments::register_experiment(builtin), std::invalid_argument);   // a built-in's shape

    EXPECT_THROW(io::register_settings_keys({io::extra_number_key("GP", "weight", 1, 0, 2, "x")}),
                 std::invalid_argument);   // a built-in section
    EXPECT_THROW(io::register_settings_keys({io::extra_number_key("RegistryTest", "weight", 1, 0, 2, "x")}),
                 std::invalid_argument);   // registered twice
    EXPECT_THROW(io::extra_choice_key("RegistryTest", "m", {"a", "b"}, "c", "x"), std::invalid_argument);
    EXPECT_THROW(experiments::experiment_kind("nothing"), std::logic_error);
    EXPECT_THROW((void)io::extra_number(io::Settings{}, "RegistryTest", "rounds"), std::invalid_argument);   // not a number key
}

// A type that only scores differently: its score (reading the centre's path,
// asked for with WalkNeeds) is all it registers; the registry gives it HyperGP's
// experiment and a job kind named after it, and replays score with it too.
double path_steps(const hypergp::Model&, const io::Settings&, const hypergp::Outcome& o) {
    return static_cast<double>(o.result.trace.size());
}

const experiments::Registrar score_registrar{[] {
    ExperimentKind k;
    k.type = {"registry-path", io::ExperimentFamily::HyperGP, "", "scored by its path's length in control steps"};
    k.check_inputs = &hypergp::check_inputs;
    k.score = &path_steps;
    k.needs.trace = true;
    return k;
}()};

TEST(Registry, AScoreOfItsOwnIsAllATypeNeeds) {
    const ExperimentKind& k = experiments::experiment_kind("registry-path");
    EXPECT_TRUE(k.make);
    ASSERT_EQ(k.job_kinds.count("registry-path"), 1u);
    io::Settings s = io::read_settings_string(R"(<settings><Experiment><type>registry-path</type></Experiment>
      <Simulator><sample_to>1</sample_to><delayed_start>0</delayed_start></Simulator></settings>)");
    const hypergp::Model model = hypergp::Model::from_settings(s);
    const tree::Forest genotype{tree::Tree::parse("(mul x0 x1)")};
    // The replay's score: the path it asked for (80 control steps of 0.0125 s), eq. 7.1 beside it.
    const hypergp::Outcome o = experiments::evaluate_as_type(model, s, genotype);
    EXPECT_EQ(o.fitness, 80.0);
    EXPECT_EQ(o.distance_fitness, hypergp::run(model, genotype).fitness);
    // Its worker job scores the same.
    const JobHandler job = k.job_kinds.at("registry-path")(WorkerContext{.settings_file = {}, .settings_text =
                                                                             io::write_settings(s)});
    EXPECT_EQ(sim::parse_eval_reply(job(hypergp::job_body(genotype))).fitness, 80.0);
    // The built-in type records no path: a score pays only for what it asks.
    io::Settings plain = s;
    plain.experiment.type = "hypergp";
    EXPECT_TRUE(experiments::evaluate_as_type(model, plain, genotype).result.trace.empty());
    // Only HyperGP-family types score the walk.
    ExperimentKind gait;
    gait.type = {"registry-gait-score", io::ExperimentFamily::Gait, "", "x"};
    gait.score = &path_steps;
    EXPECT_THROW(experiments::register_experiment(gait), std::invalid_argument);
}

TEST(Registry, ItsSectionSelectsTheTypeAndItsKeysReadTyped) {
    const io::Settings s = io::read_settings_string(kFile, "test.xml");
    EXPECT_EQ(s.experiment.type, "registry-test");
    EXPECT_EQ(io::family_of(s), io::ExperimentFamily::Symreg);
    EXPECT_EQ(io::extra_number(s, "RegistryTest", "weight"), 2.25);
    EXPECT_EQ(io::extra_integer(s, "RegistryTest", "rounds"), 3);   // default
    EXPECT_EQ(io::extra_choice(s, "RegistryTest", "mode"), "fast");
}

TEST(Registry, ItsKeysAreAsStrictAsAnyOther) {
    const std::string out_of_range = R"(<settings>
  <RegistryTest>
    <rounds>12</rounds>
  </RegistryTest>
</settings>
)";
    try {
        (void)io::read_settings_string(out_of_range, "bad.xml");
        FAIL() << "accepted rounds = 12";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 3);
        EXPECT_NE(std::string(e.what()).find("integer in [1, 9]"), std::string::npos) << e.what();
    }
    const std::string misspelt = R"(<settings>
  <RegistryTest>
    <weigth>1</weigth>
  </RegistryTest>
</settings>
)";
    try {
        (void)io::read_settings_string(misspelt, "bad.xml");
        FAIL() << "accepted a misspelt key";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean weight?"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)io::read_settings_string("<settings><Experiment><type>registry-tset</type></Experiment></settings>"),
                 InputError);
}

TEST(Registry, ItsSettingsRoundTripAndShapeTheDigestOnlyOffTheirDefault) {
    const io::Settings s = io::read_settings_string(kFile, "test.xml");
    const io::Settings again = io::read_settings_string(io::write_settings(s), "written.xml");
    for (const char* key : {"weight", "rounds", "mode"})
        EXPECT_EQ(io::find_setting("RegistryTest", key)->get(again), io::find_setting("RegistryTest", key)->get(s)) << key;
    EXPECT_EQ(io::extra_number(again, "RegistryTest", "weight"), 2.25);
    EXPECT_EQ(io::settings_digest(again), io::settings_digest(s));

    io::Settings at_default = s;
    at_default.extra.clear();
    io::Settings written_default = at_default;
    written_default.extra["RegistryTest.weight"] = "1.5";
    EXPECT_EQ(io::settings_digest(written_default), io::settings_digest(at_default)) << "a default leaves the digest";
    EXPECT_NE(io::settings_digest(s), io::settings_digest(at_default));
}

// A controller registered by name: the gait substrate's spec, amplitudes halved.
std::unique_ptr<hypergp::Controller> half_gait(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                               const nn::NeuralConfig& cfg, double) {
    sim::GaitSpec spec = hypergp::gait_spec(robot, genotype, cfg);
    for (auto& j : spec.joints) j.amplitude /= 2;
    const std::size_t joints = spec.joints.size();
    return std::make_unique<hypergp::RecordedController>(std::make_unique<sim::GaitController>(std::move(spec)), 1.0,
                                                          joints);
}

const hypergp::ControllerRegistrar controller_registrar{{"registry-half-gait", "half the gait's amplitudes", &half_gait}};

std::vector<double> commands(const char* substrate) {
    nn::NeuralConfig cfg;
    cfg.substrate = substrate;
    const auto robot = sim::preset(1, false);
    auto c = hypergp::make_controller(robot, {tree::Tree::parse("(sin (add x0 x1))")}, cfg, 0.0125);
    c->set_recording(true);
    const std::size_t n = robot.actuated().size();
    c->reset(n);
    std::vector<double> angles(n, 0.0), desired(n);
    for (int s = 0; s < 40; ++s) c->step(s * 0.0125, angles, desired);
    return c->record().commands;
}

TEST(ControllerRegistry, ARegisteredControllerIsBuiltByName) {
    ASSERT_NE(hypergp::find_controller("registry-half-gait"), nullptr);
    for (const char* builtin : {"network", "cpg", "gait"}) EXPECT_NE(hypergp::find_controller(builtin), nullptr);
    const auto half = commands("registry-half-gait");
    EXPECT_EQ(half, commands("registry-half-gait")) << "the same genotype gives the same commands";
    EXPECT_NE(half, commands("gait"));
    const io::Settings s = io::read_settings_string(
        "<settings><Neural><substrate>registry-half-gait</substrate></Neural></settings>", "s.xml");
    EXPECT_EQ(s.neural.substrate, "registry-half-gait");
    EXPECT_EQ(io::read_settings_string(io::write_settings(s), "w.xml").neural.substrate, "registry-half-gait");
}

TEST(ControllerRegistry, BadRegistrationsAndUnknownNamesThrow) {
    EXPECT_THROW(hypergp::register_controller({"registry-half-gait", "again", &half_gait}), std::invalid_argument);
    EXPECT_THROW(hypergp::register_controller({"registry-no-make", "none", {}}), std::invalid_argument);
    EXPECT_THROW(hypergp::register_controller({"Bad Name", "bad", &half_gait}), std::invalid_argument);
    EXPECT_EQ(hypergp::find_controller("nothing"), nullptr);
    nn::NeuralConfig cfg;
    cfg.substrate = "nothing";
    EXPECT_THROW(hypergp::make_controller(sim::preset(1, false), {tree::Tree::parse("x0")}, cfg, 0.0125),
                 std::invalid_argument);
    EXPECT_THROW((void)io::read_settings_string("<settings><Neural><substrate>nothing</substrate></Neural></settings>"),
                 InputError);
}

// An emitter of gait vectors registered from outside: every new solution is
// the archive's first elite pulled halfway to the box's centre.
gp::Emitter<std::vector<double>> halfway(const io::Settings&, const gp::VectorMapElitesConfig& c) {
    gp::Emitter<std::vector<double>> e = gp::gaussian_emitter(c);
    e.vary = [](Rng&, const gp::GridArchive<std::vector<double>>& archive) {
        std::vector<double> x = archive.elites().begin()->second.solution;
        for (double& v : x) v = (v + 0.5) / 2;
        return x;
    };
    return e;
}

const experiments::EmitterRegistrar emitter_registrar{
    {.name = "registry-halfway", .doc = "toward the centre", .forest = {}, .vector = &halfway, .check = {}}};

io::Settings map_elites_settings(const std::string& type, const std::string& emitter) {
    return io::read_settings_string("<settings><Experiment><type>" + type +
                                        "</type></Experiment><MapElites><enabled>1</enabled><emitter>" + emitter +
                                        "</emitter></MapElites></settings>",
                                    "me.xml");
}

gp::VectorMapElitesConfig vector_config() {
    gp::VectorMapElitesConfig c;
    c.grid = gp::GridSpec{{4}, {0}, {1}};
    c.dimension = 3;
    return c;
}

std::vector<double> varied(const gp::Emitter<std::vector<double>>& e) {
    gp::GridArchive<std::vector<double>> archive(vector_config().grid);
    archive.offer({0.1}, 1.0, {0.25, 0.75, 0.5});
    Rng rng(4);
    return e.vary(rng, archive);
}

TEST(EmitterRegistry, ARegisteredEmitterIsChosenByItsKeyInItsFamilyOnly) {
    const io::Settings s = map_elites_settings("gait", "registry-halfway");
    EXPECT_EQ(s.map_elites.emitter, "registry-halfway");
    EXPECT_EQ(io::read_settings_string(io::write_settings(s), "w.xml").map_elites.emitter, "registry-halfway");
    EXPECT_EQ(varied(experiments::make_vector_emitter(s, vector_config())), (std::vector<double>{0.375, 0.625, 0.5}));
    // auto is the family's own: the Gaussian mutation for gait vectors.
    EXPECT_EQ(varied(experiments::make_vector_emitter(map_elites_settings("gait", "auto"), vector_config())),
              varied(gp::gaussian_emitter(vector_config())));
    EXPECT_NE(varied(experiments::make_vector_emitter(map_elites_settings("gait", "iso-line"), vector_config())),
              varied(gp::gaussian_emitter(vector_config())));
    // A gait emitter for a HyperGP run is refused when the settings are read,
    // with the names that family allows.
    try {
        (void)map_elites_settings("hypergp", "registry-halfway");
        FAIL() << "a gait-family emitter was accepted for hypergp";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("allowed here: auto | gp"), std::string::npos) << e.what();
    }
    try {
        (void)map_elites_settings("gait", "gp");
        FAIL() << "the GP emitter was accepted for gait";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("allowed here: auto | gaussian | iso-line | "), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("| registry-halfway"), std::string::npos) << e.what();
    }
    // Off the family, the factory lookup refuses too (a caller that skipped the check).
    io::Settings wrong = s;
    EXPECT_THROW((void)experiments::make_forest_emitter(wrong, tree::PrimitiveSet(wrong.gp.primitives)),
                 std::invalid_argument);
}

TEST(EmitterRegistry, BadRegistrationsAndUnknownNamesThrow) {
    EXPECT_THROW(experiments::register_emitter({"registry-halfway", "again", {}, &halfway, {}}), std::invalid_argument);
    EXPECT_THROW(experiments::register_emitter({"gaussian", "a built-in's name", {}, &halfway, {}}), std::invalid_argument);
    EXPECT_THROW(experiments::register_emitter({"auto", "the default's name", {}, &halfway, {}}), std::invalid_argument);
    EXPECT_THROW(experiments::register_emitter({"registry-none", "no factory", {}, {}, {}}), std::invalid_argument);
    EXPECT_THROW(experiments::register_emitter({"Bad Name", "bad", {}, &halfway, {}}), std::invalid_argument);
    EXPECT_EQ(io::find_emitter_name("registry-none"), nullptr);
    EXPECT_THROW((void)map_elites_settings("gait", "cma-mae"), InputError);
}

} // namespace
