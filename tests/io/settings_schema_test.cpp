// The committed XSD is the generated one, and it accepts every shipped settings file
// and everything the writer produces.
#include <gtest/gtest.h>

#include <filesystem>

#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"

namespace fs = std::filesystem;
using namespace cic::io;

namespace {

const fs::path kSource = CIC_SOURCE_DIR;
const fs::path kXsd = kSource / "settings" / "cic-settings.xsd";

std::vector<fs::path> shipped_settings() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(kSource / "settings"))
        if (e.path().extension() == ".xml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::string> problems(const std::string& text) {
    return xml::Document::parse_string(text, "generated.xml").validate(kXsd);
}

} // namespace

TEST(SettingsSchema, CommittedSchemaIsTheGeneratedOne) {
    EXPECT_EQ(xml::read_file(kXsd), settings_schema())
        << "settings/cic-settings.xsd is stale: regenerate it with `cic settings --schema > settings/cic-settings.xsd`";
}

TEST(SettingsSchema, ShippedFilesValidateAndLoad) {
    auto files = shipped_settings();
    ASSERT_FALSE(files.empty());
    for (const auto& f : files) {
        auto doc = xml::Document::load_file(f);
        auto errors = doc.validate(kXsd);
        EXPECT_TRUE(errors.empty()) << errors.front();
        EXPECT_NO_THROW(read_settings(f)) << f;
    }
}

TEST(SettingsSchema, WriterOutputValidates) {
    EXPECT_TRUE(problems(write_settings(Settings{}, true)).empty());
    Settings s = load_settings({}, {"Simulator.friction=inf", "GP.terminalConsts=", "Neural.forestMap=0 0 0 0 0",
                                    "Control.minimumFitness=-inf"});
    auto p = problems(write_settings(s));
    EXPECT_TRUE(p.empty()) << p.front();
}

TEST(SettingsSchema, RejectsWhatTheReaderRejects) {
    // A few representative bad values: the schema and the reader agree.
    for (const char* bad : {"<settings><GP><tournament_size>0</tournament_size></GP></settings>",
                            "<settings><GP><selection_type>best</selection_type></GP></settings>",
                            "<settings><GP><functions>add mull</functions></GP></settings>",
                            "<settings><Simulator><sample_step>inf</sample_step></Simulator></settings>",
                            "<settings><Simulator><friction>-inf</friction></Simulator></settings>",
                            "<settings><GP><populationSize>5</populationSize></GP></settings>",
                            "<settings><Neural><forestMap>0 0 0 0 0 0</forestMap></Neural></settings>"}) {
        EXPECT_FALSE(problems(bad).empty()) << bad;
        EXPECT_THROW(read_settings_string(bad), cic::InputError) << bad;
    }
}

// Each robot's family of settings files (r0_*, r1_*, r2_* with the same suffix)
// differs only in the robot: the same experiment on another body, nothing else.
// The gait, MAP-Elites and hybrid (issue 38) examples ship for R1 alone (--set Simulator.robot_type=N);
// r*_best*.xml are each robot's own winner (SweepFile.ShippedBestSettingsAreTheComparisonWinners).
TEST(SettingsSchema, ShippedRobotVariantsDifferOnlyInTheRobot) {
    int families = 0;
    for (const auto& f : shipped_settings()) {
        const std::string name = f.filename().string();
        if (name.rfind("r1", 0) != 0 || name.find("gait") != std::string::npos ||
            name.find("map_elites") != std::string::npos || name.find("_best") != std::string::npos ||
            name.find("_hybrid") != std::string::npos)
            continue;
        const std::string r1 = write_settings(read_settings(f));
        for (const char* other : {"r0", "r2"}) {
            const fs::path g = f.parent_path() / (other + name.substr(2));
            ASSERT_TRUE(fs::exists(g)) << g << " is missing: every r1 settings file has an r0 and an r2 twin";
            EXPECT_EQ(write_settings(load_settings(g, {"Simulator.robot_type=1"})), r1) << g << " against " << f;
        }
        ++families;
    }
    EXPECT_GE(families, 4);
}

