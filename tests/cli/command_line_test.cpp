// cli::Command / cli::Option, the subcommands' CLI11-free way to declare
// options: values, checks, counts and hidden commands, parsed by a real CLI11 app.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cic/cli/command_line.hpp"

namespace {

using cic::cli::Command;
using cic::cli::Option;

struct Parsed {
    int jobs = 1;
    long task = -1;
    double speed = 1.0, at = 0.0, fps = 25.0;
    std::string file;
    std::vector<std::string> joints;
    bool dry_run = false;
    bool ran = false;
    std::size_t fps_given = 0;
};

// `cic demo ...` with one option of each kind; parses `args` (after the program name).
void parse(Parsed& p, const std::vector<std::string>& args) {
    CLI::App app{"test"};
    Command root(&app);
    Command demo = root.subcommand("demo", "a demo command");
    demo.option("file", p.file, "a positional").required();
    demo.option("--jobs,-j", p.jobs, "runs").show_default().range(1, 4096);
    demo.option("--task", p.task, "task").range(0L, 100L);
    demo.option("--speed", p.speed, "speed").range(1.0 / 16, 16.0);
    demo.option("--at", p.at, "seconds").non_negative();
    Option fps = demo.option("--fps", p.fps, "frames per second").positive();
    demo.option("--joints", p.joints, "joints").delimiter(',');
    demo.flag("--dry-run", p.dry_run, "list only");
    demo.on_run([&p, fps] {
        p.ran = true;
        p.fps_given = fps.count();
    });
    Command hidden = root.subcommand("internal", "not in --help");
    hidden.hide();
    std::vector<std::string> argv_text = {"cic"};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_text) argv.push_back(a.data());
    app.parse(static_cast<int>(argv.size()), argv.data());
}

TEST(CommandLine, OptionsReceiveTheirValues) {
    Parsed p;
    parse(p, {"demo", "f.xml", "-j", "3", "--task", "7", "--speed", "2.5", "--at", "0", "--fps", "30",
              "--joints", "a,b", "--dry-run"});
    EXPECT_TRUE(p.ran);
    EXPECT_EQ(p.file, "f.xml");
    EXPECT_EQ(p.jobs, 3);
    EXPECT_EQ(p.task, 7);
    EXPECT_DOUBLE_EQ(p.speed, 2.5);
    EXPECT_EQ(p.joints, (std::vector<std::string>{"a", "b"}));
    EXPECT_TRUE(p.dry_run);
    EXPECT_EQ(p.fps_given, 1u);
    Parsed q;
    parse(q, {"demo", "f.xml"});
    EXPECT_EQ(q.fps_given, 0u);
    EXPECT_EQ(q.jobs, 1);
}

TEST(CommandLine, ChecksRefuseValuesOutsideTheirRange) {
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"demo"}, {"demo", "f", "-j", "0"}, {"demo", "f", "-j", "4097"},
          {"demo", "f", "--task", "101"}, {"demo", "f", "--speed", "20"}, {"demo", "f", "--at", "-1"},
          {"demo", "f", "--fps", "0"}, {"demo", "f", "-j", "two"}}) {
        Parsed p;
        EXPECT_THROW(parse(p, bad), CLI::ParseError) << bad.back();
        EXPECT_FALSE(p.ran);
    }
}

TEST(CommandLine, HiddenCommandsAreLeftOutOfHelpAndDefaultsShown) {
    CLI::App app{"test"};
    Command root(&app);
    int jobs = 2;
    Command demo = root.subcommand("demo", "a demo command");
    demo.option("--jobs", jobs, "runs").show_default();
    root.subcommand("internal", "not in help").hide();
    const std::string help = app.help();
    EXPECT_NE(help.find("demo"), std::string::npos);
    EXPECT_EQ(help.find("internal"), std::string::npos);
    EXPECT_NE(demo.app()->help().find("=2"), std::string::npos) << demo.app()->help();
}

} // namespace
