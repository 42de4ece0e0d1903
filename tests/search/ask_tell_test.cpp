// search::VectorAskTell (include/cic/search/ask_tell.hpp): a batch that is not
// gait vectors of the settings' gait is refused before any worker starts.
// (Its runs, the same bytes for 1 or 2 workers and after kill -9: the plug-in
// search in Install.PluginTypeBuildsAndRunsThroughCicsCommandLine.)
#include <gtest/gtest.h>

#include <stdexcept>

#include "cic/search/ask_tell.hpp"

namespace {

using namespace cic;

class Fixed : public search::VectorAskTell {
public:
    using VectorAskTell::VectorAskTell;
    std::vector<std::vector<double>> batch;
    search::StatsLayout stats_layout() const override { return {}; }
    std::optional<search::Row> start() override { return std::nullopt; }
    search::Stop stop(bool) override { return {}; }
    bool checkpoint_due(const search::Stop&) override { return false; }
    search::CheckpointText checkpoint() const override { return {}; }
    std::string summary(const search::Stop&) override { return {}; }
    std::vector<std::vector<double>> ask() override { return batch; }
    search::Row tell(const std::vector<std::vector<double>>&, const std::vector<gp::Evaluation>&) override {
        return {};
    }
    std::size_t dimension() const { return setup().dimension(); }
};

TEST(VectorAskTell, RefusesABatchThatIsNotTheSettingsGaitVectors) {
    io::Settings s;
    s.experiment.type = "gait";
    const experiments::Context ctx{s, ".", "settings.xml", "/nonexistent/cic", 1};
    const search::Services services{s, ctx, ".", false, [](const std::string&) {}, [](const std::string&) {}};
    Fixed f(services);
    EXPECT_THROW(f.step(), std::invalid_argument);   // empty
    f.batch = {std::vector<double>(f.dimension() + 1, 0.5)};
    EXPECT_THROW(f.step(), std::invalid_argument);   // too long
    f.batch = {std::vector<double>(f.dimension(), 0.5)};
    f.batch[0][3] = 1.5;
    EXPECT_THROW(f.step(), std::invalid_argument);   // outside the unit box
    f.batch[0][3] = std::nan("");
    EXPECT_THROW(f.step(), std::invalid_argument);
    EXPECT_EQ(f.dimension(), 37u);   // R1's gait: 3 numbers for each of 12 hinges and one frequency
}

} // namespace
