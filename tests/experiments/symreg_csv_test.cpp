// CSV data files: reading, relative paths, and errors with file:line.
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cic/core/error.hpp"
#include "cic/experiments/symreg/problem.hpp"

using namespace cic::symreg;
using cic::InputError;
using testing::HasSubstr;

namespace {

namespace fs = std::filesystem;

fs::path write(const std::string& name, const std::string& text) {
    const fs::path dir = fs::path(testing::TempDir()) / "cic_symreg_csv";
    fs::create_directories(dir);
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
}

InputError error_of(const fs::path& p) {
    try {
        load_csv(p);
    } catch (const InputError& e) {
        return e;
    }
    return InputError("no error");
}

} // namespace

TEST(SymregCsv, ReadsHeaderRowsCommentsAndBlankLines) {
    const auto p = write("good.csv",
                         "# made by hand\n"
                         "a, b ,y\n"
                         "1,2,3\n"
                         "\n"
                         " -0.5 , 1e-3 , 4.25 \r\n"
                         "# trailing comment\n");
    const auto d = load_csv(p);
    EXPECT_EQ(d.variable_names, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.variables(), 2);
    ASSERT_EQ(d.rows(), 2u);
    EXPECT_EQ(d.columns[0], (std::vector<double>{1, -0.5}));
    EXPECT_EQ(d.columns[1], (std::vector<double>{2, 1e-3}));
    EXPECT_EQ(d.target, (std::vector<double>{3, 4.25}));
}

TEST(SymregCsv, DataFileWinsAndResolvesAgainstBaseDir) {
    const auto p = write("rel.csv", "x,y\n0,1\n1,2\n");
    SymregConfig c;
    c.target = "koza-1";
    c.data_file = p.filename().string();
    const auto d = make_dataset(c, p.parent_path().string());
    EXPECT_EQ(d.rows(), 2u);
    EXPECT_EQ(d.target, (std::vector<double>{1, 2}));
    c.data_file = p.string();   // absolute paths ignore base_dir
    EXPECT_EQ(make_dataset(c, "/nonexistent").rows(), 2u);
}

TEST(SymregCsv, ErrorsNameFileAndLine) {
    auto e = error_of(write("cols.csv", "x,y\n1,2\n\n3,4,5\n"));
    EXPECT_EQ(e.line(), 4);
    EXPECT_THAT(e.what(), HasSubstr("cols.csv:4: expected 2 columns as in the header, found 3"));

    e = error_of(write("nan.csv", "x,y\n1,2\n3,abc\n"));
    EXPECT_EQ(e.line(), 3);
    EXPECT_THAT(e.what(), HasSubstr("column 2 (target): 'abc' is not a finite number"));

    e = error_of(write("var.csv", "speed,y\n1x,2\n"));
    EXPECT_EQ(e.line(), 2);
    EXPECT_THAT(e.what(), HasSubstr("column 1 (speed): '1x'"));

    e = error_of(write("inf.csv", "x,y\n1,inf\n"));
    EXPECT_EQ(e.line(), 2);

    e = error_of(write("empty_field.csv", "x,y\n1,\n"));
    EXPECT_EQ(e.line(), 2);

    EXPECT_THAT(error_of(write("header_only.csv", "x,y\n")).what(), HasSubstr("no data rows"));
    EXPECT_THAT(error_of(write("empty.csv", "# nothing\n")).what(), HasSubstr("empty"));
    EXPECT_THAT(error_of(write("one.csv", "y\n1\n")).what(), HasSubstr("one.csv:1: the header needs at least two"));
    EXPECT_THAT(error_of("/nonexistent/dir/data.csv").what(), HasSubstr("cannot open"));
}

TEST(SymregCsv, SameFileSameData) {
    const auto p = write("same.csv", "x,y\n0.1,0.2\n0.3,0.4\n");
    const auto a = load_csv(p), b = load_csv(p);
    EXPECT_EQ(a.columns, b.columns);
    EXPECT_EQ(a.target, b.target);
}
