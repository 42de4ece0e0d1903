// Evolving for transfer (experiments/hypergp/bodies.cpp): a genotype scored on
// several bodies gets the stated aggregate of the fitnesses each body gives
// alone, every body's score the same bits wherever it runs, and a growing
// robot's job names its body.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cic/experiments/hypergp/bodies.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/robot_xml.hpp"

namespace cic {
namespace {

namespace fs = std::filesystem;
const fs::path kRobots = fs::path(CIC_SOURCE_DIR) / "settings" / "robots";

std::uint64_t bits(double d) { return std::bit_cast<std::uint64_t>(d); }

// centipede-2 with centipede-4 beside it, 2.5 s walks: about 0.1 s per body.
io::Settings two_bodies(io::BodiesAggregate how) {
    io::Settings s;
    s.robot.robot_file = (kRobots / "centipede-2.xml").string();
    s.robot.extra_robot_files = {(kRobots / "centipede-4.xml").string()};
    s.robot.bodies_aggregate = how;
    s.sim.sample_to = 2.5;
    s.sim.delayed_start = 0.5;
    s.sim.collision_space = sim::kCollisionSweep;
    s.neural.substrate = "gait";
    return s;
}

hypergp::Job job_of(std::initializer_list<const char*> trees) {
    hypergp::Job job;
    for (const char* t : trees) job.genotype.push_back(tree::Tree::parse(t));
    return job;
}

// The fitness one body gives alone (a model of that body only).
double alone(const io::Settings& s, const std::string& robot_file, const hypergp::Job& job) {
    hypergp::Model m = hypergp::Model::from_settings(s);
    m.robot = io::read_robot_file(robot_file);
    m.extra_robots.clear();
    return hypergp::evaluate_job(m, s, job).fitness;
}

TEST(Bodies, AggregateIsTheMeanOrTheMinimum) {
    const std::vector<double> f{3.0, -1.0, 4.5};
    EXPECT_EQ(hypergp::aggregate_fitness(f, io::BodiesAggregate::Mean), (3.0 - 1.0 + 4.5) / 3.0);
    EXPECT_EQ(hypergp::aggregate_fitness(f, io::BodiesAggregate::Min), -1.0);
    EXPECT_THROW(hypergp::aggregate_fitness({}, io::BodiesAggregate::Mean), std::invalid_argument);
}

TEST(Bodies, AJobScoresTheAggregateOfEachBodyAlone) {
    const auto job = job_of({"(sin (add x0 x3))", "(mul x1 x2)", "(sub x0 0.5)"});
    for (auto how : {io::BodiesAggregate::Mean, io::BodiesAggregate::Min}) {
        const io::Settings s = two_bodies(how);
        const hypergp::Model m = hypergp::Model::from_settings(s);
        ASSERT_EQ(m.extra_robots.size(), 1u);
        const hypergp::Outcome o = hypergp::evaluate_job(m, s, job);
        ASSERT_FALSE(o.failed) << o.failure;
        const double a = alone(s, s.robot.robot_file, job), b = alone(s, s.robot.extra_robot_files[0], job);
        EXPECT_NE(bits(a), bits(b));   // the bodies walk differently
        ASSERT_EQ(o.body_fitness.size(), 2u);
        EXPECT_EQ(bits(o.body_fitness[0]), bits(a));
        EXPECT_EQ(bits(o.body_fitness[1]), bits(b));
        const double want = how == io::BodiesAggregate::Mean ? (a + b) / 2.0 : std::min(a, b);
        EXPECT_EQ(bits(o.fitness), bits(want));
        // The same bits again (ODE's random state is reset for every body), and
        // through a worker's job handler, whose reply carries the robot's terms.
        EXPECT_EQ(bits(hypergp::evaluate_job(m, s, job).fitness), bits(o.fitness));
        const auto handler = hypergp::make_job_handler([s] { return s; });
        const sim::EvalReply reply = sim::parse_eval_reply(handler(hypergp::job_body(job.genotype)));
        EXPECT_EQ(bits(reply.fitness), bits(o.fitness));
    }
}

TEST(Bodies, AFailingBodyFailsTheGenotype) {
    io::Settings s = two_bodies(io::BodiesAggregate::Mean);
    s.sim.max_body_speed = 1e-6;   // every walk is a "blow-up"
    const hypergp::Model m = hypergp::Model::from_settings(s);
    const hypergp::Outcome o = hypergp::evaluate_job(m, s, job_of({"(sin x0)", "x1", "x2"}));
    EXPECT_TRUE(o.failed);
    EXPECT_EQ(o.fitness, s.sim.failure_fitness);
}

TEST(Bodies, AGrowingRobotsJobNamesItsBody) {
    const auto job = job_of({"(sin x0)", "x1"});
    const std::string text = hypergp::job_body(job.genotype, sim::Descriptor::None, {}, 2);
    EXPECT_NE(text.find("\nbody 2\n"), std::string::npos) << text;
    EXPECT_EQ(hypergp::parse_job_body(text).body, 2u);
    EXPECT_EQ(hypergp::job_body(job.genotype), hypergp::job_body(job.genotype, sim::Descriptor::None, {}, 0));
    EXPECT_EQ(hypergp::parse_job_body(hypergp::job_body(job.genotype)).body, 0u);
    for (const char* bad : {"body 1\n(sin x0)\n", "(sin x0)\nbody 0\n", "(sin x0)\nbody x\n", "(sin x0)\nbody 1\nbody 2\n",
                            "(sin x0)\nbody 1\n(sin x1)\n", "(sin x0)\nbody 1\noffsets 0.5\n"})
        EXPECT_THROW(hypergp::parse_job_body(bad), std::invalid_argument) << bad;

    io::Settings s = two_bodies(io::BodiesAggregate::Mean);
    s.robot.extra_robot_files.clear();
    s.robot.grow_robot_files = {(kRobots / "centipede-4.xml").string()};
    s.robot.grow_at = {0.5};
    const hypergp::Model m = hypergp::Model::from_settings(s);
    EXPECT_EQ(m.on_body(0).robot.name, "centipede-2");
    EXPECT_EQ(m.on_body(1).robot.name, "centipede-4");
    EXPECT_THROW((void)m.on_body(2), std::out_of_range);
    // A worker scores body 1 as the bigger robot alone.
    const auto handler = hypergp::make_job_handler([s] { return s; });
    const auto three = job_of({"(sin (add x0 x3))", "(mul x1 x2)", "(sub x0 0.5)"});
    const sim::EvalReply reply =
        sim::parse_eval_reply(handler(hypergp::job_body(three.genotype, sim::Descriptor::None, {}, 1)));
    EXPECT_EQ(bits(reply.fitness), bits(alone(s, s.robot.grow_robot_files[0], three)));
    EXPECT_THROW(handler(hypergp::job_body(three.genotype, sim::Descriptor::None, {}, 2)), std::invalid_argument);
}

} // namespace
} // namespace cic
