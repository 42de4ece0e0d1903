// `cic export` (cic/report/export.hpp): one CSV row per individual per saved
// generation, from run folders and studies; eq. 7.1's terms on request.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cic/io/population_xml.hpp"
#include "cic/report/export.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using namespace cic::testing;

namespace {

std::vector<std::vector<std::string>> rows_of(const std::string& csv) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);   // header
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream fields(line);
        while (std::getline(fields, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

TEST(Export, EveryIndividualOfEverySavedGenerationWithItsTerms) {
    const fs::path dir = temp_dir("export-run");
    const auto r = run_settings(dir, "h", tiny_hypergp_settings(3, 2));
    ASSERT_EQ(r.rc, 0) << r.log;
    ASSERT_EQ(run_command("export " + r.run.string() + " --terms --out " + (dir / "x.csv").string(), dir / "x.log"), 0)
        << read_text(dir / "x.log");
    const std::string csv = read_text(dir / "x.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n') + 1), cic::report::kExportHeader);
    const auto rows = rows_of(csv);
    std::size_t expected = 0;
    for (int g = 0; g < 3; ++g) {
        const auto pop = cic::io::load_population(r.run / ("populations/gen-000" + std::to_string(g) + ".xml"));
        expected += pop.population.size();
        const auto& first = pop.population.individuals.front();
        bool found = false;
        for (const auto& row : rows)
            if (row[3] == std::to_string(g) && row[4] == std::to_string(first->id)) {
                found = true;
                EXPECT_EQ(std::stod(row[5]), first->fitness);
                EXPECT_EQ(row[10], first->failed ? "1" : "0");
                EXPECT_EQ(row[11], first->genotype.front().to_string());
            }
        EXPECT_TRUE(found) << "generation " << g;
    }
    EXPECT_EQ(rows.size(), expected);
    for (const auto& row : rows) {
        ASSERT_EQ(row.size(), 14u);
        EXPECT_EQ(row[12] + row[13], "");   // cell and descriptor belong to MAP-Elites runs
        if (row[10] == "1") continue;
        // No penalty in these settings: the terms add up to the fitness (eq. 7.1).
        EXPECT_NEAR(std::stod(row[6]) + std::stod(row[7]), std::stod(row[5]), 1e-9) << row[11];
    }
    EXPECT_EQ(run_command("export " + (dir / "nothing").string(), dir / "bad.log"), 2);
    EXPECT_NE(read_text(dir / "bad.log").find("not a run folder"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Export, AStudyGivesEachRunWithItsConfigAndSeed) {
    const fs::path dir = temp_dir("export-study");
    write_text(dir / "s.xml", tiny_sweep_text("s", dir / "study", 6, 2, 2.0,
                                              "<grid><vary key=\"GP.tournament_size\">2 3</vary></grid>", 2));
    ASSERT_EQ(run_command("--quiet sweep " + (dir / "s.xml").string() + " --jobs 2", dir / "s.log"), 0)
        << read_text(dir / "s.log");
    ASSERT_EQ(run_command("export " + (dir / "study").string() + " --out " + (dir / "x.csv").string(), dir / "x.log"), 0)
        << read_text(dir / "x.log");
    const auto rows = rows_of(read_text(dir / "x.csv"));
    EXPECT_EQ(rows.size(), 4u * 2u * 6u);   // 4 runs, 2 generations, 6 individuals
    for (const auto& row : rows) {
        EXPECT_TRUE(row[1] == "tournament_size=2" || row[1] == "tournament_size=3") << row[1];
        EXPECT_TRUE(row[2] == "1" || row[2] == "2") << row[2];
        EXPECT_NE(row[0].find("/runs/" + row[1] + "/s" + row[2]), std::string::npos) << row[0];
        EXPECT_EQ(row[6], "");   // no --terms
    }
    fs::remove_all(dir);
}

} // namespace
