// `cic robot centipede`: the shipped centipedes are its output, bad input
// exits 2 naming the option, and nothing is written then.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cic/io/robot_xml.hpp"
#include "cic/io/xml.hpp"

namespace fs = std::filesystem;

namespace {

std::string binary() {
    const char* env = std::getenv("CIC_BINARY");
    return env && *env ? env : CIC_BINARY;
}

// Exit code and stderr of `cic ARGS`.
std::pair<int, std::string> run(const std::string& args) {
    const std::string cmd = "'" + binary() + "' " + args + " 2>&1 >/dev/null";
    std::string out;
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return {-1, out};
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    const int status = ::pclose(p);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

class RobotCommand : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("cic-robot-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
};

} // namespace

// settings/robots/centipede-*.xml are this command's output, byte for byte.
TEST_F(RobotCommand, RegeneratesTheShippedCentipedes) {
    for (int p : {2, 4, 8, 16, 32, 64})
        for (bool irregular : {false, true}) {
            const std::string name = "centipede-" + std::to_string(p) + (irregular ? "-irregular" : "") + ".xml";
            const fs::path out = dir / name;
            const auto [code, err] = run("robot centipede --quiet --pairs " + std::to_string(p) +
                                         (irregular ? " --irregular" : "") + " --out '" + out.string() + "'");
            ASSERT_EQ(code, 0) << err;
            EXPECT_EQ(cic::io::xml::read_file(out),
                      cic::io::xml::read_file(fs::path(CIC_SOURCE_DIR) / "settings" / "robots" / name))
                << name;
            EXPECT_EQ(cic::io::read_robot_file(out).actuated().size(),
                      static_cast<std::size_t>(6 * p - (irregular ? (p + 1) / 2 : 0)));
        }
}

TEST_F(RobotCommand, BadPairsExitTwoNamingTheOption) {
    for (const char* bad : {"0", "-1", "65", "x"}) {
        const fs::path out = dir / "c.xml";
        const auto [code, err] = run(std::string("robot centipede --pairs ") + bad + " --out '" + out.string() + "'");
        EXPECT_EQ(code, 2) << bad << ": " << err;
        EXPECT_NE(err.find("--pairs"), std::string::npos) << err;
        if (std::string(bad) != "x") {
            EXPECT_NE(err.find("64"), std::string::npos) << err;
        }
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST_F(RobotCommand, UnknownKindExitsTwo) {
    const fs::path out = dir / "c.xml";
    const auto [code, err] = run("robot millipede --pairs 2 --out '" + out.string() + "'");
    EXPECT_EQ(code, 2);
    EXPECT_NE(err.find("centipede"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(out));
}
