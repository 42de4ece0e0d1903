// The settings table's <Simulator> rows come from sim::for_each_field.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cic/io/settings_table.hpp"
#include "cic/sim/config.hpp"

using namespace cic::sim;

TEST(SettingsTable, SimulatorRowsAreSimConfigsFieldsWithTheirRanges) {
    std::set<std::string> keys;
    const SimConfig defaults;
    for_each_field(defaults, [&](const FieldSpec& spec, const auto&) {
        const auto* row = cic::io::find_setting("Simulator", spec.key);
        ASSERT_NE(row, nullptr) << spec.key;
        EXPECT_EQ(row->doc, spec.doc);
        if (row->type != cic::io::ValueType::Bool) {
            EXPECT_EQ(row->min, spec.min) << spec.key;
            EXPECT_EQ(row->max, spec.max) << spec.key;
            EXPECT_EQ(row->min_exclusive, spec.min_exclusive) << spec.key;
        }
        keys.insert(std::string(spec.key));
    });
    EXPECT_EQ(keys.size(), 21u);
}
