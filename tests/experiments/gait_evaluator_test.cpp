// The gait experiment's evaluator (experiments/gait/setup.hpp) gives each point
// its duty-factor descriptor for MAP-Elites, with the fitness bits of the plain
// evaluation. Jobs run in this process through a runner of the test's own.
#include <gtest/gtest.h>

#include <bit>

#include "cic/experiments/gait/setup.hpp"
#include "cic/io/settings_io.hpp"

namespace cic {
namespace {

// Runs each job here: its first line names the kind, the rest is the body.
class InProcessRunner : public JobRunner {
public:
    std::vector<JobResult> run(const std::vector<std::string>& jobs) override {
        std::vector<JobResult> out;
        for (const auto& job : jobs) {
            const auto nl = job.find('\n');
            const std::string kind = job.substr(0, nl), body = job.substr(nl + 1);
            JobResult r;
            r.ok = true;
            r.output = kind == "cpg" ? sim::run_cpg_job(body) : sim::run_gait_job(body);
            out.push_back(r);
        }
        return out;
    }
    int workers() const override { return 1; }
};

void expect_described_like_plain(const std::vector<std::string>& overrides, std::size_t feet) {
    const io::Settings s = io::load_settings(std::filesystem::path(CIC_SOURCE_DIR) / "settings" / "r1_gait.xml", overrides);
    const gait::Setup setup = gait::Setup::from_settings(s);
    experiments::Context ctx{s, {}, {}, {}, 1};   // no worker processes: the runner below
    ctx.make_runner = [] { return std::make_unique<InProcessRunner>(); };
    gait::Evaluator evaluator(ctx, setup);
    Rng rng(3);
    std::vector<std::vector<double>> xs(3, std::vector<double>(setup.dimension()));
    for (auto& x : xs)
        for (double& v : x) v = rng.uniform();
    const std::vector<double> plain = evaluator(xs);
    const std::vector<gp::Evaluation> described = evaluator.described(xs);
    ASSERT_EQ(described.size(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(described[i].fitness), std::bit_cast<std::uint64_t>(plain[i])) << i;
        ASSERT_EQ(described[i].descriptor.size(), feet) << i;
        for (double d : described[i].descriptor) {
            EXPECT_GE(d, 0.0);
            EXPECT_LE(d, 1.0);
        }
    }
}

TEST(GaitEvaluator, DescribedPointsCarryEachFootsDutyFactor) {
    expect_described_like_plain({"Simulator.sample_to=3", "Simulator.delayed_start=0.5"}, 4);
}

TEST(GaitEvaluator, DescribedCpgPointsCarryEachFootsDutyFactor) {
    expect_described_like_plain({"Simulator.sample_to=3", "Simulator.delayed_start=0.5", "Gait.controller=cpg"}, 4);
}

} // namespace
} // namespace cic
